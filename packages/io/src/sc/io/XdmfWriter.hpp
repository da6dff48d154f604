#pragma once
// Parallel HDF5 + XDMF 3 output for ParaView (docs/output.md, "Fields"): one HDF5 file per step
// (adaptive cycle), written collectively by all ranks, and one .xdmf file holding a temporal
// collection of all steps so far. Each step is a spatial collection of grids ("domain",
// "boundary", ...). Every grid gets an integer cell field "partition" (owning rank).
//
// Crash safety: each .h5 is written under a temporary name and renamed once closed; the .xdmf is
// rewritten atomically after that, so it only ever references complete .h5 files.
//
// Usage (every rank, once per cycle):
//   sc::io::XdmfWriter writer(comm, "output", "solution");
//   sc::io::GridPiece domain("domain", sc::io::CellType::Triangle, 2);
//   domain.coordinates = ...;   // owned vertices, x y x y ...
//   domain.connectivity = ...;  // owned triangles, global vertex ids
//   domain.addPointField("displacement", sc::io::FieldKind::Vector, u);
//   domain.addCellField("stress", sc::io::FieldKind::SymmetricTensor, sigma);
//   sc::io::GridPiece boundary("boundary", sc::io::CellType::Line, 2);
//   boundary.geometryFrom = "domain";           // facets index the domain's vertices
//   boundary.connectivity = ...;                // owned facets (may be empty)
//   boundary.addCellField("boundary_id", ids);  // std::vector<int>
//   boundary.setBoundaryNames({{1, "contact"}, {2, "clamped"}});
//   sc::io::GridPiece points("contact", sc::io::CellType::Vertex, 2);  // a point cloud:
//   points.coordinates = ...;                    // owned points; one cell each, no connectivity
//   points.addPointField("status", states);      // std::vector<int>, stored as int32
//   writer.writeStep(cycle, {domain, boundary, points});
//
// Limit: validation is collective, but a failure inside HDF5 on one rank only (not the usual
// case: the library fails collectively) cannot be reported without the other ranks waiting.

#include <sc/io/GridPiece.hpp>

#include <Teuchos_Comm.hpp>
#include <Teuchos_RCP.hpp>

#include <string>
#include <vector>

namespace sc::io {

class XdmfWriter {
public:
  /// Collective. Creates \p directory if needed (InputError naming it if impossible). Files:
  /// <directory>/<baseName>.xdmf and <directory>/<baseName>_c<NNNN>.h5.
  XdmfWriter(Teuchos::RCP<const Teuchos::Comm<int>> comm, std::string directory,
             std::string baseName);

  XdmfWriter(const XdmfWriter&) = delete;
  XdmfWriter& operator=(const XdmfWriter&) = delete;

  /// Collective: write step \p cycle at time \p time (ParaView's time axis). All ranks pass the
  /// same grids, fields and information in the same order (checked); their pieces may be empty.
  /// Writing a cycle again replaces that step. Throws sc::core::InputError for inconsistent
  /// input and sc::core::Error (naming file and dataset) for HDF5 / file system failures, on all
  /// ranks alike where the failure is detected collectively.
  void writeStep(int cycle, double time, const std::vector<GridPiece>& grids);

  /// Same with time = cycle.
  void writeStep(int cycle, const std::vector<GridPiece>& grids)
  {
    writeStep(cycle, static_cast<double>(cycle), grids);
  }

  /// <directory>/<baseName>.xdmf
  std::string xdmfPath() const;
  /// <directory>/<baseName>_c<NNNN>.h5
  std::string h5Path(int cycle) const;
  /// File name only (as referenced from the .xdmf): <baseName>_c<NNNN>.h5
  std::string h5FileName(int cycle) const;

  /// One step of the time series as the .xdmf lists it.
  struct Step {
    int cycle;
    double time;
    std::string xml;  // the step's <Grid CollectionType="Spatial"> element
  };
  /// The steps written so far (rank 0's list; empty on other ranks). A restarted run keeps them
  /// in its checkpoint (docs/adaptivity.md "Checkpoint and restart").
  const std::vector<Step>& steps() const { return steps_; }
  /// Collective: replace the list of steps by \p steps (rank 0's are used) and rewrite the
  /// .xdmf atomically: a restarted run continues the time series of the run it restarts, and
  /// a step written by that run after its last checkpoint is dropped.
  void restoreSteps(const std::vector<Step>& steps);

private:
  void rewriteXdmf() const;

  Teuchos::RCP<const Teuchos::Comm<int>> comm_;
  std::string directory_;
  std::string baseName_;
  std::vector<Step> steps_;  // in writing order; only rank 0's copy is used
};

}  // namespace sc::io
