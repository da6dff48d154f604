#pragma once
// The bodies of a mesh: its connected components, elements joined through shared faces
// (docs/reliability.md). A Gmsh file may hold several bodies that touch nowhere; each needs
// its own support (assembly::checkEveryBodyIsHeld).
#include <array>
#include <string>
#include <vector>

namespace sc::mesh {

class SimplexMesh;

struct MeshBody {
  std::vector<int> elements;         ///< ascending
  std::array<double, 3> lo{}, hi{};  ///< bounding box of its vertices (dim() entries used)
  std::vector<int> boundaryIds;      ///< the boundary parts its boundary faces belong to, ascending
  /// "2 triangles, bounding box [2, 3] × [0, 1]".
  std::string describe(int dim) const;
};

/// The connected components of the elements under "shares a face", ordered by their lowest
/// element. Elements that meet only at a vertex or an edge are separate bodies: the mixed
/// formulation couples elements through faces only (its stresses are H(div)-conforming).
std::vector<MeshBody> meshBodies(const SimplexMesh& mesh);

}  // namespace sc::mesh
