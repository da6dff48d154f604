#include <sc/io/XdmfWriter.hpp>

#include <sc/io/AtomicFile.hpp>
#include <sc/core/Collective.hpp>
#include <sc/io/OutputDirectory.hpp>

#include <sc/core/Error.hpp>

#include <hdf5.h>

#include "sc/io/detail/Hdf5Handles.hpp"
#include <mpi.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <sstream>
#include <unistd.h>

namespace sc::io {

namespace {

std::string formatDouble(double v)
{
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

std::string xmlEscape(const std::string& s)
{
  std::string out;
  out.reserve(s.size());
  for (char c : s) {
    switch (c) {
    case '&': out += "&amp;"; break;
    case '<': out += "&lt;"; break;
    case '>': out += "&gt;"; break;
    case '"': out += "&quot;"; break;
    case '\'': out += "&apos;"; break;
    default: out += c;
    }
  }
  return out;
}

using detail::Hdf5ErrorPrintingOff;
using Handle = detail::Hdf5Handle;

// Context for error messages: every HDF5 failure names the file and the object.
struct H5Context {
  std::string file;

  hid_t check(hid_t id, const std::string& what, const std::string& object) const
  {
    if (id < 0) {
      // The system's reason where it is one of the write failures (errno may be stale
      // otherwise): no space, quota, file too large, I/O error, read-only file system.
      const int err = errno;
      const bool writeError =
          err == ENOSPC || err == EDQUOT || err == EFBIG || err == EIO || err == EROFS;
      SC_THROW_IF(true, sc::core::Error,
                  "HDF5 error: " << what << " failed for '" << object << "' in file '" << file
                                 << "'"
                                 << (writeError ? std::string(": ") + std::strerror(err) : ""));
    }
    return id;
  }
};

// Collective write of a [globalRows x cols] dataset (1-D if cols == 1); this rank writes rows
// [rowOffset, rowOffset + localRows). Zero-sized pieces take part with an empty selection.
void writeDataset(const H5Context& ctx, hid_t parent, const std::string& path, hid_t memType,
                  hid_t fileType, const void* data, hsize_t localRows, hsize_t rowOffset,
                  hsize_t globalRows, hsize_t cols)
{
  const int rank = cols == 1 ? 1 : 2;
  const hsize_t globalDims[2] = {globalRows, cols};
  const hsize_t localDims[2] = {localRows, cols};
  const hsize_t start[2] = {rowOffset, 0};

  Handle fileSpace(ctx.check(H5Screate_simple(rank, globalDims, nullptr), "H5Screate_simple", path),
                   H5Sclose);
  Handle dset(ctx.check(H5Dcreate2(parent, path.c_str(), fileType, fileSpace.get(), H5P_DEFAULT,
                                   H5P_DEFAULT, H5P_DEFAULT),
                        "H5Dcreate2", path),
              H5Dclose);
  // Nothing to transfer anywhere (HDF5 rejects a write to a zero-sized dataset); every rank
  // knows globalRows, so all skip the collective write together.
  if (globalRows == 0) return;
  Handle memSpace(ctx.check(H5Screate_simple(rank, localDims, nullptr), "H5Screate_simple", path),
                  H5Sclose);
  if (localRows == 0) {
    ctx.check(H5Sselect_none(fileSpace.get()), "H5Sselect_none", path);
    ctx.check(H5Sselect_none(memSpace.get()), "H5Sselect_none", path);
  } else {
    ctx.check(
        H5Sselect_hyperslab(fileSpace.get(), H5S_SELECT_SET, start, nullptr, localDims, nullptr),
        "H5Sselect_hyperslab", path);
  }
  Handle dxpl(ctx.check(H5Pcreate(H5P_DATASET_XFER), "H5Pcreate(DATASET_XFER)", path), H5Pclose);
  ctx.check(H5Pset_dxpl_mpio(dxpl.get(), H5FD_MPIO_COLLECTIVE), "H5Pset_dxpl_mpio", path);
  // HDF5 wants a non-null buffer even for an empty selection.
  static const double dummy = 0.0;
  ctx.check(H5Dwrite(dset.get(), memType, memSpace.get(), fileSpace.get(), dxpl.get(),
                     data ? data : &dummy),
            "H5Dwrite", path);
}

void writeStringAttribute(const H5Context& ctx, hid_t object, const std::string& objectPath,
                          const std::string& name, const std::string& value)
{
  const std::string where = objectPath + "@" + name;
  Handle type(ctx.check(H5Tcopy(H5T_C_S1), "H5Tcopy", where), H5Tclose);
  ctx.check(H5Tset_size(type.get(), std::max<std::size_t>(value.size(), 1)), "H5Tset_size", where);
  ctx.check(H5Tset_strpad(type.get(), H5T_STR_NULLPAD), "H5Tset_strpad", where);
  Handle space(ctx.check(H5Screate(H5S_SCALAR), "H5Screate", where), H5Sclose);
  Handle attr(
      ctx.check(H5Acreate2(object, name.c_str(), type.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT),
                "H5Acreate2", where),
      H5Aclose);
  const char empty = '\0';
  ctx.check(H5Awrite(attr.get(), type.get(), value.empty() ? &empty : value.data()), "H5Awrite",
            where);
}

template <class T>
void writeScalarAttribute(const H5Context& ctx, hid_t object, const std::string& name,
                          hid_t memType, T value)
{
  const std::string where = "/@" + name;
  Handle space(ctx.check(H5Screate(H5S_SCALAR), "H5Screate", where), H5Sclose);
  Handle attr(
      ctx.check(H5Acreate2(object, name.c_str(), memType, space.get(), H5P_DEFAULT, H5P_DEFAULT),
                "H5Acreate2", where),
      H5Aclose);
  ctx.check(H5Awrite(attr.get(), memType, &value), "H5Awrite", where);
}

// Expand a field from the caller's layout (FieldKind.hpp) to the stored 1/3/9 components.
std::vector<double> toStoredLayout(const Field& field, int dim, std::size_t count)
{
  const int in = inputComponents(field.kind, dim);
  const int out = storedComponents(field.kind);
  if (in == out) return field.values;
  std::vector<double> stored(count * static_cast<std::size_t>(out), 0.0);
  for (std::size_t e = 0; e < count; ++e) {
    const double* v = field.values.data() + e * static_cast<std::size_t>(in);
    double* s = stored.data() + e * static_cast<std::size_t>(out);
    switch (field.kind) {
    case FieldKind::Scalar: s[0] = v[0]; break;
    case FieldKind::Vector:
      for (int i = 0; i < dim; ++i)
        s[i] = v[i];
      break;
    case FieldKind::Tensor:  // dim == 2: 2x2 into the upper-left block of 3x3
      for (int i = 0; i < dim; ++i)
        for (int j = 0; j < dim; ++j)
          s[3 * i + j] = v[dim * i + j];
      break;
    case FieldKind::SymmetricTensor:
      if (dim == 2) {  // xx, yy, xy
        s[0] = v[0], s[4] = v[1], s[1] = s[3] = v[2];
      } else {  // Voigt: xx, yy, zz, yz, xz, xy
        s[0] = v[0], s[4] = v[1], s[8] = v[2];
        s[5] = s[7] = v[3];
        s[2] = s[6] = v[4];
        s[1] = s[3] = v[5];
      }
      break;
    }
  }
  return stored;
}

// Everything all ranks must agree on, as text; compared against rank 0's.
std::string signature(const std::vector<GridPiece>& grids)
{
  std::ostringstream s;
  for (const auto& g : grids) {
    s << "grid " << g.name << ' ' << cellTypeName(g.cellType) << ' ' << g.spaceDim << " geometry<"
      << g.geometryFrom << ">\n";
    for (const auto& f : g.pointFields)
      s << "  point " << f.name << ' ' << fieldKindName(f.kind) << '\n';
    for (const auto& f : g.cellFields)
      s << "  cell " << f.name << ' ' << fieldKindName(f.kind) << '\n';
    for (const auto& f : g.integerPointFields)
      s << "  int point " << f.name << '\n';
    for (const auto& f : g.integerCellFields)
      s << "  int cell " << f.name << '\n';
    for (const auto& [k, v] : g.information)
      s << "  info " << k << '=' << v << '\n';
  }
  return s.str();
}

bool validName(const std::string& name)
{
  return !name.empty() && name.find_first_of("/.<>&\"' ") == std::string::npos;
}

// Local consistency of one rank's pieces; returns an error message or "".
std::string checkLocal(const std::vector<GridPiece>& grids)
{
  std::ostringstream err;
  for (std::size_t gi = 0; gi < grids.size(); ++gi) {
    const GridPiece& g = grids[gi];
    if (!validName(g.name)) {
      err << "grid name '" << g.name << "' is empty or contains one of / . < > & \" ' space";
      return err.str();
    }
    for (std::size_t gj = 0; gj < gi; ++gj)
      if (grids[gj].name == g.name) {
        err << "grid name '" << g.name << "' used twice in one step";
        return err.str();
      }
    if (g.spaceDim != 2 && g.spaceDim != 3) {
      err << "grid '" << g.name << "': spaceDim = " << g.spaceDim << ", valid: 2 or 3";
      return err.str();
    }
    std::size_t vertices = g.localVertexCount();
    if (g.cellType == CellType::Vertex && (!g.geometryFrom.empty() || !g.connectivity.empty())) {
      err << "grid '" << g.name << "': a vertex grid (point cloud) has its own coordinates and "
          << "no connectivity (one cell per vertex, numbered by the writer), but it has "
          << (g.geometryFrom.empty()
                  ? std::to_string(g.connectivity.size()) + " connectivity entries"
                  : "geometryFrom = '" + g.geometryFrom + "'");
      return err.str();
    }
    if (!g.geometryFrom.empty()) {
      const auto it = std::find_if(grids.begin(), grids.begin() + static_cast<long>(gi),
                                   [&](const GridPiece& o) { return o.name == g.geometryFrom; });
      if (it == grids.begin() + static_cast<long>(gi) || !it->geometryFrom.empty()) {
        err << "grid '" << g.name << "': geometryFrom = '" << g.geometryFrom
            << "' must name an earlier grid of the step that has its own coordinates";
        return err.str();
      }
      if (!g.coordinates.empty()) {
        err << "grid '" << g.name << "' has both coordinates and geometryFrom = '" << g.geometryFrom
            << "'";
        return err.str();
      }
      if (it->spaceDim != g.spaceDim) {
        err << "grid '" << g.name << "': spaceDim " << g.spaceDim << " differs from grid '"
            << it->name << "' (" << it->spaceDim << ") whose geometry it uses";
        return err.str();
      }
      vertices = it->localVertexCount();
    } else if (g.coordinates.size() % static_cast<std::size_t>(g.spaceDim) != 0) {
      err << "grid '" << g.name << "': " << g.coordinates.size()
          << " coordinates is not a multiple of spaceDim = " << g.spaceDim;
      return err.str();
    }
    const int nvpc = verticesPerCell(g.cellType);
    if (g.connectivity.size() % static_cast<std::size_t>(nvpc) != 0) {
      err << "grid '" << g.name << "': " << g.connectivity.size()
          << " connectivity entries is not a multiple of " << nvpc << " ("
          << cellTypeName(g.cellType) << ")";
      return err.str();
    }
    const std::size_t cells = g.localCellCount();
    std::vector<std::string> names{"partition"};
    auto checkName = [&](const std::string& n) {
      if (!validName(n)) {
        err << "grid '" << g.name << "': field name '" << n
            << "' is empty or contains one of / . < > & \" ' space";
        return false;
      }
      if (std::find(names.begin(), names.end(), n) != names.end()) {
        err << "grid '" << g.name << "': field name '" << n
            << "' used twice (\"partition\" is added by the writer)";
        return false;
      }
      names.push_back(n);
      return true;
    };
    for (const auto& f : g.pointFields) {
      if (!checkName(f.name)) return err.str();
      const std::size_t want =
          vertices * static_cast<std::size_t>(inputComponents(f.kind, g.spaceDim));
      if (f.values.size() != want) {
        err << "grid '" << g.name << "': point field '" << f.name << "' (" << fieldKindName(f.kind)
            << ") has " << f.values.size() << " values, expected " << want << " (" << vertices
            << " owned vertices x " << inputComponents(f.kind, g.spaceDim) << ")";
        return err.str();
      }
    }
    for (const auto& f : g.cellFields) {
      if (!checkName(f.name)) return err.str();
      const std::size_t want =
          cells * static_cast<std::size_t>(inputComponents(f.kind, g.spaceDim));
      if (f.values.size() != want) {
        err << "grid '" << g.name << "': cell field '" << f.name << "' (" << fieldKindName(f.kind)
            << ") has " << f.values.size() << " values, expected " << want << " (" << cells
            << " owned cells x " << inputComponents(f.kind, g.spaceDim) << ")";
        return err.str();
      }
    }
    for (const auto& f : g.integerPointFields) {
      if (!checkName(f.name)) return err.str();
      if (f.values.size() != vertices) {
        err << "grid '" << g.name << "': integer point field '" << f.name << "' has "
            << f.values.size() << " values, expected " << vertices << " (owned vertices)";
        return err.str();
      }
    }
    for (const auto& f : g.integerCellFields) {
      if (!checkName(f.name)) return err.str();
      if (f.values.size() != cells) {
        err << "grid '" << g.name << "': integer cell field '" << f.name << "' has "
            << f.values.size() << " values, expected " << cells << " (owned cells)";
        return err.str();
      }
    }
    for (const auto& [key, value] : g.information) {
      (void)value;
      if (!validName(key)) {
        err << "grid '" << g.name << "': information name '" << key << "' is not valid";
        return err.str();
      }
    }
  }
  return "";
}

std::string dataItem(const std::string& file, const std::string& path, unsigned long long rows,
                     int cols, const char* numberType, int precision)
{
  std::ostringstream x;
  x << "<DataItem Dimensions=\"" << rows;
  if (cols != 1) x << ' ' << cols;
  x << "\" NumberType=\"" << numberType << "\" Precision=\"" << precision << "\" Format=\"HDF\">"
    << xmlEscape(file) << ":" << path << "</DataItem>";
  return x.str();
}

}  // namespace

XdmfWriter::XdmfWriter(Teuchos::RCP<const Teuchos::Comm<int>> comm, std::string directory,
                       std::string baseName)
    : comm_(std::move(comm)), directory_(std::move(directory)), baseName_(std::move(baseName))
{
  SC_THROW_IF(comm_.is_null(), sc::core::InternalError, "XdmfWriter: null communicator");
  SC_THROW_IF(baseName_.empty() || baseName_.find('/') != std::string::npos, sc::core::InputError,
              "Output/Base name = '" << baseName_
                                     << "' is not valid: give a non-empty file name without '/'");
  createOutputDirectory(directory_, *comm_);
}

std::string XdmfWriter::xdmfPath() const
{
  return (std::filesystem::path(directory_) / (baseName_ + ".xdmf")).string();
}

std::string XdmfWriter::h5FileName(int cycle) const
{
  char buf[32];
  std::snprintf(buf, sizeof buf, "_c%04d.h5", cycle);
  return baseName_ + buf;
}

std::string XdmfWriter::h5Path(int cycle) const
{
  return (std::filesystem::path(directory_) / h5FileName(cycle)).string();
}

void XdmfWriter::writeStep(int cycle, double time, const std::vector<GridPiece>& grids)
{
  const Teuchos::Comm<int>& comm = *comm_;
  const int rank = comm.getRank();
  const int size = comm.getSize();

  // 1. Validate before any collective HDF5 call, so a bad piece on one rank cannot hang others.
  SC_THROW_IF(cycle < 0, sc::core::InputError,
              "XdmfWriter::writeStep: cycle = " << cycle << " < 0");
  core::throwIfAnyRankFailed(comm, checkLocal(grids));
  const std::string mySignature = signature(grids);
  std::string rootSignature = mySignature;
  core::broadcast(comm, 0, rootSignature);
  core::throwIfAnyRankFailed(comm, mySignature == rootSignature
                                       ? std::string()
                                       : "grids/fields/information differ from rank 0's:\n" +
                                             mySignature + "rank 0 has:\n" + rootSignature);

  // 2. Offsets of this rank's rows and global sizes, per grid: [vertices, cells].
  const std::size_t ng = grids.size();
  std::vector<long long> local(2 * ng), offset(2 * ng, 0), total(2 * ng, 0);
  for (std::size_t g = 0; g < ng; ++g) {
    local[2 * g] = static_cast<long long>(grids[g].localVertexCount());
    local[2 * g + 1] = static_cast<long long>(grids[g].localCellCount());
  }
  const MPI_Comm mpiComm = core::rawMpiComm(comm);
  if (ng > 0) {
    MPI_Exscan(local.data(), offset.data(), static_cast<int>(2 * ng), MPI_LONG_LONG, MPI_SUM,
               mpiComm);
    if (rank == 0)
      std::fill(offset.begin(), offset.end(), 0LL);  // MPI_Exscan leaves rank 0's undefined
    total = core::sumOverRanks(comm, local);
  }
  // Index of the grid providing each grid's vertices.
  std::vector<std::size_t> geometryOf(ng);
  for (std::size_t g = 0; g < ng; ++g) {
    geometryOf[g] = g;
    if (!grids[g].geometryFrom.empty())
      for (std::size_t o = 0; o < g; ++o)
        if (grids[o].name == grids[g].geometryFrom) geometryOf[g] = o;
  }

  // Connectivity must refer to existing global vertices.
  {
    std::string err;
    for (std::size_t g = 0; g < ng && err.empty(); ++g) {
      const long long nv = total[2 * geometryOf[g]];
      for (long long v : grids[g].connectivity)
        if (v < 0 || v >= nv) {
          err = "grid '" + grids[g].name + "': connectivity refers to vertex " + std::to_string(v) +
                ", valid global indices are 0.." + std::to_string(nv - 1);
          break;
        }
    }
    core::throwIfAnyRankFailed(comm, err);
  }

  // 3. Collective HDF5 write under a temporary name (rank 0's pid, shared by all ranks).
  const std::string finalPath = h5Path(cycle);
  {
    // Room for the file first (disk full, ulimit -f): HDF5 cannot close a file whose write
    // failed half-way, and crashes at MPI_Finalize (docs/reliability.md). Data plus a margin for
    // HDF5's metadata.
    unsigned long long bytes = 0;
    for (std::size_t g = 0; g < ng; ++g) {
      const auto nv = static_cast<unsigned long long>(total[2 * geometryOf[g]]);
      const auto nc = static_cast<unsigned long long>(total[2 * g + 1]);
      if (grids[g].geometryFrom.empty()) bytes += nv * 3 * 8;
      bytes += nc * static_cast<unsigned long long>(verticesPerCell(grids[g].cellType)) * 8;
      for (const auto& f : grids[g].pointFields)
        bytes += nv * static_cast<unsigned long long>(storedComponents(f.kind)) * 8;
      for (const auto& f : grids[g].cellFields)
        bytes += nc * static_cast<unsigned long long>(storedComponents(f.kind)) * 8;
      bytes += nv * 4 * grids[g].integerPointFields.size();
      bytes += nc * 4 * (grids[g].integerCellFields.size() + 1);  // + partition
    }
    bytes += bytes / 20 + (64ull << 10);
    core::runOnRoot(comm, [&] { checkRoomForFile(directory_, finalPath, bytes); });
  }
  long pid = static_cast<long>(::getpid());
  core::broadcast(comm, 0, pid);
  const std::string tmpPath = temporaryPathFor(finalPath, pid);
  const std::string h5Name = h5FileName(cycle);
  std::ostringstream stepXml;
  // An HDF5 failure normally hits all ranks (it is a collective library); a failure on one rank
  // only cannot be recovered without hanging the others, so it is simply reported.
  try {
    Hdf5ErrorPrintingOff quiet;
    const H5Context ctx{tmpPath};
    Handle fapl(ctx.check(H5Pcreate(H5P_FILE_ACCESS), "H5Pcreate(FILE_ACCESS)", "/"), H5Pclose);
    ctx.check(H5Pset_fapl_mpio(fapl.get(), mpiComm, MPI_INFO_NULL), "H5Pset_fapl_mpio", "/");
    Handle file(ctx.check(H5Fcreate(tmpPath.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, fapl.get()),
                          "H5Fcreate", "/"),
                H5Fclose);
    writeScalarAttribute<int>(ctx, file.get(), "cycle", H5T_NATIVE_INT, cycle);
    writeScalarAttribute<double>(ctx, file.get(), "time", H5T_NATIVE_DOUBLE, time);
    writeScalarAttribute<int>(ctx, file.get(), "ranks", H5T_NATIVE_INT, size);

    stepXml << "      <Grid Name=\"cycle " << cycle
            << "\" GridType=\"Collection\" CollectionType=\"Spatial\">\n"
            << "        <Time Value=\"" << formatDouble(time) << "\"/>\n";

    for (std::size_t g = 0; g < ng; ++g) {
      const GridPiece& grid = grids[g];
      const std::string group = "/" + grid.name;
      Handle gid(
          ctx.check(H5Gcreate2(file.get(), group.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                    "H5Gcreate2", group),
          H5Gclose);
      for (const auto& [key, value] : grid.information)
        writeStringAttribute(ctx, gid.get(), group, key, value);

      const std::size_t geo = geometryOf[g];
      const hsize_t nvLocal = static_cast<hsize_t>(local[2 * geo]);
      const hsize_t nvOffset = static_cast<hsize_t>(offset[2 * geo]);
      const hsize_t nvTotal = static_cast<hsize_t>(total[2 * geo]);
      const hsize_t ncLocal = static_cast<hsize_t>(local[2 * g + 1]);
      const hsize_t ncOffset = static_cast<hsize_t>(offset[2 * g + 1]);
      const hsize_t ncTotal = static_cast<hsize_t>(total[2 * g + 1]);
      const int nvpc = verticesPerCell(grid.cellType);
      const int dim = grid.spaceDim;

      // Geometry always as XYZ (z = 0 in 2D): every ParaView version reads it.
      const std::string geometryPath =
          grid.geometryFrom.empty() ? group + "/geometry" : "/" + grid.geometryFrom + "/geometry";
      if (grid.geometryFrom.empty()) {
        std::vector<double> xyz(nvLocal * 3, 0.0);
        for (hsize_t v = 0; v < nvLocal; ++v)
          for (int d = 0; d < dim; ++d)
            xyz[3 * v + static_cast<hsize_t>(d)] =
                grid.coordinates[v * static_cast<hsize_t>(dim) + static_cast<hsize_t>(d)];
        writeDataset(ctx, file.get(), geometryPath, H5T_NATIVE_DOUBLE, H5T_IEEE_F64LE,
                     xyz.empty() ? nullptr : xyz.data(), nvLocal, nvOffset, nvTotal, 3);
      }
      const std::string topologyPath = group + "/topology";
      // A point cloud's cells are its vertices, in their global numbering.
      std::vector<long long> identity;
      if (grid.cellType == CellType::Vertex)
        for (hsize_t v = 0; v < nvLocal; ++v)
          identity.push_back(static_cast<long long>(nvOffset + v));
      const std::vector<long long>& connectivity =
          grid.cellType == CellType::Vertex ? identity : grid.connectivity;
      writeDataset(ctx, file.get(), topologyPath, H5T_NATIVE_LLONG, H5T_STD_I64LE,
                   connectivity.empty() ? nullptr : connectivity.data(), ncLocal, ncOffset, ncTotal,
                   static_cast<hsize_t>(nvpc));

      // The grid's XDMF element. A grid without cells anywhere is left out of the .xdmf (its
      // datasets are still in the .h5): ParaView's reader rejects zero-sized DataItems.
      std::ostringstream x;
      x << "        <Grid Name=\"" << grid.name << "\" GridType=\"Uniform\">\n";
      for (const auto& [key, value] : grid.information)
        x << "          <Information Name=\"" << key << "\" Value=\"" << xmlEscape(value)
          << "\"/>\n";
      x << "          <Topology TopologyType=\"" << xdmfTopologyName(grid.cellType)
        << "\" NumberOfElements=\"" << ncTotal << "\"";
      if (grid.cellType == CellType::Line || grid.cellType == CellType::Vertex)
        x << " NodesPerElement=\"" << nvpc << "\"";
      x << ">\n            " << dataItem(h5Name, topologyPath, ncTotal, nvpc, "Int", 8)
        << "\n          </Topology>\n"
        << "          <Geometry GeometryType=\"XYZ\">\n            "
        << dataItem(h5Name, geometryPath, nvTotal, 3, "Float", 8) << "\n          </Geometry>\n";

      auto writeField = [&](const Field& f, bool onPoints) {
        const std::string path = group + (onPoints ? "/point/" : "/cell/") + f.name;
        const hsize_t n = onPoints ? nvLocal : ncLocal;
        const std::vector<double> stored = toStoredLayout(f, dim, n);
        const int comps = storedComponents(f.kind);
        writeDataset(ctx, file.get(), path, H5T_NATIVE_DOUBLE, H5T_IEEE_F64LE,
                     stored.empty() ? nullptr : stored.data(), n, onPoints ? nvOffset : ncOffset,
                     onPoints ? nvTotal : ncTotal, static_cast<hsize_t>(comps));
        x << "          <Attribute Name=\"" << f.name << "\" AttributeType=\""
          << xdmfAttributeType(f.kind) << "\" Center=\"" << (onPoints ? "Node" : "Cell")
          << "\">\n            "
          << dataItem(h5Name, path, onPoints ? nvTotal : ncTotal, comps, "Float", 8)
          << "\n          </Attribute>\n";
      };
      auto writeIntField = [&](const std::string& name, const std::vector<int>& values,
                               bool onPoints) {
        const std::string path = group + (onPoints ? "/point/" : "/cell/") + name;
        const hsize_t n = onPoints ? nvTotal : ncTotal;
        writeDataset(ctx, file.get(), path, H5T_NATIVE_INT, H5T_STD_I32LE,
                     values.empty() ? nullptr : values.data(), onPoints ? nvLocal : ncLocal,
                     onPoints ? nvOffset : ncOffset, n, 1);
        x << "          <Attribute Name=\"" << name << "\" AttributeType=\"Scalar\" Center=\""
          << (onPoints ? "Node" : "Cell") << "\">\n            "
          << dataItem(h5Name, path, n, 1, "Int", 4) << "\n          </Attribute>\n";
      };

      // Intermediate groups for the fields (H5Dcreate2 does not create them by default).
      for (const char* sub : {"/point", "/cell"}) {
        const std::string p = group + sub;
        Handle sg(
            ctx.check(H5Gcreate2(file.get(), p.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                      "H5Gcreate2", p),
            H5Gclose);
      }
      for (const auto& f : grid.pointFields)
        writeField(f, true);
      for (const auto& f : grid.cellFields)
        writeField(f, false);
      for (const auto& f : grid.integerPointFields)
        writeIntField(f.name, f.values, true);
      for (const auto& f : grid.integerCellFields)
        writeIntField(f.name, f.values, false);
      writeIntField("partition", std::vector<int>(ncLocal, rank), false);
      x << "        </Grid>\n";
      if (ncTotal > 0) stepXml << x.str();
    }
    stepXml << "      </Grid>\n";
    SC_THROW_IF(file.close() < 0, sc::core::Error,
                "HDF5 error: H5Fclose failed for file '" << tmpPath << "'");
  } catch (...) {
    if (rank == 0) std::remove(tmpPath.c_str());  // no stray temporary after a failed write
    throw;
  }

  // 4. Publish: every rank has closed the file, so rank 0 renames it into place, then rewrites
  // the .xdmf, which thus never references a missing or partial .h5.
  comm.barrier();
  core::runOnRoot(comm, [&] {
    renameFile(tmpPath, finalPath);
    const Step step{cycle, time, stepXml.str()};
    auto it =
        std::find_if(steps_.begin(), steps_.end(), [&](const Step& s) { return s.cycle == cycle; });
    if (it != steps_.end())
      *it = step;
    else
      steps_.push_back(step);
    rewriteXdmf();
  });
}

void XdmfWriter::restoreSteps(const std::vector<Step>& steps)
{
  core::runOnRoot(*comm_, [&] {
    steps_ = steps;
    rewriteXdmf();
  });
}

void XdmfWriter::rewriteXdmf() const
{
  std::ostringstream x;
  x << "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n"
    << "<Xdmf Version=\"3.0\" xmlns:xi=\"http://www.w3.org/2001/XInclude\">\n"
    << "  <Domain>\n"
    << "    <Grid GridType=\"Collection\" CollectionType=\"Temporal\" Name=\""
    << xmlEscape(baseName_) << "\">\n";
  for (const Step& s : steps_)
    x << s.xml;
  x << "    </Grid>\n"
    << "  </Domain>\n"
    << "</Xdmf>\n";
  writeFileAtomically(xdmfPath(), x.str());
}

}  // namespace sc::io
