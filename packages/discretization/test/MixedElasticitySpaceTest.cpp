// Tests of the discrete spaces that catch orientation and mapping mistakes before any system is
// assembled (docs/theory.md §"Mixed formulation"):
// - DOF counts against the dimension formulas of RT_k, P_k (analytic);
// - normal continuity: on every interior face, each global RT face DOF's function has the same
//   normal trace seen from both elements (this fails for a wrong orientation or Piola map);
// - continuity of CP_k on faces (k = 2 has edge DOFs, which need orientation);
// - the divergence theorem ∫_T div φ = ∫_∂T φ·n for every RT function of every element.
#include <cmath>
#include <algorithm>
#include <map>

#include <Teuchos_UnitTestHarness.hpp>

#include <sc/core/Parameters.hpp>
#include <sc/disc/ElementValues.hpp>
#include <sc/disc/FaceDofPoints.hpp>
#include <sc/disc/MixedElasticitySpace.hpp>
#include <sc/mesh/BisectionRefiner.hpp>
#include <sc/mesh/CurvedElements.hpp>
#include <sc/mesh/MeshFactory.hpp>
#include <sc/mesh/SimplexMesh.hpp>

namespace {

Teuchos::RCP<const sc::mesh::SimplexMesh> makeMesh(const std::string& source, int dim, double h)
{
  Teuchos::ParameterList pl;
  pl.set("Source", source);
  pl.set("Initial mesh size", h);
  return sc::mesh::MeshFactory::build(pl, dim)->mesh();
}

// Max over interior faces of |trace from element 0 − trace from element 1| for RT (normal
// component against the face's fixed normal) and CP values, relative to the largest value.
void checkContinuity(const sc::disc::MixedElasticitySpace& space, Teuchos::FancyOStream& out,
                     bool& success)
{
  const auto& m = space.mesh();
  const int d = m.dim();
  sc::disc::FaceValues fa(space, 2 * space.degree() + 2), fb(space, 2 * space.degree() + 2);
  double maxJumpRT = 0.0, maxRT = 0.0, maxJumpCP = 0.0, maxCP = 0.0;
  int checkedFaces = 0;
  for (int f = 0; f < m.numFaces(); ++f) {
    if (m.isBoundaryFace(f)) continue;
    const auto el = m.faceElements(f);
    int lf[2] = {-1, -1};
    for (int s = 0; s < 2; ++s)
      for (int i = 0; i <= d; ++i)
        if (m.elementFaces(el[s])[i] == f) lf[s] = i;
    fa.reinit(el[0], lf[0]);
    fb.reinit(el[1], lf[1]);
    // Match quadrature points by position (the two sides may traverse the face differently).
    const int nq = fa.numPoints();
    std::vector<int> match(nq, -1);
    for (int q = 0; q < nq; ++q)
      for (int p = 0; p < nq; ++p) {
        double dist = 0.0;
        for (int i = 0; i < d; ++i)
          dist += std::pow(fa.point(q)[i] - fb.point(p)[i], 2);
        if (dist < 1e-24) match[q] = p;
      }
    for (int q = 0; q < nq; ++q)
      TEST_ASSERT(match[q] >= 0);
    // Global dof -> local index on each side, first row block of σ.
    const long long* ga = space.elementDofs(el[0]);
    const long long* gb = space.elementDofs(el[1]);
    std::map<long long, int> locB;
    for (int b = 0; b < space.stressBasisSize(); ++b)
      locB[gb[b]] = b;
    for (int a = 0; a < space.stressBasisSize(); ++a) {
      auto it = locB.find(ga[a]);
      for (int q = 0; q < nq; ++q) {
        const double va = fa.stressNormal(a, q);  // against the normal out of el[0]
        const double vb = it == locB.end() ? 0.0 : -fb.stressNormal(it->second, match[q]);
        maxJumpRT = std::max(maxJumpRT, std::abs(va - vb));
        maxRT = std::max(maxRT, std::abs(va));
      }
    }
    // CP_k (first rotation component): the same global DOF has the same values on the face.
    std::map<long long, int> cpB;
    const int r0 = space.rotationOffset(0);
    for (int b = 0; b < space.rotationBasisSize(); ++b)
      cpB[gb[r0 + b]] = b;
    for (int a = 0; a < space.rotationBasisSize(); ++a) {
      auto it = cpB.find(ga[r0 + a]);
      for (int q = 0; q < nq; ++q) {
        const double va = fa.rotation(a, q);
        const double vb = it == cpB.end() ? 0.0 : fb.rotation(it->second, match[q]);
        maxJumpCP = std::max(maxJumpCP, std::abs(va - vb));
        maxCP = std::max(maxCP, std::abs(va));
      }
    }
    ++checkedFaces;
  }
  out << "interior faces " << checkedFaces << ", max RT normal jump " << maxJumpRT << " (max "
      << maxRT << "), max CP jump " << maxJumpCP << " (max " << maxCP << ")\n";
  TEST_COMPARE(maxJumpRT, <=, 1e-12 * maxRT);
  TEST_COMPARE(maxJumpCP, <=, 1e-12 * maxCP);
}

void checkDivergenceTheorem(const sc::disc::MixedElasticitySpace& space, Teuchos::FancyOStream& out,
                            bool& success)
{
  const auto& m = space.mesh();
  const int d = m.dim(), k = space.degree();
  sc::disc::ElementValues ev(space, 2 * k);
  sc::disc::FaceValues fv(space, 2 * k + 1);
  double worst = 0.0;
  for (int e = 0; e < std::min(m.numElements(), 200); ++e) {
    ev.reinit(e);
    std::vector<double> volume(space.stressBasisSize(), 0.0),
        boundary(space.stressBasisSize(), 0.0);
    for (int a = 0; a < space.stressBasisSize(); ++a)
      for (int q = 0; q < ev.numPoints(); ++q)
        volume[a] += ev.stressDiv(a, q) * ev.weight(q);
    for (int lf = 0; lf <= d; ++lf) {
      fv.reinit(e, lf);
      for (int a = 0; a < space.stressBasisSize(); ++a)
        for (int q = 0; q < fv.numPoints(); ++q)
          boundary[a] += fv.stressNormal(a, q) * fv.weight(q);
    }
    for (int a = 0; a < space.stressBasisSize(); ++a)
      worst =
          std::max(worst, std::abs(volume[a] - boundary[a]) / std::max(1.0, std::abs(volume[a])));
  }
  out << "divergence theorem worst relative defect " << worst << "\n";
  TEST_COMPARE(worst, <=, 1e-11);
}

}  // namespace

