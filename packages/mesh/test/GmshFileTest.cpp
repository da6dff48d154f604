// Gmsh .msh input. The stored files half_disc_h0.25_v41.msh / _v22.msh were written by Gmsh 4.8.4
// through GmshMeshIO::writeGeometryMesh(HalfDiscGeometry(1), 0.25, ...) (tool
// mesh_write_test_meshes), so reading them must give the built-in scene's boundary names and
// measure (stored reference: the scene mesh, equal to rounding).
#include "MeshTestUtils.hpp"

#include <sc/core/Error.hpp>
#include <sc/mesh/GmshMeshIO.hpp>
#include <sc/mesh/HalfBallGeometry.hpp>
#include <sc/mesh/HalfDiscGeometry.hpp>

#include <Teuchos_UnitTestHarness.hpp>

#include <fstream>
#include <sstream>

namespace {

using namespace sc::mesh;
using sc::mesh::test::contains;

const std::string dataDir = SC_MESH_TEST_DATA;

void expectInputError(const std::function<void()>& f, const std::vector<std::string>& what,
                      bool& success, Teuchos::FancyOStream& out)
{
  try {
    f();
    out << "no exception\n";
    success = false;
  } catch (const sc::core::InputError& e) {
    out << "message: " << e.what() << "\n";
    for (const auto& w : what) TEST_ASSERT(contains(e.what(), w));
  }
}

std::string writeFile(const std::string& name, const std::string& text)
{
  std::ofstream(name) << text;
  return name;
}

TEUCHOS_UNIT_TEST(GmshFile, HalfDiscFilesMatchTheScene)
{
  const HalfDiscGeometry g(1.0);
  auto scene = GmshMeshIO::meshGeometry(g, 0.25);
  for (const std::string file : {"half_disc_h0.25_v41.msh", "half_disc_h0.25_v22.msh"}) {
    auto m = GmshMeshIO::readFile(dataDir + "/" + file, 2);
    out << file << ": " << m->numElements() << " elements, measure " << m->measure() << "\n";
    TEST_ASSERT(m->boundaryNames() == std::vector<std::string>({"Top", "Arc"}));
    TEST_EQUALITY(m->numElements(), scene->numElements());
    TEST_FLOATING_EQUALITY(m->measure(), scene->measure(), 1e-12);
    TEST_FLOATING_EQUALITY(m->boundaryMeasure("Top"), 2.0, 1e-12);  // analytic: the diameter
    TEST_FLOATING_EQUALITY(m->boundaryMeasure("Arc"), scene->boundaryMeasure("Arc"), 1e-12);
    TEST_COMPARE(std::abs(m->measure() - M_PI / 2), <, 0.02);
  }
}

// 3D: half_ball_h0.5_v41.msh (same tool, HalfBallGeometry(1), size 0.5).
TEUCHOS_UNIT_TEST(GmshFile, HalfBallFileMatchesTheScene)
{
  auto scene = GmshMeshIO::meshGeometry(HalfBallGeometry(1.0), 0.5);
  auto m = GmshMeshIO::readFile(dataDir + "/half_ball_h0.5_v41.msh", 3);
  out << m->numElements() << " tetrahedra, volume " << m->measure() << "\n";
  TEST_ASSERT(m->boundaryNames() == std::vector<std::string>({"Top", "Cap"}));
  TEST_EQUALITY(m->numElements(), scene->numElements());
  TEST_FLOATING_EQUALITY(m->measure(), scene->measure(), 1e-12);
  TEST_FLOATING_EQUALITY(m->boundaryMeasure("Cap"), scene->boundaryMeasure("Cap"), 1e-12);
  TEST_COMPARE(std::abs(m->measure() - 2 * M_PI / 3), <, 0.2);  // coarse inscribed polyhedron
}

TEUCHOS_UNIT_TEST(GmshFile, MissingFileNamesTheFile)
{
  expectInputError([] { GmshMeshIO::readFile("no/such/mesh.msh", 2); },
                   {"no/such/mesh.msh", "cannot be opened"}, success, out);
}

TEUCHOS_UNIT_TEST(GmshFile, CorruptFilesNameTheFile)
{
  // Stored truncated copy of the 4.1 file (cut inside the $Elements section).
  expectInputError([] { GmshMeshIO::readFile(dataDir + "/half_disc_truncated.msh", 2); },
                   {"half_disc_truncated.msh"}, success, out);
  // Not a mesh at all.
  const std::string garbage = writeFile("garbage.msh", "this is not a mesh\n");
  expectInputError([&] { GmshMeshIO::readFile(garbage, 2); }, {"garbage.msh"}, success, out);
  // Wrong dimension.
  expectInputError([] { GmshMeshIO::readFile(dataDir + "/half_disc_h0.25_v41.msh", 3); },
                   {"half_disc_h0.25_v41.msh", "dimension 2", "Problem/Dimension = 3"}, success, out);
}

const char* kHeader = "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n";

TEUCHOS_UNIT_TEST(GmshFile, UnsupportedAndInvalidElementsNameTheEntity)
{
  // A quadrangle (Gmsh type 3).
  std::string quad = std::string(kHeader) +
                     "$Nodes\n4\n1 0 0 0\n2 1 0 0\n3 1 1 0\n4 0 1 0\n$EndNodes\n"
                     "$Elements\n1\n7 3 2 1 1 1 2 3 4\n$EndElements\n";
  expectInputError([&] { GmshMeshIO::readFile(writeFile("quad.msh", quad), 2); },
                   {"quad.msh", "unsupported element type", "element 7"}, success, out);
  // A degenerate triangle.
  std::string flat = std::string(kHeader) +
                     "$Nodes\n3\n1 0 0 0\n2 1 0 0\n3 2 0 0\n$EndNodes\n"
                     "$Elements\n1\n1 2 2 1 1 1 2 3\n$EndElements\n";
  expectInputError([&] { GmshMeshIO::readFile(writeFile("flat.msh", flat), 2); },
                   {"flat.msh", "degenerate element 1 (node 1 (0, 0), node 2 (1, 0), node 3 (2, 0))"}, success, out);
  // Three triangles on one edge (non-conforming).
  std::string fan = std::string(kHeader) +
                    "$Nodes\n5\n1 0 0 0\n2 1 0 0\n3 0.5 1 0\n4 0.5 -1 0\n5 0.5 2 0\n$EndNodes\n"
                    "$Elements\n3\n1 2 2 1 1 1 2 3\n2 2 2 1 1 2 1 4\n3 2 2 1 1 1 2 5\n$EndElements\n";
  expectInputError([&] { GmshMeshIO::readFile(writeFile("fan.msh", fan), 2); },
                   {"fan.msh", "edge (node 1 (0, 0), node 2 (1, 0)) is shared by more than two elements (element 1, element 2, element 3)"}, success, out);
  // Folded: the second triangle lies on the same side of the shared edge 1-2 (an inverted
  // element in a mesh that would otherwise be conforming).
  std::string fold = std::string(kHeader) +
                     "$Nodes\n4\n1 0 0 0\n2 1 0 0\n3 0.5 1 0\n4 0.5 0.5 0\n$EndNodes\n"
                     "$Elements\n2\n1 2 2 1 1 1 2 3\n2 2 2 1 1 2 1 4\n$EndElements\n";
  expectInputError([&] { GmshMeshIO::readFile(writeFile("fold.msh", fold), 2); },
                   {"fold.msh", "overlapping elements: element 1", "element 2"}, success, out);
  // Hanging node: node 5 in the middle of edge 1-2.
  std::string hang = std::string(kHeader) +
                     "$Nodes\n5\n1 0 0 0\n2 1 0 0\n3 0.5 1 0\n4 0.5 -1 0\n5 0.5 0 0\n$EndNodes\n"
                     "$Elements\n3\n1 2 2 1 1 1 2 3\n2 2 2 1 1 1 4 5\n3 2 2 1 1 5 4 2\n$EndElements\n";
  expectInputError([&] { GmshMeshIO::readFile(writeFile("hang.msh", hang), 2); },
                   {"hang.msh", "hanging node: node 5 lies inside the edge (node 1, node 2)"}, success, out);
}

TEUCHOS_UNIT_TEST(GmshFile, NonFiniteCoordinatesNameTheNode)
{
  // Gmsh reads "nan" and "inf" as numbers (issue #12: NaN in mesh data was untested; before, a
  // NaN y passed and the mesh checks compared NaNs).
  for (const std::string bad : {"nan", "-inf"}) {
    std::string text = std::string(kHeader) + "$Nodes\n3\n1 0 0 0\n2 1 " + bad +
                       " 0\n3 0 1 0\n$EndNodes\n$Elements\n1\n1 2 2 1 1 1 2 3\n$EndElements\n";
    expectInputError([&] { GmshMeshIO::readFile(writeFile("nan.msh", text), 2); },
                     {"nan.msh", "node 2 has a non-finite coordinate (1, "}, success, out);
  }
  // An unused node with a NaN coordinate is ignored, as unused nodes are.
  std::string unused = std::string(kHeader) +
                       "$Nodes\n4\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 nan nan nan\n$EndNodes\n"
                       "$Elements\n1\n1 2 2 1 1 1 2 3\n$EndElements\n";
  auto m = GmshMeshIO::readFile(writeFile("nan_unused.msh", unused), 2);
  TEST_EQUALITY(m->numElements(), 1);
}

TEUCHOS_UNIT_TEST(GmshFile, FileThatCrashesGmshIsAnInputError)
{
  // Found by fuzz_gmsh (docs/reliability.md "Fuzzing"): half_disc_h0.25_v41.msh with damaged
  // $Nodes lines. Gmsh 4.8's MSH4 reader reads out of bounds on it (SEGV in
  // GModel::getMeshVertexByTag): before, the whole program died of a segmentation fault.
  expectInputError([] { GmshMeshIO::readFile(dataDir + "/fuzz_msh4_damaged_nodes.msh", 2); },
                   {"fuzz_msh4_damaged_nodes.msh", "Gmsh's reader crashed on it (signal 11"},
                   success, out);
  // The good file beside it still reads (the check runs Gmsh in a child process first).
  TEST_EQUALITY(GmshMeshIO::readFile(dataDir + "/half_disc_h0.25_v41.msh", 2)->numElements() > 0,
                true);
}

TEUCHOS_UNIT_TEST(GmshFile, UnnamedPhysicalGroupsAndUntaggedFaces)
{
  // Two triangles; the bottom edge is in physical group 5 (no name), the rest untagged.
  std::string sq = std::string(kHeader) +
                   "$Nodes\n4\n1 0 0 0\n2 1 0 0\n3 1 1 0\n4 0 1 0\n$EndNodes\n"
                   "$Elements\n3\n1 1 2 5 1 1 2\n2 2 2 1 1 1 2 3\n3 2 2 1 1 1 3 4\n$EndElements\n";
  auto m = GmshMeshIO::readFile(writeFile("square.msh", sq), 2);
  TEST_ASSERT(m->boundaryNames() == std::vector<std::string>({"5", "Unnamed"}));
  TEST_FLOATING_EQUALITY(m->boundaryMeasure("5"), 1.0, 1e-14);
  TEST_FLOATING_EQUALITY(m->boundaryMeasure("Unnamed"), 3.0, 1e-14);
}

}  // namespace
