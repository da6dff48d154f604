#pragma once
// Element partitioning for the replicated mesh (docs/theory.md §"Parallel model", docs/mesh.md
// "Parallel model"): every rank holds the whole SimplexMesh; METIS assigns each element an owner
// rank, and each rank assembles its owned elements and reads the ghost layer around them.

#include <sc/mesh/SimplexMesh.hpp>

#include <Teuchos_Comm.hpp>

#include <vector>

namespace sc::mesh {

/// Owner part (0..nparts-1) of every element: METIS_PartGraphKway on the element dual graph
/// (elements adjacent through a face), fixed seed, imbalance tolerance 3%. Deterministic for a
/// given mesh; nparts = 1 gives all zeros without calling METIS.
std::vector<int> partitionElements(const SimplexMesh& mesh, int nparts);

/// The same with nparts = comm.getSize(), computed on rank 0 and broadcast, so that every rank
/// holds the identical partition even if METIS were not bitwise reproducible across processes.
std::vector<int> partitionElements(const SimplexMesh& mesh, const Teuchos::Comm<int>& comm);

/// The elements a rank works on.
struct RankElements {
  std::vector<int> owned;   ///< elements with owner == rank, ascending
  std::vector<int> ghosts;  ///< not owned, sharing at least a vertex with an owned one, ascending
};

/// Owned elements and the ghost layer (vertex neighbours, which include face neighbours).
RankElements rankElements(const SimplexMesh& mesh, const std::vector<int>& owner, int rank);

/// Vertices shared out for writing point data once (docs/output.md): each vertex is owned by the
/// lowest rank among the owners of its elements, and numbered so that every rank's owned
/// vertices form one contiguous block, ranks in order, vertex order kept within a block.
struct VertexOwnership {
  std::vector<int> owner;         ///< owning rank of every vertex
  std::vector<long long> number;  ///< the vertex's number in the blocked order
  std::vector<int> owned;         ///< the vertices `rank` owns, ascending (= their numbers' order)
};

/// The ownership of the vertices of `mesh` from the element owners `elementOwner` (ranks
/// 0..nranks-1), with the owned vertices of `rank`.
VertexOwnership vertexOwnership(const SimplexMesh& mesh, const std::vector<int>& elementOwner,
                                int rank, int nranks);

}  // namespace sc::mesh
