// SimplexMesh: connectivity, geometric quantities and the checks on bad meshes. Expected values are
// analytic (hand-built meshes of the unit square).
#include <sc/core/Error.hpp>
#include <sc/mesh/SimplexMesh.hpp>

#include <Teuchos_UnitTestHarness.hpp>

#include <cmath>
#include <functional>

namespace {

using sc::mesh::SimplexMesh;

bool contains(const std::string& text, const std::string& what)
{
  return text.find(what) != std::string::npos;
}

// Unit square split along the diagonal 0-2; the second triangle is given clockwise.
Teuchos::RCP<SimplexMesh> unitSquare()
{
  std::vector<double> x = {0, 0, 1, 0, 1, 1, 0, 1};
  std::vector<int> t = {0, 1, 2, /*clockwise:*/ 0, 2, 3};
  std::vector<int> bf = {0, 1, 1, 2, 2, 3, 3, 0};
  std::vector<int> bp = {0, 1, 2, 3};
  return Teuchos::rcp(
      new SimplexMesh(2, x, t, bf, bp, {"Bottom", "Right", "Top", "Left"}, "square"));
}

TEUCHOS_UNIT_TEST(SimplexMesh, SquareConnectivityAndGeometry)
{
  auto m = unitSquare();
  TEST_EQUALITY(m->numVertices(), 4);
  TEST_EQUALITY(m->numElements(), 2);
  TEST_EQUALITY(m->numFaces(), 5);
  TEST_EQUALITY(static_cast<int>(m->boundaryFaces().size()), 4);
  TEST_FLOATING_EQUALITY(m->measure(), 1.0, 1e-14);       // analytic
  TEST_FLOATING_EQUALITY(m->minAngleDeg(), 45.0, 1e-12);  // analytic
  TEST_FLOATING_EQUALITY(m->elementDiameter(0), std::sqrt(2.0), 1e-14);
  TEST_EQUALITY(m->eulerCharacteristic(), 1L);
  // Every element positively oriented after construction (second one was clockwise).
  for (int e = 0; e < 2; ++e) {
    const int* v = m->elementVertices(e);
    const double* a = m->vertex(v[0]);
    const double* b = m->vertex(v[1]);
    const double* c = m->vertex(v[2]);
    TEST_ASSERT((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]) > 0);
    TEST_FLOATING_EQUALITY(m->elementMeasure(e), 0.5, 1e-14);
  }
  // Outward normals and part lengths.
  for (int f : m->boundaryFaces()) {
    const auto n = m->faceNormal(f);
    const int* v = m->faceVertices(f);
    const double mid[2] = {0.5 * (m->vertex(v[0])[0] + m->vertex(v[1])[0]),
                           0.5 * (m->vertex(v[0])[1] + m->vertex(v[1])[1])};
    // Outward: the midpoint moved along n leaves the square.
    const double px = mid[0] + 0.1 * n[0], py = mid[1] + 0.1 * n[1];
    TEST_ASSERT(px < 0 || px > 1 || py < 0 || py > 1);
  }
  TEST_FLOATING_EQUALITY(m->boundaryMeasure("Left"), 1.0, 1e-14);
  TEST_EQUALITY(m->boundaryFacesOf("Top").size(), 1u);
  // Local face i opposite local vertex i.
  for (int e = 0; e < 2; ++e)
    for (int i = 0; i < 3; ++i) {
      const int f = m->elementFaces(e)[i];
      const int* fv = m->faceVertices(f);
      TEST_ASSERT(fv[0] != m->elementVertices(e)[i] && fv[1] != m->elementVertices(e)[i]);
    }
}

TEUCHOS_UNIT_TEST(SimplexMesh, UnknownBoundaryNameListsValidNames)
{
  auto m = unitSquare();
  TEST_THROW(m->boundaryId("Arc"), sc::core::InputError);
  try {
    m->boundaryId("Arc");
  } catch (const sc::core::InputError& e) {
    TEST_ASSERT(contains(e.what(), "'Arc'") && contains(e.what(), "'Bottom'") &&
                contains(e.what(), "'Left'") && contains(e.what(), "square"));
  }
}

TEUCHOS_UNIT_TEST(SimplexMesh, SingleTetrahedron)
{
  std::vector<double> x = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
  SimplexMesh m(3, x, {0, 2, 1, 3}, {}, {}, {}, "tet");   // negative order on purpose
  TEST_FLOATING_EQUALITY(m.measure(), 1.0 / 6.0, 1e-14);  // analytic
  TEST_EQUALITY(m.numFaces(), 4);
  TEST_EQUALITY(m.boundaryNames().size(), 1u);  // all faces untagged -> "Unnamed"
  TEST_EQUALITY(m.boundaryNames()[0], std::string("Unnamed"));
  // Dihedral angles of the corner tetrahedron: 90° at the three axis edges, acos(1/sqrt(3)) ≈
  // 54.7356° at the three others (analytic).
  TEST_FLOATING_EQUALITY(m.minAngleDeg(), std::acos(1 / std::sqrt(3.0)) * 180 / M_PI, 1e-10);
  TEST_EQUALITY(m.eulerCharacteristic(), 1L);
}

