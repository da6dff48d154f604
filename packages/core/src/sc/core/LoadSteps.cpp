#include "sc/core/LoadSteps.hpp"

#include <cmath>

#include "sc/core/Error.hpp"
#include "sc/core/Parameters.hpp"

namespace sc::core {

Teuchos::RCP<const Teuchos::ParameterList> LoadSteps::getValidParameters()
{
  static Teuchos::RCP<const Teuchos::ParameterList> valid = [] {
    auto pl = Teuchos::rcp(new Teuchos::ParameterList("Load steps"));
    declareRealArray(*pl, "Times", Teuchos::Array<double>(),
                     "Pseudo-times t_1 < t_2 < ... < t_n of the load steps (t_1 > 0; the unloaded "
                     "state is t = 0). Each step is solved from the state of the step before: "
                     "Coulomb and Tresca friction act on the slip increment (docs/theory.md "
                     "§\"Load steps\"). Empty: one step at t = 1. The data of each step: the "
                     "'Values per step' rows of the boundary parts and of the Body Force, "
                     "formulas of t, and 'Obstacle displacement'.",
                     {});
    declareInt(*pl, "Cycles per later step", 0,
               "Adaptive cycles of every step after the first, on the last mesh of the step "
               "before (0: one solve per step on that mesh). The first step runs "
               "'Adaptivity/Cycles'; every step stops earlier by the other stop criteria.",
               0, 1000);
    declareRealArray(*pl, "Obstacle displacement", Teuchos::Array<double>(),
                     "The rigid obstacle's displacement at each step, row after row (one value "
                     "per dimension per step), added to 'Contact/Obstacle point' (a plane) or "
                     "'Contact/Obstacle center' (an indenter), or moving the surface of a height "
                     "function as a whole. Empty: the obstacle stays.",
                     {});
    return pl;
  }();
  return valid;
}

LoadSteps LoadSteps::fromParameters(const Teuchos::ParameterList& list, int dimension)
{
  LoadSteps s;
  const auto times = list.get<Teuchos::Array<double>>("Times");
  if (!times.empty()) {
    s.given = true;
    s.times.assign(times.begin(), times.end());
    SC_THROW_IF(!(s.times[0] > 0.0) || !std::isfinite(s.times[0]), InputError,
                "'Load steps/Times' starts at "
                    << s.times[0]
                    << ": the first step's time must be positive and finite (t = 0 is the "
                       "unloaded state).");
    for (std::size_t i = 1; i < s.times.size(); ++i)
      SC_THROW_IF(!(s.times[i] > s.times[i - 1]) || !std::isfinite(s.times[i]), InputError,
                  "'Load steps/Times' entry "
                      << i + 1 << " (" << s.times[i] << ") does not follow entry " << i << " ("
                      << s.times[i - 1] << "): the times must increase strictly.");
  }
  s.cyclesPerLaterStep = list.get<int>("Cycles per later step");
  const auto obstacle = list.get<Teuchos::Array<double>>("Obstacle displacement");
  s.obstacleDisplacement.assign(obstacle.begin(), obstacle.end());
  SC_THROW_IF(!s.obstacleDisplacement.empty() &&
                  s.obstacleDisplacement.size() !=
                      static_cast<std::size_t>(s.numSteps() * dimension),
              InputError,
              "'Load steps/Obstacle displacement' has "
                  << s.obstacleDisplacement.size() << " numbers, but " << s.numSteps()
                  << " step(s) in " << dimension << "D need " << s.numSteps() * dimension
                  << " (one row of " << dimension << " per entry of 'Load steps/Times').");
  return s;
}

std::vector<double> LoadSteps::obstacleDisplacementAt(int step, int dimension) const
{
  if (obstacleDisplacement.empty()) return std::vector<double>(dimension, 0.0);
  const auto first = obstacleDisplacement.begin() + static_cast<std::ptrdiff_t>(step * dimension);
  return {first, first + dimension};
}

}  // namespace sc::core
