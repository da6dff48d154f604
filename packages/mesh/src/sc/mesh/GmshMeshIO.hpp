#pragma once
// Initial meshes through Gmsh's C++ API (Debian libgmsh-dev): meshing a scene geometry with a
// target element size, and reading .msh files (formats 2.2 and 4.1) whose physical groups of
// dimension dim−1 become the boundary parts. Gmsh is initialised quietly (General.Terminal = 0)
// for each call and finalised afterwards; it is not thread-safe, so call these from one thread.

#include <sc/mesh/Geometry.hpp>
#include <sc/mesh/SimplexMesh.hpp>

#include <Teuchos_RCP.hpp>

#include <string>

namespace sc::mesh {

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

  /// Mesh `geometry` and write it with physical groups to `path` in MSH `version` 2.2 or 4.1
  /// (used to produce the test meshes under packages/mesh/test/data).
  static void writeGeometryMesh(const Geometry& geometry, double meshSize,
                                const std::string& path, double version);
};

}  // namespace sc::mesh
