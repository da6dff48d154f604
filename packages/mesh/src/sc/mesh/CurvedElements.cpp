#include "sc/mesh/CurvedElements.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include <sc/core/Error.hpp>
#include <sc/mesh/Geometry.hpp>
#include <sc/mesh/SimplexMesh.hpp>

namespace sc::mesh {
namespace {
// Local vertex pairs of the shards edges: Triangle (edge s = (s, s+1 mod 3)), Tetrahedron.
constexpr int kTriEdges[3][2] = {{0, 1}, {1, 2}, {2, 0}};
constexpr int kTetEdges[6][2] = {{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 3}, {2, 3}};
}  // namespace

CurvedElements::CurvedElements(Teuchos::RCP<const SimplexMesh> mesh, const Geometry& geometry)
    : mesh_(std::move(mesh))
{
  const SimplexMesh& m = *mesh_;
  SC_THROW_IF(geometry.dim() != m.dim(), core::InternalError,
              "CurvedElements: a " << geometry.dim() << "D geometry for a " << m.dim() << "D mesh");
  const int d = m.dim(), nEdges = d == 2 ? 3 : 6;
  edgeSlot_.assign(m.numEdges(), -1);
  curvedElement_.assign(m.numElements(), 0);
  std::vector<char> partCurved(m.numBoundaryParts(), 0);
  for (int i = 0; i < m.numBoundaryParts(); ++i)
    partCurved[i] = geometry.isCurved(m.boundaryName(i)) ? 1 : 0;
  for (int f : m.boundaryFaces()) {
    const int part = m.faceBoundaryId(f);
    if (part < 0 || !partCurved[part]) continue;
    const int e = m.faceElements(f)[0];
    const int* fe = m.elementFaces(e);
    const int lf = static_cast<int>(std::find(fe, fe + d + 1, f) - fe);
    // The face opposite local vertex lf holds the element edges without lf.
    for (int s = 0; s < nEdges; ++s) {
      const int* lv = d == 2 ? kTriEdges[s] : kTetEdges[s];
      if (lv[0] == lf || lv[1] == lf) continue;
      const int edge = m.elementEdges(e)[s];
      if (edgeSlot_[edge] >= 0) continue;
      const double* a = m.vertex(m.edgeVertices(edge)[0]);
      const double* b = m.vertex(m.edgeVertices(edge)[1]);
      std::array<double, 3> mid{0, 0, 0};
      double length = 0.0;
      for (int i = 0; i < d; ++i) {
        mid[i] = 0.5 * (a[i] + b[i]);
        length += (b[i] - a[i]) * (b[i] - a[i]);
      }
      const auto x = geometry.project(m.boundaryName(part), mid);
      double bulge = 0.0;
      for (int i = 0; i < d; ++i)
        bulge += (x[i] - mid[i]) * (x[i] - mid[i]);
      maxBulge_ = std::max(maxBulge_, std::sqrt(bulge / length));
      edgeSlot_[edge] = static_cast<int>(midpoints_.size() / 3);
      midpoints_.insert(midpoints_.end(), {x[0], x[1], d == 2 ? 0.0 : x[2]});
    }
  }
  for (int e = 0; e < m.numElements(); ++e)
    for (int s = 0; s < nEdges; ++s)
      if (edgeSlot_[m.elementEdges(e)[s]] >= 0) {
        curvedElement_[e] = 1;
        ++numCurved_;
        break;
      }
}

int CurvedElements::dim() const { return mesh_->dim(); }

int CurvedElements::nodesPerElement() const { return mesh_->dim() == 2 ? 6 : 10; }

void CurvedElements::nodes(int e, double* xyz) const
{
  const SimplexMesh& m = *mesh_;
  const int d = m.dim(), nEdges = d == 2 ? 3 : 6;
  const int* v = m.elementVertices(e);
  for (int a = 0; a <= d; ++a) {
    const double* p = m.vertex(v[a]);
    for (int i = 0; i < 3; ++i)
      xyz[3 * a + i] = i < d ? p[i] : 0.0;
  }
  for (int s = 0; s < nEdges; ++s) {
    double* x = &xyz[3 * (d + 1 + s)];
    const int edge = m.elementEdges(e)[s];
    if (edgeSlot_[edge] >= 0) {
      std::copy(edgeMidpoint(edge), edgeMidpoint(edge) + 3, x);
      continue;
    }
    const int* lv = d == 2 ? kTriEdges[s] : kTetEdges[s];
    for (int i = 0; i < 3; ++i)
      x[i] = 0.5 * (xyz[3 * lv[0] + i] + xyz[3 * lv[1] + i]);
  }
}

}  // namespace sc::mesh
