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

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <sys/stat.h>

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
    for (const auto& w : what)
      TEST_ASSERT(contains(e.what(), w));
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
                   {"half_disc_h0.25_v41.msh", "dimension 2", "Problem/Dimension = 3"}, success,
                   out);
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
  std::string flat = std::string(kHeader) + "$Nodes\n3\n1 0 0 0\n2 1 0 0\n3 2 0 0\n$EndNodes\n"
                                            "$Elements\n1\n1 2 2 1 1 1 2 3\n$EndElements\n";
  expectInputError(
      [&] { GmshMeshIO::readFile(writeFile("flat.msh", flat), 2); },
      {"flat.msh", "degenerate element 1 (node 1 (0, 0), node 2 (1, 0), node 3 (2, 0))"}, success,
      out);
  // Three triangles on one edge (non-conforming).
  std::string fan =
      std::string(kHeader) +
      "$Nodes\n5\n1 0 0 0\n2 1 0 0\n3 0.5 1 0\n4 0.5 -1 0\n5 0.5 2 0\n$EndNodes\n"
      "$Elements\n3\n1 2 2 1 1 1 2 3\n2 2 2 1 1 2 1 4\n3 2 2 1 1 1 2 5\n$EndElements\n";
  expectInputError([&] { GmshMeshIO::readFile(writeFile("fan.msh", fan), 2); },
                   {"fan.msh", "edge (node 1 (0, 0), node 2 (1, 0)) is shared by more than two "
                               "elements (element 1, element 2, element 3)"},
                   success, out);
  // Folded: the second triangle lies on the same side of the shared edge 1-2 (an inverted
  // element in a mesh that would otherwise be conforming).
  std::string fold = std::string(kHeader) +
                     "$Nodes\n4\n1 0 0 0\n2 1 0 0\n3 0.5 1 0\n4 0.5 0.5 0\n$EndNodes\n"
                     "$Elements\n2\n1 2 2 1 1 1 2 3\n2 2 2 1 1 2 1 4\n$EndElements\n";
  expectInputError([&] { GmshMeshIO::readFile(writeFile("fold.msh", fold), 2); },
                   {"fold.msh", "overlapping elements: element 1", "element 2"}, success, out);
  // Hanging node: node 5 in the middle of edge 1-2.
  std::string hang =
      std::string(kHeader) +
      "$Nodes\n5\n1 0 0 0\n2 1 0 0\n3 0.5 1 0\n4 0.5 -1 0\n5 0.5 0 0\n$EndNodes\n"
      "$Elements\n3\n1 2 2 1 1 1 2 3\n2 2 2 1 1 1 4 5\n3 2 2 1 1 5 4 2\n$EndElements\n";
  expectInputError([&] { GmshMeshIO::readFile(writeFile("hang.msh", hang), 2); },
                   {"hang.msh", "hanging node: node 5 lies inside the edge (node 1, node 2)"},
                   success, out);
}