TEUCHOS_UNIT_TEST(MixedElasticitySpace, DofCounts2D)
{
  auto mesh = makeMesh("Unit square", 2, 0.25);
  for (int k : {1, 2}) {
    sc::disc::MixedElasticitySpace space(mesh, k, std::vector<int>(mesh->numElements(), 0), 0);
    // dim RT_k(T) = (k+1)(k+3), dim P_k(T) = (k+1)(k+2)/2 (analytic).
    TEST_EQUALITY(space.stressBasisSize(), (k + 1) * (k + 3));
    TEST_EQUALITY(space.displacementBasisSize(), (k + 1) * (k + 2) / 2);
    TEST_EQUALITY(space.stressFaceDofs(), k + 1);
    const long long ne = mesh->numElements(), nf = mesh->numFaces(), nv = mesh->numVertices();
    // Global RT_k per row: (k+1) per edge + k(k+1) interior per triangle.
    TEST_EQUALITY(space.numStressDofs(), 2 * ((k + 1) * nf + k * (k + 1) * ne));
    // CP_k: vertices + (k−1) per edge (2D, k ≤ 2).
    TEST_EQUALITY(space.numRotationDofs(), nv + (k - 1) * nf);
    TEST_EQUALITY(space.numDisplacementDofs(), 2 * ne * (k + 1) * (k + 2) / 2);
    TEST_EQUALITY(static_cast<long long>(space.ownedDofs().size()), space.numGlobalDofs());
  }
}

