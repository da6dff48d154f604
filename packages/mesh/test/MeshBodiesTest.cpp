// meshBodies: the connected components of a mesh under "shares a face", with their element
// counts, bounding boxes and boundary parts. Expected values are those of the hand-built meshes.
#include <sc/mesh/MeshBodies.hpp>
#include <sc/mesh/SimplexMesh.hpp>

#include <Teuchos_UnitTestHarness.hpp>

namespace {

using sc::mesh::meshBodies;
using sc::mesh::SimplexMesh;

// Two unit squares, [0, 1]² and [2, 3] × [0, 1], two triangles each (tests/data/two_squares.msh).
// Parts: 0 Support (A's bottom), 1 Load (both tops), 2 RightA, 3 BaseB, 4 RightB, 5 LeftB,
// 6 LeftA.
Teuchos::RCP<SimplexMesh> twoSquares()
{
  std::vector<double> x = {0, 0, 1, 0, 1, 1, 0, 1, 2, 0, 3, 0, 3, 1, 2, 1};
  std::vector<int> t = {0, 1, 2, 0, 2, 3, 4, 5, 6, 4, 6, 7};
  std::vector<int> bf = {0, 1, 1, 2, 2, 3, 3, 0, 4, 5, 5, 6, 6, 7, 7, 4};
  std::vector<int> bp = {0, 2, 1, 6, 3, 4, 1, 5};
  return Teuchos::rcp(new SimplexMesh(
      2, x, t, bf, bp, {"Support", "Load", "RightA", "BaseB", "RightB", "LeftB", "LeftA"},
      "two squares"));
}

TEUCHOS_UNIT_TEST(MeshBodies, TwoSquaresAreTwoBodies)
{
  const auto bodies = meshBodies(*twoSquares());
  TEST_EQUALITY(bodies.size(), std::size_t(2));
  TEST_COMPARE_ARRAYS(bodies[0].elements, std::vector<int>({0, 1}));
  TEST_COMPARE_ARRAYS(bodies[1].elements, std::vector<int>({2, 3}));
  TEST_COMPARE_ARRAYS(bodies[0].boundaryIds, std::vector<int>({0, 1, 2, 6}));
  TEST_COMPARE_ARRAYS(bodies[1].boundaryIds, std::vector<int>({1, 3, 4, 5}));
  TEST_EQUALITY(bodies[1].lo[0], 2.0);
  TEST_EQUALITY(bodies[1].hi[0], 3.0);
  TEST_EQUALITY(bodies[1].describe(2), "2 triangles, bounding box [2, 3] × [0, 1]");
}

// Two triangles that meet only at a vertex are two bodies (the stresses couple through faces).
TEUCHOS_UNIT_TEST(MeshBodies, AVertexDoesNotJoin)
{
  std::vector<double> x = {0, 0, 1, 0, 0, 1, 2, 0, 1, 1};
  std::vector<int> t = {0, 1, 2, 1, 3, 4};
  std::vector<int> bf = {0, 1, 1, 2, 2, 0, 1, 3, 3, 4, 4, 1};
  std::vector<int> bp = {0, 0, 0, 0, 0, 0};
  const SimplexMesh m(2, x, t, bf, bp, {"All"}, "bow tie");
  const auto bodies = meshBodies(m);
  TEST_EQUALITY(bodies.size(), std::size_t(2));
  TEST_EQUALITY(bodies[0].describe(2), "1 triangle, bounding box [0, 1] × [0, 1]");
}

// 3D: two tetrahedra sharing a face are one body; a third, apart, is another.
TEUCHOS_UNIT_TEST(MeshBodies, Tetrahedra)
{
  std::vector<double> x = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 1,  // 0-4: two, sharing 1-2-3
                           5, 0, 0, 6, 0, 0, 5, 1, 0, 5, 0, 1};          // 5-8: one apart
  std::vector<int> t = {0, 1, 2, 3, 1, 2, 3, 4, 5, 6, 7, 8};
  std::vector<int> bf = {0, 1, 2, 0, 1, 3, 0, 2, 3, 1, 2, 4, 1, 3, 4,
                         2, 3, 4, 5, 6, 7, 5, 6, 8, 5, 7, 8, 6, 7, 8};
  std::vector<int> bp = {0, 0, 0, 1, 1, 1, 2, 2, 2, 2};
  const SimplexMesh m(3, x, t, bf, bp, {"A", "B", "C"}, "tetrahedra");
  const auto bodies = meshBodies(m);
  TEST_EQUALITY(bodies.size(), std::size_t(2));
  TEST_COMPARE_ARRAYS(bodies[0].elements, std::vector<int>({0, 1}));
  TEST_COMPARE_ARRAYS(bodies[0].boundaryIds, std::vector<int>({0, 1}));
  TEST_COMPARE_ARRAYS(bodies[1].boundaryIds, std::vector<int>({2}));
  TEST_EQUALITY(bodies[1].describe(3), "1 tetrahedron, bounding box [5, 6] × [0, 1] × [0, 1]");
}

}  // namespace