TEUCHOS_UNIT_TEST(GmshFile, NonFiniteCoordinatesNameTheNode)
{
  // Gmsh reads "nan" and "inf" as numbers: the reader must name the node, or a NaN y passes and
  // the mesh checks compare NaNs (docs/reliability.md).
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
  // From fuzz_gmsh (docs/reliability.md "Fuzzing"): half_disc_h0.25_v41.msh with damaged
  // $Nodes lines. Gmsh 4.8's MSH4 reader reads out of bounds on it (SEGV in
  // GModel::getMeshVertexByTag): read in-process, the whole program dies of it.
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

// A mesh file is data (docs/mesh.md "Gmsh files"). Gmsh 4.8's gmsh::open runs any file whose
// first line is not a known data header as a .geo script, whatever its name, and merges an
// option file '<file>.opt' (a script too) beside the file it opens; a script can run shell
// commands with SystemCall. Verified with Gmsh 4.8.4: both run the command when opened directly.
TEUCHOS_UNIT_TEST(GmshFile, ScriptsInMeshFilesAreNeverRun)
{
  namespace fs = std::filesystem;
  const fs::path dir = fs::absolute("gmsh_scripts");
  fs::remove_all(dir);
  fs::create_directories(dir);
  const fs::path marker = dir / "command_ran";
  const std::string call = "SystemCall \"touch " + marker.string() + "\";\n";
  // A script named .msh that would mesh a triangle after running the command.
  const std::string script =
      call + "Point(1) = {0, 0, 0, 0.5}; Point(2) = {1, 0, 0, 0.5}; Point(3) = {0, 1, 0, 0.5};\n"
             "Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 1};\n"
             "Curve Loop(1) = {1, 2, 3}; Plane Surface(1) = {1};\nMesh 2;\n";
  const std::string evil = writeFile((dir / "evil.msh").string(), script);
  expectInputError([&] { GmshMeshIO::readFile(evil, 2); },
                   {"evil.msh", "is not a Gmsh MSH file", "its first line is 'SystemCall"}, success,
                   out);
  TEST_ASSERT(!fs::exists(marker));
  // The same after a comment line, and with a header that is not the first line.
  expectInputError(
      [&] {
        GmshMeshIO::readFile(
            writeFile((dir / "evil2.msh").string(), "// mesh\n$MeshFormat\n" + script), 2);
      },
      {"is not a Gmsh MSH file"}, success, out);
  TEST_ASSERT(!fs::exists(marker));
  // A real mesh with an option file beside it: the mesh is read, the option file is not run.
  fs::copy_file(dataDir + "/half_disc_h0.25_v41.msh", dir / "good.msh");
  writeFile((dir / "good.msh.opt").string(), call);
  auto m = GmshMeshIO::readFile((dir / "good.msh").string(), 2);
  TEST_ASSERT(m->numElements() > 0);
  TEST_ASSERT(!fs::exists(marker));
  // The private copy is removed after reading, also after an error (TMPDIR: a directory of this
  // test's own, so that other tests reading meshes at the same time do not count).
  const fs::path tmp = dir / "tmp";
  fs::create_directories(tmp);
  const char* oldTmp = std::getenv("TMPDIR");
  const std::string saved = oldTmp ? oldTmp : "";
  ::setenv("TMPDIR", tmp.c_str(), 1);
  GmshMeshIO::readFile((dir / "good.msh").string(), 2);
  expectInputError([&] { GmshMeshIO::readFile(evil, 2); }, {"is not a Gmsh MSH file"}, success,
                   out);
  if (oldTmp)
    ::setenv("TMPDIR", saved.c_str(), 1);
  else
    ::unsetenv("TMPDIR");
  TEST_ASSERT(fs::is_empty(tmp));
}

TEUCHOS_UNIT_TEST(GmshFile, HeaderAndVersionAreChecked)
{
  expectInputError([] { GmshMeshIO::readFile(writeFile("empty.msh", ""), 2); },
                   {"empty.msh", "the file is empty"}, success, out);
  expectInputError(
      [] { GmshMeshIO::readFile(writeFile("bom.msh", "\xEF\xBB\xBF" + std::string(kHeader)), 2); },
      {"bom.msh", "UTF-8 byte-order mark"}, success, out);
  expectInputError(
      [] { GmshMeshIO::readFile(writeFile("v1.msh", "$NOD\n3\n1 0 0 0\n$ENDNOD\n"), 2); },
      {"v1.msh", "its first line is '$NOD'"}, success, out);
  expectInputError(
      [] {
        GmshMeshIO::readFile(writeFile("v3.msh", "$MeshFormat\n3.0 0 8\n$EndMeshFormat\n"), 2);
      },
      {"v3.msh", "MSH format version '3.0 0 8'"}, success, out);
  expectInputError([] { GmshMeshIO::readFile(writeFile("cut.msh", "$MeshFormat\n"), 2); },
                   {"cut.msh", "the $MeshFormat section is incomplete"}, success, out);
}

TEUCHOS_UNIT_TEST(GmshFile, NonRegularFilesAreRefused)
{
  // /dev/zero made Gmsh's reader spin forever; a FIFO would block the reader.
  expectInputError([] { GmshMeshIO::readFile("/dev/zero", 2); },
                   {"'/dev/zero'", "is not a regular file"}, success, out);
  const std::string fifo = std::filesystem::absolute("mesh_fifo.msh").string();
  std::filesystem::remove(fifo);
  const int made = ::mkfifo(fifo.c_str(), 0600);
  TEST_EQUALITY(made, 0);
  expectInputError([&] { GmshMeshIO::readFile(fifo, 2); },
                   {"mesh_fifo.msh", "is not a regular file"}, success, out);
  std::filesystem::remove(fifo);
}

// Gmsh keeps one group per name: unchecked, two groups named 'Top' become the part 'Top' and a
// part called by the other's number, traction-free; a group without a name (called '3') and a
// group named '3' merge into one part.
TEUCHOS_UNIT_TEST(GmshFile, ClashingPhysicalNamesAreInputErrors)
{
  const std::string nodes = "$Nodes\n4\n1 0 0 0\n2 1 0 0\n3 1 1 0\n4 0 1 0\n$EndNodes\n";
  std::string twice =
      std::string(kHeader) +
      "$PhysicalNames\n3\n1 1 \"Top\"\n1 2 \"Top\"\n2 9 \"Body\"\n$EndPhysicalNames\n" + nodes +
      "$Elements\n4\n1 1 2 1 1 1 2\n2 1 2 2 2 3 4\n3 2 2 9 1 1 2 3\n"
      "4 2 2 9 1 1 3 4\n$EndElements\n";
  expectInputError(
      [&] { GmshMeshIO::readFile(writeFile("names_twice.msh", twice), 2); },
      {"names_twice.msh", "physical groups 1 and 2 (dimension 1) are both named 'Top'"}, success,
      out);
  std::string clash = std::string(kHeader) + "$PhysicalNames\n1\n1 1 \"3\"\n$EndPhysicalNames\n" +
                      nodes +
                      "$Elements\n4\n1 1 2 1 1 1 2\n2 1 2 3 2 3 4\n3 2 2 9 1 1 2 3\n"
                      "4 2 2 9 1 1 3 4\n$EndElements\n";
  expectInputError([&] { GmshMeshIO::readFile(writeFile("names_clash.msh", clash), 2); },
                   {"names_clash.msh", "physical group 3 has no name, so it is called '3', but "
                                       "physical group 1 is named '3' too"},
                   success, out);
}

}  // namespace
