// Transfers with the refinement history. References: a linear function is reproduced exactly by
// midpoint interpolation (analytic), element-wise constants keep their integral when refinement
// does not move the boundary (straight boundaries), and parent boundary faces contain their
// children (checked by part id and, with straight boundaries, by measure).
#include "MeshTestUtils.hpp"

#include <sc/mesh/BisectionRefiner.hpp>
#include <sc/mesh/GmshMeshIO.hpp>
#include <sc/mesh/HalfBallGeometry.hpp>
#include <sc/mesh/HalfDiscGeometry.hpp>
#include <sc/mesh/RefinementTransfer.hpp>

#include <Teuchos_UnitTestHarness.hpp>

namespace {

using namespace sc::mesh;

double linear(const double* x, int d)
{
  return 1.0 + 2.0 * x[0] - 3.0 * x[1] + (d == 3 ? 0.5 * x[2] : 0.0);
}

void checkTransfers(Teuchos::RCP<const Geometry> g, double h, bool project,
                    Teuchos::FancyOStream& out, bool& success)
{
  BisectionRefiner r(GmshMeshIO::meshGeometry(*g, h), g, project);
  for (int cycle = 0; cycle < 3; ++cycle) {
    const auto before = r.mesh();
    const int d = before->dim();
    // Mark every third element, then once uniformly: both kinds of steps.
    std::vector<int> marked;
    for (int e = 0; e < before->numElements(); e += 3)
      marked.push_back(e);
    const auto& step = cycle == 1 ? r.refineUniformly() : r.refine(marked);
    const auto& after = *r.mesh();

    // P1 field: 2 components, both linear.
    std::vector<double> f(2 * before->numVertices());
    for (int v = 0; v < before->numVertices(); ++v) {
      f[2 * v] = linear(before->vertex(v), d);
      f[2 * v + 1] = -linear(before->vertex(v), d);
    }
    const auto g2 = prolongVertexField(step, f, 2);
    TEST_EQUALITY(static_cast<int>(g2.size()), 2 * after.numVertices());
    double worst = 0;
    for (int v = 0; v < after.numVertices(); ++v) {
      // Projected boundary vertices moved off the chord (their value is the chord midpoint's), and
      // so did midpoints created from them within the step: skip those when projecting.
      if (project && v >= step.numVerticesBefore) {
        const auto pe = step.newVertexParents[v - step.numVerticesBefore];
        if (after.isBoundaryVertex(v) || pe[0] >= step.numVerticesBefore ||
            pe[1] >= step.numVerticesBefore)
          continue;
      }
      worst = std::max(worst, std::abs(g2[2 * v] - linear(after.vertex(v), d)));
      worst = std::max(worst, std::abs(g2[2 * v + 1] + linear(after.vertex(v), d)));
    }
    TEST_COMPARE(worst, <, 1e-12);

    // Element constants: integral preserved (straight boundaries).
    std::vector<double> c(before->numElements());
    double integral0 = 0, integral1 = 0;
    for (int e = 0; e < before->numElements(); ++e) {
      c[e] = std::sin(e);
      integral0 += c[e] * before->elementMeasure(e);
    }
    const auto c1 = prolongElementField(step, c);
    for (int e = 0; e < after.numElements(); ++e)
      integral1 += c1[e] * after.elementMeasure(e);
    if (!project) TEST_FLOATING_EQUALITY(integral1, integral0, 1e-12);

    // Boundary faces: parent on the same part; children's measures add up to the parent's.
    const auto parent = boundaryFaceParents(*before, after, step);
    std::vector<double> childMeasure(before->numFaces(), 0.0);
    for (int f2 : after.boundaryFaces()) {
      const int p = parent[f2];
      TEST_ASSERT(p >= 0 && before->isBoundaryFace(p));
      if (p < 0) continue;
      TEST_EQUALITY(after.faceBoundaryId(f2), before->faceBoundaryId(p));
      childMeasure[p] += after.faceMeasure(f2);
    }
    if (!project)
      for (int p : before->boundaryFaces())
        TEST_FLOATING_EQUALITY(childMeasure[p], before->faceMeasure(p), 1e-12);
    out << g->sceneName() << (project ? " (projected)" : " (straight)") << " step " << cycle << ": "
        << before->numElements() << " -> " << after.numElements() << " elements, ok\n";
  }
}

TEUCHOS_UNIT_TEST(RefinementTransfer, HalfDisc)
{
  auto g = Teuchos::rcp(new HalfDiscGeometry(1.0));
  checkTransfers(g, 0.3, false, out, success);
  checkTransfers(g, 0.3, true, out, success);
}

TEUCHOS_UNIT_TEST(RefinementTransfer, HalfBall)
{
  auto g = Teuchos::rcp(new HalfBallGeometry(1.0));
  checkTransfers(g, 0.6, false, out, success);
  checkTransfers(g, 0.6, true, out, success);
}

}  // namespace
