#pragma once
// Estimates of the size of a run before its mesh is made or refined
// (docs/mesh.md "Resource limits"): elements of the initial Gmsh mesh from the scene's measure and
// Mesh/Initial mesh size, growth under uniform and local refinement, DOFs per element from the
// counts of the mixed space, and bytes per DOF from the measured memory of docs/benchmarks.md.
// A mesh whose estimate exceeds the memory limit is an InputError naming the key, the estimate
// and the limit, instead of a hang in Gmsh or a std::bad_alloc.

#include <sc/mesh/MeshSettings.hpp>

#include <limits>
#include <string>

namespace sc::mesh {

/// Calibration of the initial Gmsh mesh: elements ≈ kGmshElementsFactor[d] · measure / m(h),
/// with m(h) the measure of the equilateral triangle (√3/4 h²) or regular tetrahedron
/// (h³/(6√2)) of edge h. Fitted on the scenes' meshes (docs/mesh.md table, test
/// MeshResources.InitialEstimateMatchesGmsh).
inline constexpr double kGmshElementsFactor2D = 1.1;
inline constexpr double kGmshElementsFactor3D = 0.75;

/// Measured memory of a run per DOF (docs/benchmarks.md "Memory per DOF": assembled system plus
/// MUMPS factors, 1 rank, k = 1; the increment between the two largest sizes): 2.2 kB/DOF in 2D,
/// 7.4 kB/DOF in 3D.
inline constexpr double kBytesPerDof2D = 2.2e3;
inline constexpr double kBytesPerDof3D = 7.4e3;
/// 3D contact (docs/mesh.md "Resource limits", measured on input/hertz3d.xml in docs/solvers.md
/// "Memory and time of 3D contact"): bytes = a·N + c·N^(4/3) for N DOFs. The contact systems are
/// not symmetric, so MUMPS factorises LU (about twice the entries of the LDLᵀ kBytesPerDof3D was
/// measured with) with delayed pivots, into a workspace it allocates from the analysis' full-rank
/// estimate, and the 3D factors grow faster than N (their estimate like N^1.47 from 2.5·10⁵ to
/// 5.1·10⁵ DOFs); the linear part is the assembled system (about 100 entries per DOF), its
/// equilibrated copy and MUMPS' copies of all its entries (not of one triangle as for LDLᵀ).
/// Fitted on the peaks at 254 430 and 505 971 DOFs (1 rank, k = 1, full rank): 3489 and 7999 MB.
inline constexpr double kContactBytesPerDof3D = 4.5e3;  ///< a, bytes per DOF
inline constexpr double kContactFactorBytes3D = 148.0;  ///< c, bytes per DOF^(4/3)
/// 3D contact solved by the stress multigrid (Linear Solver/Type = Auto from 'Auto iterative
/// contact unknowns', docs/solvers.md "Type = Auto"): bytes per DOF, linear, without the GMRES
/// basis (added by the caller). Measured on input/hertz3d.xml at 2 ranks (docs/solvers.md "3D
/// contact at 2·10⁶ DOFs"): the peak summed over the ranks less the GMRES basis and the program's
/// own 0.22 GB, 8.8 kB per DOF at 256 125 DOFs and 9.0 kB at 2 014 035 (the elasticity multigrid
/// without contact: 7.3 kB at 1 rank, 8.0 kB at 2, docs/solvers.md "3D at 2·10⁶ unknowns").
inline constexpr double kContactMultigridBytesPerDof3D = 9.0e3;
/// The replicated mesh, per element and per rank (docs/mesh.md: about 0.4 kB per tetrahedron).
inline constexpr double kMeshBytesPerElement = 400.0;
/// New elements per element selected by a bisection sweep (its bisection and the conforming
/// closure around it), fitted on the scenes (test
/// MeshResources.RefinementEstimateMatchesTheRefiner, docs/mesh.md "Resource limits"): 3 in 2D; in
/// 3D 16 for a volume region and 8 along a boundary part (3D bisection needs 3 generations to halve
/// h, and the closure cascades further).
double closureFactor(int dimension, bool alongBoundary);

/// Estimated elements of a mesh built by MeshFactory (MeshFactory::estimateRefinement).
struct MeshEstimate {
  double initial = 0.0;   ///< the initial mesh (counted)
  double uniform = 0.0;   ///< after Mesh/Uniform refinements (×2^d per level)
  double local = 0.0;     ///< after the local sweeps
  double selected = 0.0;  ///< elements selected by the first local sweep (after uniform levels)
  double growth = 1.0;    ///< growth of the selected elements per sweep
  double closure = 0.0;   ///< new elements per selected element, with the closure
};

/// Measure (area/volume) of the domain of the Mesh settings, or -1 for 'Gmsh file'.
double sceneMeasure(const MeshSettings& settings, int dimension);

/// Elements of Gmsh's mesh of a domain of this measure at target size h.
double estimateInitialElements(double measure, double h, int dimension);

/// Global DOFs per element of the mixed space RT_k^d × DP_k^d × CP_k^r (r = 1 in 2D, 3 in 3D)
/// on a large mesh (Euler: per triangle 1/2 vertex, 3/2 edges; per tetrahedron about 1/5.5
/// vertex, 1.2 edges, 2 faces). k = 1: 16.5 (2D), 39.6 (3D).
double dofsPerElement(int dimension, int degree);

/// kBytesPerDof2D / 3D.
double bytesPerDof(int dimension);

/// Memory of a run's data for `dofs` DOFs (the mesh not included): dofs · bytesPerDof(d), and
/// for 3D contact kContactBytesPerDof3D · dofs + kContactFactorBytes3D · dofs^(4/3) (MUMPS' LU),
/// or multigridBytesPerDof · dofs from `multigridFromDofs` DOFs on (Type = Auto solves those with
/// the stress multigrid; kContactMultigridBytesPerDof3D plus the caller's Krylov basis). 2D contact
/// uses the 2D constant (not measured with contact).
double dataBytes(double dofs, int dimension, bool contact,
                 double multigridFromDofs = std::numeric_limits<double>::infinity(),
                 double multigridBytesPerDof = kContactMultigridBytesPerDof3D);

/// The machine's available memory in bytes: MemAvailable of /proc/meminfo, else
/// sysconf(_SC_AVPHYS_PAGES) · page size. `source` says which.
double availableMemoryBytes(std::string* source = nullptr);

/// Resident memory of this process in bytes (VmRSS of /proc/self/status), 0 if unknown.
double residentMemoryBytes();

/// The limit a run's mesh is checked against.
struct ResourceLimit {
  double memoryBytes = std::numeric_limits<double>::infinity();
  std::string memorySource;  ///< e.g. "MemAvailable in /proc/meminfo"
  /// The program's own memory before any mesh (libraries, MPI, Kokkos: VmRSS summed over the
  /// ranks), counted in an explicit Mesh/Memory limit (GB); 0 under the default limit, the
  /// available memory, which is measured with that memory already in use.
  double baselineBytes = 0.0;
  int dimension = 2;
  int degree = 1;
  int ranks = 1;
  long long maxDofs = 0;  ///< Adaptivity/Max DOFs (0: not given), named in messages
  bool contact = false;   ///< the scene has contact (3D: the contact model of dataBytes)
  /// 3D contact under Type = Auto: the DOFs from which the multigrid solves the system and its
  /// linear model replaces MUMPS' (SolverPolicy::autoIterativeFrom); infinity: always MUMPS.
  double multigridFromDofs = std::numeric_limits<double>::infinity();
  /// Bytes per DOF there: kContactMultigridBytesPerDof3D and the Krylov basis the run's GMRES
  /// allocates (flexible GMRES: 2 (Restart + 1) vectors of 8 bytes per DOF, set by the application
  /// for Coulomb friction, whose slip steps are non-symmetric).
  double multigridBytesPerDof = kContactMultigridBytesPerDof3D;
  bool active() const { return memoryBytes < std::numeric_limits<double>::infinity(); }
  double dofs(double elements) const { return elements * dofsPerElement(dimension, degree); }
  /// Bytes of a run on a mesh of `elements` elements: dataBytes(DOFs) + ranks · mesh.
  double bytes(double elements) const
  {
    return dataBytes(dofs(elements), dimension, contact, multigridFromDofs, multigridBytesPerDof) +
           ranks * elements * kMeshBytesPerElement;
  }
  /// bytes(elements) and the baseline: what is compared with memoryBytes.
  double totalBytes(double elements) const { return bytes(elements) + baselineBytes; }
  /// Whether a mesh of `elements` elements fits: totalBytes ≤ memoryBytes.
  bool fits(double elements) const { return !(totalBytes(elements) > memoryBytes); }
  /// The most elements whose bytes fit in memoryBytes − baselineBytes (linear without 3D
  /// contact; MUMPS' superlinear model inverted by bisection; with multigridFromDofs, the larger
  /// mesh of the two models, so smaller meshes need not all fit: ask fits()).
  double maxElements() const;
  /// memorySource, with the baseline it counts: "'Mesh/Memory limit (GB)', of which the program
  /// held 0.16 GB before the mesh (VmRSS, 1 rank)".
  std::string source() const;
  /// "about 3.6e+12 elements, 6e+13 DOFs and 1.3e+08 GB, above the memory limit of 21.3 GB
  /// (MemAvailable in /proc/meminfo)" (and Max DOFs when the DOFs exceed it).
  std::string describe(double elements) const;
};

/// Limit from Mesh/Memory limit (GB) (0: the available memory). `baselineBytes`: the program's
/// memory before any mesh on all ranks (residentMemoryBytes summed), which an explicit limit
/// must exceed (else an InputError naming the key, the baseline and a valid value) and which the
/// estimates of the mesh are added to (docs/mesh.md "Resource limits").
ResourceLimit makeResourceLimit(double limitGB, int dimension, int degree, int ranks,
                                long long maxDofs, double availableBytes,
                                const std::string& availableSource, double baselineBytes = 0.0);

}  // namespace sc::mesh
