// METIS partitions of a half-disc mesh of a few thousand elements: balance within 5%
// (docs/mesh.md), identical on every rank, owned sets covering the mesh, and ghost layers holding
// every face neighbour.
#include <sc/mesh/BisectionRefiner.hpp>
#include <sc/mesh/GmshMeshIO.hpp>
#include <sc/core/Error.hpp>
#include <sc/mesh/HalfDiscGeometry.hpp>
#include <sc/mesh/MeshFactory.hpp>
#include <sc/mesh/Partitioning.hpp>

#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_DefaultComm.hpp>
#include <Teuchos_UnitTestHarness.hpp>

#include <algorithm>
#include <cstring>

namespace {

using namespace sc::mesh;

Teuchos::RCP<const SimplexMesh> testMesh()
{
  static Teuchos::RCP<const SimplexMesh> mesh;
  if (mesh.is_null()) {
    auto g = Teuchos::rcp(new HalfDiscGeometry(1.0));
    BisectionRefiner r(GmshMeshIO::meshGeometry(*g, 0.07), g, true);
    r.refineUniformly();
    mesh = r.mesh();
  }
  return mesh;
}

// Same vector on every rank: compare with rank 0's copy.
bool identicalOnAllRanks(const Teuchos::Comm<int>& comm, std::vector<int> v)
{
  std::vector<int> root = v;
  Teuchos::broadcast<int, int>(comm, 0, static_cast<int>(root.size()), root.data());
  const int same = root == v ? 1 : 0;
  int all = 0;
  Teuchos::reduceAll<int, int>(comm, Teuchos::REDUCE_MIN, same, Teuchos::outArg(all));
  return all == 1;
}

TEUCHOS_UNIT_TEST(Partitioning, BalancedAndIdenticalOnEveryRank)
{
  auto comm = Teuchos::DefaultComm<int>::getComm();
  const auto& m = *testMesh();
  out << "elements " << m.numElements() << "\n";
  TEST_COMPARE(m.numElements(), >=, 2000);
  for (int nparts : {2, 4}) {
    const auto owner = partitionElements(m, nparts);
    std::vector<int> count(nparts, 0);
    for (int o : owner) {
      TEST_ASSERT(o >= 0 && o < nparts);
      ++count[o];
    }
    const double ideal = static_cast<double>(m.numElements()) / nparts;
    const double imbalance = *std::max_element(count.begin(), count.end()) / ideal;
    out << nparts << " parts: imbalance " << imbalance << "\n";
    TEST_COMPARE(imbalance, <=, 1.05);
    TEST_ASSERT(identicalOnAllRanks(*comm, owner));
  }
}

TEUCHOS_UNIT_TEST(Partitioning, OwnedAndGhostElementsPerRank)
{
  auto comm = Teuchos::DefaultComm<int>::getComm();
  const auto& m = *testMesh();
  const auto owner = partitionElements(m, *comm);
  TEST_ASSERT(identicalOnAllRanks(*comm, owner));
  const int rank = comm->getRank();
  const auto mine = rankElements(m, owner, rank);
  int nOwned = static_cast<int>(mine.owned.size()), total = 0;
  Teuchos::reduceAll<int, int>(*comm, Teuchos::REDUCE_SUM, nOwned, Teuchos::outArg(total));
  TEST_EQUALITY(total, m.numElements());
  std::vector<char> present(m.numElements(), 0);
  for (int e : mine.owned) {
    TEST_EQUALITY(owner[e], rank);
    present[e] = 1;
  }
  for (int e : mine.ghosts) {
    TEST_ASSERT(owner[e] != rank);
    present[e] = 1;
  }
  // Every face neighbour of an owned element is owned or a ghost.
  for (int e : mine.owned)
    for (int i = 0; i <= m.dim(); ++i) {
      const auto fe = m.faceElements(m.elementFaces(e)[i]);
      const int other = fe[0] == e ? fe[1] : fe[0];
      if (other >= 0) TEST_ASSERT(present[other]);
    }
  if (comm->getSize() == 1) {
    TEST_ASSERT(mine.ghosts.empty());
  } else {
    TEST_ASSERT(!mine.ghosts.empty());
  }
}

// The vertex ownership the fields' writer uses: each vertex owned by the lowest owner among its
// elements (checked against a direct scan of the elements), the numbering a permutation in which
// every rank's vertices form one block, ranks in order, vertex order kept within a block.
TEUCHOS_UNIT_TEST(Partitioning, VertexOwnershipInRankBlocks)
{
  const auto& m = *testMesh();
  for (int nparts : {1, 3}) {
    const auto owner = partitionElements(m, nparts);
    std::vector<int> lowest(m.numVertices(), nparts);
    for (int e = 0; e < m.numElements(); ++e)
      for (int i = 0; i <= m.dim(); ++i) {
        const int v = m.elementVertices(e)[i];
        lowest[v] = std::min(lowest[v], owner[e]);
      }
    std::vector<int> blockStart(nparts + 1, 0);
    for (int v = 0; v < m.numVertices(); ++v)
      ++blockStart[lowest[v] + 1];
    for (int r = 0; r < nparts; ++r)
      blockStart[r + 1] += blockStart[r];
    for (int rank = 0; rank < nparts; ++rank) {
      const auto o = vertexOwnership(m, owner, rank, nparts);
      TEST_ASSERT(o.owner == lowest);
      std::vector<char> seen(m.numVertices(), 0);
      for (long long n : o.number) {
        TEST_ASSERT(n >= 0 && n < m.numVertices() && !seen[n]);
        seen[n] = 1;
      }
      TEST_EQUALITY(static_cast<int>(o.owned.size()), blockStart[rank + 1] - blockStart[rank]);
      for (std::size_t i = 0; i < o.owned.size(); ++i) {
        TEST_EQUALITY(lowest[o.owned[i]], rank);
        TEST_EQUALITY(o.number[o.owned[i]], blockStart[rank] + static_cast<long long>(i));
        if (i > 0) TEST_COMPARE(o.owned[i - 1], <, o.owned[i]);
      }
    }
  }
}

// MeshFactory::build with a communicator: rank 0 meshes, every rank gets the identical mesh;
// an input error on rank 0 is thrown on every rank.
TEUCHOS_UNIT_TEST(Partitioning, FactoryBroadcastsTheInitialMesh)
{
  auto comm = Teuchos::DefaultComm<int>::getComm();
  Teuchos::ParameterList p;
  p.set("Source", "Half ball");
  p.set("Initial mesh size", 0.4);
  p.set("Uniform refinements", 1);
  auto r = MeshFactory::build(p, 3, *comm);
  const auto& m = *r->mesh();
  TEST_ASSERT(identicalOnAllRanks(*comm, m.elementVertices()));
  std::vector<int> bits(m.coordinates().size() * 2);
  std::memcpy(bits.data(), m.coordinates().data(), bits.size() * sizeof(int));
  TEST_ASSERT(identicalOnAllRanks(*comm, bits));
  TEST_ASSERT(m.boundaryNames() == std::vector<std::string>({"Top", "Cap"}));

  Teuchos::ParameterList bad;
  bad.set("Source", "Gmsh file");
  bad.set("File", "missing-on-every-rank.msh");
  TEST_THROW(MeshFactory::build(bad, 2, *comm), sc::core::InputError);
}

}  // namespace
