// mesh_memory_benchmark: the memory per rank of the replicated mesh (docs/architecture.md
// "Replicated mesh: memory per rank"). Builds the unit square (triangles) or unit cube
// (tetrahedra) with Gmsh, refines it uniformly until it has at least --elements elements, then
// partitions it (METIS) and numbers the DOFs of the mixed space, as every rank of the application
// does for every cycle, and prints per phase the resident memory it keeps and the peak it needs.
//
//   mesh_memory_benchmark [--dim=2|3] [--elements=N] [--mesh-size=h] [--degree=k] [--no-numbering]
//   mpiexec -n 2 mesh_memory_benchmark --elements=1000000 --mesh-size=0.207
//
// Phases (each after a barrier; every number is the maximum over ranks):
//   mesh       the initial mesh and the uniform levels: the SimplexMesh (connectivity, faces,
//              edges, vertex-to-element lists) and the refiner's state (coordinates, element
//              vertices, generations, markings), history of every level but the last forgotten;
//   history    the refinement history of the last level (RefinementStep: parents and children),
//              what the application keeps from refine() to the contact transfer;
//   partition  the owner of every element (METIS on rank 0 on the whole dual graph, broadcast);
//   numbering  MixedElasticitySpace: the global DOF ids of every element and the owner of every
//              DOF, on the whole mesh on every rank.
// "kept" is the resident memory a phase adds and keeps (its data structures: resident memory at
// its end minus at its start; for the history, what forgetting it frees), "peak" the highest
// resident memory during the phase above the level at its start (the phase's temporaries
// included), from Linux's VmHWM reset by /proc/self/clear_refs before each phase. Allocations
// from 64 kB on are mapped pages of their own (mallopt), so that freed temporaries return to the
// system and the resident memory after a phase counts only what it keeps.
#include <malloc.h>

#include <cstdio>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

#include <Kokkos_Core.hpp>
#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_DefaultComm.hpp>
#include <Teuchos_GlobalMPISession.hpp>
#include <Teuchos_ParameterList.hpp>

#include <sc/disc/MixedElasticitySpace.hpp>
#include <sc/mesh/BisectionRefiner.hpp>
#include <sc/mesh/MeshFactory.hpp>
#include <sc/mesh/Partitioning.hpp>
#include <sc/mesh/SimplexMesh.hpp>

namespace {

/// A field of /proc/self/status in MB ("VmRSS", "VmHWM"); -1 if unreadable.
double statusMB(const char* key)
{
  std::ifstream in("/proc/self/status");
  std::string line;
  const std::size_t n = std::strlen(key);
  while (std::getline(in, line))
    if (line.compare(0, n, key) == 0 && line.size() > n && line[n] == ':')
      return std::stod(line.substr(n + 1)) / 1024.0;  // kB
  return -1.0;
}

/// Resident memory now, after returning freed heap pages to the system.
double residentMB()
{
  malloc_trim(0);
  return statusMB("VmRSS");
}

/// Reset the peak (VmHWM) to the current resident memory (Linux >= 4.0); false if refused.
bool resetPeak()
{
  std::ofstream out("/proc/self/clear_refs");
  out << "5";
  out.flush();
  return static_cast<bool>(out);
}

double maxOverRanks(const Teuchos::Comm<int>& comm, double v)
{
  double r = v;
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MAX, 1, &v, &r);
  return r;
}

/// Peak and resident memory of one phase on this rank.
struct Phase {
  const char* name;
  double startMB = 0, peakMB = 0, keptMB = 0;
};

class PhaseMeter {
public:
  explicit PhaseMeter(const Teuchos::Comm<int>& comm) : comm_(comm) { peakWorks_ = resetPeak(); }
  void begin(Phase& p)
  {
    comm_.barrier();
    p.startMB = residentMB();
    resetPeak();
  }
  void end(Phase& p)
  {
    p.peakMB = statusMB("VmHWM") - p.startMB;
    p.keptMB = residentMB() - p.startMB;
    comm_.barrier();
  }
  bool peakWorks() const { return peakWorks_; }

private:
  const Teuchos::Comm<int>& comm_;
  bool peakWorks_ = false;
};

}  // namespace

