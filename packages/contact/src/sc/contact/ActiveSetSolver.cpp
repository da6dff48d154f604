#include "sc/contact/ActiveSetSolver.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>

#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_MultiVector.hpp>
#include <Tpetra_Vector.hpp>

#include <sc/core/Collective.hpp>
#include <sc/core/Error.hpp>
#include <sc/core/Parameters.hpp>
#include <sc/disc/MixedElasticitySpace.hpp>
#include <sc/mesh/SimplexMesh.hpp>
#include <sc/solvers/LinearSolver.hpp>

#include "sc/contact/ContactConstraints.hpp"
#include "sc/contact/Obstacle.hpp"
#include "sc/contact/StateTransfer.hpp"

namespace sc::contact {

Teuchos::RCP<const Teuchos::ParameterList> ActiveSetSolver::getValidParameters()
{
  static Teuchos::RCP<const Teuchos::ParameterList> valid = [] {
    auto pl = Teuchos::rcp(new Teuchos::ParameterList("Newton"));
    core::declareInt(*pl, "Maximum iterations", 50,
                     "Semismooth Newton (active-set) steps before giving up with an error.", 1,
                     10000);
    core::declareReal(*pl, "Penalty factor", 1.0,
                      "Factor on c = 2μ/(h_F |F|) (docs/theory.md §\"Contact and friction\"). The "
                      "solution does not depend on c; "
                      "a very large c can make Coulomb cycle.",
                      0.0, true, core::kInfinity, false);
    core::declareInt(*pl, "Maximum remedies", 5,
                     "Cycle remedies (points whose slip direction flipped move to stick) before "
                     "the solver stops with an error.",
                     0, 1000);
    core::declareChoice(*pl, "3D slip linearisation", "Hueber-Stadler-Wohlmuth",
                        {"Hueber-Stadler-Wohlmuth", "Frozen direction"},
                        "3D Coulomb slip rows: the Newton linearisation of the friction disc "
                        "(Hueber, Stadler, Wohlmuth 2008), or the slip direction of the last step "
                        "frozen (a fixed point: converges linearly, many more steps).");
    core::declareChoice(
        *pl, "Coulomb method", "Newton, fixed point fallback",
        {"Newton, fixed point fallback", "Newton", "Fixed point"},
        "Coulomb friction: semismooth Newton (falling back to the fixed point if it "
        "does not converge), Newton only (error if it does not converge), or the "
        "fixed point on the friction bound (a Tresca problem per outer step).");
    core::declareInt(*pl, "Maximum fixed-point iterations", 50,
                     "Outer steps of the Coulomb fixed point before giving up with an error.", 1,
                     10000);
    core::declareReal(*pl, "Fixed-point tolerance", 1e-8,
                      "The fixed point stops when max|Δs_p| <= tolerance × max s_p (s = μ|σ_N|).",
                      0.0, true, 1.0, false);
    core::declareChoice(*pl, "Stopping", "Fixed", {"Fixed", "Balanced"},
                        "Stopping of the Newton steps' Krylov solves (Linear Solver/Type = "
                        "Iterative): Fixed, at Linear Solver/Iterative/Tolerance, and from the "
                        "second cycle on the solve of the step that settles the active set "
                        "continued to an estimated algebraic error of at most 1e-7 × η_CF of the "
                        "previous cycle (docs/solvers.md \"Iterative solver\"); Balanced, from "
                        "the second cycle on at an estimated algebraic error (energy norm of the "
                        "stresses) of at most 'Balance fraction' × η_CF of the previous cycle "
                        "(docs/theory.md §\"Solves balanced with the discretisation error\"). "
                        "The Newton loop stops on a settled active set either way.");
    core::declareReal(
        *pl, "Balance fraction", 1e-3,
        "Stopping = Balanced: the fraction γ of η_CF that the estimated algebraic "
        "error may reach. The default keeps the load, the half-width and the peak "
        "pressure as accurate as with the fixed tolerance (they converge faster than "
        "η_CF; docs/performance.md \"Solves balanced with the discretisation error\").",
        0.0, true, 1.0, false);
    return pl;
  }();
  return valid;
}

ActiveSetSolver::ActiveSetSolver(const disc::MixedElasticitySpace& space,
                                 const ContactSettings& settings, const core::Material& material,
                                 const std::vector<std::string>& contactBoundaries,
                                 Teuchos::RCP<const Teuchos::Comm<int>> comm)
    : space_(space), settings_(settings), comm_(std::move(comm)),
      obstacle_(createObstacle(settings, space.dim()))
{
  meshSize_ = missCap(space.mesh()) / 10.0;
  auto constraints =
      buildContactConstraints(space, settings, material, contactBoundaries, *obstacle_, *comm_);
  faces_ = std::move(constraints.faces);
  points_ = std::move(constraints.points);
  bernstein_ = constraints.bernstein;
}

ActiveSetSolver::~ActiveSetSolver() = default;

bool ActiveSetSolver::hasFriction() const { return settings_.needsFriction(); }

long long ActiveSetSolver::globalNumPoints() const
{
  return core::sumOverRanks(*comm_, static_cast<long long>(points_.size()));
}

void ActiveSetSolver::transferState(const std::vector<ContactPoint>& previous,
                                    const std::vector<int>& parentFace)
{
  transferContactState(points_, previous, parentFace, space_.mesh(), *comm_);
}

void ActiveSetSolver::evaluate(const CrsMatrix& K, const MultiVector& b, const MultiVector& x)
{
  const int d = space_.dim();
  MultiVector R(K.getRangeMap(), 1);
  K.apply(x, R);
  R.update(-1.0, b, 1.0);  // R = K x − b: the first block row's residual = ⟨ũ, τn⟩_ΓC
  auto xv = x.getData(0);
  auto rv = R.getData(0);
  const auto& map = *x.getMap();
  auto dot = [](const double* a, const std::array<double, 3>& v) {
    return a[0] * v[0] + a[1] * v[1] + a[2] * v[2];
  };
  for (auto& p : points_) {
    const ContactFace& cf = faces_[p.block];
    // τ_p = Σ_q V⁻¹(p, q) t(x_q), t(x_q) = s_q x_q;  ρ_p = Σ_q V(q, p) R_q / s_q.
    double t[3] = {0, 0, 0}, r[3] = {0, 0, 0};
    for (int q = 0; q < cf.m; ++q) {
      const double vinv = cf.Vinv[p.index * cf.m + q], v = cf.V[q * cf.m + p.index];
      if (vinv == 0.0 && v == 0.0) continue;
      for (int i = 0; i < d; ++i) {
        const auto lid = map.getLocalElement(cf.gids[q][i]);
        t[i] += vinv * cf.scale[q] * xv[lid];
        r[i] += v * rv[lid] / cf.scale[q];
      }
    }
    p.sigmaN = dot(t, p.n);
    p.rN = dot(r, p.n);
    double tq[3] = {0, 0, 0};
    for (int i = 0; i < d; ++i)
      tq[i] = cf.scale[p.index] * xv[map.getLocalElement(cf.gids[p.index][i])];
    p.sigmaNAtDofPoint = dot(tq, p.n);
    p.sigmaT = {dot(t, p.t1), d == 3 ? dot(t, p.t2) : 0.0};
    p.rT = {dot(r, p.t1), d == 3 ? dot(r, p.t2) : 0.0};
  }
}

namespace {
// The damped entry test of a load step's first Newton update (docs/contact.md "Load steps"): a
// free point enters contact if it penetrates at this fraction of the way from the previous
// step's r_N to the first solve's. The first solve, with the previous step's contact zone,
// leaves the surface beyond it unsupported, so it penetrates deeper than it will: the undamped
// test takes in too many points, which then leave one per Newton step. Measured on
// input/hertz2d_incremental.xml (N = 5; Newton steps of steps 2-5): 7, 6, 6, 6 undamped, 4, 5,
// 5, 5 at 0.5, 4, 3, 4, 4 at 0.7.
constexpr double kEntryDamping = 0.7;
}  // namespace

int ActiveSetSolver::firstUpdateOfLoadStep()
{
  const auto solved = points_;
  const int exact = updateState(false);
  if (exact == 0) return 0;  // converged: decided by the undamped test alone
  auto undamped = std::move(points_);
  points_ = solved;
  const int damped = updateState(false, true);
  if (damped > 0) return damped;
  points_ = std::move(undamped);  // the damped test alone would repeat the same state
  return exact;
}

int ActiveSetSolver::updateState(bool flipToStick, bool dampedEntry)
{
  const int nt = space_.dim() - 1;
  const bool friction = settings_.needsFriction();
  // In the Coulomb fixed point each inner problem is Tresca with the bounds μ|σ_N| of the last
  // outer iterate (p.frictionBound).
  const bool tresca = settings_.frictionLaw == FrictionLaw::Tresca || fixedPoint_;
  const double mu = settings_.frictionCoefficient;
  int changes = 0;
  for (auto& p : points_) {
    const double rN = dampedEntry && p.status == PointStatus::Free
                          ? (1.0 - kEntryDamping) * p.previousRN + kEntryDamping * p.rN
                          : p.rN;
    const double aug = p.sigmaN - p.c * (rN - p.gap);
    PointStatus status = PointStatus::Free;
    std::array<double, 2> xi{0.0, 0.0};
    if (aug < 0.0) {
      if (!friction) {
        status = PointStatus::Slip;  // frictionless contact: σ_T = 0, free sliding
      } else {
        // Hüeber–Stadler–Wohlmuth bound: the augmented normal stress, not the old σ_N (which
        // is 0 for a newly active point).
        const double bound = tresca ? trescaBound(p) : mu * std::max(0.0, -aug);
        // Load steps: the slip increment r_T − r_T^{n−1} (zero history in the first step).
        const auto r0 = p.previousRT();
        double z[2] = {p.sigmaT[0] - p.c * (p.rT[0] - r0[0]),
                       p.sigmaT[1] - p.c * (p.rT[1] - r0[1])},
               norm = 0.0;
        for (int k = 0; k < nt; ++k)
          norm += z[k] * z[k];
        norm = std::sqrt(norm);
        // After a load step, a point that slipped and carries the same load again sits on the
        // cone's edge, |z| = s up to round-off, where round-off alone would flip it between stick
        // and slip from one Newton step to the next (seen at 4 ranks): it sticks within 1e-9 of
        // s. Without history (one step, the static problem) the test is exact as it always was.
        const double slack = (r0[0] != 0.0 || r0[1] != 0.0) ? 1e-9 * bound : 0.0;
        if (norm <= bound + slack || norm == 0.0) {
          status = PointStatus::Stick;
        } else {
          status = PointStatus::Slip;
          for (int k = 0; k < nt; ++k)
            xi[k] = z[k] / norm;
        }
      }
    }
    bool flipped = false;
    if (status == PointStatus::Slip && p.status == PointStatus::Slip && friction)
      flipped = xi[0] * p.direction[0] + xi[1] * p.direction[1] < 0.0;
    if (flipped && flipToStick) {
      status = PointStatus::Stick;
      xi = {0.0, 0.0};
    }
    // 2D: ξ = ±1, any flip is a change. 3D: the frozen-direction fixed point converges
    // linearly; a direction that moved by less than 1e-6 counts as settled.
    double dxi = std::abs(xi[0] - p.direction[0]) + std::abs(xi[1] - p.direction[1]);
    if (status != p.status || (status == PointStatus::Slip && dxi > (nt == 1 ? 1e-9 : 1e-6)))
      ++changes;
    p.status = status;
    p.direction = xi;
  }
  return core::sumOverRanks(*comm_, changes);
}

std::array<ActiveSetSolver::ConstraintRow, 3>
ActiveSetSolver::constraintRows(const ContactPoint& p) const
{
  const int d = space_.dim();
  const bool friction = settings_.needsFriction();
  const bool tresca = settings_.frictionLaw == FrictionLaw::Tresca || fixedPoint_;
  const double mu = settings_.frictionCoefficient;
  std::array<ConstraintRow, 3> rows;
  // Frame vectors per equation: row 0 normal, rows 1.. tangential.
  const std::array<const std::array<double, 3>*, 3> frame = {&p.n, &p.t1, &p.t2};
  // 3D Coulomb slip: Hüeber–Stadler–Wohlmuth linearisation of |z|σ_T = s z (docs/theory.md
  // §"Contact and friction"), with z = σ_T − c r_T, s = μ max(0, −(σ_N − c(r_N − G))) at the last
  // iterate k, ξ = z/|z|, σ̃ = σ_T^k projected onto the disc of radius s^k, M = (σ̃ ξᵀ − s^k
  // I)/|z^k|:
  //   (I + M) σ_T − c M r_T + μ ξ σ_N − μ c ξ r_N = σ̃ − s^k ξ − μ c ξ G.
  // Frozen ξ (σ_T = −μ ξ σ_N) is the fallback when |z^k| or s^k vanish (a point that has not
  // been evaluated in contact yet).
  const bool hsw = settings_.newton.hueberStadlerWohlmuth && d == 3 && friction && !tresca &&
                   p.status == PointStatus::Slip;
  double hswM[2][2] = {{0, 0}, {0, 0}}, hswRhs[2] = {0, 0};
  bool hswRow = false;
  const auto r0 = p.previousRT();  // r_T^{n−1} of load steps (zero in the first step)
  if (hsw) {
    const double z[2] = {p.sigmaT[0] - p.c * (p.rT[0] - r0[0]),
                         p.sigmaT[1] - p.c * (p.rT[1] - r0[1])};
    const double zn = std::hypot(z[0], z[1]);
    const double bound = mu * std::max(0.0, -(p.sigmaN - p.c * (p.rN - p.gap)));
    if (zn > 0.0 && bound > 0.0) {
      hswRow = true;
      const double tn = std::hypot(p.sigmaT[0], p.sigmaT[1]);
      const double shrink = tn > bound ? bound / tn : 1.0;
      const double st[2] = {shrink * p.sigmaT[0], shrink * p.sigmaT[1]};
      for (int j = 0; j < 2; ++j) {
        for (int l = 0; l < 2; ++l)
          hswM[j][l] = (st[j] * p.direction[l] - (j == l ? bound : 0.0)) / zn;
        hswRhs[j] = st[j] - bound * p.direction[j] - mu * p.c * p.direction[j] * p.gap;
      }
      // z depends on r_T through r_T − r_T^{n−1}: −c M (r_T − r_T^{n−1}) on the left.
      for (int j = 0; j < 2; ++j)
        hswRhs[j] -= p.c * (hswM[j][0] * r0[0] + hswM[j][1] * r0[1]);
    }
  }
  for (int r = 0; r < d; ++r) {
    const auto& dir = *frame[r];
    std::array<double, 3> alpha{0, 0, 0}, beta{0, 0, 0};
    double gamma = 0.0;
    if (r == 0) {
      if (p.status == PointStatus::Free) {
        beta = dir;  // σ_N = 0
      } else {
        alpha = dir;  // r_N = G
        gamma = p.gap;
      }
    } else {
      const int k = r - 1;
      if (hswRow) {
        // Row j of the HSW system: traction part and dual part (r = ρ in the frame).
        for (int i = 0; i < d; ++i) {
          beta[i] = (1.0 + hswM[k][k]) * (k == 0 ? p.t1[i] : p.t2[i]) +
                    hswM[k][1 - k] * (k == 0 ? p.t2[i] : p.t1[i]) + mu * p.direction[k] * p.n[i];
          alpha[i] =
              -p.c * (hswM[k][0] * p.t1[i] + hswM[k][1] * p.t2[i] + mu * p.direction[k] * p.n[i]);
        }
        gamma = hswRhs[k];
      } else if (p.status == PointStatus::Stick) {
        alpha = dir;  // r_T = r_T^{n−1}: no slip increment (0 in the first load step)
        gamma = r0[k];
      } else if (p.status == PointStatus::Slip && friction) {
        if (tresca) {
          beta = dir;  // σ_T,k = s ξ_k
          gamma = trescaBound(p) * p.direction[k];
        } else {
          for (int i = 0; i < d; ++i)
            beta[i] = dir[i] + mu * p.direction[k] * p.n[i];  // σ_T,k + μ ξ_k σ_N = 0
        }
      } else {
        beta = dir;  // σ_T = 0 (free or frictionless)
      }
    }
    rows[r] = {alpha, beta, gamma};
  }
  return rows;
}

Teuchos::RCP<ActiveSetSolver::CrsMatrix>
ActiveSetSolver::modifiedMatrix(const CrsMatrix& K, MultiVector& rhs, const MultiVector& b,
                                const Teuchos::RCP<CrsMatrix>& reuse) const
{
  const int d = space_.dim();
  auto A = solvers::copyMatrixValues(K, reuse);
  A->resumeFill();
  rhs.assign(b);
  auto rhsData = rhs.getDataNonConst(0);
  auto bData = b.getData(0);
  const auto& rowMap = *K.getRowMap();
  const auto& colMap = *K.getColMap();
  using LO = CrsMatrix::local_ordinal_type;
  // The points of each face block replace the face's rows together: new row (r, p) goes into the
  // slot of DOF row (q = p, i = r). Every row is
  //   Σ_i α_i ρ_{i,p} + Σ_i β_i τ_{i,p} = γ,
  // with ρ_{i,p} = Σ_q V(q,p)(K x − b)_{q,i}/s_q (dual: rows of K) and τ_{i,p} = Σ_q V⁻¹(p,q) s_q
  // x_{q,i} (traction: columns of the face DOFs), written in the frame (n, t1[, t2]).
  std::vector<int> first(faces_.size(), -1);
  for (std::size_t k = 0; k < points_.size(); ++k)
    if (first[points_[k].block] < 0) first[points_[k].block] = static_cast<int>(k);
  for (std::size_t blk = 0; blk < faces_.size(); ++blk) {
    const ContactFace& cf = faces_[blk];
    const int m = cf.m;
    // Rows of the face DOFs on one common column pattern (they are the DOFs of one element).
    std::vector<std::vector<LO>> lid(m, std::vector<LO>(d));
    std::vector<LO> pattern;
    std::vector<std::vector<double>> rowVals(static_cast<std::size_t>(m) * d);
    std::vector<std::vector<LO>> colLid(m, std::vector<LO>(d));
    for (int q = 0; q < m; ++q)
      for (int i = 0; i < d; ++i) {
        lid[q][i] = rowMap.getLocalElement(cf.gids[q][i]);
        colLid[q][i] = colMap.getLocalElement(cf.gids[q][i]);
        CrsMatrix::local_inds_host_view_type inds;
        CrsMatrix::values_host_view_type v;
        K.getLocalRowView(lid[q][i], inds, v);
        if (pattern.empty()) pattern.assign(inds.data(), inds.data() + inds.extent(0));
        SC_THROW_IF(inds.extent(0) != pattern.size() ||
                        !std::equal(pattern.begin(), pattern.end(), inds.data()),
                    core::InternalError,
                    "the stress rows of contact face " << points_[first[blk]].face
                                                       << " have different column patterns");
        rowVals[q * d + i].assign(v.data(), v.data() + v.extent(0));
      }
    auto position = [&](LO col) {
      const auto it = std::find(pattern.begin(), pattern.end(), col);
      SC_THROW_IF(it == pattern.end(), core::InternalError, "a contact face DOF is not in its row");
      return static_cast<std::size_t>(it - pattern.begin());
    };
    for (int pp = 0; pp < m; ++pp) {
      const ContactPoint& p = points_[first[blk] + pp];
      const auto rows = constraintRows(p);
      for (int r = 0; r < d; ++r) {
        const auto& [alpha, beta, gamma] = rows[r];
        const bool traction = beta[0] != 0.0 || beta[1] != 0.0 || beta[2] != 0.0;
        std::vector<double> newVals(pattern.size(), 0.0);
        double newRhs = gamma;
        for (int q = 0; q < m; ++q) {
          const double v = cf.V[q * m + pp] / cf.scale[q], vinv = cf.Vinv[pp * m + q] * cf.scale[q];
          for (int i = 0; i < d; ++i) {
            if (alpha[i] != 0.0 && v != 0.0) {
              const auto& row = rowVals[q * d + i];
              for (std::size_t c = 0; c < pattern.size(); ++c)
                newVals[c] += alpha[i] * v * row[c];
              newRhs += alpha[i] * v * bData[lid[q][i]];
            }
            if (beta[i] != 0.0 && vinv != 0.0) newVals[position(colLid[q][i])] += beta[i] * vinv;
          }
        }
        // Scale to the size of the row the new one replaces: a dual row (combination of K rows
        // over s) by the mean |s_q|; a row with a traction part by |K_diag|/mean |s_q|, so that the
        // system's rows stay comparable under any E.
        const LO slot = lid[pp][r];
        const double w = traction
                             ? std::abs(rowVals[pp * d + r][position(colLid[pp][r])]) / cf.meanScale
                             : cf.meanScale;
        for (double& v : newVals)
          v *= w;
        A->replaceLocalValues(slot, Teuchos::ArrayView<const LO>(pattern),
                              Teuchos::ArrayView<const double>(newVals));
        rhsData[slot] = w * newRhs;
      }
    }
  }
  A->fillComplete(K.getDomainMap(), K.getRangeMap());
  return A;
}

void ActiveSetSolver::startNearestPointsInContact()
{
  long long active = 0, globalActive = 0;
  double nearest = 1e300, globalNearest = 1e300;
  for (const auto& p : points_) {
    active += p.status != PointStatus::Free;
    nearest = std::min(nearest, p.gap / p.weight);
  }
  globalActive = core::sumOverRanks(*comm_, active);
  globalNearest = core::minOverRanks(*comm_, nearest);
  if (globalActive > 0) return;
  // The mean gap, not the gap at the point: the weighted gap G_p is what the contact row
  // prescribes (r_N = G_p), and the weights are positive (checked in the constructor).
  for (auto& p : points_)
    if (p.gap / p.weight <= globalNearest + 1e-9 * meshSize_) {
      p.status = settings_.needsFriction() ? PointStatus::Stick : PointStatus::Slip;
      p.direction = {0.0, 0.0};
    }
}

void ActiveSetSolver::checkSomePointInContact(int step) const
{
  long long active = 0;
  for (const auto& p : points_)
    active += p.status != PointStatus::Free;
  const long long global = core::sumOverRanks(*comm_, active);
  SC_THROW_IF(global == 0, core::ConvergenceError,
              "no contact point is in contact after Newton step "
                  << step << ", but the contact alone holds the body along the obstacle's normal "
                  << "(no Displacement part; the Symmetry parts hold the other axes): the loads "
                  << "pull the body off the obstacle and there is no equilibrium "
                  << "(docs/theory.md §\"Loads and supports\").");
}

double ActiveSetSolver::trescaBound(const ContactPoint& p) const
{
  return fixedPoint_ ? p.frictionBound : settings_.trescaBound;
}

void ActiveSetSolver::solve(const CrsMatrix& K, const MultiVector& b, solvers::LinearSolver& solver,
                            MultiVector& x)
{
  fixedPoint_ = false;
  const bool coulomb = settings_.needsFriction() && settings_.frictionLaw == FrictionLaw::Coulomb;
  if (!coulomb || settings_.newton.coulombMethod == "Newton") {
    solveActiveSet(K, b, solver, x);
    return;
  }
  if (settings_.newton.coulombMethod == "Newton, fixed point fallback") {
    try {
      solveActiveSet(K, b, solver, x);
      return;
    } catch (const core::ConvergenceError& e) {
      // Every rank throws together (the decisions are collective): fall back on all of them.
      if (comm_->getRank() == 0)
        std::cout << "  contact: semismooth Newton failed (" << e.what()
                  << "); falling back to the Coulomb fixed point" << std::endl;
    }
  }
  // Coulomb as a fixed point on the friction bound (docs/theory.md §"Contact and friction"
  // fallback): Tresca problems with s_p = μ max(0, −σ_N,p) of the previous outer iterate, until s
  // settles.
  const auto first = stats_;
  int outer = 0, total = 0;
  fixedPoint_ = true;
  for (auto& p : points_)
    p.frictionBound = settings_.frictionCoefficient * std::max(0.0, -p.sigmaN);
  for (outer = 1; outer <= settings_.newton.maxFixedPointIterations; ++outer) {
    solveActiveSet(K, b, solver, x);
    total += stats_.newtonIterations;
    double change = 0.0, size = 0.0;
    for (auto& p : points_) {
      const double s = settings_.frictionCoefficient * std::max(0.0, -p.sigmaN);
      change = std::max(change, std::abs(s - p.frictionBound));
      size = std::max(size, s);
      p.frictionBound = s;
    }
    double local[2] = {change, size}, global[2];
    core::maxOverRanks(*comm_, 2, local, global);
    if (stepCallback_ && comm_->getRank() == 0)
      std::cout << "  contact: fixed point " << outer << ": bound change "
                << global[0] / std::max(global[1], 1e-300) << " (relative)" << std::endl;
    if (global[0] <= settings_.newton.fixedPointTolerance * global[1]) {
      fixedPoint_ = false;
      stats_.newtonIterations = total;
      stats_.fixedPointIterations = outer;
      stats_.remedies += first.remedies;
      // The last inner problem's slip points satisfy |σ_T| = s = μ|σ_N| to the tolerance.
      return;
    }
  }
  fixedPoint_ = false;
  stats_.converged = false;
  stats_.fixedPointIterations = settings_.newton.maxFixedPointIterations;
  SC_THROW_IF(true, core::ConvergenceError,
              "the Coulomb fixed point did not settle in "
                  << settings_.newton.maxFixedPointIterations
                  << " outer steps ('Contact/Newton/Maximum fixed-point iterations').");
}

namespace {
// Sets BlockStructure::stressBasis of a solver for one contact solve and restores the previous
// block structure when the solve ends (or throws).
class StressBasisScope {
public:
  explicit StressBasisScope(solvers::LinearSolver& solver)
      : solver_(solver), saved_(solver.blockStructure())
  {
  }
  ~StressBasisScope()
  {
    if (set_) solver_.setBlockStructure(saved_);
  }
  void set(const Teuchos::RCP<const Tpetra::CrsMatrix<>>& basis)
  {
    auto blocks = saved_;
    blocks.stressBasis = basis;
    solver_.setBlockStructure(blocks);
    set_ = true;
  }

private:
  solvers::LinearSolver& solver_;
  solvers::BlockStructure saved_;
  bool set_ = false;
};
}  // namespace

int ActiveSetSolver::linearSolve(solvers::LinearSolver& solver, const MultiVector& rhs,
                                 MultiVector& x, const CrsMatrix& energy)
{
  if (!balanced_ || !balanced_->appliesTo(solver)) {
    solver.solve(rhs, x);
    return solver.lastSolveStats().iterations;
  }
  const auto r = balanced_->solve(solver, rhs, x, energy, space_.numStressDofs());
  stats_.algebraicError = r.algebraicError;
  stats_.krylovTolerance = r.tolerance;
  stats_.balancedBound = balanced_->fraction() * balanced_->discretisationError();
  return r.iterations;
}

void ActiveSetSolver::solveActiveSet(const CrsMatrix& K, const MultiVector& b,
                                     solvers::LinearSolver& solver, MultiVector& x)
{
  stats_ = ContactStatistics();
  MultiVector rhs(b.getMap(), 1);
  std::vector<std::vector<long long>> history;  // local state signature per iteration
  // A state: statuses and slip directions (in 3D quantised at the settling tolerance, so that a
  // still-moving direction is not mistaken for a repeated state).
  auto signature = [&]() {
    std::vector<long long> s;
    for (const auto& p : points_) {
      s.push_back(static_cast<int>(p.status));
      for (double xi : p.direction)
        s.push_back(std::llround(xi * 1e6));
    }
    return s;
  };
  if (holdsBody_) startNearestPointsInContact();
  history.push_back(signature());
  // A direct solver is done with the previous step's matrix once it has factorised it: its
  // values are overwritten in the next step. A Krylov solver's preconditioner may keep it.
  Teuchos::RCP<CrsMatrix> A;
  // A Krylov solver with the stress multigrid gets the systems in the constraints' coordinates
  // y = T x (ContactElimination.cpp): free points' rows and columns eliminated, symmetric unless
  // slip rows mix coordinates; the multigrid learns the basis of the σ unknowns
  // (BlockStructure::stressBasis). With an exact stress block the replaced rows are kept: there
  // GMRES on them took fewer iterations on Hertz 2D (≤ 92 against 136 in cycle 15,
  // docs/solvers.md).
  const bool eliminate = solver.isIterative() && !solver.blockStructure().multigrid.empty();
  Elimination elimination;
  StressBasisScope basisScope(solver);
  if (eliminate) {
    elimination = eliminationBasis(K, b);
    basisScope.set(elimination.T);
  }
  for (int it = 1; it <= settings_.newton.maxIterations; ++it) {
    const auto stepStart = std::chrono::steady_clock::now();
    if (holdsBody_) checkSomePointInContact(it - 1);
    int linearIterations = 0;
    if (eliminate) {
      const bool symmetric = eliminatedMatrix(elimination, A, rhs);
      MultiVector y(x.getMap(), 1);
      elimination.T->apply(x, y);  // the previous iterate is the initial guess
      solver.setOperator(A, symmetric);
      linearIterations = linearSolve(solver, rhs, y, *elimination.G);  // G's σ block: Q_σᵀ A Q_σ
      elimination.Q->apply(y, x);
    } else {
      A = modifiedMatrix(K, rhs, b, solver.isIterative() ? Teuchos::null : A);
      // Contact rows make the system non-symmetric. Same graph every step: a direct solver keeps
      // its symbolic analysis and refactorises; x (the previous iterate) is a Krylov solver's
      // initial guess.
      solver.setOperator(A, false);
      linearIterations = linearSolve(solver, rhs, x, K);
    }
    if (solver.isIterative()) stats_.linearIterationsPerStep.push_back(linearIterations);
    stats_.newtonIterations = it;
    evaluate(K, b, x);
    const int changes =
        it == 1 && loadStepStart_ && !fixedPoint_ ? firstUpdateOfLoadStep() : updateState(false);
    stats_.changesPerIteration.push_back(changes);
    if (stepCallback_)
      stepCallback_(
          it, changes,
          std::chrono::duration<double>(std::chrono::steady_clock::now() - stepStart).count());
    if (changes == 0 && balanced_ && balanced_->finalApplies(solver)) {
      // The settled state's solve is the cycle's answer: it goes on until its estimated
      // algebraic error is a small fraction of η (BalancedStopping::finalSolve; η moves with the
      // algebraic residual, docs/solvers.md "Contact with the stress multigrid").
      BalancedStopping::Result r;
      if (eliminate) {
        MultiVector y(x.getMap(), 1);
        elimination.T->apply(x, y);
        r = balanced_->finalSolve(solver, rhs, y, *elimination.G, space_.numStressDofs());
        if (r.stages > 0) elimination.Q->apply(y, x);
      } else {
        r = balanced_->finalSolve(solver, rhs, x, K, space_.numStressDofs());
      }
      stats_.finalSolveIterations += r.iterations;
      stats_.finalAlgebraicError = r.algebraicError;
      stats_.finalBound = BalancedStopping::finalFraction() * balanced_->discretisationError();
      if (r.stages > 0) {
        evaluate(K, b, x);
        // the polished iterate may move a point that sat on a threshold: then go on
        const int again = updateState(false);
        stats_.changesPerIteration.back() = again;
        if (again != 0) continue;
      }
    }
    if (changes == 0 || stats_.changesPerIteration.back() == 0) {
      stats_.converged = true;
      return;
    }
    // A state seen before (on every rank) is a cycle.
    const auto sig = signature();
    int seenLocal = 0;
    for (std::size_t k = 0; k + 1 < history.size() && !seenLocal; ++k)
      seenLocal = history[k] == sig;
    const int seenAll = core::minOverRanks(*comm_, seenLocal);
    history.push_back(sig);
    if (seenAll) {
      SC_THROW_IF(stats_.remedies >= settings_.newton.maxRemedies, core::ConvergenceError,
                  "the contact active set cycles (a state repeated after "
                      << it << " Newton steps) and " << stats_.remedies
                      << " remedies did not help; try a smaller 'Contact/Newton/Penalty factor'.");
      ++stats_.remedies;
      updateState(true);  // points whose slip direction flipped go to the stick set
    }
  }
  SC_THROW_IF(true, core::ConvergenceError,
              "the contact active set did not settle in "
                  << settings_.newton.maxIterations
                  << " Newton steps ('Contact/Newton/Maximum iterations'); the last step changed "
                  << stats_.changesPerIteration.back() << " points.");
}

}  // namespace sc::contact
