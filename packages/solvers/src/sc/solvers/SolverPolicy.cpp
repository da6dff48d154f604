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
  // Stress block = Multigrid, or Type = Auto where it may choose it (3D without contact): keep
  // the nested meshes (the levels are chosen per cycle).
  hierarchy_ = (iterative && il.get<std::string>("Stress block") == "Multigrid") ||
               (isAuto() && scene.dimension == 3 && !contact);
  // The Krylov solver with contact rows is verified (against MUMPS: run_hertz2d_iterative, and
  // with Stress block = Multigrid run_hertz2d_multigrid_*) in 2D at degree 1 only; other contact
  // scenes are rejected until a test covers them.
  SC_THROW_IF(iterative && contact && (scene.dimension != 2 || scene.degree != 1), core::InputError,
              "Linear Solver/Type = Iterative with contact is verified only in 2D at "
              "'Discretization/Degree' = 1 (docs/solvers.md); this scene is "
                  << scene.dimension << "D at degree " << scene.degree << ": use MUMPS or KLU2");
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
  return resolveAutoType(list_, {scene_.dimension, dofs, scene_.ranks, scene_.contact, hierarchy_})
      .get<std::string>("Type");
}

Teuchos::RCP<LinearSolver> SolverPolicy::create(long long dofs) const
{
  return LinearSolverFactory::create(
      resolveAutoType(list_, {scene_.dimension, dofs, scene_.ranks, scene_.contact, hierarchy_}));
}

}  // namespace sc::solvers
