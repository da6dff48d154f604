// XdmfWriter at 1, 2 and 4 ranks: structured 2D and 3D meshes split into strips (each rank owns a
// contiguous block of vertex rows/layers; with 4 ranks some ranks own no cells or no boundary
// facets), two steps each, re-read with serial HDF5 on rank 0 and compared value by value.
#include <sc/io/XdmfWriter.hpp>
#include <sc/io/OutputDirectory.hpp>

#include "TestDirectory.hpp"

#include <sc/core/Error.hpp>

#include <Teuchos_DefaultComm.hpp>
#include <Teuchos_UnitTestHarness.hpp>

#include <hdf5.h>

#include <algorithm>
#include <array>
#include <fstream>
#include <regex>
#include <sstream>

#include <signal.h>
#include <sys/resource.h>

namespace {

using sc::io::CellType;
using sc::io::FieldKind;
using sc::io::GridPiece;
using sc::io::test::freshDirectory;
using sc::io::test::temporaries;

// Rows [0, nrows) split into contiguous blocks in rank order.
int ownerOfRow(int row, int nrows, int size)
{
  for (int r = 0; r < size; ++r)
    if (row < (r + 1) * nrows / size) return r;
  return size - 1;
}
std::pair<int, int> rowsOf(int rank, int nrows, int size)
{
  return {rank * nrows / size, (rank + 1) * nrows / size};
}

// ---------------------------------------------------------------------------------------------
// Structured meshes. The same functions produce one rank's piece (owned rows) or, with
// rank = -1, the whole mesh in global order, which the re-read data must equal.

struct Mesh2D {
  int nx, ny;
  int nv() const { return (nx + 1) * (ny + 1); }
  long long vid(int i, int j) const { return static_cast<long long>(j) * (nx + 1) + i; }
  double x(int i) const { return static_cast<double>(i) / nx; }
  double y(int j) const { return static_cast<double>(j) / ny; }
};

// Returns {domain, boundary}. rank < 0: everything (reference).
std::vector<GridPiece> pieces2D(const Mesh2D& m, int rank, int size)
{
  GridPiece domain("domain", CellType::Triangle, 2);
  GridPiece boundary("boundary", CellType::Line, 2);
  boundary.geometryFrom = "domain";
  boundary.setBoundaryNames({{1, "contact"}, {2, "top"}});
  const int nrows = m.ny + 1;
  auto [r0, r1] = rank < 0 ? std::pair<int, int>{0, nrows} : rowsOf(rank, nrows, size);
  std::vector<double> disp, temp, stress, eta;
  std::vector<int> bid;
  for (int j = r0; j < r1; ++j)
    for (int i = 0; i <= m.nx; ++i) {
      domain.coordinates.insert(domain.coordinates.end(), {m.x(i), m.y(j)});
      disp.insert(disp.end(), {m.x(i), -m.y(j)});
      temp.push_back(m.x(i) + 2 * m.y(j));
    }
  for (int j = r0; j < std::min(r1, m.ny); ++j)  // square row j belongs to vertex row j's owner
    for (int i = 0; i < m.nx; ++i)
      for (int t = 0; t < 2; ++t) {
        const double c = 2.0 * (j * m.nx + i) + t;  // global cell id
        if (t == 0)
          domain.connectivity.insert(domain.connectivity.end(),
                                     {m.vid(i, j), m.vid(i + 1, j), m.vid(i + 1, j + 1)});
        else
          domain.connectivity.insert(domain.connectivity.end(),
                                     {m.vid(i, j), m.vid(i + 1, j + 1), m.vid(i, j + 1)});
        stress.insert(stress.end(), {c, 2 * c, 3 * c});
        eta.push_back(c);
      }
  // Boundary: bottom edge (id 1) with square row 0, top edge (id 2) with square row ny-1.
  for (int edge = 0; edge < 2; ++edge) {
    const int squareRow = edge == 0 ? 0 : m.ny - 1;
    if (squareRow < r0 || squareRow >= r1) continue;
    const int j = edge == 0 ? 0 : m.ny;
    for (int i = 0; i < m.nx; ++i) {
      boundary.connectivity.insert(boundary.connectivity.end(), {m.vid(i, j), m.vid(i + 1, j)});
      bid.push_back(edge + 1);
    }
  }
  domain.addPointField("displacement", FieldKind::Vector, disp);
  domain.addPointField("temperature", FieldKind::Scalar, temp);
  domain.addCellField("stress", FieldKind::SymmetricTensor, stress);
  domain.addCellField("eta", FieldKind::Scalar, eta);
  boundary.addCellField("boundary_id", bid);
  return {domain, boundary};
}

struct Mesh3D {
  int n, nz;
  long long vid(int i, int j, int k) const
  {
    return (static_cast<long long>(k) * (n + 1) + j) * (n + 1) + i;
  }
  double x(int i) const { return static_cast<double>(i) / n; }
  double z(int k) const { return static_cast<double>(k) / nz; }
};

std::vector<GridPiece> pieces3D(const Mesh3D& m, int rank, int size)
{
  GridPiece domain("domain", CellType::Tetrahedron, 3);
  GridPiece bottom("boundary", CellType::Triangle, 3);
  bottom.geometryFrom = "domain";
  bottom.setBoundaryNames({{1, "contact"}});
  const int nlayers = m.nz + 1;
  auto [k0, k1] = rank < 0 ? std::pair<int, int>{0, nlayers} : rowsOf(rank, nlayers, size);
  std::vector<double> disp, sigma, grad;
  std::vector<int> bid;
  for (int k = k0; k < k1; ++k)
    for (int j = 0; j <= m.n; ++j)
      for (int i = 0; i <= m.n; ++i) {
        domain.coordinates.insert(domain.coordinates.end(), {m.x(i), m.x(j), m.z(k)});
        disp.insert(disp.end(), {m.x(i), m.x(j), m.z(k)});
      }
  // Kuhn subdivision: 6 tetrahedra per cube, one per permutation of the axes.
  const std::array<std::array<int, 3>, 6> perms{
      {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}}};
  long long cell = 0;
  for (int k = 0; k < m.nz; ++k)
    for (int j = 0; j < m.n; ++j)
      for (int i = 0; i < m.n; ++i)
        for (const auto& p : perms) {
          const bool mine = k >= k0 && k < k1;
          if (mine) {
            std::array<int, 3> c{i, j, k};
            domain.connectivity.push_back(m.vid(c[0], c[1], c[2]));
            for (int s = 0; s < 3; ++s) {
              ++c[static_cast<std::size_t>(p[static_cast<std::size_t>(s)])];
              domain.connectivity.push_back(m.vid(c[0], c[1], c[2]));
            }
            const double cd = static_cast<double>(cell);
            sigma.insert(sigma.end(), {cd, cd + 1, cd + 2, cd + 3, cd + 4, cd + 5});
            for (int q = 0; q < 9; ++q)
              grad.push_back(10 * cd + q);
          }
          ++cell;
        }
  if (k0 <= 0 && 0 < k1)  // bottom face z = 0, with cube layer 0
    for (int j = 0; j < m.n; ++j)
      for (int i = 0; i < m.n; ++i) {
        bottom.connectivity.insert(bottom.connectivity.end(),
                                   {m.vid(i, j, 0), m.vid(i + 1, j, 0), m.vid(i + 1, j + 1, 0),
                                    m.vid(i, j, 0), m.vid(i + 1, j + 1, 0), m.vid(i, j + 1, 0)});
        bid.insert(bid.end(), {1, 1});
      }
  domain.addPointField("displacement", FieldKind::Vector, disp);
  domain.addCellField("stress", FieldKind::SymmetricTensor, sigma);
  domain.addCellField("gradient", FieldKind::Tensor, grad);
  bottom.addCellField("boundary_id", bid);
  return {domain, bottom};
}

