#include "sc/estimator/ErrorEstimator.hpp"

#include <algorithm>
#include <cmath>

#include "sc/core/Collective.hpp"

#include <sc/assembly/ElementSolution.hpp>
#include <sc/core/Error.hpp>
#include <sc/disc/ElementValues.hpp>
#include <sc/disc/MixedElasticitySpace.hpp>
#include <sc/mesh/SimplexMesh.hpp>

namespace sc::estimator {

double ErrorEstimate::total() const
{
  double s = 0.0;
  for (const auto& p : parts)
    s += p.second;
  return std::sqrt(s);
}

double ErrorEstimate::squared(const std::string& name) const
{
  for (const auto& p : parts)
    if (p.first == name) return p.second;
  throw core::InternalError("the estimate has no part '" + name + "'");
}

ErrorEstimator::ErrorEstimator(const assembly::MixedElasticityAssembler& assembler,
                               const EstimatorSettings& settings,
                               Teuchos::RCP<const Teuchos::Comm<int>> comm)
    : assembler_(assembler), comm_(std::move(comm))
{
  const auto& S = assembler.space();
  reconstruction_ = std::make_unique<DisplacementReconstruction>(
      S, settings.reconstructionDegree(S.degree()), comm_);
}

ErrorEstimator::~ErrorEstimator() = default;

void ErrorEstimator::addContribution(std::shared_ptr<const EstimatorContribution> contribution)
{
  contributions_.push_back(std::move(contribution));
}

ErrorEstimate ErrorEstimator::estimate(const assembly::MultiVector& solution,
                                       const assembly::ElasticityData& data)
{
  reconstruct(solution, data);
  return estimateReconstructed(solution, data);
}

void ErrorEstimator::reconstruct(const assembly::MultiVector& solution,
                                 const assembly::ElasticityData& data)
{
  SC_THROW_IF(data.boundaryConditions.hasContact() && contributions_.empty(), core::InputError,
              "a scene with a boundary of Type Contact needs the contact terms of η_CF: add an "
              "estimator::ContactContribution before estimate().");
  assembly::ElementSolution sol(assembler_, solution);
  reconstruction_->reconstruct(sol, data);
  reconstructed_ = true;
}

ErrorEstimate ErrorEstimator::estimateReconstructed(const assembly::MultiVector& solution,
                                                    const assembly::ElasticityData& data)
{
  SC_THROW_IF(!reconstructed_, core::InternalError,
              "ErrorEstimator::estimateReconstructed before reconstruct()");
  const auto& S = assembler_.space();
  const auto& m = S.mesh();
  const int d = S.dim();
  const double twoMu = 2.0 * data.material.shearModulus(),
               cd = data.material.complianceCoefficient(d);
  const core::ExactSolution* exact = data.exactSolution;

  assembly::ElementSolution sol(assembler_, solution);
  const auto& rec = *reconstruction_;

  disc::ElementValues ev(S, rec.cubatureDegree());
  disc::FaceValues fv(S, rec.cubatureDegree());
  std::vector<double> uR, gradUR;
  assembly::PointValues v;
  const auto& terms = assembly::asymmetryTerms(d);
  ErrorEstimate est;
  est.indicators.assign(S.ownedElements().size(), 0.0);
  // Local sums: volume, asymmetry, oscillation, ‖A^{1/2}σ_h‖².
  double local[4] = {0, 0, 0, 0}, global[4];
  for (std::size_t idx = 0; idx < S.ownedElements().size(); ++idx) {
    const int e = S.ownedElements()[idx];
    ev.reinit(e);
    sol.gather(e);
    rec.valuesAt(e, ev, uR, gradUR);
    const double hT = m.elementDiameter(e);
    double vol = 0.0, asym = 0.0, osc = 0.0, norm = 0.0;
    for (int q = 0; q < ev.numPoints(); ++q) {
      sol.evaluate(ev, q, v);
      const double w = ev.weight(q);
      double trace = 0.0;
      for (int i = 0; i < d; ++i)
        trace += v.sigma[i * d + i];
      norm += w * data.material.complianceEnergyDensity(v.sigma, d);
      for (int i = 0; i < d; ++i)
        for (int j = 0; j < d; ++j) {
          const double Asigma = (v.sigma[i * d + j] - (i == j ? cd * trace : 0.0)) / twoMu;
          const double eps = 0.5 * (gradUR[(q * d + i) * d + j] + gradUR[(q * d + j) * d + i]);
          vol += w * twoMu * (Asigma - eps) * (Asigma - eps);
        }
      double as[3] = {0, 0, 0};
      for (const auto& t : terms)
        as[t.comp] += t.sign * v.sigma[t.row * d + t.col];
      for (int r = 0; r < S.numRotationComponents(); ++r)
        asym += w * as[r] * as[r] / twoMu;
      if (data.hasBodyForce()) {
        // div σ_h = −Π_k f, so f + div σ_h = f − Π_k f.
        double f[3];
        data.bodyForceAt(ev.point(q), d, f);
        for (int i = 0; i < d; ++i)
          osc += w * std::pow(hT / M_PI, 2) * std::pow(f[i] + v.divSigma[i], 2) / twoMu;
      }
    }
    const int* faces = m.elementFaces(e);
    for (int lf = 0; lf <= d; ++lf) {
      const int f = faces[lf];
      if (!m.isBoundaryFace(f)) continue;
      const core::BoundaryCondition* bc =
          data.boundaryConditions.find(m.boundaryName(m.faceBoundaryId(f)));
      // Free faces: σ_h n = 0 exactly; contact faces: the contact contribution; Symmetry faces:
      // the tangential components are zero exactly and u^R·n = 0 at the face's nodes, hence on
      // the (flat) face: nothing to measure. Normal displacement faces: u^R·n = g at the nodes,
      // so only the interpolation error of g, measured like a displacement's. Components faces:
      // each displacement component like a Displacement face's (u^R_i = g_i at the nodes), each
      // traction component like a Traction face's.
      if (!bc || bc->type == core::BoundaryType::Contact ||
          bc->type == core::BoundaryType::Symmetry ||
          (bc->type == core::BoundaryType::NormalDisplacement && bc->isZero()))
        continue;
      if ((bc->type == core::BoundaryType::Traction || bc->type == core::BoundaryType::Pressure) &&
          bc->isZero())
        continue;
      const double hF = d == 2 ? m.faceMeasure(f) : std::sqrt(m.faceMeasure(f));
      fv.reinit(e, lf);
      for (int q = 0; q < fv.numPoints(); ++q) {
        const double* x = fv.point(q);
        double value[3] = {0, 0, 0};
        bc->evaluate(x, fv.normal(q).data(), d, exact, value);
        if (bc->type == core::BoundaryType::Displacement) {
          double u[3];
          rec.valueAt(e, x, u);
          for (int i = 0; i < d; ++i)
            osc += fv.weight(q) * twoMu / hF * std::pow(value[i] - u[i], 2);
        } else if (bc->type == core::BoundaryType::Components) {
          double u[3], sigma[9];
          rec.valueAt(e, x, u);
          sol.stress(fv, q, sigma);
          for (int i = 0; i < d; ++i) {
            if (bc->displacementComponent(i)) {
              osc += fv.weight(q) * twoMu / hF * std::pow(value[i] - u[i], 2);
              continue;
            }
            double sn = 0.0;
            for (int j = 0; j < d; ++j)
              sn += sigma[i * d + j] * fv.normal(q)[j];
            osc += fv.weight(q) * hF * std::pow(value[i] - sn, 2) / twoMu;
          }
        } else if (bc->type == core::BoundaryType::NormalDisplacement) {
          double u[3];
          rec.valueAt(e, x, u);
          double gap = 0.0;  // (g n − u^R)·n
          for (int i = 0; i < d; ++i)
            gap += (value[i] - u[i]) * fv.normal(q)[i];
          osc += fv.weight(q) * twoMu / hF * gap * gap;
        } else {
          double sigma[9];
          sol.stress(fv, q, sigma);
          for (int i = 0; i < d; ++i) {
            double sn = 0.0;
            for (int j = 0; j < d; ++j)
              sn += sigma[i * d + j] * fv.normal(q)[j];
            osc += fv.weight(q) * hF * std::pow(value[i] - sn, 2) / twoMu;
          }
        }
      }
    }
    est.indicators[idx] = vol + asym + osc;
    local[0] += vol;
    local[1] += asym;
    local[2] += osc;
    local[3] += norm;
  }
  core::sumOverRanks(*comm_, 4, local, global);
  est.addPart("volume", global[0]);
  est.addPart("asymmetry", global[1]);
  est.addPart("oscillation", global[2]);
  est.stressEnergyNorm = std::sqrt(std::max(global[3], 0.0));
  for (const auto& c : contributions_)
    c->addTo(est, sol, rec, *comm_);
  return est;
}

}  // namespace sc::estimator
