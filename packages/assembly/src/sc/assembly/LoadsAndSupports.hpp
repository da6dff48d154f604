#pragma once
// Checks of the loads and supports against the mesh (docs/theory.md §"Loads and supports"): the
// plane of each Symmetry / Normal displacement part, rigid-body motions fixed, and the formulas of
// the deck finite on the body. The mesh is replicated, so every rank computes the same result
// and an error is collective.
#include <array>
#include <map>
#include <string>
#include <vector>

#include <sc/assembly/MixedElasticityAssembler.hpp>
#include <sc/core/ProblemData.hpp>

namespace sc::mesh {
class SimplexMesh;
class CurvedElements;
}  // namespace sc::mesh

namespace sc::assembly {

/// The plane of a part with a condition in its normal–tangential frame (Type Symmetry or Normal
/// displacement, docs/theory.md §"Loads and supports"): its outward unit normal n, and the
/// coordinate axis a with n = ±e_a (−1 when n is oblique). Such a part must be flat: a line in
/// 2D, a plane in 3D, of any orientation.
struct NormalFramePart {
  std::array<double, 3> normal{};
  int axis = -1;
};

/// The plane of every Symmetry and Normal displacement part the mesh has. A part whose vertices
/// lie in a plane x_a = const (to 1e-9 of the mesh's size) gets n = ±e_a exactly; otherwise n is
/// the area-weighted mean of its faces' outward normals, and a part whose vertices are farther
/// than 1e-9 of the mesh's size from that plane, or whose faces face opposite ways, is an
/// InputError naming the key, the part and how far from flat it is (curved parts are not
/// supported). MixedElasticityAssembler checks the faces of curved elements in addition.
std::map<std::string, NormalFramePart>
normalFrameParts(const mesh::SimplexMesh& mesh, const core::BoundaryConditions& boundaryConditions);

/// normalFrameParts for the quadratic geometry: every curved edge of a face on a Symmetry or
/// Normal displacement part must have its midpoint node in the part's plane (to 1e-9 of the
/// mesh's size); otherwise an InputError names the key and the part (a part curved only by
/// Mesh/Geometry order = 2, e.g. a single edge of an arc). MixedElasticityAssembler checks the
/// same at its quadrature points; this finds it before any work.
void checkNormalFramePartsFlat(const mesh::SimplexMesh& mesh,
                               const core::BoundaryConditions& boundaryConditions,
                               const mesh::CurvedElements& curved);

/// A direction along which a part prescribes the displacement, u·direction = data (docs/theory.md
/// §"Loads and supports"): the normal of a Symmetry or Normal displacement part, e_i for each
/// displacement component i of a Components part.
struct SupportDirection {
  std::string part;
  std::array<double, 3> direction{};
};

/// The support directions of every Symmetry, Normal displacement and Components part the mesh
/// has (`frameParts` from normalFrameParts); not those of Displacement parts, which hold
/// every motion.
std::vector<SupportDirection>
supportDirections(const mesh::SimplexMesh& mesh, const core::BoundaryConditions& boundaryConditions,
                  const std::map<std::string, NormalFramePart>& frameParts);

/// The rigid motions v(x) = c + ω × x (2D: c + ω (−y, x)) with v·direction = 0 at the vertices
/// of all of the given parts (on their faces that belong to `elements`, ascending, when given):
/// a basis of the null space, each vector (c, ω) with d + 1 (2D) or 6 (3D) entries, translations
/// first. Empty when the parts hold the body.
std::vector<std::vector<double>> freeRigidMotions(const mesh::SimplexMesh& mesh,
                                                  const std::vector<SupportDirection>& supports,
                                                  const std::vector<int>* elements = nullptr);

/// "along y", "along (0.5, 0.866)" or "against a rotation" for a free rigid motion.
std::string describeRigidMotion(const std::vector<double>& motion, int dim);

/// "x = const" for an axis-normal part, "normal (0.5, 0.866)" otherwise.
std::string describePlane(const NormalFramePart& part, int dim);

/// A rigid plane obstacle of the Contact parts (Contact/Obstacle = Plane): its unit normal ν,
/// pointing towards the body.
struct ContactPlane {
  std::array<double, 3> normal{};
};

/// normalFrameParts, and: without a Displacement part the Symmetry, Normal displacement and
/// Components parts (supportDirections) must hold every rigid motion (freeRigidMotions; otherwise
/// the matrix is singular), or all but the translation along the normal of a contact `plane` ν =
/// ±e_a: then the contact alone holds the body along e_a, as a roller does when in contact
/// (docs/theory.md §"Loads and supports"), and the function returns a. Every formula (boundary data
/// on its part's vertices, body force on all vertices) must be finite. Throws InputError naming the
/// keys. Returns −1 when the body is held without the contact.
int checkLoadsAndSupports(const mesh::SimplexMesh& mesh, const ElasticityData& data,
                          const ContactPlane* plane = nullptr);

}  // namespace sc::assembly