TEUCHOS_UNIT_TEST(MixedElasticitySpace, DofCounts3D)
{
  auto mesh = makeMesh("Unit cube", 3, 0.5);
  sc::disc::MixedElasticitySpace space(mesh, 1, std::vector<int>(mesh->numElements(), 0), 0);
  // dim RT_1(tet) = (k+1)(k+2)(k+4)/2 = 15, 3 DOFs per face, 3 interior.
  TEST_EQUALITY(space.stressBasisSize(), 15);
  TEST_EQUALITY(space.stressFaceDofs(), 3);
  TEST_EQUALITY(space.numStressDofs(), 3 * (3LL * mesh->numFaces() + 3LL * mesh->numElements()));
  TEST_EQUALITY(space.numRotationDofs(), 3LL * mesh->numVertices());
}

TEUCHOS_UNIT_TEST(MixedElasticitySpace, NormalContinuityAndDivergence2D)
{
  auto mesh = makeMesh("Half disc", 2, 0.3);
  for (int k : {1, 2}) {
    sc::disc::MixedElasticitySpace space(mesh, k, std::vector<int>(mesh->numElements(), 0), 0);
    checkContinuity(space, out, success);
    checkDivergenceTheorem(space, out, success);
  }
}

TEUCHOS_UNIT_TEST(MixedElasticitySpace, NormalContinuityAndDivergence3D)
{
  auto mesh = makeMesh("Half ball", 3, 0.5);
  for (int k : {1, 2}) {
    sc::disc::MixedElasticitySpace space(mesh, k, std::vector<int>(mesh->numElements(), 0), 0);
    checkContinuity(space, out, success);
    checkDivergenceTheorem(space, out, success);
  }
}

TEUCHOS_UNIT_TEST(MixedElasticitySpace, OwnershipCoversAllDofsOnce)
{
  auto mesh = makeMesh("Unit square", 2, 0.25);
  std::vector<int> owner(mesh->numElements());
  for (int e = 0; e < mesh->numElements(); ++e)
    owner[e] = e % 3;
  long long total = 0;
  for (int r = 0; r < 3; ++r) {
    sc::disc::MixedElasticitySpace space(mesh, 1, owner, r);
    total += static_cast<long long>(space.ownedDofs().size());
    for (long long g : space.ownedDofs())
      TEST_ASSERT(std::binary_search(space.overlapDofs().begin(), space.overlapDofs().end(), g));
  }
  sc::disc::MixedElasticitySpace space(mesh, 1, owner, 0);
  TEST_EQUALITY(total, space.numGlobalDofs());
}