void expectInputError(const std::function<void()>& f, const std::string& what, bool& success,
                      Teuchos::FancyOStream& out)
{
  try {
    f();
    out << "no exception, expected one containing '" << what << "'\n";
    success = false;
  } catch (const sc::core::InputError& e) {
    out << "message: " << e.what() << "\n";
    TEST_ASSERT(contains(e.what(), what));
  }
}

TEUCHOS_UNIT_TEST(SimplexMesh, BadMeshesAreInputErrors)
{
  // Three triangles on one edge.
  expectInputError(
      [] {
        SimplexMesh(2, {0, 0, 1, 0, 0.5, 1, 0.5, -1, 0.5, 2}, {0, 1, 2, 1, 0, 3, 0, 1, 4}, {}, {},
                    {}, "fan");
      },
      "more than two", success, out);
  // Hanging node 4 at the midpoint of edge 0-1.
  expectInputError(
      [] {
        SimplexMesh(2, {0, 0, 1, 0, 0.5, 1, 0.5, -1, 0.5, 0}, {0, 1, 2, 0, 3, 4, 4, 3, 1}, {}, {},
                    {}, "hanging");
      },
      "hanging node: vertex 4", success, out);
  // Degenerate (collinear) triangle.
  expectInputError(
      [] {
        SimplexMesh(2, {0, 0, 1, 0, 2, 0}, {0, 1, 2}, {}, {}, {}, "flat");
      },
      "degenerate", success, out);
  // Folded: both triangles on the same side of edge 0-1.
  expectInputError(
      [] {
        SimplexMesh(2, {0, 0, 1, 0, 0.5, 1, 0.5, 0.5}, {0, 1, 2, 0, 1, 3}, {}, {}, {}, "folded");
      },
      "overlapping", success, out);
  // Tagged face that is interior.
  expectInputError(
      [] {
        SimplexMesh(2, {0, 0, 1, 0, 1, 1, 0, 1}, {0, 1, 2, 0, 2, 3}, {0, 2}, {0}, {"Diag"}, "diag");
      },
      "not a boundary face", success, out);
}

}  // namespace

namespace {

// Shards/Intrepid2 numbering (Shards_BasicTopologies.hpp): tetrahedron sides {0,1,3}, {1,2,3},
// {0,3,2}, {0,2,1}; edges (0,1), (1,2), (2,0), (0,3), (1,3), (2,3).
TEUCHOS_UNIT_TEST(SimplexMesh, ShardsSideAndEdgeNumbering)
{
  std::vector<double> x = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
  sc::mesh::SimplexMesh m(3, x, {0, 1, 2, 3}, {}, {}, {}, "tet");
  const int sides[4][3] = {{0, 1, 3}, {1, 2, 3}, {0, 2, 3}, {0, 1, 2}};  // sorted
  for (int s = 0; s < 4; ++s) {
    const int* fv = m.faceVertices(m.sideFace(0, s));
    for (int k = 0; k < 3; ++k)
      TEST_EQUALITY(fv[k], sides[s][k]);
  }
  const int edges[6][2] = {{0, 1}, {1, 2}, {0, 2}, {0, 3}, {1, 3}, {2, 3}};  // sorted
  TEST_EQUALITY(m.numEdges(), 6);
  for (int k = 0; k < 6; ++k) {
    const int* ev = m.edgeVertices(m.elementEdges(0)[k]);
    TEST_EQUALITY(ev[0], edges[k][0]);
    TEST_EQUALITY(ev[1], edges[k][1]);
  }
  sc::mesh::SimplexMesh t(2, {0, 0, 1, 0, 0, 1}, {0, 1, 2}, {}, {}, {}, "tri");
  const int tedges[3][2] = {{0, 1}, {1, 2}, {0, 2}};
  for (int s = 0; s < 3; ++s) {
    const int* ev = t.edgeVertices(t.elementEdges(0)[s]);
    TEST_EQUALITY(ev[0], tedges[s][0]);
    TEST_EQUALITY(ev[1], tedges[s][1]);
    TEST_EQUALITY(t.sideFace(0, s), t.elementEdges(0)[s]);
  }
}

}  // namespace
