#include <sc/mesh/BoundarySimplexSplit.hpp>

namespace sc::mesh {

Teuchos::RCP<SimplexMesh> splitElementsWithAllVerticesOnBoundary(const SimplexMesh& mesh)
{
  const int d = mesh.dim(), nve = d + 1;
  std::vector<double> coords = mesh.coordinates();
  std::vector<int> elems = mesh.elementVertices();
  for (int e : mesh.elementsWithAllVerticesOnBoundary()) {
    const int* v = mesh.elementVertices(e);
    const int c = static_cast<int>(coords.size()) / d;
    for (int k = 0; k < d; ++k) {
      double s = 0;
      for (int i = 0; i < nve; ++i)
        s += mesh.vertex(v[i])[k];
      coords.push_back(s / nve);
    }
    // Child i: the face opposite local vertex i, plus the barycentre in place of vertex i (keeps
    // the positive orientation of the parent's vertex order).
    for (int i = 0; i < nve; ++i) {
      std::vector<int> child(v, v + nve);
      child[i] = c;
      if (i == 0)
        std::copy(child.begin(), child.end(), elems.begin() + static_cast<std::ptrdiff_t>(e) * nve);
      else
        elems.insert(elems.end(), child.begin(), child.end());
    }
  }
  std::vector<int> bfv, bpart;
  for (int f : mesh.boundaryFaces()) {
    bfv.insert(bfv.end(), mesh.faceVertices(f), mesh.faceVertices(f) + d);
    bpart.push_back(mesh.faceBoundaryId(f));
  }
  return Teuchos::rcp(new SimplexMesh(d, std::move(coords), std::move(elems), bfv, bpart,
                                      mesh.boundaryNames(), mesh.origin()));
}

}  // namespace sc::mesh
