#pragma once
// The "Mesh" sublist read once into values (docs/mesh.md). Its keys, defaults and validators are
// declared in MeshFactory::getValidParameters(); the members carry no defaults of their own, so
// that the declaration is the only place a key gets its default value.

#include <Teuchos_ParameterList.hpp>

#include <string>
#include <vector>

namespace sc::mesh {

/// "Mesh/Local refinement": bisection sweeps towards a region.
struct LocalRefinementSettings {
  int levels{};                ///< sweeps; 0 = off
  std::vector<double> center;  ///< centre of the region (Problem/Dimension values when levels > 0)
  double radius{};             ///< elements whose centroid lies within this distance are selected
  std::string boundary;        ///< if not empty: only elements with a face on this part

  /// The values of a validated "Local refinement" list.
  static LocalRefinementSettings fromParameters(const Teuchos::ParameterList& validatedLocal);
  /// The same for a list not yet checked: a copy is validated against the declaration (errors
  /// name 'Mesh/Local refinement/<key>') and completed with its defaults.
  static LocalRefinementSettings fromUncheckedParameters(const Teuchos::ParameterList& local);
};

/// "Mesh": the domain, the initial mesh and its refinements, the memory limit.
struct MeshSettings {
  std::string source;        ///< one of MeshFactory::sources()
  double initialMeshSize{};  ///< Gmsh Mesh.MeshSizeMax of the initial mesh
  int uniformRefinements{};  ///< uniform bisection levels of the initial mesh
  double memoryLimitGB{};    ///< 0: the memory available when the run starts
  bool projectBoundary{};    ///< new vertices on curved boundaries go onto the exact boundary
  int geometryOrder{};       ///< 1: straight-sided elements, 2: quadratic at curved boundaries
  double radius{};           ///< Half disc / Half ball
  std::string file;          ///< Gmsh file / Gmsh geometry
  std::vector<double> lowerCorner, upperCorner;  ///< Rectangle
  LocalRefinementSettings local;

  /// The values of a validated "Mesh" list (the deck's, validated when it was read).
  static MeshSettings fromParameters(const Teuchos::ParameterList& validatedMesh);
  /// The same for a list not yet checked (tests, tools): a copy is validated against
  /// MeshFactory::getValidParameters() (errors name 'Mesh/<key>') and completed with its
  /// defaults.
  static MeshSettings fromUncheckedParameters(const Teuchos::ParameterList& meshList);
};

}  // namespace sc::mesh
