// Curved boundaries of a user's geometry (docs/mesh.md "Curved boundaries from files"): a
// quadratic .msh file keeps its quadratic surface under refinement, a Gmsh geometry (.geo) its
// CAD entities, and a linear file its polygon, with a warning. Sources of the expected numbers:
// the exact circle/sphere of the Hertz scenes, and the interpolation error of a quadratic curve
// through three points of a circle of radius R at arc angle θ: max |r − R| ≈ R θ⁴/512 (computed
// for θ = 0.5, 0.25, 0.125: 0.00193, 0.00195, 0.00195 × θ⁴).
#include "MeshTestUtils.hpp"

#include <sc/core/Error.hpp>
#include <sc/mesh/CadGeometry.hpp>
#include <sc/mesh/CurvedElements.hpp>
#include <sc/mesh/GmshMeshIO.hpp>
#include <sc/mesh/HalfBallGeometry.hpp>
#include <sc/mesh/HalfDiscGeometry.hpp>
#include <sc/mesh/MeshBoundaryGeometry.hpp>
#include <sc/mesh/MeshFactory.hpp>

#include <Teuchos_UnitTestHarness.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>

namespace {

using namespace sc::mesh;
using sc::mesh::test::contains;

const std::string inputDir = SC_INPUT_DIR;

// Largest | |x − c| − R | over the vertices of the faces on `part`, and the largest arc angle of
// those faces (2 asin(chord / 2R)).
struct CircleFit {
  double radialError = 0.0, maxAngle = 0.0;
};
CircleFit circleFit(const SimplexMesh& m, const std::string& part, const std::array<double, 3>& c,
                    double R)
{
  CircleFit fit;
  const int id = m.boundaryId(part);
  for (int f : m.boundaryFaces()) {
    if (m.faceBoundaryId(f) != id) continue;
    const int* v = m.faceVertices(f);
    for (int i = 0; i < m.dim(); ++i) {
      const double* x = m.vertex(v[i]);
      double r2 = 0;
      for (int k = 0; k < m.dim(); ++k)
        r2 += (x[k] - c[k]) * (x[k] - c[k]);
      fit.radialError = std::max(fit.radialError, std::abs(std::sqrt(r2) - R));
      for (int j = i + 1; j < m.dim(); ++j) {
        const double* y = m.vertex(v[j]);
        double l2 = 0;
        for (int k = 0; k < m.dim(); ++k)
          l2 += (x[k] - y[k]) * (x[k] - y[k]);
        fit.maxAngle = std::max(fit.maxAngle, 2 * std::asin(std::sqrt(l2) / (2 * R)));
      }
    }
  }
  return fit;
}

Teuchos::ParameterList meshList(const std::string& source, const std::string& file, double h = 0.25)
{
  Teuchos::ParameterList p;
  p.set("Source", source);
  p.set("File", file);
  p.set("Initial mesh size", h);
  return p;
}

// A second-order .msh of the half disc: its 3-node arc faces carry the circle; refinement puts
// new vertices on the quadratic arcs (within θ⁴/512 of the circle), not on the chords, and the
// area converges to the disc's; the same file read linearly would keep the polygon's area.
TEUCHOS_UNIT_TEST(CurvedBoundary, QuadraticFileRefinesOntoItsQuadraticArcs)
{
  const std::string file = std::filesystem::absolute("half_disc_order2.msh").string();
  GmshMeshIO::writeGeometryMesh(HalfDiscGeometry(1.0), 0.25, file, 4.1, 2);
  const auto read = GmshMeshIO::readMeshFile(file, 2);
  TEST_ASSERT(read.boundary->quadratic());
  TEST_ASSERT(read.boundary->isCurved("Arc"));
  TEST_ASSERT(!read.boundary->isCurved("Top"));
  TEST_ASSERT(read.boundary->warning().empty());
  const double theta0 = circleFit(*read.mesh, "Arc", {0, 1, 0}, 1.0).maxAngle;
  auto refiner = MeshFactory::build(meshList("Gmsh file", file), 2);
  double area0 = refiner->mesh()->measure();
  for (int level = 0; level < 4; ++level)
    refiner->refineUniformly();
  const auto fit = circleFit(*refiner->mesh(), "Arc", {0, 1, 0}, 1.0);
  out << "initial arc angle " << theta0 << ", radial error after 4 levels " << fit.radialError
      << " (bound θ⁴/500 = " << std::pow(theta0, 4) / 500 << ")\n";
  TEST_COMPARE(fit.radialError, <=, std::pow(theta0, 4) / 500);
  TEST_COMPARE(fit.radialError, >, 0.0);  // the quadratic arcs, not the circle itself
  // Area: the polygon of the refined mesh converges to the disc (error ~ θ²/12 per segment
  // area shrinking by 4 per level) instead of staying at the initial polygon's.
  const double exact = M_PI / 2;
  out << "area: initial " << area0 << ", refined " << refiner->mesh()->measure() << ", exact "
      << exact << "\n";
  TEST_COMPARE(std::abs(refiner->mesh()->measure() - exact), <, 0.02 * std::abs(area0 - exact));
  // Curved elements take their midpoints from the same arcs.
  CurvedElements curved(refiner->mesh(), *refiner->geometry());
  TEST_ASSERT(curved.numCurvedElements() > 0);
  double worst = 0;
  for (int e = 0; e < refiner->mesh()->numEdges(); ++e)
    if (curved.isCurvedEdge(e)) {
      const double* x = curved.edgeMidpoint(e);
      worst = std::max(worst, std::abs(std::hypot(x[0], x[1] - 1) - 1));
    }
  TEST_COMPARE(worst, <=, std::pow(theta0, 4) / 500);
}

// 3D: a second-order .msh of the half ball (10-node tetrahedra, 6-node triangle faces on the
// sphere): new vertices on the cap lie on the quadratic patches, far closer to the sphere than the
// chords' midpoints (θ²/8 for an edge of arc angle θ); the patches' own distance from the sphere
// is of order θ⁴ (bounded here by θ⁴/100, measured below).
TEUCHOS_UNIT_TEST(CurvedBoundary, QuadraticTetrahedraFileRefinesOntoItsPatches)
{
  const std::string file = std::filesystem::absolute("half_ball_order2.msh").string();
  GmshMeshIO::writeGeometryMesh(HalfBallGeometry(1.0), 0.5, file, 4.1, 2);
  const auto read = GmshMeshIO::readMeshFile(file, 3);
  TEST_ASSERT(read.boundary->quadratic());
  TEST_ASSERT(read.boundary->isCurved("Cap"));
  // The flat top is not curved, though its rim edges are (within its plane): the rim's new
  // vertices are placed on the cap's patches.
  TEST_ASSERT(!read.boundary->isCurved("Top"));
  const double theta0 = circleFit(*read.mesh, "Cap", {0, 0, 1}, 1.0).maxAngle;
  auto refiner = MeshFactory::build(meshList("Gmsh file", file), 3);
  refiner->refineUniformly();
  const auto fit = circleFit(*refiner->mesh(), "Cap", {0, 0, 1}, 1.0);
  out << "initial edge angle " << theta0 << ", radial error after 1 level " << fit.radialError
      << " (chord midpoints: θ²/8 = " << theta0 * theta0 / 8
      << ", bound θ⁴/100 = " << std::pow(theta0, 4) / 100 << ")\n";
  TEST_COMPARE(fit.radialError, <=, std::pow(theta0, 4) / 100);
  TEST_COMPARE(fit.radialError, <, 0.1 * theta0 * theta0 / 8);
}

// The stored linear file of the half disc: the arc is a polygon of n chords, neighbouring chords
// meet at 180/n degrees; the geometry says so (warning) and keeps the polygon.
TEUCHOS_UNIT_TEST(CurvedBoundary, LinearFileWarnsThatItsBodyIsThePolygon)
{
  const auto read =
      GmshMeshIO::readMeshFile(std::string(SC_MESH_TEST_DATA) + "/half_disc_h0.25_v41.msh", 2);
  TEST_ASSERT(!read.boundary->quadratic());
  TEST_ASSERT(!read.boundary->isCurved("Arc"));
  int n = 0;
  for (int f : read.mesh->boundaryFaces())
    n += read.mesh->faceBoundaryId(f) == read.mesh->boundaryId("Arc");
  const double kink = read.boundary->maxKinkAngleDegrees(read.mesh->boundaryId("Arc"));
  out << n << " chords on the arc, largest kink " << kink << " degrees (uniform: " << 180.0 / n
      << ")\n";
  TEST_FLOATING_EQUALITY(kink, 180.0 / n, 1e-3);  // Gmsh divides the arc uniformly
  TEST_EQUALITY(read.boundary->maxKinkAngleDegrees(read.mesh->boundaryId("Top")), 0.0);
  out << read.boundary->warning() << "\n";
  TEST_ASSERT(
      contains(read.boundary->warning(), "is a linear mesh whose boundary part 'Arc' is not flat"));
  TEST_ASSERT(contains(read.boundary->warning(), "the body is the polygon of the file"));
}

// A user's .geo (built-in kernel circle): new vertices on the arc lie on the exact circle, and so
// do the curved elements' midpoints (Gmsh's closest point, to rounding).
TEUCHOS_UNIT_TEST(CurvedBoundary, GmshGeometryPlacesNewVerticesOnTheCircle)
{
  auto refiner =
      MeshFactory::build(meshList("Gmsh geometry", inputDir + "/geometry/hertz_half_disc.geo"), 2);
  TEST_ASSERT(refiner->mesh()->boundaryNames() == std::vector<std::string>({"Arc", "Top"}));
  TEST_ASSERT(refiner->geometry()->isCurved("Arc"));
  TEST_ASSERT(!refiner->geometry()->isCurved("Top"));
  for (int level = 0; level < 3; ++level)
    refiner->refineUniformly();
  const auto fit = circleFit(*refiner->mesh(), "Arc", {0, 1, 0}, 1.0);
  out << "radial error after 3 levels: " << fit.radialError << "\n";
  TEST_COMPARE(fit.radialError, <, 1e-12);
  CurvedElements curved(refiner->mesh(), *refiner->geometry());
  double worst = 0;
  for (int e = 0; e < refiner->mesh()->numEdges(); ++e)
    if (curved.isCurvedEdge(e)) {
      const double* x = curved.edgeMidpoint(e);
      worst = std::max(worst, std::abs(std::hypot(x[0], x[1] - 1) - 1));
    }
  TEST_COMPARE(worst, <, 1e-12);
  TEST_FLOATING_EQUALITY(refiner->mesh()->boundaryMeasure("Top"), 2.0, 1e-12);
}

// 3D: the OpenCASCADE half ball; new vertices on the cap lie on the unit sphere.
TEUCHOS_UNIT_TEST(CurvedBoundary, GmshGeometryPlacesNewVerticesOnTheSphere)
{
  auto refiner = MeshFactory::build(
      meshList("Gmsh geometry", inputDir + "/geometry/hertz_half_ball.geo", 0.5), 3);
  TEST_ASSERT(refiner->geometry()->isCurved("Cap"));
  TEST_ASSERT(!refiner->geometry()->isCurved("Top"));
  refiner->refineUniformly();
  const auto fit = circleFit(*refiner->mesh(), "Cap", {0, 0, 1}, 1.0);
  out << "radial error after 1 level: " << fit.radialError << "\n";
  TEST_COMPARE(fit.radialError, <, 1e-10);
}

// Bad geometry input: errors name the file and what is wrong.
TEUCHOS_UNIT_TEST(CurvedBoundary, BadGeometriesNameTheFile)
{
  auto error = [&](const std::string& text, int dim) {
    const std::string file = std::filesystem::absolute("bad_geometry.geo").string();
    std::ofstream(file) << text;
    return sc::mesh::test::errorOf([&] { CadGeometry g(file, dim); });
  };
  const std::string syntax = error("Point(1) = {0, 0, 0;\n", 2);
  out << syntax << "\n";
  TEST_ASSERT(contains(syntax, "bad_geometry.geo' (Mesh/File) cannot be run by Gmsh"));
  const std::string noGroups = error("Point(1) = {0,0,0}; Point(2) = {1,0,0}; Point(3) = {0,1,0};\n"
                                     "Line(1) = {1,2}; Line(2) = {2,3}; Line(3) = {3,1};\n"
                                     "Curve Loop(1) = {1,2,3}; Plane Surface(1) = {1};\n",
                                     2);
  out << noGroups << "\n";
  TEST_ASSERT(contains(noGroups, "has no physical group of dimension 1 (Physical Curve)"));
  const std::string wrongDim = error("Point(1) = {0,0,0}; Point(2) = {1,0,0}; Point(3) = {0,1,0};\n"
                                     "Line(1) = {1,2}; Line(2) = {2,3}; Line(3) = {3,1};\n"
                                     "Curve Loop(1) = {1,2,3}; Plane Surface(1) = {1};\n"
                                     "Physical Curve(\"Edge\") = {1};\n",
                                     3);
  TEST_ASSERT(contains(wrongDim, "defines a model of dimension 2 but Problem/Dimension = 3"));
  const std::string missing = sc::mesh::test::errorOf([] { CadGeometry g("no/such.geo", 2); });
  TEST_ASSERT(contains(missing, "no/such.geo' (Mesh/File) cannot be opened"));
}

// A quadratic face whose midpoint node lies outside the middle half of its chord folds.
TEUCHOS_UNIT_TEST(CurvedBoundary, FoldedQuadraticFaceIsAnInputError)
{
  const std::string text =
      "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$PhysicalNames\n1\n1 1 \"Bottom\"\n$EndPhysicalNames\n"
      "$Nodes\n6\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0.9 -0.1 0\n5 0.5 0.5 0\n6 0 0.5 0\n$EndNodes\n"
      "$Elements\n2\n1 9 2 0 1 1 2 3 4 5 6\n2 8 2 1 1 1 2 4\n$EndElements\n";
  const std::string file = std::filesystem::absolute("folded.msh").string();
  std::ofstream(file) << text;
  const std::string e = sc::mesh::test::errorOf([&] { GmshMeshIO::readMeshFile(file, 2); });
  out << e << "\n";
  TEST_ASSERT(contains(e, "folded.msh"));
  TEST_ASSERT(contains(e, "the boundary face of physical group 'Bottom' with nodes 1, 2, 4 folds"));
}

}  // namespace
