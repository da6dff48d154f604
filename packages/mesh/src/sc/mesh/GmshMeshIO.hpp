#pragma once
// Initial meshes through Gmsh's C++ API (Debian libgmsh-dev): meshing a scene geometry or a
// user's Gmsh geometry (CadGeometry) with a target element size, and reading .msh files (formats
// 2.2 and 4.1, linear or quadratic) whose physical groups of dimension dim−1 become the boundary
// parts. Each call works in a GmshSession of its own; Gmsh is not thread-safe, so call these from
// one thread.

#include <sc/mesh/Geometry.hpp>
#include <sc/mesh/MeshBoundaryGeometry.hpp>
#include <sc/mesh/SimplexMesh.hpp>

#include <Teuchos_RCP.hpp>

#include <string>

namespace sc::mesh {

class CadGeometry;

class GmshMeshIO {
public:
  /// Mesh `geometry` with Gmsh's default algorithms and Mesh.MeshSizeMax = meshSize. Boundary
  /// parts are named and ordered as geometry.boundaryNames().
  static Teuchos::RCP<SimplexMesh> meshGeometry(const Geometry& geometry, double meshSize);

  /// Read a linear triangle (dim 2) or tetrahedron (dim 3) mesh. Physical groups of dimension
  /// dim−1 name the boundary parts (a group without a name is called by its number); boundary
  /// faces in no group form the part "Unnamed". Missing or unreadable files, a model of another
  /// dimension, unsupported element types and invalid meshes are sc::core::InputError naming the
  /// file and the entity.
  static Teuchos::RCP<SimplexMesh> readFile(const std::string& path, int dim);

  /// A mesh file's mesh and its boundary as the file gives it (docs/mesh.md "Curved boundaries
  /// from files").
  struct MeshFile {
    Teuchos::RCP<SimplexMesh> mesh;
    Teuchos::RCP<MeshBoundaryGeometry> boundary;
  };
  /// readFile, with the boundary: quadratic elements (6-node triangles, 10-node tetrahedra) and
  /// faces (3-node lines, 6-node triangles) give curved boundary faces through their mid-edge
  /// nodes; the mesh holds the elements' vertices.
  static MeshFile readMeshFile(const std::string& path, int dim);

  /// Mesh the model of `cad` (Mesh/Source = Gmsh geometry) with Mesh.MeshSizeMax = meshSize
  /// and the script's own point sizes, at geometric order `order` (1 or 2: Gmsh places the
  /// mid-edge nodes on the CAD entities); boundary parts are its physical groups of dimension
  /// dim−1, in cad.boundaryNames() order. Gmsh failing to mesh is an InputError naming the file.
  static Teuchos::RCP<SimplexMesh> meshCad(const CadGeometry& cad, double meshSize, int order);

  /// Mesh `geometry` and write it with physical groups to `path` in MSH `version` 2.2 or 4.1, at
  /// geometric order `order` (used to produce the test meshes under packages/mesh/test/data and
  /// the second-order meshes of the tests).
  static void writeGeometryMesh(const Geometry& geometry, double meshSize, const std::string& path,
                                double version, int order = 1);
};

}  // namespace sc::mesh
