// The "Linear Solver" sublist: defaults, validation, and (f) an unknown type is an InputError
// listing the known types.

#include <string>

#include <Teuchos_ParameterList.hpp>
#include <Teuchos_UnitTestHarness.hpp>

#include <sc/core/Error.hpp>
#include <sc/solvers/LinearSolverFactory.hpp>
#include <sc/solvers/SolverPolicy.hpp>

namespace {

using sc::solvers::LinearSolverFactory;

TEUCHOS_UNIT_TEST(LinearSolverFactory, UnknownTypeListsKnownTypes)
{
  Teuchos::ParameterList pl;
  pl.set("Type", std::string("SuperLU"));
  try {
    sc::solvers::createDirectSolver(pl);
    TEST_ASSERT(false);
  } catch (const sc::core::InputError& e) {
    const std::string what = e.what();
    out << what << "\n";
    TEST_ASSERT(what.find("SuperLU") != std::string::npos);
    TEST_ASSERT(what.find("KLU2") != std::string::npos);
    TEST_ASSERT(what.find("MUMPS") != std::string::npos);
  }
}

TEUCHOS_UNIT_TEST(LinearSolverFactory, UnknownKeyAndBadValueAreInputErrors)
{
  Teuchos::ParameterList typo;
  typo.set("Equilibrat", false);
  TEST_THROW(sc::solvers::createDirectSolver(typo), sc::core::InputError);
  Teuchos::ParameterList bad;
  bad.sublist("MUMPS").set("Ordering", std::string("RCM"));
  TEST_THROW(sc::solvers::createDirectSolver(bad), sc::core::InputError);
}

TEUCHOS_UNIT_TEST(LinearSolverFactory, DefaultsAndDocumentation)
{
  const auto valid = LinearSolverFactory::getValidParameters();
  // MUMPS by default: KLU2 fills badly on the saddle-point systems (docs/benchmarks.md).
  TEST_EQUALITY(valid->get<std::string>("Type"), "MUMPS");
  TEST_EQUALITY(valid->get<bool>("Equilibrate"), true);
  TEST_EQUALITY(valid->get<bool>("Symmetric"), true);
  TEST_EQUALITY(valid->sublist("MUMPS").get<int>("Memory relaxation percent"), 30);
  // every entry documented
  for (auto it = valid->begin(); it != valid->end(); ++it)
    TEST_ASSERT(!valid->entry(it).docString().empty());
  for (auto it = valid->sublist("MUMPS").begin(); it != valid->sublist("MUMPS").end(); ++it)
    TEST_ASSERT(!valid->sublist("MUMPS").entry(it).docString().empty());
  Teuchos::ParameterList pl;  // all defaults
  auto solver = sc::solvers::createDirectSolver(pl);
  TEST_EQUALITY(solver->name(), "MUMPS");
  TEST_ASSERT(solver->equilibrationEnabled());
  pl.set("Type", std::string("KLU2"));
  TEST_EQUALITY(sc::solvers::createDirectSolver(pl)->name(), "KLU2");
  pl.set("Type", std::string("MUMPS"));
  pl.set("Symmetric", true);
  solver = sc::solvers::createDirectSolver(pl);
  TEST_EQUALITY(solver->name(), "MUMPS");
  TEST_ASSERT(solver->exploitsSymmetry());
}

// Type = Auto (docs/solvers.md "Type = Auto"): MUMPS except 3D with a hierarchy at or above
// kAutoIterativeDofs3D unknowns without contact, or kAutoIterativeContactDofs3D with contact at
// degree 1; it must be resolved before a solver is built.
TEUCHOS_UNIT_TEST(LinearSolverFactory, AutoPolicy)
{
  using sc::solvers::ProblemSize;
  Teuchos::ParameterList pl;
  pl.set("Type", std::string("Auto"));
  TEST_THROW(sc::solvers::createLinearSolver(pl), sc::core::InputError);
  const long long big = sc::solvers::kAutoIterativeDofs3D;
  // resolveAutoType takes the validated list (the application's; defaults filled in).
  auto typeFor = [&](const ProblemSize& p) {
    return sc::solvers::resolveAutoType(sc::solvers::LinearSolverFactory::validate(pl), p)
        .get<std::string>("Type");
  };
  TEST_EQUALITY(typeFor({2, 10 * big, 1, false, true}), "MUMPS");  // 2D: MUMPS is faster
  TEST_EQUALITY(typeFor({3, big - 1, 1, false, true}), "MUMPS");   // below the threshold
  TEST_EQUALITY(typeFor({3, big, 2, false, false}), "MUMPS");      // no hierarchy
  TEST_EQUALITY(typeFor({3, big, 2, false, true}), "Iterative");
  // Contact: its own threshold, below the one without contact (MUMPS factorises LU, 4.5 kB N +
  // 148 B N^(4/3): ~19 GB at 10^6), in 3D at degree 1 only.
  const long long contactBig = sc::solvers::kAutoIterativeContactDofs3D;
  TEST_ASSERT(contactBig < big);
  TEST_EQUALITY(typeFor({3, contactBig - 1, 2, true, true, 1}), "MUMPS");
  TEST_EQUALITY(typeFor({3, contactBig, 2, true, true, 1}), "Iterative");
  TEST_EQUALITY(typeFor({3, contactBig, 1, true, true, 1}), "Iterative");  // any rank count
  TEST_EQUALITY(typeFor({3, contactBig - 1, 2, false, true}), "MUMPS");    // not without contact
  TEST_EQUALITY(typeFor({3, 10 * big, 2, true, true, 2}), "MUMPS");        // degree 2: not verified
  TEST_EQUALITY(typeFor({2, 10 * big, 2, true, true, 1}), "MUMPS");        // 2D contact
  TEST_EQUALITY(typeFor({3, 10 * big, 2, true, false, 1}), "MUMPS");       // no hierarchy
  {
    const auto c = sc::solvers::resolveAutoType(sc::solvers::LinearSolverFactory::validate(pl),
                                                {3, contactBig, 2, true, true, 1});
    TEST_EQUALITY(c.sublist("Iterative").get<std::string>("Stress block"), "Multigrid");
    TEST_EQUALITY(c.sublist("Iterative").get<std::string>("Method"), "Auto");  // GMRES w/ contact
    // the key moves the contact threshold only
    Teuchos::ParameterList lowered(pl);
    lowered.set("Auto iterative contact unknowns", 1000);
    const auto v = sc::solvers::LinearSolverFactory::validate(lowered);
    TEST_EQUALITY(
        sc::solvers::resolveAutoType(v, {3, 1000, 1, true, true, 1}).get<std::string>("Type"),
        "Iterative");
    TEST_EQUALITY(
        sc::solvers::resolveAutoType(v, {3, 999, 1, true, true, 1}).get<std::string>("Type"),
        "MUMPS");
    TEST_EQUALITY(
        sc::solvers::resolveAutoType(v, {3, 1000, 1, false, true}).get<std::string>("Type"),
        "MUMPS");
    lowered.set("Auto iterative contact unknowns", 0);
    TEST_THROW(sc::solvers::LinearSolverFactory::validate(lowered), sc::core::InputError);
  }
  const auto resolved = sc::solvers::resolveAutoType(sc::solvers::LinearSolverFactory::validate(pl),
                                                     {3, big, 1, false, true});
  TEST_EQUALITY(resolved.sublist("Iterative").get<std::string>("Stress block"), "Multigrid");
  auto solver = sc::solvers::createLinearSolver(pl, {3, big, 1, false, true});
  TEST_ASSERT(solver->isIterative());
  TEST_EQUALITY(sc::solvers::createLinearSolver(pl, {3, 1000, 1, false, true})->name(), "MUMPS");
  // another Type passes through unchanged
  pl.set("Type", std::string("KLU2"));
  TEST_EQUALITY(typeFor({3, big, 1, false, true}), "KLU2");
}

// SolverPolicy (docs/solvers.md): what a validated Linear Solver list means for a scene, decided
// once. The Auto rule as above; the nested meshes kept exactly when the multigrid may be used;
// the combinations without a covering test rejected.
TEUCHOS_UNIT_TEST(LinearSolverFactory, SolverPolicyDecidesOnce)
{
  using sc::solvers::LinearSolverFactory;
  using sc::solvers::SolverPolicy;
  const long long big = sc::solvers::kAutoIterativeDofs3D;
  auto list = [](const std::string& type, const std::string& stressBlock = "MUMPS",
                 const std::string& method = "Auto", bool symmetric = true) {
    Teuchos::ParameterList pl;
    pl.set("Type", type);
    pl.set("Symmetric", symmetric);
    pl.sublist("Iterative").set("Stress block", stressBlock);
    pl.sublist("Iterative").set("Method", method);
    return LinearSolverFactory::validate(pl);
  };
  const SolverPolicy::Scene plain3D{3, 1, false, 2}, contact3D{3, 1, true, 2},
      plain2D{2, 1, false, 1}, contact2D{2, 1, true, 1}, contact2DDegree2{2, 2, true, 1};

  const SolverPolicy autoPlain3D(list("Auto"), plain3D);
  TEST_ASSERT(autoPlain3D.isAuto() && autoPlain3D.needsHierarchy());
  TEST_EQUALITY(autoPlain3D.typeFor(big - 1), "MUMPS");
  TEST_ASSERT(!autoPlain3D.usesMultigrid(big - 1));
  TEST_EQUALITY(autoPlain3D.typeFor(big), "Iterative");
  TEST_ASSERT(autoPlain3D.usesMultigrid(big));
  TEST_EQUALITY(autoPlain3D.create(0)->name(), "MUMPS");
  TEST_EQUALITY(autoPlain3D.autoIterativeFrom(), big);
  const long long contactBig = sc::solvers::kAutoIterativeContactDofs3D;
  const SolverPolicy autoContact3D(list("Auto"), contact3D);
  TEST_ASSERT(autoContact3D.needsHierarchy());
  TEST_EQUALITY(autoContact3D.typeFor(contactBig - 1), "MUMPS");
  TEST_ASSERT(!autoContact3D.usesMultigrid(contactBig - 1));
  TEST_EQUALITY(autoContact3D.typeFor(contactBig), "Iterative");
  TEST_ASSERT(autoContact3D.usesMultigrid(contactBig));
  TEST_EQUALITY(autoContact3D.autoIterativeFrom(), contactBig);
  TEST_EQUALITY(autoContact3D.gmresBasisVectors(), 2 * (300 + 1));  // default Restart = 300
  const SolverPolicy autoContact3DDegree2(list("Auto"), SolverPolicy::Scene{3, 2, true, 2});
  TEST_ASSERT(!autoContact3DDegree2.needsHierarchy());
  TEST_EQUALITY(autoContact3DDegree2.typeFor(10 * big), "MUMPS");
  TEST_EQUALITY(autoContact3DDegree2.autoIterativeFrom(), -1);
  TEST_ASSERT(!SolverPolicy(list("Auto"), contact2D).needsHierarchy());
  TEST_EQUALITY(SolverPolicy(list("Auto"), contact2D).typeFor(10 * big), "MUMPS");
  TEST_ASSERT(!SolverPolicy(list("Auto"), plain2D).needsHierarchy());

  const SolverPolicy multigrid(list("Iterative", "Multigrid"), plain2D);
  TEST_ASSERT(!multigrid.isAuto() && multigrid.needsHierarchy() && multigrid.usesMultigrid(10));
  const SolverPolicy exactBlock(list("Iterative"), contact2D);  // verified: run_hertz2d_iterative
  TEST_ASSERT(!exactBlock.needsHierarchy());
  TEST_EQUALITY(exactBlock.typeFor(10), "Iterative");
  TEST_ASSERT(exactBlock.create(10)->isIterative());
  const SolverPolicy mumps(list("MUMPS"), plain3D);
  TEST_ASSERT(!mumps.needsHierarchy() && !mumps.usesMultigrid(10 * big));
  TEST_EQUALITY(mumps.typeFor(10 * big), "MUMPS");
  TEST_NOTHROW(SolverPolicy(list("Iterative", "MUMPS", "MINRES"), plain3D));

  TEST_THROW(SolverPolicy(list("Iterative"), contact3D), sc::core::InputError);
  TEST_THROW(SolverPolicy(list("Iterative"), contact2DDegree2), sc::core::InputError);
  // verified: run_hertz2d_multigrid_*, run_hertz3d_multigrid_* and, at degree 2 in 2D,
  // run_hertz2d_multigrid_degree2_*; the 3D exact block, the exact block at k >= 2 (above), 2D
  // k >= 3 and 3D k >= 2 stay rejected
  TEST_ASSERT(SolverPolicy(list("Iterative", "Multigrid"), contact2D).needsHierarchy());
  TEST_ASSERT(SolverPolicy(list("Iterative", "Multigrid"), contact3D).needsHierarchy());
  TEST_ASSERT(SolverPolicy(list("Iterative", "Multigrid"), contact2DDegree2).needsHierarchy());
  TEST_THROW(SolverPolicy(list("Iterative", "Multigrid"), SolverPolicy::Scene{2, 3, true, 1}),
             sc::core::InputError);
  TEST_THROW(SolverPolicy(list("Iterative", "Multigrid"), SolverPolicy::Scene{3, 2, true, 2}),
             sc::core::InputError);
  TEST_THROW(SolverPolicy(list("Iterative", "MUMPS", "MINRES"), contact2D), sc::core::InputError);
  TEST_THROW(SolverPolicy(list("Iterative", "MUMPS", "MINRES", false), plain3D),
             sc::core::InputError);
}

}  // namespace