int main(int argc, char* argv[])
{
  mallopt(M_MMAP_THRESHOLD, 64 * 1024);  // fixed: also turns off glibc's dynamic threshold
  Teuchos::GlobalMPISession session(&argc, &argv, nullptr);
  Kokkos::ScopeGuard kokkos(argc, argv);
  auto comm = Teuchos::DefaultComm<int>::getComm();
  int dim = 2, degree = 1;
  long long targetElements = 100000;
  double meshSize = 0.0;
  bool numberDofs = true;  // --no-numbering: mesh, history and partition only (less memory)
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a.rfind("--dim=", 0) == 0)
      dim = std::stoi(a.substr(6));
    else if (a.rfind("--elements=", 0) == 0)
      targetElements = std::stoll(a.substr(11));
    else if (a.rfind("--mesh-size=", 0) == 0)
      meshSize = std::stod(a.substr(12));
    else if (a.rfind("--degree=", 0) == 0)
      degree = std::stoi(a.substr(9));
    else if (a == "--no-numbering")
      numberDofs = false;
    else {
      if (comm->getRank() == 0)
        std::fprintf(stderr,
                     "unknown option %s\nusage: mesh_memory_benchmark [--dim=2|3] [--elements=N] "
                     "[--mesh-size=h] [--degree=k] [--no-numbering]\n",
                     a.c_str());
      return 1;
    }
  }
  if (dim != 2 && dim != 3) {
    if (comm->getRank() == 0) std::fprintf(stderr, "--dim must be 2 or 3, not %d\n", dim);
    return 1;
  }
  if (meshSize <= 0.0) meshSize = dim == 2 ? 0.25 : 0.5;
  const int rank = comm->getRank(), nRanks = comm->getSize();
  PhaseMeter meter(*comm);
  const double baseMB = maxOverRanks(*comm, residentMB());

  Phase mesh{"mesh"}, history{"history"}, partition{"partition"}, numbering{"numbering"};
  // mesh: Gmsh on rank 0, broadcast, then uniform levels on every rank (replicated).
  meter.begin(mesh);
  Teuchos::ParameterList meshList;
  meshList.set("Source", std::string(dim == 2 ? "Unit square" : "Unit cube"));
  meshList.set("Initial mesh size", meshSize);
  auto refiner = sc::mesh::MeshFactory::build(meshList, dim, *comm);
  int levels = 0;
  while (refiner->mesh()->numElements() < targetElements) {
    refiner->forgetHistory();  // the application forgets each step after its transfer
    refiner->refineUniformly();
    ++levels;
  }
  meter.end(mesh);
  // history: the last level's step is still held; its size is what forgetting it frees.
  const double withHistoryMB = residentMB();
  refiner->forgetHistory();
  history.keptMB = withHistoryMB - residentMB();
  history.peakMB = 0.0;           // made inside the last refinement (counted in mesh's peak)
  mesh.keptMB -= history.keptMB;  // mesh's resident memory at its end held the history too
  auto m = refiner->mesh();
  const long long elements = m->numElements(), vertices = m->numVertices();

  meter.begin(partition);
  auto owner = std::make_unique<std::vector<int>>(sc::mesh::partitionElements(*m, *comm));
  meter.end(partition);

  std::unique_ptr<sc::disc::MixedElasticitySpace> space;
  long long dofs = 0, ownedDofs = 0;
  if (numberDofs) {
    meter.begin(numbering);
    space = std::make_unique<sc::disc::MixedElasticitySpace>(m, degree, *owner, rank);
    meter.end(numbering);
    dofs = space->numGlobalDofs();
    ownedDofs = static_cast<long long>(space->ownedDofs().size());
  }
  const double allMB = maxOverRanks(*comm, residentMB());
  // The refiner's own state (coordinates, element vertices, generations, markings, boundary maps)
  // within "mesh": what dropping the refiner frees while the SimplexMesh stays (the space holds
  // it).
  const double beforeDropMB = residentMB();
  refiner = Teuchos::null;
  const double refinerMB = maxOverRanks(*comm, beforeDropMB - residentMB());

  const double perElement = 1.0e6 / static_cast<double>(elements);  // MB -> bytes per element
  if (rank == 0) {
    std::printf("# mesh_memory_benchmark %dD k=%d ranks=%d mesh-size=%g: %lld %s, %lld vertices "
                "(%d uniform levels)",
                dim, degree, nRanks, meshSize, elements, dim == 2 ? "triangles" : "tetrahedra",
                vertices, levels);
    if (numberDofs)
      std::printf(", %lld DOFs (%lld owned by rank 0)\n", dofs, ownedDofs);
    else
      std::printf(", DOFs not numbered\n");
    std::printf("# resident memory per rank, maximum over ranks [MB]; start (MPI, Kokkos, "
                "libraries) %.0f MB; after all phases %.0f MB%s\n",
                baseMB, allMB,
                meter.peakWorks() ? "" : "; peak not measured (/proc/self/clear_refs refused)");
    std::printf("# %-10s %10s %10s %12s %12s\n", "phase", "kept_MB", "peak_MB", "kept_B/elem",
                "peak_B/elem");
  }
  double keptSum = 0.0;
  for (Phase* p : {&mesh, &history, &partition, &numbering}) {
    if (p == &numbering && !numberDofs) {
      if (rank == 0) std::printf("  %-10s not run (--no-numbering)\n", p->name);
      continue;
    }
    const double kept = maxOverRanks(*comm, p->keptMB);
    const double peak = maxOverRanks(*comm, p->peakMB);
    keptSum += kept;
    if (rank == 0)
      std::printf("  %-10s %10.1f %10.1f %12.1f %12.1f\n", p->name, kept, peak, kept * perElement,
                  peak * perElement);
  }
  if (rank == 0) {
    std::printf("  %-10s %10.1f %10s %12.1f\n", "all kept", keptSum, "", keptSum * perElement);
    std::printf("# of mesh's kept memory, the refiner's state: %.1f MB (%.1f B/elem); the "
                "SimplexMesh the rest\n",
                refinerMB, refinerMB * perElement);
  }
  return 0;
}
