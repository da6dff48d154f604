// Estimates of mesh size, DOFs and memory before meshing and refining,
// calibrated on the real meshes: each test prints measured against estimated (docs/mesh.md,
// "Resource limits", has the table), and refusals name the key, the estimate and the limit.
#include "MeshTestUtils.hpp"

#include <sc/core/Error.hpp>
#include <sc/mesh/MeshFactory.hpp>
#include <sc/mesh/ResourceEstimate.hpp>

#include <Teuchos_UnitTestHarness.hpp>

#include <chrono>
#include <iomanip>

namespace {

using namespace sc::mesh;
using sc::mesh::test::contains;
using sc::mesh::test::errorOf;

Teuchos::ParameterList scene(const std::string& source, double h)
{
  Teuchos::ParameterList p;
  p.set("Source", source);
  p.set("Initial mesh size", h);
  return p;
}

bool withinFactor2(double measured, double estimated)
{
  return estimated >= 0.5 * measured && estimated <= 2.0 * measured;
}

TEUCHOS_UNIT_TEST(MeshResources, InitialEstimateMatchesGmsh)
{
  struct Case {
    std::string source;
    int dim;
    double h;
  };
  const std::vector<Case> cases = {
      {"Half disc", 2, 0.25},   {"Half disc", 2, 0.1},    {"Half disc", 2, 0.05},
      {"Half disc", 2, 0.02},   {"Unit square", 2, 0.25}, {"Unit square", 2, 0.1},
      {"Unit square", 2, 0.05}, {"Rectangle", 2, 0.1},    {"Half ball", 3, 0.5},
      {"Half ball", 3, 0.25},   {"Half ball", 3, 0.15},   {"Half ball", 3, 0.1},
      {"Unit cube", 3, 0.5},    {"Unit cube", 3, 0.25},   {"Unit cube", 3, 0.15},
      {"Unit cube", 3, 0.1}};
  out << std::setw(12) << "scene" << std::setw(7) << "h" << std::setw(10) << "measured"
      << std::setw(11) << "estimated" << std::setw(7) << "ratio\n";
  for (const auto& c : cases) {
    Teuchos::ParameterList p = scene(c.source, c.h);
    if (c.source == "Rectangle")
      p.set("Upper corner", Teuchos::Array<double>(std::vector<double>{2.0, 0.5}));
    const double estimated = MeshFactory::estimateInitialElements(p, c.dim);
    const double measured = MeshFactory::build(p, c.dim)->mesh()->numElements();
    out << std::setw(12) << c.source << std::setw(7) << c.h << std::setw(10) << measured
        << std::setw(11) << std::lround(estimated) << std::setw(7) << std::setprecision(3)
        << estimated / measured << "\n";
    TEST_ASSERT(withinFactor2(measured, estimated));
  }
  Teuchos::ParameterList g;
  g.set("Source", "Gmsh file");
  TEST_EQUALITY(MeshFactory::estimateInitialElements(g, 2), -1.0);
}

TEUCHOS_UNIT_TEST(MeshResources, RefinementEstimateMatchesTheRefiner)
{
  struct Case {
    std::string source;
    int dim;
    double h;
    int uniform;
    int levels;
    std::vector<double> center;
    double radius;
    std::string boundary;
  };
  const std::vector<Case> cases = {{"Half disc", 2, 0.25, 3, 0, {}, 0.25, ""},
                                   {"Half ball", 3, 0.5, 1, 0, {}, 0.25, ""},
                                   // the Hertz 2D test's local sweeps at (0, 0), and more
                                   {"Half disc", 2, 0.1, 0, 2, {0, 0}, 0.25, ""},
                                   {"Half disc", 2, 0.1, 0, 6, {0, 0}, 0.25, ""},
                                   {"Half disc", 2, 0.1, 0, 10, {0, 0}, 0.25, ""},
                                   {"Half disc", 2, 0.1, 1, 4, {0, 0}, 0.25, ""},
                                   {"Half disc", 2, 0.1, 0, 6, {0, 0}, 0.25, "Arc"},
                                   {"Half disc", 2, 0.1, 0, 12, {0, 0}, 0.25, "Arc"},
                                   // input/hertz3d.xml (9 sweeps along the Cap), and more
                                   {"Half ball", 3, 0.25, 0, 3, {0, 0, 0}, 0.22, "Cap"},
                                   {"Half ball", 3, 0.25, 0, 9, {0, 0, 0}, 0.22, "Cap"},
                                   {"Half ball", 3, 0.25, 0, 12, {0, 0, 0}, 0.22, "Cap"},
                                   {"Half ball", 3, 0.25, 0, 3, {0, 0, 0}, 0.22, ""},
                                   {"Half ball", 3, 0.25, 0, 6, {0, 0, 0}, 0.22, ""}};
  out << std::setw(10) << "scene" << std::setw(6) << "h" << std::setw(4) << "U" << std::setw(4)
      << "L" << std::setw(10) << "boundary" << std::setw(10) << "measured" << std::setw(11)
      << "estimated" << std::setw(7) << "ratio\n";
  for (const auto& c : cases) {
    Teuchos::ParameterList p = scene(c.source, c.h);
    p.set("Uniform refinements", c.uniform);
    auto& local = p.sublist("Local refinement");
    local.set("Levels", c.levels);
    local.set("Center", Teuchos::Array<double>(c.center));
    local.set("Radius", c.radius);
    local.set("Boundary", c.boundary);
    const auto refiner = MeshFactory::build(p, c.dim);
    const double measured = refiner->mesh()->numElements();
    const auto initial = MeshFactory::build(scene(c.source, c.h), c.dim)->mesh();
    const auto e = MeshFactory::estimateRefinement(p, *initial);
    out << std::setw(10) << c.source << std::setw(6) << c.h << std::setw(4) << c.uniform
        << std::setw(4) << c.levels << std::setw(10) << c.boundary << std::setw(10) << measured
        << std::setw(11) << std::lround(e.local) << std::setw(7) << std::setprecision(3)
        << e.local / measured << "\n";
    TEST_ASSERT(withinFactor2(measured, e.local));
    if (c.levels == 0) TEST_EQUALITY(e.local, measured);  // uniform: exactly ×2^d per level
  }
}

TEUCHOS_UNIT_TEST(MeshResources, DofsPerElementMatchTheMeasuredSpaces)
{
  // docs/benchmarks.md, k = 1 on uniformly refined unit square / cube: 744705 DOFs on 45056
  // triangles, 478383 DOFs on 11776 tetrahedra (16.53 and 40.6 per element).
  TEST_FLOATING_EQUALITY(dofsPerElement(2, 1), 744705.0 / 45056.0, 0.02);
  TEST_FLOATING_EQUALITY(dofsPerElement(3, 1), 478383.0 / 11776.0, 0.05);
  // k grows the count like the local spaces: more per element, 2D below 3D.
  for (int k = 1; k < 4; ++k) {
    TEST_ASSERT(dofsPerElement(2, k + 1) > dofsPerElement(2, k));
    TEST_ASSERT(dofsPerElement(3, k + 1) > dofsPerElement(3, k));
  }
  TEST_EQUALITY(bytesPerDof(2), 2.2e3);
  TEST_EQUALITY(bytesPerDof(3), 7.4e3);
}

TEUCHOS_UNIT_TEST(MeshResources, AvailableMemoryAndTheLimitKey)
{
  std::string source;
  const double bytes = availableMemoryBytes(&source);
  out << "available: " << bytes / 1e9 << " GB (" << source << ")\n";
  TEST_ASSERT(bytes > 1e6 && bytes < 1e16);
  TEST_ASSERT(!source.empty());
  const auto deflt = makeResourceLimit(0.0, 2, 1, 1, 0, bytes, source);
  TEST_EQUALITY(deflt.memoryBytes, bytes);
  TEST_ASSERT(contains(deflt.memorySource, source));
  const auto set = makeResourceLimit(2.5, 3, 1, 2, 1000, bytes, source);
  TEST_EQUALITY(set.memoryBytes, 2.5e9);
  TEST_ASSERT(contains(set.memorySource, "Mesh/Memory limit (GB)"));
  TEST_FLOATING_EQUALITY(set.bytes(1000.0),
                         1000.0 * (dofsPerElement(3, 1) * 7.4e3 + 2 * kMeshBytesPerElement), 1e-12);
  TEST_ASSERT(contains(set.describe(1e6), "'Adaptivity/Max DOFs' is 1000"));
}

// 3D contact memory (docs/mesh.md "Resource limits"). Stored reference: the peak resident memory
// (/usr/bin/time -v, MB = 2^20 bytes) of one-cycle runs of input/hertz3d.xml (Coulomb) and
// input/hertz3d_frictionless.xml, 1 rank, k = 1, MUMPS full rank, measured 2026-12-07 and tabulated
// in docs/solvers.md ("Memory and time of 3D contact", "Block low-rank"). The model was fitted on
// the two Coulomb runs; the frictionless run is an independent check, the stopped run at 10⁶ DOFs a
// lower bound. The per-DOF constant of the elasticity benchmarks (7.4 kB) predicted about half of
// every peak.
TEUCHOS_UNIT_TEST(MeshResources, ContactModelMatchesTheMeasuredPeaks)
{
  struct Run {
    double dofs, elements, peakMB;
    const char* what;
  };
  const std::vector<Run> stored = {{254430, 6216, 3489, "Coulomb, mesh size 0.12"},
                                   {505971, 12456, 7999, "Coulomb, mesh size 0.0935"},
                                   {204852, 4993, 2784, "frictionless, mesh size 0.13"}};
  const double baseline = 0.112e9;  // the program before any mesh, 1 rank (docs/mesh.md)
  auto limit = makeResourceLimit(24.0, 3, 1, 1, 0, 0.0, "", baseline);
  limit.contact = true;
  for (const auto& r : stored) {
    const double model = dataBytes(r.dofs, 3, true) + r.elements * kMeshBytesPerElement + baseline;
    const double old = dataBytes(r.dofs, 3, false) + r.elements * kMeshBytesPerElement + baseline;
    const double peak = r.peakMB * 1048576.0;
    out << r.what << ": " << r.dofs << " DOFs, measured " << r.peakMB << " MB, model "
        << model / 1048576.0 << " MB (ratio " << model / peak << "), without the contact model "
        << old / 1048576.0 << " MB (ratio " << old / peak << ")\n";
    TEST_FLOATING_EQUALITY(model, peak, 0.05);
  }
  // The run at 1026492 DOFs (25422 tetrahedra, mesh size 0.0733) was stopped by `ulimit -v` 16 GB
  // in its first factorisation at 15029 MB resident, with MUMPS' analysis asking for 13750 MB:
  // the model must lie above what it reached.
  const double stopped = dataBytes(1026492, 3, true) + 25422 * kMeshBytesPerElement + baseline;
  out << "1026492 DOFs: model " << stopped / 1048576.0 << " MB, stopped at 15029 MB\n";
  TEST_COMPARE(stopped, >, 15029 * 1048576.0);
  // The limit inverts the superlinear model: the largest mesh that fits uses the memory.
  const double n = limit.maxElements();
  out << "24 GB: at most " << n << " tetrahedra, " << limit.dofs(n) << " DOFs\n";
  TEST_FLOATING_EQUALITY(limit.totalBytes(n), 24e9, 1e-6);
  TEST_ASSERT(limit.dofs(n) > 1e6 && limit.dofs(n) < 1.3e6);
  TEST_ASSERT(contains(limit.describe(2e5), "3D contact"));
  // 2D contact and scenes without contact keep the per-DOF constants.
  TEST_EQUALITY(dataBytes(1e5, 2, true), 1e5 * kBytesPerDof2D);
  TEST_EQUALITY(dataBytes(1e5, 3, false), 1e5 * kBytesPerDof3D);
}

// 3D contact under Linear Solver/Type = Auto (docs/mesh.md "Resource limits", docs/solvers.md
// "Type = Auto"): from the DOFs where Auto takes the stress multigrid the linear multigrid model
// replaces MUMPS' superlinear one, so a mesh that MUMPS could not factorise in the limit is not
// refused when the multigrid will solve it, while a smaller one that MUMPS would factorise still
// is when MUMPS' model exceeds the limit.
TEUCHOS_UNIT_TEST(MeshResources, AutoMultigridContactUsesTheMultigridModel)
{
  auto limit = makeResourceLimit(24.0, 3, 1, 2, 0, 0.0, "", 0.2e9);
  limit.contact = true;
  const double perElement = dofsPerElement(3, 1);
  const double big = 2.2e6 / perElement;  // the 2·10⁶ DOF cycle
  TEST_ASSERT(!limit.fits(big));          // MUMPS' LU: ~43 GB
  limit.multigridFromDofs = 1e6;
  TEST_FLOATING_EQUALITY(dataBytes(2.2e6, 3, true, 1e6), 2.2e6 * kContactMultigridBytesPerDof3D,
                         1e-14);
  TEST_EQUALITY(dataBytes(0.9e6, 3, true, 1e6), dataBytes(0.9e6, 3, true));
  TEST_EQUALITY(dataBytes(2.2e6, 3, false, 1e6), dataBytes(2.2e6, 3, false));  // contact only
  TEST_EQUALITY(dataBytes(2.2e6, 2, true, 1e6), dataBytes(2.2e6, 2, true));    // 3D only
  TEST_ASSERT(limit.fits(big));
  TEST_ASSERT(contains(limit.describe(big), "stress multigrid"));
  TEST_ASSERT(contains(limit.describe(0.5e6 / perElement), "MUMPS' LU factors of 3D contact"));
  // The largest mesh that fits is in the multigrid's range, inverted linearly.
  const double n = limit.maxElements();
  out << "24 GB, multigrid from 1e6 DOFs: at most " << limit.dofs(n) << " DOFs\n";
  TEST_FLOATING_EQUALITY(limit.totalBytes(n), 24e9, 1e-9);
  TEST_ASSERT(limit.dofs(n) > 2.5e6);
  // 16 GB: MUMPS' model refuses 0.95·10⁶ DOFs (about 18 GB), the multigrid takes 1.5·10⁶.
  auto small = makeResourceLimit(16.0, 3, 1, 2, 0, 0.0, "", 0.2e9);
  small.contact = true;
  small.multigridFromDofs = 1e6;
  TEST_ASSERT(!small.fits(0.95e6 / perElement));
  TEST_ASSERT(small.fits(1.5e6 / perElement));
  TEST_ASSERT(small.fits(small.maxElements()));
  // Coulomb friction: the flexible GMRES basis, 2 (Restart + 1) vectors, counts too. At the
  // default Restart = 300 it is 4.8 kB per DOF and a 2.2·10⁶ DOF cycle no longer fits 24 GB.
  limit.multigridBytesPerDof = kContactMultigridBytesPerDof3D + 8.0 * 2 * 301;
  TEST_FLOATING_EQUALITY(dataBytes(2.2e6, 3, true, 1e6, limit.multigridBytesPerDof),
                         2.2e6 * (kContactMultigridBytesPerDof3D + 4816.0), 1e-14);
  TEST_ASSERT(!limit.fits(big));
  TEST_FLOATING_EQUALITY(limit.totalBytes(limit.maxElements()), 24e9, 1e-9);
  // Stored reference (docs/solvers.md "3D contact at 2·10⁶ DOFs"): the peaks, summed over 2
  // ranks, of input/hertz3d.xml on the 0.255 mesh's uniform cycles with the multigrid, 2026-12-07:
  // 256 125 DOFs (6 264 tetrahedra) with Restart = 300, 3 540.7 MB (/usr/bin/time -v); 2 014 035
  // DOFs (50 112 tetrahedra) with Restart = 80, 20 003 MB in the first Newton step (VmRSS every 5
  // s; the second step's rebuild, two multigrids held at once, passed 21 815 MB and was stopped).
  // The model, with the program's own 0.22 GB, within 5%.
  struct Peak {
    double dofs, elements, restart, mb;
  };
  for (const Peak& p : {Peak{256125, 6264, 300, 3540.7}, Peak{2014035, 50112, 80, 20003.0}}) {
    auto run = makeResourceLimit(24.0, 3, 1, 2, 0, 0.0, "", 0.22e9);
    run.contact = true;
    run.multigridFromDofs = 1e5;
    run.multigridBytesPerDof = kContactMultigridBytesPerDof3D + 8.0 * 2 * (p.restart + 1);
    const double model = run.totalBytes(p.elements), peak = p.mb * 1048576.0;
    out << p.dofs << " DOFs, Restart " << p.restart << ": model " << model / 1048576.0
        << " MB, measured " << p.mb << " MB\n";
    TEST_FLOATING_EQUALITY(run.dofs(p.elements) / p.dofs, 1.0, 0.05);
    TEST_FLOATING_EQUALITY(model, peak, 0.05);
  }
  // A threshold above what fits: MUMPS' range only, bisected.
  small.multigridFromDofs = 5e6;
  TEST_FLOATING_EQUALITY(small.totalBytes(small.maxElements()), 16e9, 1e-6);
  TEST_ASSERT(small.dofs(small.maxElements()) < 1e6);
}

// An explicit limit counts the program's own memory before the mesh (docs/mesh.md "Resource
// limits"): a limit at or below it is refused naming the key, the baseline and a valid value; above
// it, the mesh may use what is left. The default limit (the available memory, measured with the
// program resident) does not count it again.
TEUCHOS_UNIT_TEST(MeshResources, LimitCountsTheProgramsOwnMemory)
{
  const double resident = residentMemoryBytes();
  out << "resident: " << resident / 1e9 << " GB\n";
  TEST_ASSERT(resident > 1e6 && resident < 1e12);
  const std::string msg = errorOf([] { makeResourceLimit(0.05, 2, 1, 2, 0, 8e9, "x", 0.11e9); });
  out << msg << "\n";
  TEST_ASSERT(contains(msg, "'Mesh/Memory limit (GB)' = 0.05 is below the memory the program holds "
                            "before any mesh is made: 0.11 GB (VmRSS of /proc/self/status, summed "
                            "over the 2 ranks"));
  TEST_ASSERT(contains(msg, "Give more than 0.11 GB, e.g. 0.7 (about 0.59 GB for the run's data)"));
  TEST_ASSERT(contains(errorOf([] { makeResourceLimit(0.11, 2, 1, 2, 0, 8e9, "x", 0.11e9); }),
                       "is below the memory the program holds"));
  const auto set = makeResourceLimit(0.3, 2, 1, 2, 0, 8e9, "x", 0.1e9);
  TEST_EQUALITY(set.memoryBytes, 0.3e9);
  TEST_EQUALITY(set.baselineBytes, 0.1e9);
  TEST_FLOATING_EQUALITY(set.maxElements(), 0.2e9 / set.bytes(1.0), 1e-14);
  TEST_FLOATING_EQUALITY(set.totalBytes(1000.0), set.bytes(1000.0) + 0.1e9, 1e-14);
  TEST_EQUALITY(set.source(), "'Mesh/Memory limit (GB)', of which the program held 0.1 GB before "
                              "the mesh (VmRSS, 2 ranks)");
  const auto deflt = makeResourceLimit(0.0, 2, 1, 2, 0, 8e9, "MemAvailable", 0.1e9);
  TEST_EQUALITY(deflt.baselineBytes, 0.0);
  TEST_FLOATING_EQUALITY(deflt.maxElements(), 8e9 / deflt.bytes(1.0), 1e-14);
}

// Without the estimates these hung in Gmsh or died in std::bad_alloc (docs/mesh.md "Resource
// limits").
TEUCHOS_UNIT_TEST(MeshResources, TooLargeMeshesAreRefusedBeforeTheyAreMade)
{
  const auto limit = makeResourceLimit(1.0, 2, 1, 1, 2000000, 0.0, "");
  const auto start = std::chrono::steady_clock::now();
  {
    const std::string msg =
        errorOf([&] { MeshFactory::build(scene("Half disc", 1e-6), 2, false, limit); });
    out << msg << "\n";
    TEST_ASSERT(contains(msg, "'Mesh/Initial mesh size' = 1e-06 is too small"));
    TEST_ASSERT(contains(msg, "triangles") && contains(msg, "DOFs") && contains(msg, "GB"));
    TEST_ASSERT(contains(msg, "memory limit of 1 GB"));
    TEST_ASSERT(contains(msg, "'Adaptivity/Max DOFs' is 2000000"));
  }
  {
    const auto l3 = makeResourceLimit(1.0, 3, 1, 1, 0, 0.0, "");
    const std::string msg =
        errorOf([&] { MeshFactory::build(scene("Half ball", 1e-3), 3, false, l3); });
    TEST_ASSERT(contains(msg, "'Mesh/Initial mesh size' = 0.001 is too small") &&
                contains(msg, "tetrahedra"));
  }
  {
    Teuchos::ParameterList p = scene("Half disc", 0.25);
    p.set("Uniform refinements", 20);
    const std::string msg = errorOf([&] { MeshFactory::build(p, 2, false, limit); });
    out << msg << "\n";
    TEST_ASSERT(contains(msg, "'Mesh/Uniform refinements' = 20 is too many"));
    TEST_ASSERT(contains(msg, "uniform levels fit"));
  }
  {
    Teuchos::ParameterList p = scene("Half disc", 0.1);
    p.sublist("Local refinement").set("Levels", 40);
    p.sublist("Local refinement")
        .set("Center", Teuchos::Array<double>(std::vector<double>{0.0, 0.0}));
    const std::string msg = errorOf([&] { MeshFactory::build(p, 2, false, limit); });
    out << msg << "\n";
    TEST_ASSERT(contains(msg, "'Mesh/Local refinement/Levels' = 40 is too many"));
    TEST_ASSERT(contains(msg, "sweeps fit"));
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  TEST_ASSERT(seconds < 10.0);
  // Within the limit nothing changes.
  Teuchos::ParameterList ok = scene("Half disc", 0.1);
  ok.set("Uniform refinements", 1);
  TEST_EQUALITY(MeshFactory::build(ok, 2, false, limit)->mesh()->numElements(), 4 * 390);
}

TEUCHOS_UNIT_TEST(MeshResources, LocalSweepsAreCheckedWithTheRealCounts)
{
  // refineLocally() checks each sweep again: a limit of about 2000 triangles stops the sweeps
  // at (0, 0) of the half disc at h = 0.1 (390 triangles) before they pass it.
  auto refiner = MeshFactory::build(scene("Half disc", 0.1), 2);
  auto limit = makeResourceLimit(1.0, 2, 1, 1, 0, 0.0, "");
  limit.memoryBytes = limit.bytes(2000.0);
  Teuchos::ParameterList local;
  local.set("Levels", 20);
  local.set("Center", Teuchos::Array<double>(std::vector<double>{0.0, 0.0}));
  const std::string msg = errorOf([&] { MeshFactory::refineLocally(*refiner, local, limit); });
  out << msg << "\n";
  TEST_ASSERT(contains(msg, "'Mesh/Local refinement/Levels' = 20 is too many: sweep"));
  TEST_ASSERT(refiner->mesh()->numElements() <= 2000);
}

}  // namespace
