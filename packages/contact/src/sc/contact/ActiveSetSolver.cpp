#include "sc/contact/ActiveSetSolver.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>

#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_MultiVector.hpp>
#include <Tpetra_Vector.hpp>

#include <sc/core/Error.hpp>
#include <sc/core/Parameters.hpp>
#include <sc/disc/ElementValues.hpp>
#include <sc/disc/FaceDofPoints.hpp>
#include <sc/disc/MixedElasticitySpace.hpp>
#include <sc/mesh/SimplexMesh.hpp>
#include <sc/solvers/DirectSolver.hpp>

#include "sc/contact/Obstacle.hpp"

namespace sc::contact {

std::string toString(PointStatus s)
{
  switch (s) {
  case PointStatus::Free: return "free";
  case PointStatus::Stick: return "stick";
  case PointStatus::Slip: return "slip";
  }
  return "?";
}

Teuchos::RCP<const Teuchos::ParameterList> ActiveSetSolver::getValidParameters()
{
  static Teuchos::RCP<const Teuchos::ParameterList> valid = [] {
    auto pl = Teuchos::rcp(new Teuchos::ParameterList("Newton"));
    core::declareInt(*pl, "Maximum iterations", 50,
                     "Semismooth Newton (active-set) steps before giving up with an error.", 1, 10000);
    core::declareReal(*pl, "Penalty factor", 1.0,
                      "Factor on c = 2μ/(h_F |F|) (DESIGN §3). The solution does not depend on c; "
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
    core::declareChoice(*pl, "Coulomb method", "Newton, fixed point fallback",
                        {"Newton, fixed point fallback", "Newton", "Fixed point"},
                        "Coulomb friction: semismooth Newton (falling back to the fixed point if it "
                        "does not converge), Newton only (error if it does not converge), or the "
                        "fixed point on the friction bound (a Tresca problem per outer step).");
    core::declareInt(*pl, "Maximum fixed-point iterations", 50,
                     "Outer steps of the Coulomb fixed point before giving up with an error.", 1, 10000);
    core::declareReal(*pl, "Fixed-point tolerance", 1e-8,
                      "The fixed point stops when max|Δs_p| <= tolerance × max s_p (s = μ|σ_N|).",
                      0.0, true, 1.0, false);
    return pl;
  }();
  return valid;
}

void checkContactDegree(int dim, int degree)
{
  const double w = disc::minRelativeFaceDofWeight(dim, degree);
  SC_THROW_IF(w <= 1e-10, core::InputError,
              "'Discretization/Degree' = "
                  << degree << " with contact in " << dim << "D: a contact point of RT_" << degree
                  << " has a non-positive quadrature weight (min ∫_F L_p / |F| = " << w
                  << "), so tractions that are non-positive at the points could pull on average: "
                     "the contact conditions would not bound the load. Valid with contact: "
                  << (dim == 2 ? "1, 2, 3, 4" : "1, 2") << " (docs/contact.md, 'Degree').");
  // 3D k = 4 has positive weights but no verification (a Hertz 3D run at k = 4 that resolves the
  // zone needs millions of DOFs): rejected rather than trusted untested.
  SC_THROW_IF(dim == 3 && degree > 2, core::InputError,
              "'Discretization/Degree' = " << degree << " with contact in 3D is not verified "
                  "(the Hertz 3D tests cover k = 1, 2). Valid with contact: 1, 2 "
                  "(docs/contact.md, 'Degree').");
}

ActiveSetSolver::ActiveSetSolver(const disc::MixedElasticitySpace& space,
                                 const core::ContactSettings& settings,
                                 const core::Material& material,
                                 const std::vector<std::string>& contactBoundaries,
                                 const Teuchos::ParameterList& newtonList,
                                 Teuchos::RCP<const Teuchos::Comm<int>> comm)
  : space_(space), settings_(settings), comm_(std::move(comm)),
    obstacle_(createObstacle(settings, space.dim()))
{
  Teuchos::ParameterList nl = newtonList;
  core::validateParameters(nl, *getValidParameters(), "Contact/Newton");
  maxIterations_ = nl.get<int>("Maximum iterations");
  maxRemedies_ = nl.get<int>("Maximum remedies");
  penaltyFactor_ = nl.get<double>("Penalty factor");
  useHsw_ = nl.get<std::string>("3D slip linearisation") == "Hueber-Stadler-Wohlmuth";
  coulombMethod_ = nl.get<std::string>("Coulomb method");
  maxFixedPointIterations_ = nl.get<int>("Maximum fixed-point iterations");
  fixedPointTolerance_ = nl.get<double>("Fixed-point tolerance");

  const auto& m = space.mesh();
  const int d = m.dim();
  // Gap cap for rays that miss the obstacle: 10 × the domain's bounding-box diagonal.
  double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300};
  for (int v = 0; v < m.numVertices(); ++v)
    for (int i = 0; i < d; ++i) {
      lo[i] = std::min(lo[i], m.vertex(v)[i]);
      hi[i] = std::max(hi[i], m.vertex(v)[i]);
    }
  double diag = 0.0;
  for (int i = 0; i < d; ++i)
    diag += (hi[i] - lo[i]) * (hi[i] - lo[i]);
  const double cap = 10.0 * std::sqrt(diag);
  const double twoMu = 2.0 * material.shearModulus();

  std::vector<int> contactIds;
  for (const auto& name : contactBoundaries)
    contactIds.push_back(m.boundaryId(name));
  const bool obstacleFrame = settings.frame == core::ContactFrame::ObstacleNormal;
  double minRelativeWeight = 1.0;  // min over points of ∫_F L_p / |F| (affine-invariant)
  disc::FaceValues fv(space, 2 * space.degree() + 2);
  for (int e : space.ownedElements()) {
    for (int lf = 0; lf <= d; ++lf) {
      const int f = m.elementFaces(e)[lf];
      if (!m.isBoundaryFace(f) ||
          std::find(contactIds.begin(), contactIds.end(), m.faceBoundaryId(f)) == contactIds.end())
        continue;
      const auto dofPoints = disc::stressFaceDofPoints(space, e, lf);
      fv.reinit(e, lf);
      // The contact frame (n, t1[, t2]): n along the obstacle's normal (out of the body) or the
      // face's outward normal; fv.normal() is the latter.
      std::array<double, 3> n = fv.normal();
      if (obstacleFrame)
        n = obstacle_->contactNormal(dofPoints.front().x.data());
      std::array<double, 3> t1{}, t2{};
      if (d == 2) {
        t1 = {-n[1], n[0], 0.0};
      } else {
        // t1 ⟂ n from the coordinate axis least aligned with n; t2 = n × t1.
        int axis = 0;
        for (int i = 1; i < 3; ++i)
          if (std::abs(n[i]) < std::abs(n[axis]))
            axis = i;
        std::array<double, 3> a{0, 0, 0};
        a[axis] = 1.0;
        const double an = a[0] * n[0] + a[1] * n[1] + a[2] * n[2];
        double norm = 0.0;
        for (int i = 0; i < 3; ++i) {
          t1[i] = a[i] - an * n[i];
          norm += t1[i] * t1[i];
        }
        for (double& c : t1)
          c /= std::sqrt(norm);
        t2 = {n[1] * t1[2] - n[2] * t1[1], n[2] * t1[0] - n[0] * t1[2], n[0] * t1[1] - n[1] * t1[0]};
      }
      const double area = m.faceMeasure(f);
      const double hF = d == 2 ? area : std::sqrt(area);
      for (const auto& dp : dofPoints) {
        ContactPoint p;
        p.face = f;
        for (int i = 0; i < d; ++i)
          p.gids[i] = space.elementDofs(e)[space.stressOffset(i) + dp.localDof];
        p.x = dp.x;
        p.n = n;
        p.t1 = t1;
        p.t2 = t2;
        p.scale = dp.scale;
        p.c = penaltyFactor_ * twoMu / (hF * area);
        for (int q = 0; q < fv.numPoints(); ++q) {
          const double psi = fv.stressNormal(dp.localDof, q) / dp.scale;  // ψ_p·n_F
          p.gap += fv.weight(q) * obstacle_->gap(fv.point(q), n.data(), cap) * psi;
          p.weight += fv.weight(q) * psi;
        }
        minRelativeWeight = std::min(minRelativeWeight, p.weight / area);
        points_.push_back(p);
      }
    }
  }
  // The contact conditions hold at the points; the load is Σ_p ∫_F L_p σ_N(p). With a negative
  // weight ∫_F L_p, tractions that are non-positive at every point can pull on average, and the
  // solver returns nonsense (degree 2 on the equispaced lattice did: a force of −40404). Reject
  // such a degree on every rank together.
  // checkContactDegree() rejects such degrees up front; this is the same check on the actual
  // faces (they must agree: the ratio is affine-invariant).
  double globalMin = 1.0;
  Teuchos::reduceAll<int, double>(*comm_, Teuchos::REDUCE_MIN, 1, &minRelativeWeight, &globalMin);
  SC_THROW_IF(globalMin <= 1e-10, core::InternalError,
              "a contact point of RT_" << space.degree() << " in " << d
                  << "D has a non-positive weight (min ∫_F L_p / |F| = " << globalMin
                  << ") although checkContactDegree accepted the degree.");
}

ActiveSetSolver::~ActiveSetSolver() = default;

bool ActiveSetSolver::hasFriction() const { return settings_.needsFriction(); }

long long ActiveSetSolver::globalNumPoints() const
{
  long long local = static_cast<long long>(points_.size()), global = 0;
  Teuchos::reduceAll<int, long long>(*comm_, Teuchos::REDUCE_SUM, 1, &local, &global);
  return global;
}

void ActiveSetSolver::setInitialState(const std::vector<ContactPoint>& previous)
{
  if (previous.empty())
    return;
  const int d = space_.dim();
  for (auto& p : points_) {
    double best = 1e300;
    for (const auto& q : previous) {
      double dist = 0.0;
      for (int i = 0; i < d; ++i)
        dist += (p.x[i] - q.x[i]) * (p.x[i] - q.x[i]);
      if (dist < best) {
        best = dist;
        p.status = q.status;
        p.direction = q.direction;
      }
    }
  }
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
  for (auto& p : points_) {
    double t[3] = {0, 0, 0}, r[3] = {0, 0, 0};
    for (int i = 0; i < d; ++i) {
      const auto lid = map.getLocalElement(p.gids[i]);
      t[i] = p.scale * xv[lid];
      r[i] = rv[lid] / p.scale;
    }
    auto dot = [&](const double* a, const std::array<double, 3>& v) {
      return a[0] * v[0] + a[1] * v[1] + a[2] * v[2];
    };
    p.sigmaN = dot(t, p.n);
    p.rN = dot(r, p.n);
    p.sigmaT = {dot(t, p.t1), d == 3 ? dot(t, p.t2) : 0.0};
    p.rT = {dot(r, p.t1), d == 3 ? dot(r, p.t2) : 0.0};
  }
}

int ActiveSetSolver::updateState(bool flipToStick)
{
  const int nt = space_.dim() - 1;
  const bool friction = settings_.needsFriction();
  // In the Coulomb fixed point each inner problem is Tresca with the bounds μ|σ_N| of the last
  // outer iterate (p.frictionBound).
  const bool tresca = settings_.frictionLaw == core::FrictionLaw::Tresca || fixedPoint_;
  const double mu = settings_.frictionCoefficient;
  int changes = 0;
  for (auto& p : points_) {
    const double aug = p.sigmaN - p.c * (p.rN - p.gap);
    PointStatus status = PointStatus::Free;
    std::array<double, 2> xi{0.0, 0.0};
    if (aug < 0.0) {
      if (!friction) {
        status = PointStatus::Slip;  // frictionless contact: σ_T = 0, free sliding
      } else {
        // Hüeber–Stadler–Wohlmuth bound: the augmented normal stress, not the old σ_N (which
        // is 0 for a newly active point).
        const double bound = tresca ? trescaBound(p) : mu * std::max(0.0, -aug);
        double z[2] = {p.sigmaT[0] - p.c * p.rT[0], p.sigmaT[1] - p.c * p.rT[1]}, norm = 0.0;
        for (int k = 0; k < nt; ++k)
          norm += z[k] * z[k];
        norm = std::sqrt(norm);
        if (norm <= bound || norm == 0.0) {
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
  int global = 0;
  Teuchos::reduceAll<int, int>(*comm_, Teuchos::REDUCE_SUM, 1, &changes, &global);
  return global;
}

Teuchos::RCP<ActiveSetSolver::CrsMatrix>
ActiveSetSolver::modifiedMatrix(const CrsMatrix& K, MultiVector& rhs, const MultiVector& b) const
{
  const int d = space_.dim();
  const bool friction = settings_.needsFriction();
  const bool tresca = settings_.frictionLaw == core::FrictionLaw::Tresca || fixedPoint_;
  const double mu = settings_.frictionCoefficient;
  auto A = Teuchos::rcp(new CrsMatrix(K, Teuchos::Copy));
  A->resumeFill();
  rhs.assign(b);
  auto rhsData = rhs.getDataNonConst(0);
  auto bData = b.getData(0);
  const auto& rowMap = *K.getRowMap();
  const auto& colMap = *K.getColMap();
  using LO = CrsMatrix::local_ordinal_type;
  for (const auto& p : points_) {
    LO lid[3];
    std::vector<std::vector<LO>> cols(d);
    std::vector<std::vector<double>> vals(d);
    for (int i = 0; i < d; ++i) {
      lid[i] = rowMap.getLocalElement(p.gids[i]);
      CrsMatrix::local_inds_host_view_type inds;
      CrsMatrix::values_host_view_type v;
      K.getLocalRowView(lid[i], inds, v);
      cols[i].assign(inds.data(), inds.data() + inds.extent(0));
      vals[i].assign(v.data(), v.data() + v.extent(0));
    }
    auto entry = [&](int row, LO col) {
      for (std::size_t k = 0; k < cols[row].size(); ++k)
        if (cols[row][k] == col)
          return vals[row][k];
      return 0.0;
    };
    // Frame vectors per equation: row 0 normal, rows 1.. tangential.
    const std::array<const std::array<double, 3>*, 3> frame = {&p.n, &p.t1, &p.t2};
    // 3D Coulomb slip: Hüeber–Stadler–Wohlmuth linearisation of |z|σ_T = s z (DESIGN §3), with
    // z = σ_T − c r_T, s = μ max(0, −(σ_N − c(r_N − G))) at the last iterate k, ξ = z/|z|,
    // σ̃ = σ_T^k projected onto the disc of radius s^k, M = (σ̃ ξᵀ − s^k I)/|z^k|:
    //   (I + M) σ_T − c M r_T + μ ξ σ_N − μ c ξ r_N = σ̃ − s^k ξ − μ c ξ G.
    // Frozen ξ (σ_T = −μ ξ σ_N) is the fallback when |z^k| or s^k vanish (a point that has not
    // been evaluated in contact yet).
    const bool hsw = useHsw_ && d == 3 && friction && !tresca && p.status == PointStatus::Slip;
    double hswM[2][2] = {{0, 0}, {0, 0}}, hswRhs[2] = {0, 0};
    bool hswRow = false;
    if (hsw) {
      const double z[2] = {p.sigmaT[0] - p.c * p.rT[0], p.sigmaT[1] - p.c * p.rT[1]};
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
      }
    }
    for (int r = 0; r < d; ++r) {
      const auto& dir = *frame[r];
      std::vector<double> newVals(cols[r].size(), 0.0);
      double newRhs = 0.0;
      enum { KeepRow, Traction } kind = Traction;
      std::array<double, 3> coeff{0, 0, 0};  // traction row: Σ_i coeff_i x_{g_i} = newRhs
      if (r == 0) {
        if (p.status == PointStatus::Free) {
          for (int i = 0; i < d; ++i)
            coeff[i] = p.scale * dir[i];  // σ_N = 0
        } else {
          kind = KeepRow;  // r_N = G
          newRhs = p.scale * p.gap;
        }
      } else {
        const int k = r - 1;
        if (p.status == PointStatus::Stick) {
          kind = KeepRow;  // r_T = 0
        } else if (p.status == PointStatus::Slip && friction) {
          if (tresca) {
            for (int i = 0; i < d; ++i)
              coeff[i] = p.scale * dir[i];  // σ_T,k = s ξ_k
            newRhs = trescaBound(p) * p.direction[k];
          } else {
            for (int i = 0; i < d; ++i)
              coeff[i] = p.scale * (dir[i] + mu * p.direction[k] * p.n[i]);  // σ_T,k + μ ξ_k σ_N = 0
          }
        } else {
          for (int i = 0; i < d; ++i)
            coeff[i] = p.scale * dir[i];  // σ_T = 0 (free or frictionless)
        }
      }
      if (r > 0 && hswRow) {
        // Row j of the HSW system: traction part on the point's DOFs, K-row part from r_T, r_N
        // (r = (K x − b)/s_p per frame direction), all scaled like a traction row.
        const int j = r - 1;
        std::array<double, 3> tractionDir{0, 0, 0}, rowDir{0, 0, 0};
        for (int i = 0; i < d; ++i) {
          tractionDir[i] = (1.0 + hswM[j][j]) * (j == 0 ? p.t1[i] : p.t2[i]) +
                           hswM[j][1 - j] * (j == 0 ? p.t2[i] : p.t1[i]) +
                           mu * p.direction[j] * p.n[i];
          rowDir[i] = -p.c / p.scale *
                      (hswM[j][0] * p.t1[i] + hswM[j][1] * p.t2[i] + mu * p.direction[j] * p.n[i]);
        }
        const double w = std::abs(entry(r, colMap.getLocalElement(p.gids[r]))) / std::abs(p.scale);
        newRhs = hswRhs[j];
        for (std::size_t c = 0; c < cols[r].size(); ++c) {
          for (int i = 0; i < d; ++i) {
            newVals[c] += rowDir[i] * entry(i, cols[r][c]);
            if (cols[r][c] == colMap.getLocalElement(p.gids[i]))
              newVals[c] += p.scale * tractionDir[i];
          }
          newVals[c] *= w;
        }
        for (int i = 0; i < d; ++i)
          newRhs += rowDir[i] * bData[lid[i]];
        newRhs *= w;
      } else if (kind == KeepRow) {
        for (std::size_t c = 0; c < cols[r].size(); ++c)
          for (int i = 0; i < d; ++i)
            newVals[c] += dir[i] * entry(i, cols[r][c]);
        for (int i = 0; i < d; ++i)
          newRhs += dir[i] * bData[lid[i]];
      } else {
        // A traction row (σ·e = value) is rescaled to the size of the row it replaces (its
        // A-block diagonal), so that the system's rows stay comparable under any E.
        const double w = std::abs(entry(r, colMap.getLocalElement(p.gids[r]))) / std::abs(p.scale);
        for (std::size_t c = 0; c < cols[r].size(); ++c)
          for (int i = 0; i < d; ++i)
            if (cols[r][c] == colMap.getLocalElement(p.gids[i]))
              newVals[c] += w * coeff[i];
        newRhs *= w;
      }
      A->replaceLocalValues(lid[r], Teuchos::ArrayView<const LO>(cols[r]),
                            Teuchos::ArrayView<const double>(newVals));
      rhsData[lid[r]] = newRhs;
    }
  }
  A->fillComplete(K.getDomainMap(), K.getRangeMap());
  return A;
}

double ActiveSetSolver::trescaBound(const ContactPoint& p) const
{
  return fixedPoint_ ? p.frictionBound : settings_.trescaBound;
}

void ActiveSetSolver::solve(const CrsMatrix& K, const MultiVector& b,
                            solvers::DirectSolver& solver, MultiVector& x,
                            const MultiVector* scaling)
{
  fixedPoint_ = false;
  const bool coulomb = settings_.needsFriction() && settings_.frictionLaw == core::FrictionLaw::Coulomb;
  if (!coulomb || coulombMethod_ == "Newton") {
    solveActiveSet(K, b, solver, x, scaling);
    return;
  }
  if (coulombMethod_ == "Newton, fixed point fallback") {
    try {
      solveActiveSet(K, b, solver, x, scaling);
      return;
    } catch (const core::ConvergenceError& e) {
      // Every rank throws together (the decisions are collective): fall back on all of them.
      if (comm_->getRank() == 0)
        std::cout << "  contact: semismooth Newton failed (" << e.what()
                  << "); falling back to the Coulomb fixed point" << std::endl;
    }
  }
  // Coulomb as a fixed point on the friction bound (DESIGN §3 fallback): Tresca problems with
  // s_p = μ max(0, −σ_N,p) of the previous outer iterate, until s settles.
  const auto first = stats_;
  int outer = 0, total = 0;
  fixedPoint_ = true;
  for (auto& p : points_)
    p.frictionBound = settings_.frictionCoefficient * std::max(0.0, -p.sigmaN);
  for (outer = 1; outer <= maxFixedPointIterations_; ++outer) {
    solveActiveSet(K, b, solver, x, scaling);
    total += stats_.newtonIterations;
    double change = 0.0, size = 0.0;
    for (auto& p : points_) {
      const double s = settings_.frictionCoefficient * std::max(0.0, -p.sigmaN);
      change = std::max(change, std::abs(s - p.frictionBound));
      size = std::max(size, s);
      p.frictionBound = s;
    }
    double local[2] = {change, size}, global[2];
    Teuchos::reduceAll<int, double>(*comm_, Teuchos::REDUCE_MAX, 2, local, global);
    if (stepCallback_ && comm_->getRank() == 0)
      std::cout << "  contact: fixed point " << outer << ": bound change " << global[0] / std::max(global[1], 1e-300)
                << " (relative)" << std::endl;
    if (global[0] <= fixedPointTolerance_ * global[1]) {
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
  stats_.fixedPointIterations = maxFixedPointIterations_;
  SC_THROW_IF(true, core::ConvergenceError,
              "the Coulomb fixed point did not settle in " << maxFixedPointIterations_
                  << " outer steps ('Contact/Newton/Maximum fixed-point iterations').");
}

void ActiveSetSolver::solveActiveSet(const CrsMatrix& K, const MultiVector& b,
                                     solvers::DirectSolver& solver, MultiVector& x,
                                     const MultiVector* scaling)
{
  Teuchos::RCP<const Tpetra::Vector<>> D;
  if (scaling)
    D = scaling->getVector(0);
  MultiVector y(b.getMap(), 1), scaledRhs(b.getMap(), 1);
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
  history.push_back(signature());
  // Contact rows make the system non-symmetric.
  solver.setSymmetric(false);
  for (int it = 1; it <= maxIterations_; ++it) {
    const auto stepStart = std::chrono::steady_clock::now();
    auto A = modifiedMatrix(K, rhs, b);
    if (D.is_null()) {
      // Same graph every step: the solver keeps its symbolic analysis and refactorises.
      solver.setOperator(A);
      solver.solve(rhs, x);
    } else {
      A->leftScale(*D);
      A->rightScale(*D);
      scaledRhs.elementWiseMultiply(1.0, *D, rhs, 0.0);
      solver.setOperator(A);
      solver.solve(scaledRhs, y);
      x.elementWiseMultiply(1.0, *D, y, 0.0);
    }
    stats_.newtonIterations = it;
    evaluate(K, b, x);
    const int changes = updateState(false);
    stats_.changesPerIteration.push_back(changes);
    if (stepCallback_)
      stepCallback_(it, changes,
                    std::chrono::duration<double>(std::chrono::steady_clock::now() - stepStart).count());
    if (changes == 0) {
      stats_.converged = true;
      return;
    }
    // A state seen before (on every rank) is a cycle.
    const auto sig = signature();
    int seenLocal = 0;
    for (std::size_t k = 0; k + 1 < history.size() && !seenLocal; ++k)
      seenLocal = history[k] == sig;
    int seenAll = 0;
    Teuchos::reduceAll<int, int>(*comm_, Teuchos::REDUCE_MIN, 1, &seenLocal, &seenAll);
    history.push_back(sig);
    if (seenAll) {
      SC_THROW_IF(stats_.remedies >= maxRemedies_, core::ConvergenceError,
                  "the contact active set cycles (a state repeated after " << it
                      << " Newton steps) and " << stats_.remedies
                      << " remedies did not help; try a smaller 'Contact/Newton/Penalty factor'.");
      ++stats_.remedies;
      updateState(true);  // points whose slip direction flipped go to the stick set
    }
  }
  SC_THROW_IF(true, core::ConvergenceError,
              "the contact active set did not settle in " << maxIterations_
                  << " Newton steps ('Contact/Newton/Maximum iterations'); the last step changed "
                  << stats_.changesPerIteration.back() << " points.");
}

}  // namespace sc::contact
