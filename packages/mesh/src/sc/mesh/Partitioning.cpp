#include <sc/mesh/Partitioning.hpp>

#include <sc/core/Error.hpp>

#include <sc/core/Collective.hpp>

#include <metis.h>

#include <algorithm>
#include <numeric>

namespace sc::mesh {

std::vector<int> partitionElements(const SimplexMesh& mesh, int nparts)
{
  const int ne = mesh.numElements();
  SC_THROW_IF(nparts < 1, sc::core::InputError,
              "partitionElements: " << nparts << " parts requested");
  if (nparts == 1) return std::vector<int>(ne, 0);
  SC_THROW_IF(nparts > ne, sc::core::InputError,
              mesh.origin() << ": cannot split " << ne << " elements into " << nparts
                            << " parts (refine the initial mesh or use fewer ranks)");
  // Dual graph in CSR form from the face -> elements table.
  std::vector<idx_t> xadj(ne + 1, 0);
  for (int f = 0; f < mesh.numFaces(); ++f) {
    const auto fe = mesh.faceElements(f);
    if (fe[1] < 0) continue;
    ++xadj[fe[0] + 1];
    ++xadj[fe[1] + 1];
  }
  for (int e = 0; e < ne; ++e)
    xadj[e + 1] += xadj[e];
  std::vector<idx_t> adjncy(xadj[ne]);
  std::vector<idx_t> fill(xadj.begin(), xadj.end() - 1);
  for (int f = 0; f < mesh.numFaces(); ++f) {
    const auto fe = mesh.faceElements(f);
    if (fe[1] < 0) continue;
    adjncy[fill[fe[0]]++] = fe[1];
    adjncy[fill[fe[1]]++] = fe[0];
  }
  idx_t options[METIS_NOPTIONS];
  METIS_SetDefaultOptions(options);
  options[METIS_OPTION_SEED] = 1;
  options[METIS_OPTION_UFACTOR] = 30;  // max part weight <= 1.03 x ideal (we promise 5%)
  options[METIS_OPTION_NUMBERING] = 0;
  idx_t nv = ne, ncon = 1, np = nparts, objval = 0;
  std::vector<idx_t> part(ne, 0);
  const int status =
      METIS_PartGraphKway(&nv, &ncon, xadj.data(), adjncy.data(), nullptr, nullptr, nullptr, &np,
                          nullptr, nullptr, options, &objval, part.data());
  SC_THROW_IF(status != METIS_OK, sc::core::InternalError,
              mesh.origin() << ": METIS_PartGraphKway failed with status " << status);
  return std::vector<int>(part.begin(), part.end());
}

std::vector<int> partitionElements(const SimplexMesh& mesh, const Teuchos::Comm<int>& comm)
{
  std::vector<int> owner;
  if (comm.getRank() == 0) owner = partitionElements(mesh, comm.getSize());
  core::broadcast(comm, 0, owner);
  return owner;
}

RankElements rankElements(const SimplexMesh& mesh, const std::vector<int>& owner, int rank)
{
  const int ne = mesh.numElements();
  SC_THROW_IF(static_cast<int>(owner.size()) != ne, sc::core::InternalError,
              "rankElements: owner has " << owner.size() << " entries for " << ne << " elements");
  RankElements out;
  std::vector<char> mark(ne, 0);
  for (int e = 0; e < ne; ++e)
    if (owner[e] == rank) {
      out.owned.push_back(e);
      mark[e] = 1;
    }
  for (int e : out.owned) {
    const int* v = mesh.elementVertices(e);
    for (int i = 0; i <= mesh.dim(); ++i) {
      auto [b, en] = mesh.vertexElements(v[i]);
      for (const int* p = b; p != en; ++p)
        if (!mark[*p]) {
          mark[*p] = 2;
          out.ghosts.push_back(*p);
        }
    }
  }
  std::sort(out.ghosts.begin(), out.ghosts.end());
  return out;
}

VertexOwnership vertexOwnership(const SimplexMesh& mesh, const std::vector<int>& elementOwner,
                                int rank, int nranks)
{
  const std::size_t nv = mesh.numVertices(), ne = mesh.numElements();
  const int nodesPerElement = mesh.dim() + 1;
  VertexOwnership v;
  v.owner.assign(nv, nranks);
  for (std::size_t e = 0; e < ne; ++e) {
    const int* ev = mesh.elementVertices(static_cast<int>(e));
    for (int i = 0; i < nodesPerElement; ++i)
      v.owner[ev[i]] = std::min(v.owner[ev[i]], elementOwner[e]);
  }
  std::vector<std::size_t> order(nv);
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return v.owner[a] < v.owner[b]; });
  v.number.resize(nv);
  for (std::size_t i = 0; i < nv; ++i)
    v.number[order[i]] = static_cast<long long>(i);
  for (std::size_t i = 0; i < nv; ++i)
    if (v.owner[i] == rank) v.owned.push_back(static_cast<int>(i));
  return v;
}

}  // namespace sc::mesh
