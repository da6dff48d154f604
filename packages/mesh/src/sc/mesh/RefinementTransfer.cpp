#include <sc/mesh/RefinementTransfer.hpp>

#include <sc/core/Error.hpp>

#include <algorithm>
#include <array>

namespace sc::mesh {

std::vector<double> prolongVertexField(const RefinementStep& step, const std::vector<double>& old,
                                       int components)
{
  const std::size_t nOld = static_cast<std::size_t>(step.numVerticesBefore) * components;
  SC_THROW_IF(old.size() != nOld, sc::core::InternalError,
              "prolongVertexField: " << old.size() << " values for " << step.numVerticesBefore
                                     << " vertices x " << components << " components");
  std::vector<double> out(old);
  out.resize(nOld + step.newVertexParents.size() * components);
  for (std::size_t i = 0; i < step.newVertexParents.size(); ++i) {
    const auto [a, b] = step.newVertexParents[i];
    for (int c = 0; c < components; ++c)
      out[nOld + i * components + c] = 0.5 * (out[static_cast<std::size_t>(a) * components + c] +
                                              out[static_cast<std::size_t>(b) * components + c]);
  }
  return out;
}

std::vector<double> prolongElementField(const RefinementStep& step, const std::vector<double>& old,
                                        int components)
{
  SC_THROW_IF(old.size() != static_cast<std::size_t>(step.numElementsBefore) * components,
              sc::core::InternalError,
              "prolongElementField: " << old.size() << " values for " << step.numElementsBefore
                                      << " elements x " << components << " components");
  std::vector<double> out(step.elementParent.size() * components);
  for (std::size_t e = 0; e < step.elementParent.size(); ++e)
    for (int c = 0; c < components; ++c)
      out[e * components + c] =
          old[static_cast<std::size_t>(step.elementParent[e]) * components + c];
  return out;
}

std::vector<int> boundaryFaceParents(const SimplexMesh& previous, const SimplexMesh& refined,
                                     const RefinementStep& step)
{
  const int d = refined.dim();
  // Support of each vertex: the old vertices whose convex hull contains it by construction (a
  // midpoint's support is the union of its parents'). At most d+1 old vertices (one element).
  const int nOld = step.numVerticesBefore;
  std::vector<std::array<int, 4>> support(step.newVertexParents.size());
  auto supportOf = [&](int v) {
    if (v < nOld) return std::array<int, 4>{v, -1, -1, -1};
    return support[v - nOld];
  };
  for (std::size_t i = 0; i < support.size(); ++i) {
    const auto sa = supportOf(step.newVertexParents[i][0]);
    const auto sb = supportOf(step.newVertexParents[i][1]);
    std::array<int, 4> u{-1, -1, -1, -1};
    int n = 0;
    for (const auto& s : {sa, sb})
      for (int x : s)
        if (x >= 0 && std::find(u.begin(), u.begin() + n, x) == u.begin() + n) {
          SC_THROW_IF(n == 4, sc::core::InternalError, "boundaryFaceParents: support overflow");
          u[n++] = x;
        }
    support[i] = u;
  }
  std::vector<int> parent(refined.numFaces(), -1);
  for (int f : refined.boundaryFaces()) {
    const int e = refined.faceElements(f)[0];
    const int p = step.elementParent[e];
    const int* fv = refined.faceVertices(f);
    for (int k = 0; k <= d && parent[f] < 0; ++k) {
      const int pf = previous.elementFaces(p)[k];
      if (!previous.isBoundaryFace(pf)) continue;
      const int* pv = previous.faceVertices(pf);
      bool inside = true;
      for (int i = 0; i < d && inside; ++i)
        for (int x : supportOf(fv[i]))
          if (x >= 0 && std::find(pv, pv + d, x) == pv + d) inside = false;
      if (inside) parent[f] = pf;
    }
    SC_THROW_IF(parent[f] < 0, sc::core::InternalError,
                refined.origin() << ": boundary face " << f << " has no parent boundary face");
  }
  return parent;
}

}  // namespace sc::mesh