// ---------------------------------------------------------------------------------------------
// Serial HDF5 reading.

struct Dataset {
  std::vector<hsize_t> dims;
  std::vector<double> values;  // converted by HDF5 from the stored type
};

bool exists(hid_t file, const std::string& path)
{
  // Check each prefix: H5Lexists fails (not returns 0) if an intermediate group is missing.
  std::size_t pos = 0;
  while ((pos = path.find('/', pos + 1)) != std::string::npos)
    if (H5Lexists(file, path.substr(0, pos).c_str(), H5P_DEFAULT) <= 0) return false;
  return H5Lexists(file, path.c_str(), H5P_DEFAULT) > 0;
}

Dataset readDataset(hid_t file, const std::string& path)
{
  Dataset d;
  hid_t dset = H5Dopen2(file, path.c_str(), H5P_DEFAULT);
  if (dset < 0) return d;
  hid_t space = H5Dget_space(dset);
  const int rank = H5Sget_simple_extent_ndims(space);
  d.dims.resize(static_cast<std::size_t>(rank));
  H5Sget_simple_extent_dims(space, d.dims.data(), nullptr);
  hsize_t n = 1;
  for (hsize_t x : d.dims)
    n *= x;
  d.values.resize(n);
  if (n > 0) H5Dread(dset, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, d.values.data());
  H5Sclose(space);
  H5Dclose(dset);
  return d;
}