TEUCHOS_UNIT_TEST(FaceDofPoints, PointValuesOnBoundaryFaces)
{
  // docs/theory.md §"Contact and friction": for RT_1 in 2D the face DOFs sit at 1/3 and 2/3 of each
  // edge (Intrepid2 equispaced lattice); the traction at p_j is s_j times the coefficient. Checked:
  // the points lie on the face at the expected fractions, s_j ≠ 0, and Σ_j over a face of (φ_j·n)
  // weights reproduces a constant flux (the flux of φ_j integrates to |F|/(k+1)·s_j·... is not
  // needed).
  auto mesh = makeMesh("Half disc", 2, 0.3);
  sc::disc::MixedElasticitySpace space(mesh, 1, std::vector<int>(mesh->numElements(), 0), 0);
  int checked = 0;
  for (int f : mesh->boundaryFaces()) {
    const int e = mesh->faceElements(f)[0];
    int lf = 0;
    while (mesh->elementFaces(e)[lf] != f)
      ++lf;
    const auto pts = sc::disc::stressFaceDofPoints(space, e, lf);
    TEST_EQUALITY(pts.size(), 2u);
    const double* a = mesh->vertex(mesh->faceVertices(f)[0]);
    const double* b = mesh->vertex(mesh->faceVertices(f)[1]);
    std::vector<double> fractions;
    for (const auto& p : pts) {
      TEST_COMPARE(std::abs(p.scale), >, 0.0);
      // Position along the edge: x = a + s (b − a), s ∈ {1/3, 2/3}.
      const double len2 = std::pow(b[0] - a[0], 2) + std::pow(b[1] - a[1], 2);
      const double s = ((p.x[0] - a[0]) * (b[0] - a[0]) + (p.x[1] - a[1]) * (b[1] - a[1])) / len2;
      const double off =
          std::abs((p.x[0] - a[0]) * (b[1] - a[1]) - (p.x[1] - a[1]) * (b[0] - a[0]));
      TEST_COMPARE(off, <=, 1e-12);
      fractions.push_back(s);
      // Intrepid2 13.2 scaling (docs/theory.md §"Contact and friction"): |s_j| = 2/|e|.
      TEST_FLOATING_EQUALITY(std::abs(p.scale), 2.0 / mesh->faceMeasure(f), 1e-10);
    }
    std::sort(fractions.begin(), fractions.end());
    TEST_FLOATING_EQUALITY(fractions[0], 1.0 / 3.0, 1e-10);
    TEST_FLOATING_EQUALITY(fractions[1], 2.0 / 3.0, 1e-10);
    ++checked;
  }
  TEST_COMPARE(checked, >, 10);
  // 3D, k = 1: three points per face, nonzero scales.
  auto mesh3 = makeMesh("Half ball", 3, 0.5);
  sc::disc::MixedElasticitySpace space3(mesh3, 1, std::vector<int>(mesh3->numElements(), 0), 0);
  const int f = mesh3->boundaryFaces().front();
  const int e = mesh3->faceElements(f)[0];
  int lf = 0;
  while (mesh3->elementFaces(e)[lf] != f)
    ++lf;
  const auto pts3 = sc::disc::stressFaceDofPoints(space3, e, lf);
  TEST_EQUALITY(pts3.size(), 3u);
  for (const auto& p : pts3)
    TEST_COMPARE(std::abs(p.scale), >, 0.0);
}

// Curved (quadratic-geometry) elements, Mesh/Geometry order = 2 (docs/mesh.md "Curved elements").
namespace {

struct CurvedScene {
  Teuchos::RCP<sc::mesh::BisectionRefiner> refiner;
  Teuchos::RCP<const sc::mesh::CurvedElements> curved;
};

CurvedScene makeCurved(const std::string& source, int dim, double h, int refinements = 0)
{
  Teuchos::ParameterList pl;
  pl.set("Source", source);
  pl.set("Initial mesh size", h);
  pl.set("Uniform refinements", refinements);
  CurvedScene s;
  s.refiner = sc::mesh::MeshFactory::build(pl, dim);
  s.curved = Teuchos::rcp(new sc::mesh::CurvedElements(s.refiner->mesh(), *s.refiner->geometry()));
  return s;
}

double measureError(const CurvedScene& s, int geometryOrder, int degree = 1)
{
  auto mesh = s.refiner->mesh();
  sc::disc::MixedElasticitySpace space(mesh, degree, std::vector<int>(mesh->numElements(), 0), 0,
                                       geometryOrder == 2 ? s.curved : Teuchos::null);
  return std::abs(sc::disc::ownedMeasure(space) - s.refiner->geometry()->exactMeasure()) /
         s.refiner->geometry()->exactMeasure();
}

}  // namespace

