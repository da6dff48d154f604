#pragma once
// The output step's fields (docs/output.md "Fields in a run's files"): a cycle's results as the
// grids of one XDMF/HDF5 step: domain (cell averages, η_T, u^R at the vertices), boundary (part
// ids, mean contact traction per face) and, with contact, the contact points.
#include <vector>

#include "CycleResults.hpp"

namespace sc::mesh {
class SimplexMesh;
}
namespace sc::io {
class XdmfWriter;
}

namespace sc::app {

/// Writes step `results.cycle` with `writer` (collective); `elementOwner` is the owning rank of
/// every element of `mesh`, `results.fields` must be filled.
void writeCycleFields(io::XdmfWriter& writer, const mesh::SimplexMesh& mesh,
                      const std::vector<int>& elementOwner, int rank, const CycleResults& results);

}  // namespace sc::app
