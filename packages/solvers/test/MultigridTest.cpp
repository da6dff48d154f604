// Building blocks of the stress-block multigrid (docs/theory.md §"Linear solvers",
// docs/solvers.md):
//  - the RT prolongation is exact between nested meshes: the prolongated coarse solution, a
//    fine-mesh function, equals the coarse one (values and divergence) at the cubature points of
//    every fine element to rounding, 2D and 3D, k = 1 and 2, at any rank count;
//  - the vertex (2D) and edge (3D) patches cover every σ DOF, one patch per entity over the ranks;
//  - StressHierarchy chooses levels that shrink by the ratio from a locally refined sequence, and
//    the multigrid on them solves to the MUMPS solution.
#include <cmath>
#include <set>

#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_UnitTestHarness.hpp>
#include <Tpetra_Core.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Import.hpp>

#include <sc/solvers/StressHierarchy.hpp>
#include <sc/disc/ElementValues.hpp>
#include <sc/mesh/BisectionRefiner.hpp>
#include <sc/solvers/LinearSolverFactory.hpp>

#include <sc/testing/ElasticityTestProblem.hpp>

namespace {

TEUCHOS_UNIT_TEST(Multigrid, ProlongationIsExact)
{
  auto comm = Tpetra::getDefaultComm();
  for (int dim : {2, 3})
    for (int k : {1, 2}) {
      Teuchos::ParameterList meshList;
      meshList.set("Source", std::string(dim == 2 ? "Unit square" : "Unit cube"));
      meshList.set("Initial mesh size", dim == 2 ? 0.25 : 0.5);
      auto refiner = sc::mesh::MeshFactory::build(meshList, dim);
      sc::core::Material material{1.0, 0.3};
      auto exact = sc::core::createExactSolution("Manufactured smooth", dim, material, M_PI);
      auto coarseMesh = refiner->mesh();
      sc::assembly::MixedElasticitySystem coarse(coarseMesh, k, comm);
      auto coarseSpace = coarse.spacePtr();
      sc::assembly::ElasticityData data{material, sc::test::verificationBoundaryConditions(dim),
                                        exact.get()};
      coarse.assemble(data);
      Teuchos::ParameterList sl;
      sl.set("Type", std::string("MUMPS"));
      auto solver = sc::solvers::createLinearSolver(sl);
      auto xc = coarse.solve(*solver);

      const auto& step = refiner->refineUniformly();
      auto fineMesh = refiner->mesh();
      sc::assembly::MixedElasticitySystem fine(fineMesh, k, comm);
      fine.setupAssembler();
      auto fineSpace = fine.spacePtr();
      const auto& fa = fine.assembler();
      auto P = sc::solvers::stressProlongation(*coarseSpace, *fineSpace, step.elementParent, comm);
      // σ part of xc on P's domain map, P σ_c into a fine monolithic vector (u, θ = 0)
      Tpetra::MultiVector<> sc(P->getDomainMap(), 1), sf(P->getRangeMap(), 1);
      {
        auto src = xc->getData(0);
        auto dst = sc.getDataNonConst(0);
        const auto& cmap = *xc->getMap();
        for (size_t i = 0; i < sc.getLocalLength(); ++i)
          dst[i] = src[cmap.getLocalElement(P->getDomainMap()->getGlobalElement(i))];
      }
      P->apply(sc, sf);
      auto xf = fa.createVector();
      {
        auto src = sf.getData(0);
        auto dst = xf->getDataNonConst(0);
        const auto& fmap = *xf->getMap();
        for (size_t i = 0; i < sf.getLocalLength(); ++i)
          dst[fmap.getLocalElement(P->getRangeMap()->getGlobalElement(i))] = src[i];
      }
      // The fine function at the cubature points of each owned fine element against the coarse
      // one at the same points (evaluated on the parent element): the same function.
      auto xfo = fa.toOverlap(*xf);
      // the coarse solution on every rank (the parent of an owned fine element may be owned by
      // another rank in the coarse partition)
      std::vector<long long> allGids(coarseSpace->numGlobalDofs());
      for (std::size_t g = 0; g < allGids.size(); ++g)
        allGids[g] = static_cast<long long>(g);
      auto replicated =
          Teuchos::rcp(new Tpetra::Map<>(Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid(),
                                         Teuchos::ArrayView<const long long>(allGids), 0, comm));
      auto xco = Teuchos::rcp(new Tpetra::MultiVector<>(replicated, 1));
      xco->doImport(*xc, Tpetra::Import<>(xc->getMap(), replicated), Tpetra::INSERT);
      const auto& fo = *xfo->getMap();
      const auto& co = *xco->getMap();
      const auto fv = xfo->getData(0);
      const auto cv = xco->getData(0);
      sc::disc::ElementValues evF(*fineSpace, 2 * k + 2), evC(*coarseSpace, 2 * k + 2);
      double worst = 0.0, size = 0.0;
      for (int f : fineSpace->ownedElements()) {
        evF.reinit(f);
        std::vector<double> pts(evF.point(0), evF.point(0) + 3 * evF.numPoints());
        const int p = step.elementParent[f];
        evC.reinitAtPoints(p, pts);
        const long long* fd = fineSpace->elementDofs(f);
        const long long* cd = coarseSpace->elementDofs(p);
        for (int q = 0; q < evF.numPoints(); ++q)
          for (int i = 0; i < dim; ++i) {
            double vf[3] = {0, 0, 0}, vc[3] = {0, 0, 0}, df = 0, dc = 0;
            for (int a = 0; a < fineSpace->stressBasisSize(); ++a) {
              const double xfa = fv[fo.getLocalElement(fd[fineSpace->stressOffset(i) + a])];
              const double xca = cv[co.getLocalElement(cd[coarseSpace->stressOffset(i) + a])];
              for (int c = 0; c < dim; ++c) {
                vf[c] += xfa * evF.stress(a, q, c);
                vc[c] += xca * evC.stress(a, q, c);
              }
              df += xfa * evF.stressDiv(a, q);
              dc += xca * evC.stressDiv(a, q);
            }
            for (int c = 0; c < dim; ++c) {
              worst = std::max(worst, std::abs(vf[c] - vc[c]));
              size = std::max(size, std::abs(vc[c]));
            }
            worst = std::max(worst, std::abs(df - dc));
          }
      }
      double g[2] = {worst, size}, r[2];
      Teuchos::reduceAll(*comm, Teuchos::REDUCE_MAX, 2, g, r);
      out << dim << "D k=" << k << ": max |P σ_H − σ_H| at fine cubature points " << r[0]
          << " (max |σ_H| " << r[1] << ")\n";
      TEST_COMPARE(r[0], <=, 1e-11 * r[1]);
    }
}

// Vertex stars (2D) and edge stars (3D) cover every σ DOF, one patch per entity over all ranks.
void checkPatches(int dim, Teuchos::FancyOStream& out, bool& success)
{
  auto comm = Tpetra::getDefaultComm();
  Teuchos::ParameterList meshList;
  meshList.set("Source", std::string(dim == 2 ? "Unit square" : "Unit cube"));
  meshList.set("Initial mesh size", dim == 2 ? 0.25 : 0.5);
  auto refiner = sc::mesh::MeshFactory::build(meshList, dim);
  auto m = refiner->mesh();
  sc::assembly::MixedElasticitySystem system(m, 1, comm);
  const auto& space = system.space();
  const auto patches = sc::solvers::stressPatches(space);
  std::set<long long> covered;
  std::size_t largest = 0;
  for (const auto& p : patches) {
    covered.insert(p.begin(), p.end());
    largest = std::max(largest, p.size());
  }
  // every σ DOF is in some rank's patch: count the union over ranks
  std::vector<int> mine(space.numStressDofs(), 0), all(space.numStressDofs(), 0);
  for (long long g : covered)
    mine[g] = 1;
  Teuchos::reduceAll(*comm, Teuchos::REDUCE_MAX, static_cast<int>(mine.size()), mine.data(),
                     all.data());
  int missing = 0;
  for (int v : all)
    missing += v == 0;
  long long nPatches = static_cast<long long>(patches.size()), total = 0;
  Teuchos::reduceAll(*comm, Teuchos::REDUCE_SUM, 1, &nPatches, &total);
  // the entities: vertices (2D) or edges (3D) of the mesh
  std::set<std::pair<int, int>> edges;
  for (int e = 0; dim == 3 && e < m->numElements(); ++e) {
    const int* v = m->elementVertices(e);
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j)
        edges.insert({std::min(v[i], v[j]), std::max(v[i], v[j])});
  }
  const long long entities = dim == 2 ? m->numVertices() : static_cast<long long>(edges.size());
  out << dim << "D: " << total << " patches for " << entities << (dim == 2 ? " vertices" : " edges")
      << ", largest " << largest << " DOFs, " << missing << " σ DOFs uncovered\n";
  TEST_EQUALITY(missing, 0);
  TEST_EQUALITY(total, entities);
  // docs/theory.md §"Linear solvers": ≤ 64 DOFs in 2D k = 1 (design notes); 3D edge stars of
  // k = 1: 9 per face and 9 interior per element, ≤ 8 elements around an edge of these meshes
  TEST_COMPARE(largest, <=, dim == 2 ? 64u : 144u);
}