std::string readStringAttribute(hid_t file, const std::string& object, const std::string& name)
{
  hid_t attr = H5Aopen_by_name(file, object.c_str(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT);
  if (attr < 0) return "<missing>";
  hid_t type = H5Aget_type(attr);
  std::string s(H5Tget_size(type), '\0');
  H5Aread(attr, type, s.data());
  H5Tclose(type);
  H5Aclose(attr);
  return s.substr(0, s.find('\0'));
}

double readDoubleAttribute(hid_t file, const std::string& name)
{
  double v = -1;
  hid_t attr = H5Aopen(file, name.c_str(), H5P_DEFAULT);
  H5Aread(attr, H5T_NATIVE_DOUBLE, &v);
  H5Aclose(attr);
  return v;
}

std::vector<double> asDoubles(const std::vector<long long>& v) { return {v.begin(), v.end()}; }

// 2 -> 3 components (z = 0).
std::vector<double> pad3(const std::vector<double>& v, int dim)
{
  if (dim == 3) return v;
  std::vector<double> out;
  for (std::size_t i = 0; i < v.size(); i += 2)
    out.insert(out.end(), {v[i], v[i + 1], 0.0});
  return out;
}

// Checks of the XDMF text: temporal collection, times, and every referenced dataset exists.
void checkXdmf(const std::string& dir, const std::string& xdmfPath,
               const std::vector<double>& times, Teuchos::FancyOStream& out, bool& success)
{
  std::ifstream in(xdmfPath);
  std::stringstream s;
  s << in.rdbuf();
  const std::string xml = s.str();
  TEST_ASSERT(xml.rfind("<?xml", 0) == 0);
  TEST_ASSERT(xml.find("<Xdmf Version=\"3.0\"") != std::string::npos);
  TEST_ASSERT(xml.find("<Grid GridType=\"Collection\" CollectionType=\"Temporal\"") !=
              std::string::npos);
  TEST_ASSERT(xml.find("</Xdmf>") != std::string::npos);
  // Well-formedness, minimally: every opening tag of the element types used is closed.
  for (const std::string tag :
       {"Grid", "Topology", "Geometry", "Attribute", "DataItem", "Domain"}) {
    const std::regex open("<" + tag + "[ >]"), close("</" + tag + ">"),
        selfClosing("<" + tag + "[^>]*/>");
    const auto count = [&](const std::regex& re) {
      return std::distance(std::sregex_iterator(xml.begin(), xml.end(), re),
                           std::sregex_iterator());
    };
    TEST_EQUALITY(count(open) - count(selfClosing), count(close));
  }
  std::vector<double> found;
  const std::regex timeRe("<Time Value=\"([^\"]+)\"/>");
  for (auto it = std::sregex_iterator(xml.begin(), xml.end(), timeRe); it != std::sregex_iterator();
       ++it)
    found.push_back(std::stod((*it)[1]));
  TEST_COMPARE_ARRAYS(found, times);
  // Every DataItem "file.h5:/path" must exist in that file.
  const std::regex itemRe(">([^<>:]+\\.h5):(/[^<]+)</DataItem>");
  int items = 0;
  for (auto it = std::sregex_iterator(xml.begin(), xml.end(), itemRe); it != std::sregex_iterator();
       ++it) {
    ++items;
    const std::string file = dir + "/" + (*it)[1].str(), path = (*it)[2];
    hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    TEST_ASSERT(f >= 0);
    if (f >= 0) {
      const bool ok = exists(f, path);
      if (!ok) out << "missing " << file << ":" << path << "\n";
      TEST_ASSERT(ok);
      H5Fclose(f);
    }
  }
  TEST_ASSERT(items > 0);
}

TEUCHOS_UNIT_TEST(XdmfWriter, TwoDimensionalStripsTwoSteps)
{
  auto comm = Teuchos::DefaultComm<int>::getComm();
  const int rank = comm->getRank(), size = comm->getSize();
  const std::string dir = freshDirectory(*comm, "xdmf2d");
  sc::io::XdmfWriter writer(comm, dir, "solution");
  const std::vector<Mesh2D> meshes{{2, 3}, {4, 6}};
  const std::vector<double> times{0.0, 0.5};
  for (int cycle = 0; cycle < 2; ++cycle)
    writer.writeStep(cycle, times[static_cast<std::size_t>(cycle)],
                     pieces2D(meshes[static_cast<std::size_t>(cycle)], rank, size));
  comm->barrier();
  if (rank != 0) return;

  TEST_EQUALITY(writer.h5Path(1), dir + "/solution_c0001.h5");
  TEST_EQUALITY(temporaries(dir).size(), 0u);
  for (int cycle = 0; cycle < 2; ++cycle) {
    const Mesh2D& m = meshes[static_cast<std::size_t>(cycle)];
    const auto ref = pieces2D(m, -1, size);
    const GridPiece& dom = ref[0];
    const GridPiece& bnd = ref[1];
    const hsize_t nv = static_cast<hsize_t>(m.nv()), nc = 2u * m.nx * m.ny, nb = 2u * m.nx;
    hid_t f = H5Fopen(writer.h5Path(cycle).c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    TEST_ASSERT(f >= 0);
    if (f < 0) continue;
    TEST_EQUALITY(readDoubleAttribute(f, "time"), times[static_cast<std::size_t>(cycle)]);

    const Dataset geo = readDataset(f, "/domain/geometry");
    TEST_COMPARE_ARRAYS(geo.dims, (std::vector<hsize_t>{nv, 3}));
    TEST_COMPARE_ARRAYS(geo.values, pad3(dom.coordinates, 2));
    double sumX = 0;
    for (hsize_t v = 0; v < nv; ++v)
      sumX += geo.values[3 * v];
    TEST_FLOATING_EQUALITY(sumX, (m.ny + 1) * (m.nx + 1) * 0.5, 1e-14);

    const Dataset topo = readDataset(f, "/domain/topology");
    TEST_COMPARE_ARRAYS(topo.dims, (std::vector<hsize_t>{nc, 3}));
    TEST_COMPARE_ARRAYS(topo.values, asDoubles(dom.connectivity));

    const Dataset part = readDataset(f, "/domain/cell/partition");
    TEST_COMPARE_ARRAYS(part.dims, (std::vector<hsize_t>{nc}));
    std::vector<double> expectedPart;
    for (int j = 0; j < m.ny; ++j)
      for (int c = 0; c < 2 * m.nx; ++c)
        expectedPart.push_back(ownerOfRow(j, m.ny + 1, size));
    TEST_COMPARE_ARRAYS(part.values, expectedPart);

    const Dataset disp = readDataset(f, "/domain/point/displacement");
    TEST_COMPARE_ARRAYS(disp.dims, (std::vector<hsize_t>{nv, 3}));
    TEST_COMPARE_ARRAYS(disp.values, pad3(dom.pointFields[0].values, 2));
    const Dataset temp = readDataset(f, "/domain/point/temperature");
    TEST_COMPARE_ARRAYS(temp.dims, (std::vector<hsize_t>{nv}));
    TEST_COMPARE_ARRAYS(temp.values, dom.pointFields[1].values);

    // Symmetric (xx, yy, xy) = (c, 2c, 3c) expanded to a full 3x3 tensor.
    const Dataset stress = readDataset(f, "/domain/cell/stress");
    TEST_COMPARE_ARRAYS(stress.dims, (std::vector<hsize_t>{nc, 9}));
    std::vector<double> expectedStress;
    for (hsize_t c = 0; c < nc; ++c) {
      const double cd = static_cast<double>(c);
      expectedStress.insert(expectedStress.end(), {cd, 3 * cd, 0, 3 * cd, 2 * cd, 0, 0, 0, 0});
    }
    TEST_COMPARE_ARRAYS(stress.values, expectedStress);

    // Boundary grid: lines on the domain's vertices, ids and names.
    TEST_ASSERT(!exists(f, "/boundary/geometry"));
    const Dataset btopo = readDataset(f, "/boundary/topology");
    TEST_COMPARE_ARRAYS(btopo.dims, (std::vector<hsize_t>{nb, 2}));
    TEST_COMPARE_ARRAYS(btopo.values, asDoubles(bnd.connectivity));
    const Dataset bid = readDataset(f, "/boundary/cell/boundary_id");
    TEST_COMPARE_ARRAYS(bid.values, std::vector<double>(bnd.integerCellFields[0].values.begin(),
                                                        bnd.integerCellFields[0].values.end()));
    const Dataset bpart = readDataset(f, "/boundary/cell/partition");
    std::vector<double> expectedBpart(static_cast<std::size_t>(m.nx), 0.0);
    expectedBpart.resize(nb, ownerOfRow(m.ny - 1, m.ny + 1, size));
    TEST_COMPARE_ARRAYS(bpart.values, expectedBpart);
    TEST_EQUALITY(readStringAttribute(f, "/boundary", "boundary_names"),
                  std::string("{\"1\":\"contact\",\"2\":\"top\"}"));
    H5Fclose(f);
  }
  checkXdmf(dir, writer.xdmfPath(), times, out, success);
  std::ifstream in(writer.xdmfPath());
  std::stringstream s;
  s << in.rdbuf();
  TEST_ASSERT(
      s.str().find(
          "<Information Name=\"boundary_names\" Value=\"{&quot;1&quot;:&quot;contact&quot;") !=
      std::string::npos);
  TEST_ASSERT(
      s.str().find("TopologyType=\"Polyline\" NumberOfElements=\"8\" NodesPerElement=\"2\"") !=
      std::string::npos);
}

TEUCHOS_UNIT_TEST(XdmfWriter, ThreeDimensionalStripsTwoSteps)
{
  auto comm = Teuchos::DefaultComm<int>::getComm();
  const int rank = comm->getRank(), size = comm->getSize();
  const std::string dir = freshDirectory(*comm, "xdmf3d");
  sc::io::XdmfWriter writer(comm, dir, "cube");
  const std::vector<Mesh3D> meshes{{2, 2}, {2, 5}};
  for (int cycle = 0; cycle < 2; ++cycle)
    writer.writeStep(cycle, pieces3D(meshes[static_cast<std::size_t>(cycle)], rank, size));
  comm->barrier();
  if (rank != 0) return;

  TEST_EQUALITY(temporaries(dir).size(), 0u);
  for (int cycle = 0; cycle < 2; ++cycle) {
    const Mesh3D& m = meshes[static_cast<std::size_t>(cycle)];
    const auto ref = pieces3D(m, -1, size);
    const hsize_t nv = static_cast<hsize_t>((m.n + 1) * (m.n + 1) * (m.nz + 1));
    const hsize_t nc = 6u * m.n * m.n * m.nz, nb = 2u * m.n * m.n;
    hid_t f = H5Fopen(writer.h5Path(cycle).c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    TEST_ASSERT(f >= 0);
    if (f < 0) continue;
    const Dataset geo = readDataset(f, "/domain/geometry");
    TEST_COMPARE_ARRAYS(geo.dims, (std::vector<hsize_t>{nv, 3}));
    TEST_COMPARE_ARRAYS(geo.values, ref[0].coordinates);
    double sumZ = 0;
    for (hsize_t v = 0; v < nv; ++v)
      sumZ += geo.values[3 * v + 2];
    TEST_FLOATING_EQUALITY(sumZ, (m.n + 1) * (m.n + 1) * (m.nz + 1) * 0.5, 1e-14);

    const Dataset topo = readDataset(f, "/domain/topology");
    TEST_COMPARE_ARRAYS(topo.dims, (std::vector<hsize_t>{nc, 4}));
    TEST_COMPARE_ARRAYS(topo.values, asDoubles(ref[0].connectivity));
    const Dataset part = readDataset(f, "/domain/cell/partition");
    std::vector<double> expectedPart;
    for (int k = 0; k < m.nz; ++k)
      for (int c = 0; c < 6 * m.n * m.n; ++c)
        expectedPart.push_back(ownerOfRow(k, m.nz + 1, size));
    TEST_COMPARE_ARRAYS(part.values, expectedPart);

    // Voigt (xx, yy, zz, yz, xz, xy) = c + (0..5) expanded to 3x3.
    const Dataset stress = readDataset(f, "/domain/cell/stress");
    TEST_COMPARE_ARRAYS(stress.dims, (std::vector<hsize_t>{nc, 9}));
    const double c1 = 7;  // check one cell fully
    const std::vector<double> cell7(stress.values.begin() + 63, stress.values.begin() + 72);
    TEST_COMPARE_ARRAYS(cell7, (std::vector<double>{c1, c1 + 5, c1 + 4, c1 + 5, c1 + 1, c1 + 3,
                                                    c1 + 4, c1 + 3, c1 + 2}));
    const Dataset grad = readDataset(f, "/domain/cell/gradient");
    TEST_COMPARE_ARRAYS(grad.dims, (std::vector<hsize_t>{nc, 9}));
    TEST_COMPARE_ARRAYS(grad.values, ref[0].cellFields[1].values);

    const Dataset btopo = readDataset(f, "/boundary/topology");
    TEST_COMPARE_ARRAYS(btopo.dims, (std::vector<hsize_t>{nb, 3}));
    TEST_COMPARE_ARRAYS(btopo.values, asDoubles(ref[1].connectivity));
    const Dataset bpart = readDataset(f, "/boundary/cell/partition");
    // With 4 ranks and 3 vertex layers rank 0 owns nothing, so the bottom face is rank 1's.
    TEST_COMPARE_ARRAYS(bpart.values, std::vector<double>(nb, ownerOfRow(0, m.nz + 1, size)));
    H5Fclose(f);
  }
  checkXdmf(dir, writer.xdmfPath(), {0.0, 1.0}, out, success);
}

TEUCHOS_UNIT_TEST(XdmfWriter, RewritingACycleReplacesItsStep)
{
  auto comm = Teuchos::DefaultComm<int>::getComm();
  const std::string dir = freshDirectory(*comm, "xdmf_rewrite");
  sc::io::XdmfWriter writer(comm, dir, "solution");
  const Mesh2D m{2, 3};
  writer.writeStep(0, pieces2D(m, comm->getRank(), comm->getSize()));
  writer.writeStep(1, pieces2D(m, comm->getRank(), comm->getSize()));
  writer.writeStep(1, 7.0, pieces2D(m, comm->getRank(), comm->getSize()));
  comm->barrier();
  if (comm->getRank() == 0) checkXdmf(dir, writer.xdmfPath(), {0.0, 7.0}, out, success);
}

TEUCHOS_UNIT_TEST(XdmfWriter, GridEmptyOnAllRanksIsWrittenToH5AndLeftOutOfXdmf)
{
  auto comm = Teuchos::DefaultComm<int>::getComm();
  const std::string dir = freshDirectory(*comm, "xdmf_empty");
  sc::io::XdmfWriter writer(comm, dir, "solution");
  auto grids = pieces2D({2, 3}, comm->getRank(), comm->getSize());
  grids[1].connectivity.clear();  // no boundary facets anywhere (e.g. no contact yet)
  grids[1].integerCellFields[0].values.clear();
  writer.writeStep(0, grids);
  comm->barrier();
  if (comm->getRank() != 0) return;
  hid_t f = H5Fopen(writer.h5Path(0).c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  TEST_ASSERT(f >= 0);
  if (f >= 0) {
    const Dataset topo = readDataset(f, "/boundary/topology");
    TEST_COMPARE_ARRAYS(topo.dims, (std::vector<hsize_t>{0, 2}));
    H5Fclose(f);
  }
  checkXdmf(dir, writer.xdmfPath(), {0.0}, out, success);
  std::ifstream in(writer.xdmfPath());
  std::stringstream s;
  s << in.rdbuf();
  TEST_ASSERT(s.str().find("Name=\"boundary\"") == std::string::npos);
  TEST_ASSERT(s.str().find("Name=\"domain\"") != std::string::npos);
}

TEUCHOS_UNIT_TEST(XdmfWriter, BadPieceOnLastRankThrowsInputErrorOnAllRanks)
{
  auto comm = Teuchos::DefaultComm<int>::getComm();
  const int rank = comm->getRank(), size = comm->getSize();
  const std::string dir = freshDirectory(*comm, "xdmf_bad");
  sc::io::XdmfWriter writer(comm, dir, "solution");
  auto grids = pieces2D({2, 3}, rank, size);
  if (rank == size - 1) grids[0].pointFields[1].values.push_back(1.0);  // one value too many
  bool threw = false;
  try {
    writer.writeStep(0, grids);
  } catch (const sc::core::InputError& e) {
    threw = true;
    out << e.what() << "\n";
    TEST_ASSERT(std::string(e.what()).find("temperature") != std::string::npos);
  }
  TEST_ASSERT(threw);

  // Different field sets on different ranks are caught too (only possible with > 1 rank).
  auto grids2 = pieces2D({2, 3}, rank, size);
  if (size > 1 && rank == size - 1) grids2[0].pointFields[1].name = "pressure";
  bool threw2 = false;
  try {
    writer.writeStep(0, grids2);
  } catch (const sc::core::InputError& e) {
    threw2 = true;
  }
  TEST_EQUALITY(threw2, size > 1);

  // Vertex index out of range.
  auto grids3 = pieces2D({2, 3}, rank, size);
  if (rank == 0) grids3[0].connectivity[0] = 1000;
  TEST_THROW(writer.writeStep(0, grids3), sc::core::InputError);
  comm->barrier();
  if (rank == 0) TEST_EQUALITY(temporaries(dir).size(), 0u);
}

// A point cloud (CellType::Vertex, XDMF Polyvertex) beside a mesh grid, as the contact points
// of a cycle are written (docs/output.md "Fields"): rank r owns 2r + 1 points except rank 1,
// which owns none; the writer numbers one cell per point (global index = rank offset + i),
// writes the integer point field as int32 and the partition per point.
TEUCHOS_UNIT_TEST(XdmfWriter, PointCloudGridWithIntegerPointField)
{
  auto comm = Teuchos::DefaultComm<int>::getComm();
  const int rank = comm->getRank(), size = comm->getSize();
  const std::string dir = freshDirectory(*comm, "xdmf_points");
  sc::io::XdmfWriter writer(comm, dir, "solution");
  auto count = [](int r) { return r == 1 ? 0 : 2 * r + 1; };
  int offset = 0, total = 0;
  for (int r = 0; r < size; ++r) {
    if (r < rank) offset += count(r);
    total += count(r);
  }
  GridPiece cloud("contact", CellType::Vertex, 2);
  std::vector<double> pressure, traction;
  std::vector<int> status;
  for (int i = 0; i < count(rank); ++i) {
    const double g = offset + i;
    cloud.coordinates.insert(cloud.coordinates.end(), {g, -2 * g});
    pressure.push_back(10 * g);
    traction.insert(traction.end(), {g, 1.0});
    status.push_back((offset + i) % 3);
  }
  cloud.addPointField("contact_pressure", FieldKind::Scalar, pressure);
  cloud.addPointField("tangential_traction", FieldKind::Vector, traction);
  cloud.addPointField("status", status);
  auto grids = pieces2D({2, 3}, rank, size);
  grids.push_back(cloud);
  writer.writeStep(0, grids);

  // A vertex grid takes no connectivity, and an integer point field one value per point.
  auto withCells = grids;
  withCells[2].connectivity = {0};
  TEST_THROW(writer.writeStep(1, withCells), sc::core::InputError);
  auto shortField = grids;
  if (rank == size - 1) shortField[2].integerPointFields[0].values.push_back(7);
  TEST_THROW(writer.writeStep(1, shortField), sc::core::InputError);
  comm->barrier();
  if (rank != 0) return;

  const auto n = static_cast<hsize_t>(total);
  hid_t f = H5Fopen(writer.h5Path(0).c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  TEST_ASSERT(f >= 0);
  if (f < 0) return;
  std::vector<double> xyz, ids, p, t, st, part;
  for (int r = 0, g = 0; r < size; ++r)
    for (int i = 0; i < count(r); ++i, ++g) {
      xyz.insert(xyz.end(), {double(g), -2.0 * g, 0.0});
      ids.push_back(g);
      p.push_back(10.0 * g);
      t.insert(t.end(), {double(g), 1.0, 0.0});
      st.push_back(g % 3);
      part.push_back(r);
    }
  const Dataset geo = readDataset(f, "/contact/geometry");
  TEST_COMPARE_ARRAYS(geo.dims, (std::vector<hsize_t>{n, 3}));
  TEST_COMPARE_ARRAYS(geo.values, xyz);
  const Dataset topo = readDataset(f, "/contact/topology");
  TEST_COMPARE_ARRAYS(topo.dims, (std::vector<hsize_t>{n}));
  TEST_COMPARE_ARRAYS(topo.values, ids);
  TEST_COMPARE_ARRAYS(readDataset(f, "/contact/point/contact_pressure").values, p);
  TEST_COMPARE_ARRAYS(readDataset(f, "/contact/point/tangential_traction").values, t);
  TEST_COMPARE_ARRAYS(readDataset(f, "/contact/point/status").values, st);
  TEST_COMPARE_ARRAYS(readDataset(f, "/contact/cell/partition").values, part);
  hid_t statusSet = H5Dopen2(f, "/contact/point/status", H5P_DEFAULT);
  hid_t type = H5Dget_type(statusSet);
  TEST_EQUALITY(H5Tget_class(type), H5T_INTEGER);
  TEST_EQUALITY(H5Tget_size(type), std::size_t{4});
  H5Tclose(type);
  H5Dclose(statusSet);
  H5Fclose(f);

  checkXdmf(dir, writer.xdmfPath(), {0.0}, out, success);
  std::ifstream in(writer.xdmfPath());
  std::stringstream s;
  s << in.rdbuf();
  const std::string xml = s.str();
  TEST_ASSERT(xml.find("<Grid Name=\"contact\" GridType=\"Uniform\">") != std::string::npos);
  TEST_ASSERT(xml.find("<Topology TopologyType=\"Polyvertex\" NumberOfElements=\"" +
                       std::to_string(total) + "\" NodesPerElement=\"1\">") != std::string::npos);
  TEST_ASSERT(xml.find("<Attribute Name=\"status\" AttributeType=\"Scalar\" Center=\"Node\">\n"
                       "            <DataItem Dimensions=\"" +
                       std::to_string(total) +
                       "\" NumberType=\"Int\" Precision=\"4\" "
                       "Format=\"HDF\">solution_c0000.h5:/contact/point/status</DataItem>") !=
              std::string::npos);
  TEST_ASSERT(
      xml.find(
          "<Attribute Name=\"tangential_traction\" AttributeType=\"Vector\" Center=\"Node\">") !=
      std::string::npos);
}

TEUCHOS_UNIT_TEST(XdmfWriter, UnwritableDirectoryThrowsNamingIt)
{
  auto comm = Teuchos::DefaultComm<int>::getComm();
  const std::string base = freshDirectory(*comm, "xdmf_unwritable");
  const std::string regularFile = base + "/plain_file";
  if (comm->getRank() == 0) std::ofstream(regularFile) << "x\n";
  comm->barrier();
  for (const std::string& bad : {std::string("/proc/forbidden"), regularFile + "/out"}) {
    bool threw = false;
    try {
      sc::io::XdmfWriter writer(comm, bad, "solution");
    } catch (const sc::core::InputError& e) {
      threw = true;
      TEST_ASSERT(std::string(e.what()).find(bad) != std::string::npos);
    }
    TEST_ASSERT(threw);
  }
}

}  // namespace

namespace {

// A full disk, simulated with a file-size limit (RLIMIT_FSIZE, `ulimit -f`; writes beyond it fail
// with EFBIG as writes to a full disk fail with ENOSPC): the writer finds that there is no room
// before HDF5 writes anything, names the file, the size and the limit, leaves no temporary, and
// the process ends normally (otherwise HDF5 reports "H5Dwrite failed" without a reason, then
// dies of a segmentation fault at MPI_Finalize; docs/reliability.md).
TEUCHOS_UNIT_TEST(XdmfWriter, NoRoomForTheFileIsFoundBeforeWriting)
{
  auto comm = Teuchos::DefaultComm<int>::getComm();
  const std::string dir = freshDirectory(*comm, "xdmf_file_size_limit");
  sc::io::XdmfWriter writer(comm, dir, "solution");
  const auto pieces = pieces2D(Mesh2D{200, 200}, comm->getRank(), comm->getSize());  // ~2.5 MB

  struct sigaction ignore {
  }, previous{};
  ignore.sa_handler = SIG_IGN;
  sigaction(SIGXFSZ, &ignore, &previous);
  rlimit saved{};
  getrlimit(RLIMIT_FSIZE, &saved);
  rlimit limited = saved;
  limited.rlim_cur = 64 * 1024;
  setrlimit(RLIMIT_FSIZE, &limited);
  std::string message;
  try {
    writer.writeStep(0, pieces);
  } catch (const sc::core::Error& e) {
    message = e.what();
  }
  setrlimit(RLIMIT_FSIZE, &saved);
  sigaction(SIGXFSZ, &previous, nullptr);
  out << message << "\n";
  TEST_ASSERT(message.find("no room for '") != std::string::npos);
  TEST_ASSERT(message.find("solution_c0000.h5") != std::string::npos);
  TEST_ASSERT(message.find("file-size limit of 65536 bytes (ulimit -f)") != std::string::npos);
  comm->barrier();
  TEST_ASSERT(temporaries(dir).empty());
  // With the limit lifted the same step is written.
  writer.writeStep(0, pieces);
}

TEUCHOS_UNIT_TEST(XdmfWriter, CheckRoomForFileNamesTheFreeSpace)
{
  const std::string dir = ".";
  sc::io::checkRoomForFile(dir, "./small.h5", 1024);
  try {
    sc::io::checkRoomForFile(dir, "./huge.h5", 1ull << 62);
    TEST_ASSERT(false);
  } catch (const sc::core::Error& e) {
    out << e.what() << "\n";
    const std::string m = e.what();
    TEST_ASSERT(m.find("no room for './huge.h5'") != std::string::npos);
    TEST_ASSERT(m.find("free (disk full?)") != std::string::npos);
  }
}

}  // namespace
