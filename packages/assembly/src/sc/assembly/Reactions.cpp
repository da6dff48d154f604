#include "sc/assembly/Reactions.hpp"

#include <sc/core/Collective.hpp>

#include <sc/disc/ElementValues.hpp>
#include <sc/disc/MixedElasticitySpace.hpp>
#include <sc/mesh/SimplexMesh.hpp>

#include "sc/assembly/ElementSolution.hpp"

namespace sc::assembly {

std::vector<BoundaryForce> computeBoundaryForces(const MixedElasticityAssembler& assembler,
                                                 const MultiVector& solution,
                                                 const std::array<double, 3>& momentPoint,
                                                 const Teuchos::Comm<int>& comm)
{
  const auto& S = assembler.space();
  const auto& m = S.mesh();
  const int d = S.dim(), parts = m.numBoundaryParts();
  // Six numbers per part: force (3) and moment (3).
  std::vector<double> local(static_cast<std::size_t>(parts) * 6, 0.0), global(local.size(), 0.0);
  ElementSolution sol(assembler, solution);
  disc::FaceValues fv(S, 2 * S.degree() + 2);
  double sigma[9];
  for (int e : S.ownedElements()) {
    bool gathered = false;
    for (int lf = 0; lf <= d; ++lf) {
      const int f = m.elementFaces(e)[lf];
      if (!m.isBoundaryFace(f)) continue;
      const int part = m.faceBoundaryId(f);
      if (part < 0 || part >= parts) continue;
      if (!gathered) {
        sol.gather(e);
        gathered = true;
      }
      fv.reinit(e, lf);
      double* out = &local[static_cast<std::size_t>(part) * 6];
      for (int q = 0; q < fv.numPoints(); ++q) {
        sol.stress(fv, q, sigma);
        const auto& n = fv.normal(q);
        const double* x = fv.point(q);
        double t[3] = {0, 0, 0}, r[3] = {0, 0, 0};
        for (int i = 0; i < d; ++i) {
          for (int j = 0; j < d; ++j)
            t[i] += sigma[i * d + j] * n[j];
          r[i] = x[i] - momentPoint[i];
        }
        const double w = fv.weight(q);
        for (int i = 0; i < d; ++i)
          out[i] += w * t[i];
        // (x − x₀) × t; in 2D only its z component is not zero.
        out[3] += w * (r[1] * t[2] - r[2] * t[1]);
        out[4] += w * (r[2] * t[0] - r[0] * t[2]);
        out[5] += w * (r[0] * t[1] - r[1] * t[0]);
      }
    }
  }
  core::sumOverRanks(comm, static_cast<int>(local.size()), local.data(), global.data());
  std::vector<BoundaryForce> out(parts);
  for (int p = 0; p < parts; ++p) {
    out[p].part = m.boundaryName(p);
    for (int i = 0; i < 3; ++i) {
      out[p].force[i] = global[static_cast<std::size_t>(p) * 6 + i];
      out[p].moment[i] = global[static_cast<std::size_t>(p) * 6 + 3 + i];
    }
  }
  return out;
}

std::array<double, 3> computeBodyForceResultant(const MixedElasticityAssembler& assembler,
                                                const ElasticityData& data,
                                                const Teuchos::Comm<int>& comm)
{
  std::array<double, 3> local{0, 0, 0}, global{0, 0, 0};
  if (data.hasBodyForce()) {
    const auto& S = assembler.space();
    const int d = S.dim();
    // The assembler's element quadrature (MixedElasticityAssembler: degree 2k + 2), so that the
    // sum is the one the right-hand side −(f, v) holds for v = e_i.
    disc::ElementValues ev(S, 2 * S.degree() + 2);
    double f[3] = {0, 0, 0};
    for (int e : S.ownedElements()) {
      ev.reinit(e);
      for (int q = 0; q < ev.numPoints(); ++q) {
        data.bodyForceAt(ev.point(q), d, f);
        for (int i = 0; i < d; ++i)
          local[i] += ev.weight(q) * f[i];
      }
    }
  }
  core::sumOverRanks(comm, 3, local.data(), global.data());
  return global;
}

}  // namespace sc::assembly
