// The "Linear Solver" sublist and the registry of solvers. No Tpetra headers here.

#include <sc/solvers/LinearSolverFactory.hpp>

#include <algorithm>
#include <functional>
#include <map>
#include <sstream>

#include <sc/core/Error.hpp>
#include <sc/core/Parameters.hpp>
#include <sc/solvers/IterativeSolver.hpp>
#include <sc/solvers/Klu2Solver.hpp>
#include <sc/solvers/MumpsSolver.hpp>

namespace sc::solvers {

namespace {

const std::vector<std::string>& orderingNames()
{
  // index = ICNTL(7) value; 1 (user-given) is not offered
  static const std::vector<std::string> names = {"AMD",  "",      "AMF",  "SCOTCH",
                                                 "PORD", "METIS", "QAMD", "Auto"};
  return names;
}

using Builder = std::function<Teuchos::RCP<LinearSolver>(const Teuchos::ParameterList&)>;

// Registered types, in the order listed to users.
const std::vector<std::pair<std::string, Builder>>& registry()
{
  static const std::vector<std::pair<std::string, Builder>> types = {
      {"KLU2",
       [](const Teuchos::ParameterList&) -> Teuchos::RCP<LinearSolver> {
         return Teuchos::rcp(new Klu2Solver());
       }},
      {"MUMPS",
       [](const Teuchos::ParameterList& pl) -> Teuchos::RCP<LinearSolver> {
         const auto& mp = pl.sublist("MUMPS");
         MumpsOptions o;
         o.memoryRelaxationPercent = mp.get<int>("Memory relaxation percent");
         o.workspaceRetries = mp.get<int>("Workspace retries");
         const auto& names = orderingNames();
         o.ordering = static_cast<int>(
             std::find(names.begin(), names.end(), mp.get<std::string>("Ordering")) -
             names.begin());
         o.verbose = pl.get<bool>("Verbose");
         o.lowRankTolerance = mp.get<double>("Low-rank tolerance");
         const auto scaling = mp.get<std::string>("Scaling");
         o.scaling = scaling == "None" ? 0 : scaling == "MUMPS" ? 77 : -1;
         return Teuchos::rcp(new MumpsSolver(o));
       }},
      {"Iterative",
       [](const Teuchos::ParameterList& pl) -> Teuchos::RCP<LinearSolver> {
         const auto& il = pl.sublist("Iterative");
         IterativeOptions o;
         o.method = il.get<std::string>("Method");
         o.tolerance = il.get<double>("Tolerance");
         o.maxIterations = il.get<int>("Maximum iterations");
         o.restart = il.get<int>("Restart");
         o.outputFrequency = il.get<int>("Output frequency");
         o.stressBlock = il.get<std::string>("Stress block");
         o.smootherDegree = il.get<int>("Multigrid smoother degree");
         o.smootherRatio = il.get<double>("Multigrid smoother eigenvalue ratio");
         o.directList = pl;  // the sub-solver inherits MUMPS options and equilibration
         o.directList.remove("Iterative");
         return Teuchos::rcp(new IterativeSolver(o));
       }},
  };
  return types;
}

}  // namespace

std::vector<std::string> LinearSolverFactory::knownTypes()
{
  std::vector<std::string> names;
  for (const auto& t : registry())
    names.push_back(t.first);
  names.push_back("Auto");  // resolved to one of the above by resolveAutoType
  return names;
}

Teuchos::RCP<const Teuchos::ParameterList> LinearSolverFactory::getValidParameters()
{
  static const Teuchos::RCP<const Teuchos::ParameterList> valid = [] {
    using namespace sc::core;
    auto pl = Teuchos::rcp(new Teuchos::ParameterList("Linear Solver"));
    declareChoice(*pl, "Type", "MUMPS", knownTypes(),
                  "Solver for the saddle-point system (docs/theory.md §\"Linear solvers\"): KLU2 "
                  "(Amesos2; gathers the "
                  "matrix on rank 0, serial LU), MUMPS (parallel multifrontal LU/LDLᵀ) or "
                  "Iterative (Belos MINRES/GMRES with the block-diagonal preconditioner, see the "
                  "Iterative sublist; docs/solvers.md), or Auto: MUMPS, except for 3D systems "
                  "of at least 'Auto iterative unknowns' (without contact) or 'Auto iterative "
                  "contact unknowns' (with contact, degree 1), where MUMPS' memory exceeds a 24 "
                  "GB node and Iterative with Stress block = Multigrid is used (the choice is "
                  "made per adaptive cycle; measured in docs/solvers.md).");
    declareInt(*pl, "Auto iterative unknowns", static_cast<int>(kAutoIterativeDofs3D),
               "Type = Auto: 3D systems without contact with at least this many unknowns use "
               "Iterative with Stress block = Multigrid, smaller ones MUMPS (the default is the "
               "measured limit of MUMPS on a 24 GB node, docs/solvers.md).",
               1, 2000000000);
    declareInt(*pl, "Auto iterative contact unknowns",
               static_cast<int>(kAutoIterativeContactDofs3D),
               "Type = Auto: 3D contact systems at Discretization/Degree = 1 with at least this "
               "many unknowns use Iterative with Stress block = Multigrid, smaller ones MUMPS "
               "(the default is where MUMPS' measured LU memory of 3D contact, 4.5 kB N + 148 B "
               "N^(4/3), reaches about 19 GB, docs/solvers.md \"Type = Auto\"). 2D contact and "
               "degree >= 2 always use MUMPS.",
               1, 2000000000);
    declareBool(*pl, "Symmetric", true,
                "Exploit symmetry when the system is symmetric (elasticity without contact rows; "
                "the application knows which systems are): MUMPS factorises LDLᵀ (SYM = 2), about "
                "half the work and memory, and Iterative uses MINRES. false: always LU / GMRES. "
                "Systems with contact rows are non-symmetric (docs/theory.md §\"Contact and "
                "friction\") and always use LU / "
                "GMRES. KLU2 ignores it.");
    declareBool(
        *pl, "Equilibrate", true,
        "Scale rows and columns (Ruiz, powers of two; symmetric if Symmetric = true) before "
        "factorising: the stress, displacement and rotation blocks differ by orders of "
        "magnitude (docs/theory.md §\"Contact and friction\").");
    declareInt(*pl, "Equilibration iterations", 20,
               "Maximum Ruiz sweeps; they stop earlier when every row and column ∞-norm is within "
               "0.1 of 1.",
               1, 1000);
    declareReal(*pl, "Maximum relative residual", 1e-6,
                "A solve whose ‖b − A x‖₂/‖b‖₂ exceeds this is an error (singular or nearly "
                "singular matrix, or Symmetric = true for a non-symmetric one); 0 disables the "
                "check.",
                0.0, false, kInfinity, false);
    declareBool(*pl, "Verbose", false, "Let MUMPS print its diagnostics (ICNTL(1..4)).");
    auto& il = pl->sublist("Iterative", false,
                           "Options of the Krylov solver (used when Type = Iterative; "
                           "docs/solvers.md).");
    declareChoice(il, "Method", "Auto", IterativeSolver::methods(),
                  "Belos method: MINRES (symmetric systems, SPD preconditioner), GMRES, or Auto "
                  "(MINRES when the system is symmetric and Symmetric = true, GMRES otherwise, "
                  "e.g. with contact rows).");
    declareReal(
        il, "Tolerance", 1e-8,
        "Relative residual ‖b − A x‖/‖b‖ of the scaled system to reach (checked on the true "
        "residual, not only Belos' own).",
        0.0, false, 1.0, false);
    declareInt(il, "Maximum iterations", 1000,
               "Krylov iterations per solve (all restarts); reaching it without the tolerance is "
               "an error naming the residual reached.",
               1, 1000000);
    declareInt(il, "Restart", 300, "GMRES: Krylov subspace size before a restart.", 1, 100000);
    declareInt(il, "Output frequency", 0,
               "Print Belos' residual every this many iterations (0: never).", 0, 1000000);
    declareChoice(
        il, "Stress block", "MUMPS", IterativeSolver::stressBlockSolvers(),
        "Solver of the stress block S_σ = A + (2μ)⁻¹B_uᵀM_u⁻¹B_u of the block-diagonal "
        "preconditioner diag(S_σ, 2μM_u, 2μM_θ) (docs/theory.md §\"Linear solvers\"): MUMPS or "
        "KLU2 (exact: "
        "iterations independent of h and λ, the cost of a direct solve of the SPD σ "
        "block); Multigrid (one geometric V-cycle with vertex-patch (2D) or edge-patch (3D) "
        "smoothers on the hierarchy of the run's nested meshes, which the application "
        "keeps, levels chosen per adaptive cycle; with contact at degree 1 in 2D and 3D and at "
        "degree 2 in 2D, "
        "docs/solvers.md \"Contact with the stress multigrid\"); or MueLu (smoothed aggregation "
        "AMG, one V-cycle: not robust, "
        "the kernel of div; offered for comparison). SuperLU is not in Debian's "
        "Trilinos.");
    declareInt(il, "Multigrid smoother degree", 0,
               "Stress block = Multigrid: degree of the Chebyshev polynomial of the patch "
               "smoother, applied before and after the coarse correction on every level; 0: 2 in "
               "2D, 3 in 3D (docs/solvers.md, measured).",
               0, 20);
    declareReal(il, "Multigrid smoother eigenvalue ratio", 10.0,
                "Stress block = Multigrid: the Chebyshev smoother damps the spectrum of B A in "
                "[λ_max/ratio, λ_max] (B the patch smoother, λ_max from Lanczos or Arnoldi steps).",
                1.0, true, 1e6, false);
    auto& mp = pl->sublist(
        "MUMPS", false,
        "Options of the MUMPS solver (used when Type = MUMPS, or as the Iterative stress block).");
    declareInt(mp, "Memory relaxation percent", 30,
               "ICNTL(14): workspace added to the analysis estimate, in percent. Pivoting in "
               "indefinite systems can need more; see Workspace retries.",
               0, 100000);
    declareInt(mp, "Workspace retries", 3,
               "On MUMPS errors -8/-9 (workspace too small) refactorise up to this many times, "
               "doubling ICNTL(14) each time.",
               0, 20);
    declareChoice(mp, "Ordering", "AMF", {"Auto", "AMD", "AMF", "SCOTCH", "PORD", "METIS", "QAMD"},
                  "ICNTL(7), the fill-reducing ordering of the (sequential) analysis. METIS: "
                  "computed by StressContact on rank 0 (METIS nested dissection of A + A^T with "
                  "each zero-diagonal row glued to a nonzero-diagonal neighbour and eliminated "
                  "right after it) and given to MUMPS as its pivot order (ICNTL(7) = 1): smaller "
                  "factors than AMF on 3D contact, a slower analysis. SCOTCH: not in Debian's "
                  "MUMPS, which then makes its Auto choice. Auto lets MUMPS choose, which may "
                  "depend on the number of ranks (docs/solvers.md \"Ordering\", measured).");
    declareReal(mp, "Low-rank tolerance", 0.0,
                "CNTL(7): block low-rank (BLR) factorisation with this dropping parameter, "
                "relative to the equilibrated matrix (ICNTL(35) = 2: BLR in the factorisation "
                "and the solve); 0: the exact (full-rank) factorisation. The factors become an "
                "approximation: the solve's relative residual grows with the tolerance and must "
                "stay below 'Maximum relative residual' (docs/solvers.md \"Block low-rank\", "
                "measured).",
                0.0, false, 1e-2, false);
    declareChoice(mp, "Scaling", "Auto", {"Auto", "MUMPS", "None"},
                  "ICNTL(8), MUMPS' own row/column scaling of the matrix it is given (the "
                  "Ruiz-equilibrated one when Equilibrate = true). Auto: none when Equilibrate = "
                  "true (redundant there: 3% of the factorisation time, answers the same to "
                  "1e-10, docs/solvers.md \"Equilibration\"), else MUMPS' choice; MUMPS: "
                  "ICNTL(8) = 77, MUMPS chooses; None: ICNTL(8) = 0.");
    return pl;
  }();
  return valid;
}

Teuchos::ParameterList LinearSolverFactory::validate(const Teuchos::ParameterList& list)
{
  const auto types = knownTypes();
  if (list.isParameter("Type") && list.isType<std::string>("Type")) {
    const auto type = list.get<std::string>("Type");
    if (std::find(types.begin(), types.end(), type) == types.end()) {
      std::ostringstream known;
      for (size_t i = 0; i < types.size(); ++i)
        known << (i ? ", " : "") << types[i];
      const std::string near = sc::core::closestMatch(type, types);
      throw sc::core::InputError("Linear Solver/Type = \"" + type +
                                 "\" is not a known solver type; known types: " + known.str() +
                                 (near.empty() ? "" : " (did you mean " + near + "?)"));
    }
  }
  Teuchos::ParameterList pl(list);
  sc::core::validateParameters(pl, *getValidParameters(), "Linear Solver");
  return pl;
}

Teuchos::RCP<LinearSolver> LinearSolverFactory::create(const Teuchos::ParameterList& pl)
{
  const auto type = pl.get<std::string>("Type");
  SC_THROW_IF(type == "Auto", sc::core::InputError,
              "Linear Solver/Type = Auto is chosen from the problem (dimension, unknowns, ranks, "
              "contact): resolve it with sc::solvers::resolveAutoType, or "
              "createLinearSolver(list, ProblemSize)");
  const auto it = std::find_if(registry().begin(), registry().end(),
                               [&](const auto& t) { return t.first == type; });
  auto solver = it->second(pl);
  solver->setExploitSymmetry(pl.get<bool>("Symmetric"));
  solver->setMaximumRelativeResidual(pl.get<double>("Maximum relative residual"));
  if (auto direct = Teuchos::rcp_dynamic_cast<DirectSolver>(solver); !direct.is_null()) {
    direct->setEquilibration(pl.get<bool>("Equilibrate"));
    direct->setEquilibrationIterations(pl.get<int>("Equilibration iterations"));
  }
  return solver;
}

Teuchos::RCP<LinearSolver> createLinearSolver(const Teuchos::ParameterList& linearSolverList)
{
  return LinearSolverFactory::create(LinearSolverFactory::validate(linearSolverList));
}

bool autoMayUseMultigrid(int dimension, bool contact, int degree)
{
  // With contact rows the multigrid route is verified in 3D at degree 1 only (docs/solvers.md
  // "Contact with the stress multigrid"); 2D always has MUMPS (faster wherever it fits).
  return dimension == 3 && (!contact || degree == 1);
}

long long autoIterativeThreshold(const Teuchos::ParameterList& validatedList, bool contact)
{
  return validatedList.get<int>(contact ? "Auto iterative contact unknowns"
                                        : "Auto iterative unknowns");
}

Teuchos::ParameterList resolveAutoType(const Teuchos::ParameterList& validatedList,
                                       const ProblemSize& problem)
{
  Teuchos::ParameterList pl(validatedList);
  if (pl.get<std::string>("Type") != "Auto") return pl;
  const bool iterative = autoMayUseMultigrid(problem.dimension, problem.contact, problem.degree) &&
                         problem.hierarchy &&
                         problem.dofs >= autoIterativeThreshold(pl, problem.contact);
  pl.set("Type", std::string(iterative ? "Iterative" : "MUMPS"));
  if (iterative) pl.sublist("Iterative").set("Stress block", std::string("Multigrid"));
  return pl;
}

Teuchos::RCP<LinearSolver> createLinearSolver(const Teuchos::ParameterList& linearSolverList,
                                              const ProblemSize& problem)
{
  return LinearSolverFactory::create(
      resolveAutoType(LinearSolverFactory::validate(linearSolverList), problem));
}

Teuchos::RCP<DirectSolver> createDirectSolver(const Teuchos::ParameterList& linearSolverList)
{
  return createDirectSolverFromValidated(LinearSolverFactory::validate(linearSolverList));
}

Teuchos::RCP<DirectSolver>
createDirectSolverFromValidated(const Teuchos::ParameterList& linearSolverList)
{
  auto direct =
      Teuchos::rcp_dynamic_cast<DirectSolver>(LinearSolverFactory::create(linearSolverList));
  SC_THROW_IF(direct.is_null(), sc::core::InputError,
              "Linear Solver/Type = \"" << linearSolverList.get<std::string>("Type")
                                        << "\" is not a direct solver here; use KLU2 or MUMPS");
  return direct;
}

}  // namespace sc::solvers
