// Writes the stored test meshes of packages/mesh/test/data (run once; output is committed):
//   mesh_write_test_meshes <dir>
#include <sc/mesh/GmshMeshIO.hpp>
#include <sc/mesh/HalfBallGeometry.hpp>
#include <sc/mesh/HalfDiscGeometry.hpp>

#include <cstdio>
#include <string>

int main(int argc, char** argv)
{
  if (argc != 2) {
    std::fprintf(stderr, "usage: %s <output directory>\n", argv[0]);
    return 2;
  }
  const std::string dir = argv[1];
  const sc::mesh::HalfDiscGeometry g(1.0);
  sc::mesh::GmshMeshIO::writeGeometryMesh(g, 0.25, dir + "/half_disc_h0.25_v41.msh", 4.1);
  sc::mesh::GmshMeshIO::writeGeometryMesh(g, 0.25, dir + "/half_disc_h0.25_v22.msh", 2.2);
  // Second order (6-node triangles, 3-node arc faces on the circle): a user's curved mesh file.
  sc::mesh::GmshMeshIO::writeGeometryMesh(g, 0.1, dir + "/half_disc_h0.1_order2_v41.msh", 4.1, 2);
  const sc::mesh::HalfBallGeometry b(1.0);
  sc::mesh::GmshMeshIO::writeGeometryMesh(b, 0.5, dir + "/half_ball_h0.5_v41.msh", 4.1);
  return 0;
}