// Normal continuity across the (straight) faces between curved and affine elements, and the
// divergence theorem ∫_T div φ = ∫_∂T φ·n on curved elements: checks the non-affine Piola map,
// the per-point normals and surface elements of the curved faces (exact identities, round-off).
TEUCHOS_UNIT_TEST(CurvedElements, NormalContinuityAndDivergence)
{
  for (int dim : {2, 3}) {
    const auto s = makeCurved(dim == 2 ? "Half disc" : "Half ball", dim, dim == 2 ? 0.3 : 0.5);
    TEST_COMPARE(s.curved->numCurvedElements(), >, 0);
    out << dim << "D: " << s.curved->numCurvedElements() << " curved of "
        << s.refiner->mesh()->numElements() << " elements, max bulge "
        << s.curved->maxRelativeBulge() << "\n";
    for (int k : {1, 2}) {
      auto mesh = s.refiner->mesh();
      sc::disc::MixedElasticitySpace space(mesh, k, std::vector<int>(mesh->numElements(), 0), 0,
                                           s.curved);
      checkContinuity(space, out, success);
      checkDivergenceTheorem(space, out, success);
    }
  }
}

// The measure of the discrete domain: O(h^2) with straight boundary faces, O(h^4) with the
// quadratic map (analytic: the area between an arc and its P2 interpolant). Source: π/2 (half
// disc of radius 1), 2π/3 (half ball).
TEUCHOS_UNIT_TEST(CurvedElements, DomainMeasureConvergesAtOrderFour)
{
  const auto coarse = makeCurved("Half disc", 2, 0.25), fine = makeCurved("Half disc", 2, 0.25, 2);
  const double s0 = measureError(coarse, 1), s1 = measureError(fine, 1);
  const double c0 = measureError(coarse, 2), c1 = measureError(fine, 2);
  out << "half disc |Ω_h|/|Ω| − 1: straight " << s0 << " → " << s1 << ", curved " << c0 << " → "
      << c1 << "\n";
  // Two uniform 2D levels (×4 elements each) divide h by 4: straight ×16, curved ×256
  // (measured 16.0 and 255).
  TEST_COMPARE(s0 / s1, >, 12.0);
  TEST_COMPARE(c0 / c1, >, 150.0);
  TEST_COMPARE(c1, <, s1 / 100.0);
  const auto ball = makeCurved("Half ball", 3, 0.5);
  const double sb = measureError(ball, 1), cb = measureError(ball, 2);
  out << "half ball |Ω_h|/|Ω| − 1: straight " << sb << ", curved " << cb << "\n";
  TEST_COMPARE(cb, <, sb / 20.0);
}

// The RT face DOFs stay point values of the normal flux on curved faces, at points on the
// curved face (within O(h^4) of the circle) with the normal of the curve there.
TEUCHOS_UNIT_TEST(CurvedElements, FaceDofPointsOnTheCurve)
{
  const auto s = makeCurved("Half disc", 2, 0.3);
  auto mesh = s.refiner->mesh();
  for (int k : {1, 2}) {
    sc::disc::MixedElasticitySpace space(mesh, k, std::vector<int>(mesh->numElements(), 0), 0,
                                         s.curved);
    double worstCurved = 0.0, worstChord = 0.0, worstNormal = 0.0;
    for (int f : mesh->boundaryFacesOf("Arc")) {
      const int e = mesh->faceElements(f)[0];
      int lf = 0;
      while (mesh->elementFaces(e)[lf] != f)
        ++lf;
      for (const auto& p : sc::disc::stressFaceDofPoints(space, e, lf)) {
        // Circle: centre (0, 1), radius 1.
        const double r = std::hypot(p.x[0], p.x[1] - 1.0),
                     rc = std::hypot(p.xAffine[0], p.xAffine[1] - 1.0);
        worstCurved = std::max(worstCurved, std::abs(r - 1.0));
        worstChord = std::max(worstChord, std::abs(rc - 1.0));
        const double nx = p.x[0] / r, ny = (p.x[1] - 1.0) / r;  // exact outward normal
        worstNormal = std::max(worstNormal, std::hypot(p.normal[0] - nx, p.normal[1] - ny));
        TEST_COMPARE(std::abs(p.scale), >, 0.0);
      }
    }
    out << "k = " << k << ": distance to the circle, curved " << worstCurved << ", chord "
        << worstChord << "; normal error " << worstNormal << "\n";
    TEST_COMPARE(worstCurved, <, worstChord / 20.0);
    TEST_COMPARE(worstNormal, <, 0.01);
  }
}
