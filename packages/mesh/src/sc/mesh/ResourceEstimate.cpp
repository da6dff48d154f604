#include <sc/mesh/ResourceEstimate.hpp>

#include <sc/core/Error.hpp>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <unistd.h>

namespace sc::mesh {

double sceneMeasure(const MeshSettings& p, int dimension)
{
  const std::string& source = p.source;
  const double R = p.radius;
  if (source == "Half disc") return M_PI * R * R / 2.0;
  if (source == "Half ball") return 2.0 * M_PI * R * R * R / 3.0;
  if (source == "Unit square" || source == "Unit cube") return 1.0;
  if (source == "Rectangle") {
    const auto& lo = p.lowerCorner;
    const auto& hi = p.upperCorner;
    double m = 1.0;
    for (int i = 0; i < dimension && i < static_cast<int>(lo.size()); ++i)
      m *= std::abs(hi[i] - lo[i]);
    return m;
  }
  return -1.0;  // Gmsh file: its element count is known once read
}

double estimateInitialElements(double measure, double h, int dimension)
{
  if (dimension == 2) return kGmshElementsFactor2D * measure / (std::sqrt(3.0) / 4.0 * h * h);
  return kGmshElementsFactor3D * measure / (h * h * h / (6.0 * std::sqrt(2.0)));
}

double dofsPerElement(int d, int k)
{
  // Per element of a large mesh: vertices V, edges E, faces F (interior faces shared by 2).
  const double V = d == 2 ? 0.5 : 1.0 / 5.5, E = d == 2 ? 1.5 : 1.2 + V, F = d == 2 ? 1.0 : 2.0;
  double stressRow, disp, rot;
  if (d == 2) {
    stressRow = (k + 1) * E + k * (k + 1);            // RT_k: k+1 per edge
    disp = 2.0 * (k + 1) * (k + 2) / 2.0;             // DP_k, 2 components
    rot = V + (k - 1) * E + (k - 1) * (k - 2) / 2.0;  // CP_k, 1 component
    return 2.0 * stressRow + disp + rot;
  }
  stressRow = (k + 1) * (k + 2) / 2.0 * F + k * (k + 1) * (k + 2) / 2.0;
  disp = 3.0 * (k + 1) * (k + 2) * (k + 3) / 6.0;
  rot = 3.0 * (V + (k - 1) * E + (k - 1) * (k - 2) / 2.0 * F + (k - 1) * (k - 2) * (k - 3) / 6.0);
  return 3.0 * stressRow + disp + rot;
}

double closureFactor(int dimension, bool alongBoundary)
{
  if (dimension == 2) return 3.0;
  return alongBoundary ? 8.0 : 16.0;
}

double bytesPerDof(int dimension) { return dimension == 2 ? kBytesPerDof2D : kBytesPerDof3D; }

double dataBytes(double dofs, int dimension, bool contact, double multigridFromDofs,
                 double multigridBytesPerDof)
{
  if (contact && dimension == 3 && dofs >= multigridFromDofs) return multigridBytesPerDof * dofs;
  if (contact && dimension == 3)
    return kContactBytesPerDof3D * dofs + kContactFactorBytes3D * std::pow(dofs, 4.0 / 3.0);
  return dofs * bytesPerDof(dimension);
}

double ResourceLimit::maxElements() const
{
  const double room = memoryBytes - baselineBytes;
  if (!(contact && dimension == 3) || !(room < std::numeric_limits<double>::infinity()))
    return room / bytes(1.0);
  // From multigridFromDofs on the model is linear: the largest mesh there, if one fits.
  const double switchElements = multigridFromDofs / dofsPerElement(dimension, degree);
  if (switchElements < std::numeric_limits<double>::infinity()) {
    const double linear = room / (multigridBytesPerDof * dofsPerElement(dimension, degree) +
                                  ranks * kMeshBytesPerElement);
    if (linear >= switchElements) return linear;
  }
  // Below it MUMPS' bytes(e) is increasing and superlinear: bisect on [0, the linear bound].
  double lo = 0.0, hi = std::max(std::min(room / bytes(1.0), switchElements), 1.0);
  for (int i = 0; i < 200 && hi - lo > 1e-9 * hi; ++i) {
    const double mid = 0.5 * (lo + hi);
    (bytes(mid) > room ? hi : lo) = mid;
  }
  return lo;
}

double availableMemoryBytes(std::string* source)
{
  std::ifstream in("/proc/meminfo");
  std::string key;
  double kb;
  std::string unit;
  while (in >> key >> kb) {
    std::getline(in, unit);
    if (key == "MemAvailable:") {
      if (source) *source = "MemAvailable in /proc/meminfo";
      return kb * 1024.0;
    }
  }
  const long pages = sysconf(_SC_AVPHYS_PAGES), size = sysconf(_SC_PAGESIZE);
  if (pages > 0 && size > 0) {
    if (source) *source = "available physical pages (sysconf)";
    return static_cast<double>(pages) * static_cast<double>(size);
  }
  if (source) *source = "unknown";
  return std::numeric_limits<double>::infinity();
}

double residentMemoryBytes()
{
  std::ifstream in("/proc/self/status");
  std::string key;
  while (in >> key) {
    if (key == "VmRSS:") {
      double kb = 0.0;
      return (in >> kb) ? kb * 1024.0 : 0.0;
    }
    std::getline(in, key);
  }
  return 0.0;
}

namespace {
std::string gb(double bytes)
{
  std::ostringstream os;
  os.precision(3);
  os << bytes / 1e9 << " GB";
  return os.str();
}
}  // namespace

std::string ResourceLimit::source() const
{
  if (!(baselineBytes > 0.0)) return memorySource;
  std::ostringstream os;
  os << memorySource << ", of which the program held " << gb(baselineBytes)
     << " before the mesh (VmRSS, " << ranks << (ranks == 1 ? " rank)" : " ranks)");
  return os.str();
}

std::string ResourceLimit::describe(double elements) const
{
  std::ostringstream os;
  os.precision(2);
  os << "about " << elements << (dimension == 2 ? " triangles, " : " tetrahedra, ")
     << dofs(elements) << " DOFs (degree " << degree << ") and " << gb(totalBytes(elements))
     << " of memory (";
  if (contact && dimension == 3 && dofs(elements) >= multigridFromDofs)
    os << multigridBytesPerDof / 1e3
       << " kB per DOF for the system, the stress multigrid and its Krylov basis, which Linear "
       << "Solver/Type = Auto chooses from " << multigridFromDofs << " DOFs, docs/mesh.md";
  else if (contact && dimension == 3)
    os << dataBytes(dofs(elements), dimension, contact) / dofs(elements) / 1e3
       << " kB per DOF at this size for the system and MUMPS' LU factors of 3D contact, "
       << "growing like DOFs^(1/3), measured in docs/solvers.md";
  else
    os << bytesPerDof(dimension) / 1e3
       << " kB per DOF for the system and MUMPS factors, measured in docs/benchmarks.md";
  os << (baselineBytes > 0.0 ? ", and the program's own memory" : "")
     << "), above the memory limit of " << gb(memoryBytes) << " (" << source() << ")";
  if (maxDofs > 0 && dofs(elements) > static_cast<double>(maxDofs))
    os << "; 'Adaptivity/Max DOFs' is " << maxDofs;
  return os.str();
}

ResourceLimit makeResourceLimit(double limitGB, int dimension, int degree, int ranks,
                                long long maxDofs, double availableBytes,
                                const std::string& availableSource, double baselineBytes)
{
  ResourceLimit l;
  l.dimension = dimension;
  l.degree = degree;
  l.ranks = ranks;
  l.maxDofs = maxDofs;
  if (limitGB > 0.0) {
    // The limit is what the run may use, as its peak resident memory (summary.json's
    // peak_rss_sum_mb) counts it: libraries and MPI included. A limit below what the program
    // holds before any mesh cannot be kept (0.1 GB: hertz2d.xml peaked at 0.278 GB on 1 rank).
    if (limitGB * 1e9 <= baselineBytes) {
      const double suggestion = std::ceil((baselineBytes + 0.5e9) / 1e8) / 10.0;
      SC_THROW_IF(true, sc::core::InputError,
                  "'Mesh/Memory limit (GB)' = "
                      << limitGB << " is below the memory the program "
                      << "holds before any mesh is made: " << gb(baselineBytes)
                      << " (VmRSS of /proc/self/status, summed over the " << ranks
                      << (ranks == 1 ? " rank" : " ranks") << ": libraries, MPI, Kokkos). The "
                      << "limit covers that memory and the run's data on top of it (mesh, "
                      << "matrices, solver; docs/mesh.md \"Resource limits\"). Give more than "
                      << gb(baselineBytes) << ", e.g. " << suggestion << " (about "
                      << gb(suggestion * 1e9 - baselineBytes) << " for the run's data), or 0 "
                      << "for the memory available.");
    }
    l.memoryBytes = limitGB * 1e9;
    l.memorySource = "'Mesh/Memory limit (GB)'";
    l.baselineBytes = baselineBytes;
  } else {
    l.memoryBytes = availableBytes;
    l.memorySource = availableSource + ", the default of 'Mesh/Memory limit (GB)'";
  }
  return l;
}

}  // namespace sc::mesh
