#pragma once
// Builds the mesh of a run from the "Mesh" sublist (docs/mesh.md): scene geometry or Gmsh file,
// initial Gmsh mesh, uniform and local refinements, and the BisectionRefiner that the adaptive
// loop keeps.

#include <sc/mesh/BisectionRefiner.hpp>
#include <sc/mesh/CurvedElements.hpp>
#include <sc/mesh/Geometry.hpp>
#include <sc/mesh/MeshSettings.hpp>
#include <sc/mesh/ResourceEstimate.hpp>

#include <Teuchos_Comm.hpp>
#include <Teuchos_ParameterList.hpp>
#include <Teuchos_RCP.hpp>

#include <string>
#include <vector>

namespace sc::mesh {

class MeshFactory {
public:
  /// Valid "Mesh" sublist: Source, Initial mesh size, Uniform refinements, Project boundary,
  /// Radius, File, Lower corner, Upper corner, and the "Local refinement" sublist (each with
  /// default, doc string and validator).
  static Teuchos::RCP<const Teuchos::ParameterList> getValidParameters();

  /// Values of Mesh/Source.
  static const std::vector<std::string>& sources();

  /// Build the mesh of `settings` (MeshSettings::fromParameters of the validated "Mesh" list),
  /// checked against Problem/Dimension `dimension` (2 or 3): mesh the initial domain, apply
  /// Mesh/Uniform refinements and Mesh/Local refinement, and return the refiner holding the
  /// current mesh.
  /// splitBoundarySimplices: split initial elements with all vertices on the boundary at their
  /// barycentre first (BoundarySimplexSplit.hpp; for 3D Taylor–Hood stability, docs/theory.md
  /// §"Mixed formulation"). `limit` (ResourceEstimate.hpp; default: none): the initial mesh of a
  /// scene, the uniform levels and the local sweeps are estimated first, and one that exceeds the
  /// limit is an InputError naming the key, the estimate and the limit (before Gmsh or the refiner
  /// runs).
  static Teuchos::RCP<BisectionRefiner> build(const MeshSettings& settings, int dimension,
                                              bool splitBoundarySimplices = false,
                                              const ResourceLimit& limit = ResourceLimit());

  /// The same for a run on `comm`: rank 0 builds the initial mesh (Gmsh) and broadcasts it, so
  /// every rank holds the identical replicated mesh (and then identical refinements). An
  /// InputError on rank 0 is rethrown on every rank with the same message.
  static Teuchos::RCP<BisectionRefiner> build(const MeshSettings& settings, int dimension,
                                              const Teuchos::Comm<int>& comm,
                                              bool splitBoundarySimplices = false,
                                              const ResourceLimit& limit = ResourceLimit());

  /// build() from a "Mesh" list not yet checked (tests, tools):
  /// MeshSettings::fromUncheckedParameters (errors name 'Mesh/<key>'), then build().
  static Teuchos::RCP<BisectionRefiner> build(const Teuchos::ParameterList& meshList, int dimension,
                                              bool splitBoundarySimplices = false,
                                              const ResourceLimit& limit = ResourceLimit());
  static Teuchos::RCP<BisectionRefiner> build(const Teuchos::ParameterList& meshList, int dimension,
                                              const Teuchos::Comm<int>& comm,
                                              bool splitBoundarySimplices = false,
                                              const ResourceLimit& limit = ResourceLimit());

  /// Apply "Mesh/Local refinement" (Levels, Center, Radius, Boundary): `Levels` sweeps, each
  /// bisecting (with conforming closure) every element whose centroid — or, with `Boundary`,
  /// whose face on that part — lies within `Radius` of `Center`. The closure grades the mesh
  /// away from the region. build() calls it after the uniform levels. With `limit`, a sweep
  /// whose result (current elements + closureFactor() · selected) would exceed it is an
  /// InputError naming Levels.
  static void refineLocally(BisectionRefiner& refiner, const LocalRefinementSettings& local,
                            const ResourceLimit& limit = ResourceLimit());
  /// The same for a "Local refinement" list not yet checked (tests).
  static void refineLocally(BisectionRefiner& refiner, const Teuchos::ParameterList& local,
                            const ResourceLimit& limit = ResourceLimit());

  /// Estimated elements of the initial Gmsh mesh of a scene (ResourceEstimate.hpp), -1 for a
  /// Gmsh file. Validates `meshList`.
  static double estimateInitialElements(const Teuchos::ParameterList& meshList, int dimension);

  /// Estimated elements after the uniform levels and the local sweeps of `settings`, starting
  /// from `initial` (counts its selected elements; Center/Boundary must be valid).
  static MeshEstimate estimateRefinement(const MeshSettings& settings, const SimplexMesh& initial);
  /// The same for a "Mesh" list not yet checked (tests).
  static MeshEstimate estimateRefinement(const Teuchos::ParameterList& meshList,
                                         const SimplexMesh& initial);

  /// The quadratic geometry of the refiner's current mesh for Mesh/Geometry order = 2, or null:
  /// order 1, a domain without curved parts (a linear Gmsh file), or no projection.
  static Teuchos::RCP<const CurvedElements> curvedElements(const MeshSettings& settings,
                                                           const BisectionRefiner& refiner);
  /// Whether curvedElements() gives elements (without making them).
  static bool hasCurvedElements(const MeshSettings& settings, const BisectionRefiner& refiner);

  /// The geometry of the settings: a scene's exact geometry, the CadGeometry of a Gmsh geometry
  /// (runs its script), or null for a Gmsh file, whose boundary (MeshBoundaryGeometry) comes
  /// with the file: build() gives it to the refiner.
  static Teuchos::RCP<const Geometry> buildGeometry(const MeshSettings& settings, int dimension);
  /// The same for a "Mesh" list not yet checked (tests).
  static Teuchos::RCP<const Geometry> buildGeometry(const Teuchos::ParameterList& meshList,
                                                    int dimension);
};

}  // namespace sc::mesh