TEUCHOS_UNIT_TEST(Multigrid, PatchesCoverTheStressDofs2D) { checkPatches(2, out, success); }

TEUCHOS_UNIT_TEST(Multigrid, PatchesCoverTheStressDofs3D) { checkPatches(3, out, success); }

// Local refinement towards the corner (0, 0), 7 steps that add few elements each: the levels
// chosen shrink by at least the ratio 2, the first mesh is the coarsest, and MINRES with the
// multigrid on them reaches the MUMPS solution (docs/solvers.md, "The application's hierarchy").
TEUCHOS_UNIT_TEST(Multigrid, HierarchyOfLocalRefinements)
{
  auto comm = Tpetra::getDefaultComm();
  Teuchos::ParameterList meshList;
  meshList.set("Source", std::string("Unit square"));
  meshList.set("Initial mesh size", 0.25);
  auto refiner = sc::mesh::MeshFactory::build(meshList, 2);
  sc::solvers::StressHierarchy hierarchy(1, comm);
  hierarchy.addMesh(refiner->mesh(), {});
  for (int step = 0; step < 7; ++step) {
    const auto& m = *refiner->mesh();
    std::vector<int> marked;
    for (int e = 0; e < m.numElements(); ++e) {
      const int* v = m.elementVertices(e);
      double x = 0.0, y = 0.0;
      for (int j = 0; j < 3; ++j) {
        x += m.coordinates()[2 * v[j]] / 3.0;
        y += m.coordinates()[2 * v[j] + 1] / 3.0;
      }
      if (x + y < 0.6) marked.push_back(e);
    }
    const auto& st = refiner->refine(marked);
    hierarchy.addMesh(refiner->mesh(), st.elementParent);
  }
  auto m = refiner->mesh();
  sc::assembly::MixedElasticitySystem system(m, 1, comm);
  const auto levels = hierarchy.levels(system.space());
  const auto& chosen = hierarchy.chosen();
  out << "meshes:";
  for (int i = 0; i < hierarchy.numMeshes(); ++i)
    out << " " << hierarchy.meshElements(i);
  out << "\nchosen:";
  for (int i : chosen)
    out << " " << hierarchy.meshElements(i);
  out << "\n";
  TEST_EQUALITY(levels.size(), chosen.size());
  TEST_COMPARE(chosen.size(), >=, 3u);
  TEST_EQUALITY(chosen.front(), 0);
  TEST_EQUALITY(chosen.back(), hierarchy.numMeshes() - 1);
  for (std::size_t l = 1; l < chosen.size(); ++l)
    TEST_COMPARE(2 * hierarchy.meshElements(chosen[l - 1]), <=, hierarchy.meshElements(chosen[l]));

  sc::core::Material material{1.0, 0.3};
  auto exact = sc::core::createExactSolution("Manufactured smooth", 2, material, M_PI);
  system.assemble({material, sc::test::verificationBoundaryConditions(2), exact.get()});
  Teuchos::ParameterList direct, krylov;
  direct.set("Type", std::string("MUMPS"));
  krylov.set("Type", std::string("Iterative"));
  krylov.sublist("Iterative").set("Stress block", std::string("Multigrid"));
  auto mumps = sc::solvers::createLinearSolver(direct);
  auto mg = sc::solvers::createLinearSolver(krylov);
  auto x = system.solve(*mumps);
  auto y = system.solve(*mg, levels);
  y->update(-1.0, *x, 1.0);
  Teuchos::Array<double> dn(1), xn(1);
  y->norm2(dn());
  x->norm2(xn());
  out << system.space().numGlobalDofs() << " DOFs: " << mg->lastSolveStats().iterations
      << " MINRES iterations, |x_MG − x_MUMPS| / |x_MUMPS| = " << dn[0] / xn[0] << "\n";
  TEST_COMPARE(dn[0] / xn[0], <=, 1e-6);
  TEST_COMPARE(mg->lastSolveStats().iterations, <=, 120);  // uniform hierarchies: 75-86
}

}  // namespace
