// Errors against exact solutions (docs/verification.md) and cell averages for output
// (docs/output.md "Fields in a run's files").
#include <algorithm>
#include <cmath>

#include <sc/core/Collective.hpp>
#include <Tpetra_Map.hpp>
#include <Tpetra_MultiVector.hpp>

#include <sc/disc/ElementValues.hpp>
#include <sc/disc/MixedElasticitySpace.hpp>

#include "sc/assembly/ElementSolution.hpp"
#include "sc/assembly/MixedElasticityAssembler.hpp"

namespace sc::assembly {

ElementSolution::ElementSolution(const MixedElasticityAssembler& assembler,
                                 const MultiVector& solution)
    : space_(assembler.space()), overlapMap_(assembler.overlapMap()),
      overlap_(assembler.toOverlap(solution)), x_(overlap_->getData(0)),
      c_(static_cast<std::size_t>(assembler.space().localSize()))
{
}

ElementSolution::~ElementSolution() = default;

void ElementSolution::gather(int e)
{
  const long long* g = space_.elementDofs(e);
  for (int i = 0; i < space_.localSize(); ++i)
    c_[i] = x_[overlapMap_->getLocalElement(g[i])];
}

void ElementSolution::evaluate(const disc::ElementValues& ev, int q, PointValues& v) const
{
  const auto& S = space_;
  const auto& c = c_;
  const int d = S.dim(), nRT = S.stressBasisSize(), nP = S.displacementBasisSize();
  for (int i = 0; i < d; ++i) {
    v.divSigma[i] = 0.0;
    for (int j = 0; j < d; ++j)
      v.sigma[i * d + j] = 0.0;
    for (int a = 0; a < nRT; ++a) {
      const double ca = c[S.stressOffset(i) + a];
      v.divSigma[i] += ca * ev.stressDiv(a, q);
      for (int j = 0; j < d; ++j)
        v.sigma[i * d + j] += ca * ev.stress(a, q, j);
    }
    v.u[i] = 0.0;
    for (int a = 0; a < nP; ++a)
      v.u[i] += c[S.displacementOffset(i) + a] * ev.displacement(a, q);
  }
  for (int r = 0; r < S.numRotationComponents(); ++r) {
    v.theta[r] = 0.0;
    for (int a = 0; a < S.rotationBasisSize(); ++a)
      v.theta[r] += c[S.rotationOffset(r) + a] * ev.rotation(a, q);
  }
}

void ElementSolution::stress(const disc::FaceValues& fv, int q, double* sigma) const
{
  const int d = space_.dim(), nRT = space_.stressBasisSize();
  for (int i = 0; i < d; ++i)
    for (int j = 0; j < d; ++j) {
      double s = 0.0;
      for (int a = 0; a < nRT; ++a)
        s += c_[space_.stressOffset(i) + a] * fv.stress(a, q, j);
      sigma[i * d + j] = s;
    }
}

ErrorNorms computeErrors(const MixedElasticityAssembler& assembler, const MultiVector& solution,
                         const core::ExactSolution& exact, const Teuchos::Comm<int>& comm,
                         const core::Material* material)
{
  const auto& S = assembler.space();
  const int d = S.dim(), r = S.numRotationComponents();
  ElementSolution sol(assembler, solution);
  disc::ElementValues ev(S, 2 * S.degree() + 4);
  double local[9] = {0, 0, 0, 0, 0, 0, 0, 0, 0}, global[9];
  PointValues v;
  for (int e : S.ownedElements()) {
    ev.reinit(e);
    sol.gather(e);
    for (int q = 0; q < ev.numPoints(); ++q) {
      sol.evaluate(ev, q, v);
      double sigma[9], f[3], u[3], theta[3];
      exact.stress(ev.point(q), sigma);
      exact.bodyForce(ev.point(q), f);
      exact.displacement(ev.point(q), u);
      exact.rotation(ev.point(q), theta);
      const double w = ev.weight(q);
      double err[9];
      for (int i = 0; i < d * d; ++i) {
        err[i] = sigma[i] - v.sigma[i];
        local[0] += w * err[i] * err[i];
        local[4] += w * sigma[i] * sigma[i];
      }
      if (material) local[8] += w * material->complianceEnergyDensity(err, d);
      for (int i = 0; i < d; ++i) {
        local[1] += w * std::pow(-f[i] - v.divSigma[i], 2);  // div σ = −f
        local[5] += w * f[i] * f[i];
        local[2] += w * std::pow(u[i] - v.u[i], 2);
        local[6] += w * u[i] * u[i];
      }
      for (int i = 0; i < r; ++i) {
        local[3] += w * std::pow(theta[i] - v.theta[i], 2);
        local[7] += w * theta[i] * theta[i];
      }
    }
  }
  core::sumOverRanks(comm, 9, local, global);
  ErrorNorms n;
  n.stress = std::sqrt(global[0]);
  n.stressDiv = std::sqrt(global[1]);
  n.displacement = std::sqrt(global[2]);
  n.rotation = std::sqrt(global[3]);
  n.stressNorm = std::sqrt(global[4]);
  n.stressDivNorm = std::sqrt(global[5]);
  n.displacementNorm = std::sqrt(global[6]);
  n.rotationNorm = std::sqrt(global[7]);
  n.stressEnergy = material ? std::sqrt(std::max(global[8], 0.0)) : -1.0;
  return n;
}

double computeStressEnergyError(const MixedElasticityAssembler& assembler,
                                const MultiVector& solution, const core::ExactSolution& exact,
                                const core::Material& material, const Teuchos::Comm<int>& comm)
{
  return computeErrors(assembler, solution, exact, comm, &material).stressEnergy;
}

CellAverages computeCellAverages(const MixedElasticityAssembler& assembler,
                                 const MultiVector& solution)
{
  const auto& S = assembler.space();
  const int d = S.dim(), r = S.numRotationComponents();
  ElementSolution sol(assembler, solution);
  disc::ElementValues ev(S, 2 * S.degree());
  CellAverages out;
  PointValues v;
  for (int e : S.ownedElements()) {
    ev.reinit(e);
    sol.gather(e);
    double sigma[9] = {0}, u[3] = {0}, theta[3] = {0}, vol = 0.0;
    for (int q = 0; q < ev.numPoints(); ++q) {
      sol.evaluate(ev, q, v);
      const double w = ev.weight(q);
      vol += w;
      for (int i = 0; i < d * d; ++i)
        sigma[i] += w * v.sigma[i];
      for (int i = 0; i < d; ++i)
        u[i] += w * v.u[i];
      for (int i = 0; i < r; ++i)
        theta[i] += w * v.theta[i];
    }
    double trace = 0.0;
    for (int i = 0; i < d * d; ++i)
      sigma[i] /= vol;
    for (int i = 0; i < d; ++i)
      trace += sigma[i * d + i];
    // von Mises of the (plane-strain: in-plane part of the) stress: sqrt(3/2 s:s), s = dev σ.
    double ss = 0.0;
    for (int i = 0; i < d; ++i)
      for (int j = 0; j < d; ++j) {
        const double s = 0.5 * (sigma[i * d + j] + sigma[j * d + i]) - (i == j ? trace / d : 0.0);
        ss += s * s;
      }
    out.stress.insert(out.stress.end(), sigma, sigma + d * d);
    out.vonMises.push_back(std::sqrt(1.5 * ss));
    out.pressure.push_back(-trace / d);
    for (int i = 0; i < d; ++i)
      out.displacement.push_back(u[i] / vol);
    for (int i = 0; i < r; ++i)
      out.rotation.push_back(theta[i] / vol);
  }
  return out;
}

}  // namespace sc::assembly
