#pragma once
// Conforming local and uniform refinement of simplicial meshes by bisection (docs/theory.md
// §"Adaptivity"):
// - 2D: newest-vertex bisection (NVB). Each triangle stores its vertices (v0, v1, v2) with the
//   refinement edge v0v1 opposite the newest vertex v2; children (v2, v0, m) and (v1, v2, m) keep
//   the positive orientation. The initial refinement edge is the longest edge.
// - 3D: the marked-tetrahedron algorithm of Arnold, Mukherjee and Pouly (SISC 22, 2000), which
//   works from any conforming initial mesh: every face carries a marked edge (initially its longest
//   edge, ties broken by vertex ids so that neighbours agree), a tetrahedron's refinement edge is
//   its longest edge, and the children's markings follow the AMP rules (types P/A/M/O, flag for
//   planar tetrahedra). After the first generations it coincides with Maubach/Kossaczký bisection,
//   whence finitely many similarity classes and bounded shape regularity.
// Closure: an element containing an edge that was bisected is bisected until none of its edges
// is, so the result has no hanging nodes. New vertices on a curved boundary part are projected
// onto the exact geometry (Geometry::project) unless boundary projection is off.
//
// The refiner owns the refinement state (markings, generations, boundary parts of split faces)
// and produces a new immutable SimplexMesh per call; it is the place the adaptive loop keeps.

#include <sc/mesh/Geometry.hpp>
#include <sc/mesh/HashIndexMap.hpp>
#include <sc/mesh/RefinementStep.hpp>
#include <sc/mesh/SimplexMesh.hpp>

#include <Teuchos_RCP.hpp>

#include <cstdint>
#include <deque>
#include <string>
#include <vector>

namespace sc::mesh {

class BisectionRefiner {
public:
  /// geometry may be null (Gmsh file: no exact boundary). projectBoundary = Mesh/Project boundary.
  BisectionRefiner(Teuchos::RCP<const SimplexMesh> initialMesh,
                   Teuchos::RCP<const Geometry> geometry, bool projectBoundary);

  BisectionRefiner(const BisectionRefiner&) = delete;
  BisectionRefiner& operator=(const BisectionRefiner&) = delete;

  /// The current (finest) mesh.
  Teuchos::RCP<const SimplexMesh> mesh() const { return mesh_; }
  Teuchos::RCP<const Geometry> geometry() const { return geometry_; }
  bool projectsBoundary() const { return project_; }

  /// Bisect each marked element (indices into mesh()) once, plus the closure. Duplicates and an
  /// empty list are allowed (an empty list changes nothing but still records a step).
  const RefinementStep& refine(const std::vector<int>& markedElements);
  /// One uniform level: every element bisected dim() times, plus closure. 2D: always exactly ×4.
  /// 3D: exactly ×8 from the initial mesh and from uniformly refined meshes; after local steps, an
  /// element in the third phase of the bisection cycle (Maubach tag 1) keeps one edge unsplit after
  /// three bisections, so the closure adds some elements (docs/mesh.md).
  const RefinementStep& refineUniformly();

  /// All steps so far (index 0 = first refinement of the initial mesh, or the first step after
  /// forgetHistory()). References returned by refine() stay valid until forgetHistory().
  const std::deque<RefinementStep>& history() const { return history_; }
  /// Drop the recorded steps (their per-element arrays) once the caller has used them.
  void forgetHistory() { history_.clear(); }
  /// Bisection generation of element e of mesh() (0 for initial elements).
  int generation(int e) const { return gen_[e]; }

  /// Everything the refiner carries from one call to the next: with it, a refiner built on the
  /// same initial mesh and geometry refines exactly (bit for bit) as the one it was taken from
  /// (checkpoint/restart, docs/adaptivity.md). Boundary maps as (key, part) lists, part -1 for a
  /// face that was split.
  struct State {
    int dim = 0;
    std::vector<double> coordinates;           ///< dim per vertex
    std::vector<int> elementVertices;          ///< dim+1 per element, in refinement order
    std::vector<int> generations;              ///< per element
    std::vector<unsigned char> codes;          ///< 3D: face markings and flag, per element
    std::vector<std::uint64_t> boundaryEdges;  ///< 2D: edge keys
    std::vector<int> boundaryEdgeParts;
    std::vector<int> boundaryFaces;  ///< 3D: 3 sorted vertices per face
    std::vector<int> boundaryFaceParts;
    std::vector<std::uint64_t> curvedEdges;  ///< 3D: edges of curved boundary faces
    std::vector<int> curvedEdgeParts;
  };
  State state() const;
  /// Replace the refinement state by \p state (taken by state() from a refiner on the same
  /// initial mesh, geometry and boundary parts) and rebuild mesh(); the history is cleared.
  /// Throws sc::core::InputError, quoting \p source, if the state is inconsistent.
  void restore(const State& state, const std::string& source);

private:
  const RefinementStep& run();
  bool needsBisection(int e) const;
  void bisect(int e);
  void bisectTriangle(int e);
  void bisectTetrahedron(int e);
  int midpoint(int a, int b);
  void setTetrahedron(int slot, const int w[4], const std::array<int, 2> markers[4], bool flag);
  std::array<double, 3> point(int v) const;
  Teuchos::RCP<const SimplexMesh> buildMesh() const;

  int dim_;
  Teuchos::RCP<const SimplexMesh> mesh_;
  Teuchos::RCP<const Geometry> geometry_;
  bool project_;
  std::vector<std::string> names_;
  std::vector<char> partCurved_;
  std::string origin_;

  // Refinement state of the current mesh.
  std::vector<double> coords_;
  std::vector<int> verts_;           // dim+1 per element; 3D: (a, b, c, d), refinement edge ab
  std::vector<unsigned char> code_;  // 3D: face markings and flag, see BisectionRefiner.cpp
  std::vector<int> gen_;
  HashIndexMap<std::uint64_t> boundaryEdges_;  // 2D: boundary edge -> part (-1: split)
  HashIndexMap<FaceKey> boundaryFaces_;        // 3D: boundary face -> part (-1: split)
  HashIndexMap<std::uint64_t> curvedEdges_;    // 3D: edge of a curved boundary face -> part

  // Per call.
  std::vector<int> target_, ancestor_;
  HashIndexMap<std::uint64_t> midpoints_;
  std::vector<char> splitEndpoint_;
  RefinementStep* step_ = nullptr;
  std::deque<RefinementStep> history_;  // deque: references stay valid as it grows
};

}  // namespace sc::mesh
