// MeshFactory: the Mesh sublist (keys, defaults, errors) and the scenes it builds. Reference
// values are analytic (areas/volumes and side lengths of the boxes).
#include "MeshTestUtils.hpp"

#include <sc/core/Error.hpp>
#include <sc/core/Parameters.hpp>
#include <sc/mesh/MeshFactory.hpp>

#include <Teuchos_UnitTestHarness.hpp>

namespace {

using namespace sc::mesh;
using sc::mesh::test::contains;
using sc::mesh::test::errorOf;

TEUCHOS_UNIT_TEST(MeshFactory, ValidParametersHaveDefaultsAndDocs)
{
  auto valid = MeshFactory::getValidParameters();
  for (const std::string key :
       {"Source", "Initial mesh size", "Uniform refinements", "Project boundary", "Radius", "File",
        "Lower corner", "Upper corner", "Memory limit (GB)", "Geometry order"}) {
    TEST_ASSERT(valid->isParameter(key));
    if (valid->isParameter(key)) TEST_ASSERT(!valid->getEntry(key).docString().empty());
  }
  TEST_ASSERT(valid->isSublist("Local refinement"));
  TEST_EQUALITY(valid->numParams(), 11);
  TEST_EQUALITY(valid->get<std::string>("Source"), std::string("Half disc"));
  TEST_EQUALITY(valid->get<bool>("Project boundary"), true);
}

// Mesh/Geometry order = 2 with Project boundary = false contradicts itself: an input error
// naming both keys.
TEUCHOS_UNIT_TEST(MeshFactory, CurvedGeometryNeedsProjection)
{
  Teuchos::ParameterList pl;
  pl.set("Source", "Half disc");
  pl.set("Geometry order", 2);
  pl.set("Project boundary", false);
  const std::string e = errorOf([&] { MeshFactory::build(pl, 2); });
  TEST_ASSERT(e.find("'Mesh/Geometry order' = 2") != std::string::npos);
  TEST_ASSERT(e.find("'Mesh/Project boundary' = false") != std::string::npos);
}

TEUCHOS_UNIT_TEST(MeshFactory, UnknownSourceListsTheChoices)
{
  Teuchos::ParameterList p;
  p.set("Source", "Half disk");
  const std::string msg = errorOf([&] { MeshFactory::build(p, 2); });
  out << msg << "\n";
  for (const auto& s : MeshFactory::sources())
    TEST_ASSERT(contains(msg, s));
  TEST_ASSERT(contains(msg, "Mesh/Source"));
}

TEUCHOS_UNIT_TEST(MeshFactory, NonPositiveMeshSizeNamesTheKey)
{
  for (double h : {0.0, -1.0}) {
    Teuchos::ParameterList p;
    p.set("Initial mesh size", h);
    const std::string msg = errorOf([&] { MeshFactory::build(p, 2); });
    out << msg << "\n";
    TEST_ASSERT(contains(msg, "Mesh/Initial mesh size"));
  }
  Teuchos::ParameterList p;
  p.set("Uniform refinements", -1);
  TEST_ASSERT(contains(errorOf([&] { MeshFactory::build(p, 2); }), "Mesh/Uniform refinements"));
}

TEUCHOS_UNIT_TEST(MeshFactory, SceneAndDimensionMustAgree)
{
  Teuchos::ParameterList p;
  p.set("Source", "Half ball");
  const std::string msg = errorOf([&] { MeshFactory::build(p, 2); });
  out << msg << "\n";
  TEST_ASSERT(contains(msg, "Half ball") && contains(msg, "Problem/Dimension = 2"));
  p.set("Source", "Gmsh file");
  TEST_ASSERT(contains(errorOf([&] { MeshFactory::build(p, 2); }), "Mesh/File"));
}

TEUCHOS_UNIT_TEST(MeshFactory, BoxScenes)
{
  Teuchos::ParameterList p;
  p.set("Source", "Unit square");
  p.set("Initial mesh size", 0.25);
  p.set("Uniform refinements", 1);
  auto sq = MeshFactory::build(p, 2)->mesh();
  TEST_ASSERT(sq->boundaryNames() == std::vector<std::string>({"Left", "Right", "Bottom", "Top"}));
  TEST_FLOATING_EQUALITY(sq->measure(), 1.0, 1e-13);
  for (const auto& n : sq->boundaryNames())
    TEST_FLOATING_EQUALITY(sq->boundaryMeasure(n), 1.0, 1e-13);

  p.set("Source", "Rectangle");
  p.set("Lower corner", Teuchos::Array<double>(std::vector<double>{-1.0, 0.0}));
  p.set("Upper corner", Teuchos::Array<double>(std::vector<double>{2.0, 0.5}));
  auto re = MeshFactory::build(p, 2)->mesh();
  TEST_FLOATING_EQUALITY(re->measure(), 1.5, 1e-13);
  TEST_FLOATING_EQUALITY(re->boundaryMeasure("Bottom"), 3.0, 1e-13);
  TEST_FLOATING_EQUALITY(re->boundaryMeasure("Left"), 0.5, 1e-13);

  Teuchos::ParameterList c;
  c.set("Source", "Unit cube");
  c.set("Initial mesh size", 0.5);
  auto cube = MeshFactory::build(c, 3)->mesh();
  TEST_ASSERT(cube->boundaryNames() ==
              std::vector<std::string>({"Left", "Right", "Front", "Back", "Bottom", "Top"}));
  TEST_FLOATING_EQUALITY(cube->measure(), 1.0, 1e-13);
  for (const auto& n : cube->boundaryNames())
    TEST_FLOATING_EQUALITY(cube->boundaryMeasure(n), 1.0, 1e-13);
  // Front is y = 0: its outward normal is -e_y.
  const int f = cube->boundaryFacesOf("Front").front();
  TEST_FLOATING_EQUALITY(cube->faceNormal(f)[1], -1.0, 1e-13);
}

// Radius: the half disc of radius 0.5 has area π/8 (analytic); projection keeps every Arc vertex on
// the circle around (0, 1).
TEUCHOS_UNIT_TEST(MeshFactory, HalfDiscRadius)
{
  Teuchos::ParameterList p;
  p.set("Radius", 0.5);
  p.set("Initial mesh size", 0.1);
  p.set("Uniform refinements", 2);
  auto m = MeshFactory::build(p, 2)->mesh();
  TEST_FLOATING_EQUALITY(m->measure(), M_PI / 8, 1e-3);
  TEST_FLOATING_EQUALITY(m->boundaryMeasure("Top"), 1.0, 1e-13);
  for (int f : m->boundaryFacesOf("Arc"))
    for (int i = 0; i < 2; ++i) {
      const double* x = m->vertex(m->faceVertices(f)[i]);
      TEST_FLOATING_EQUALITY(std::hypot(x[0], x[1] - 1), 0.5, 1e-13);
    }
}

// Local refinement: generations count the bisections since the initial mesh (each halves the
// element's measure), so the expected numbers are exact counts, not tolerances.
namespace {
double centroidDistance(const SimplexMesh& m, const int* v, int n, double cx, double cy)
{
  double x = 0, y = 0;
  for (int i = 0; i < n; ++i) {
    x += m.vertex(v[i])[0] / n;
    y += m.vertex(v[i])[1] / n;
  }
  return std::hypot(x - cx, y - cy);
}

// Half disc, Gmsh 0.1, 4 sweeps within 0.2 of the bottom point (0, 0), optionally along one part.
Teuchos::RCP<BisectionRefiner> locallyRefinedHalfDisc(const std::string& boundary)
{
  Teuchos::ParameterList p;
  p.set("Initial mesh size", 0.1);
  auto& local = p.sublist("Local refinement");
  local.set("Levels", 4);
  local.set("Center", Teuchos::Array<double>(2, 0.0));
  local.set("Radius", 0.2);
  local.set("Boundary", boundary);
  return MeshFactory::build(p, 2);
}
}  // namespace

TEUCHOS_UNIT_TEST(MeshFactory, LocalRefinementAroundAPoint)
{
  auto refiner = locallyRefinedHalfDisc("");
  const auto m = refiner->mesh();
  int near = 0, far = 0;
  for (int e = 0; e < m->numElements(); ++e) {
    const double r = centroidDistance(*m, m->elementVertices(e), 3, 0.0, 0.0);
    if (r < 0.05) {  // inside the region at every sweep: bisected by each one
      TEST_COMPARE(refiner->generation(e), >=, 4);
      ++near;
    } else if (r > 0.6) {  // far outside: the closure does not reach it
      TEST_EQUALITY(refiner->generation(e), 0);
      ++far;
    }
  }
  TEST_COMPARE(near, >, 0);
  TEST_COMPARE(far, >, 0);
}

TEUCHOS_UNIT_TEST(MeshFactory, LocalRefinementAlongABoundary)
{
  auto refiner = locallyRefinedHalfDisc("Arc");
  const auto m = refiner->mesh();
  int onArc = 0, maxInterior = 0;
  for (int f : m->boundaryFacesOf("Arc"))
    if (centroidDistance(*m, m->faceVertices(f), 2, 0.0, 0.0) < 0.1) {
      TEST_COMPARE(refiner->generation(m->faceElements(f)[0]), >=, 4);
      ++onArc;
    }
  // Elements away from the arc (the point (0, 0.17) is 0.17 inside) are refined less.
  for (int e = 0; e < m->numElements(); ++e)
    if (centroidDistance(*m, m->elementVertices(e), 3, 0.0, 0.17) < 0.03)
      maxInterior = std::max(maxInterior, refiner->generation(e));
  TEST_COMPARE(onArc, >, 0);
  TEST_COMPARE(maxInterior, <, 4);
}

TEUCHOS_UNIT_TEST(MeshFactory, LocalRefinementErrorsNameTheKey)
{
  Teuchos::ParameterList p;
  p.set("Initial mesh size", 0.2);
  p.sublist("Local refinement").set("Levels", 2);
  // No Center: named, with the number of values needed.
  auto msg = errorOf([&] { MeshFactory::build(p, 2); });
  TEST_ASSERT(contains(msg, "Local refinement/Center"));
  TEST_ASSERT(contains(msg, "2 values"));
  p.sublist("Local refinement").set("Center", Teuchos::Array<double>(2, 0.0));
  p.sublist("Local refinement").set("Boundary", std::string("Rim"));
  msg = errorOf([&] { MeshFactory::build(p, 2); });
  TEST_ASSERT(contains(msg, "Rim"));
  TEST_ASSERT(contains(msg, "Arc"));  // the valid part names
}

TEUCHOS_UNIT_TEST(MeshFactory, GmshFileSource)
{
  Teuchos::ParameterList p;
  p.set("Source", "Gmsh file");
  p.set("File", std::string(SC_MESH_TEST_DATA) + "/half_disc_h0.25_v41.msh");
  auto r = MeshFactory::build(p, 2);
  // The file's own boundary (docs/mesh.md "Curved boundaries from files"): a linear file, so no
  // part is curved and its arc stays the polygon (with a warning).
  TEST_ASSERT(!r->geometry().is_null());
  TEST_ASSERT(r->geometry()->curvedBoundaryNames().empty());
  TEST_ASSERT(!r->geometry()->warning().empty());
  TEST_ASSERT(r->mesh()->hasBoundary("Arc"));
  TEST_COMPARE(std::abs(r->mesh()->measure() - M_PI / 2), <, 0.02);
}

}  // namespace
