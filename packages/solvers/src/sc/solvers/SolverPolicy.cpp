#include <sc/solvers/SolverPolicy.hpp>

#include <sc/core/Error.hpp>
#include <sc/solvers/LinearSolverFactory.hpp>

namespace sc::solvers {

SolverPolicy::SolverPolicy(const Teuchos::ParameterList& validatedList, const Scene& scene)
    : list_(validatedList), scene_(scene), type_(validatedList.get<std::string>("Type"))
{
  const auto& il = list_.sublist("Iterative");
  const bool iterative = type_ == "Iterative";
  const bool contact = scene.contact;
  // Stress block = Multigrid, or Type = Auto where it may choose it (3D; with contact at degree
  // 1): keep the nested meshes (the levels are chosen per cycle).
  hierarchy_ = (iterative && il.get<std::string>("Stress block") == "Multigrid") ||
               (isAuto() && autoMayUseMultigrid(scene.dimension, contact, scene.degree));
  // The Krylov solver with contact rows is verified (against MUMPS) at degree 1 in 2D with every
  // stress block (run_hertz2d_iterative, run_hertz2d_multigrid_*) and in 3D with Stress block =
  // Multigrid (run_hertz3d_multigrid_*), and at degree 2 in 2D with Stress block = Multigrid
  // (run_hertz2d_multigrid_degree2_*); other contact scenes are rejected until a test covers them.
  const bool multigrid = il.get<std::string>("Stress block") == "Multigrid";
  const bool verified = (scene.degree == 1 && (scene.dimension == 2 || multigrid)) ||
                        (scene.degree == 2 && scene.dimension == 2 && multigrid);
  SC_THROW_IF(iterative && contact && !verified, core::InputError,
              "Linear Solver/Type = Iterative with contact is verified only at "
              "'Discretization/Degree' = 1 (in 3D only with 'Linear Solver/Iterative/Stress "
              "block' = Multigrid) and in 2D at degree 2 with Stress block = Multigrid "
              "(docs/solvers.md); this scene is "
                  << scene.dimension << "D at degree " << scene.degree << " with Stress block = "
                  << il.get<std::string>("Stress block") << ": use MUMPS or KLU2");
  // MINRES needs a symmetric system: contact rows make it non-symmetric (docs/theory.md
  // §"Contact and friction"), and Symmetric = false declines to exploit symmetry.
  SC_THROW_IF(iterative && il.get<std::string>("Method") == "MINRES" &&
                  (contact || !list_.get<bool>("Symmetric")),
              core::InputError,
              "Linear Solver/Iterative/Method = MINRES needs a symmetric system, but "
                  << (contact ? "this scene has a Contact boundary (contact rows are not symmetric)"
                              : "Linear Solver/Symmetric = false")
                  << "; use GMRES or Auto");
}

std::string SolverPolicy::typeFor(long long dofs) const
{
  if (!isAuto()) return type_;
  return resolveAutoType(list_, problem(dofs)).get<std::string>("Type");
}

Teuchos::RCP<LinearSolver> SolverPolicy::create(long long dofs) const
{
  return LinearSolverFactory::create(resolveAutoType(list_, problem(dofs)));
}

ProblemSize SolverPolicy::problem(long long dofs) const
{
  return {scene_.dimension, dofs, scene_.ranks, scene_.contact, hierarchy_, scene_.degree};
}

int SolverPolicy::gmresBasisVectors() const
{
  return 2 * (list_.sublist("Iterative").get<int>("Restart") + 1);
}

long long SolverPolicy::autoIterativeFrom() const
{
  if (!isAuto() || !hierarchy_) return -1;
  return autoIterativeThreshold(list_, scene_.contact);
}

}  // namespace sc::solvers
