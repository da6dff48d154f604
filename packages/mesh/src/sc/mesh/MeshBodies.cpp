#include <sc/mesh/MeshBodies.hpp>

#include <sc/mesh/SimplexMesh.hpp>

#include <algorithm>
#include <numeric>
#include <set>
#include <sstream>

namespace sc::mesh {

std::string MeshBody::describe(int dim) const
{
  const bool one = elements.size() == 1;
  std::ostringstream os;
  os << elements.size() << " "
     << (dim == 2 ? (one ? "triangle" : "triangles") : (one ? "tetrahedron" : "tetrahedra"));
  os << ", bounding box ";
  for (int c = 0; c < dim; ++c)
    os << (c ? " × " : "") << "[" << lo[c] << ", " << hi[c] << "]";
  return os.str();
}

std::vector<MeshBody> meshBodies(const SimplexMesh& m)
{
  const int ne = m.numElements(), d = m.dim();
  // Union-find over the elements, joined through every interior face.
  std::vector<int> parent(ne);
  std::iota(parent.begin(), parent.end(), 0);
  auto root = [&](int e) {
    while (parent[e] != e)
      e = parent[e] = parent[parent[e]];
    return e;
  };
  for (int f = 0; f < m.numFaces(); ++f) {
    const auto el = m.faceElements(f);
    if (el[1] < 0) continue;
    const int a = root(el[0]), b = root(el[1]);
    if (a != b) parent[std::max(a, b)] = std::min(a, b);  // the root is the lowest element
  }
  std::vector<int> bodyOfRoot(ne, -1);
  std::vector<MeshBody> bodies;
  std::vector<std::set<int>> ids;
  for (int e = 0; e < ne; ++e) {
    const int r = root(e);
    if (bodyOfRoot[r] < 0) {
      bodyOfRoot[r] = static_cast<int>(bodies.size());
      bodies.emplace_back();
      ids.emplace_back();
      const double* p = m.vertex(m.elementVertices(e)[0]);
      for (int c = 0; c < d; ++c)
        bodies.back().lo[c] = bodies.back().hi[c] = p[c];
    }
    MeshBody& b = bodies[bodyOfRoot[r]];
    b.elements.push_back(e);
    for (int i = 0; i <= d; ++i) {
      const double* p = m.vertex(m.elementVertices(e)[i]);
      for (int c = 0; c < d; ++c)
        b.lo[c] = std::min(b.lo[c], p[c]), b.hi[c] = std::max(b.hi[c], p[c]);
      const int f = m.elementFaces(e)[i];
      if (m.isBoundaryFace(f)) ids[bodyOfRoot[r]].insert(m.faceBoundaryId(f));
    }
  }
  for (std::size_t i = 0; i < bodies.size(); ++i)
    bodies[i].boundaryIds.assign(ids[i].begin(), ids[i].end());
  return bodies;
}

}  // namespace sc::mesh
