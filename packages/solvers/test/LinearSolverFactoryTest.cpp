// The "Linear Solver" sublist: defaults, validation, and (f) an unknown type is an InputError
// listing the known types.

#include <string>

#include <Teuchos_ParameterList.hpp>
#include <Teuchos_UnitTestHarness.hpp>

#include <sc/core/Error.hpp>
#include <sc/solvers/LinearSolverFactory.hpp>

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

// Type = Auto (docs/solvers.md): MUMPS except 3D, no contact, with a hierarchy, at or above
// kAutoIterativeDofs3D unknowns; it must be resolved before a solver is built.
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
  TEST_EQUALITY(typeFor({2, 10 * big, 1, false, true}), "MUMPS");     // 2D: MUMPS is faster
  TEST_EQUALITY(typeFor({3, big - 1, 1, false, true}), "MUMPS");      // below the threshold
  TEST_EQUALITY(typeFor({3, big, 4, true, true}), "MUMPS");           // contact
  TEST_EQUALITY(typeFor({3, big, 2, false, false}), "MUMPS");         // no hierarchy
  TEST_EQUALITY(typeFor({3, big, 2, false, true}), "Iterative");
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

}  // namespace
