#include "ForceBalance.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>

#include <sc/assembly/Reactions.hpp>
#include <sc/core/ProblemData.hpp>
#include <sc/disc/MixedElasticitySpace.hpp>

namespace sc::app {
namespace {

double norm(const std::array<double, 3>& v)
{
  return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
}

std::vector<double> firstComponents(const std::array<double, 3>& v, int d)
{
  return std::vector<double>(v.begin(), v.begin() + d);
}

}  // namespace

CycleForces computeCycleForces(const assembly::MixedElasticityAssembler& assembler,
                               const assembly::MultiVector& solution,
                               const assembly::ElasticityData& data,
                               const std::array<double, 3>* contactForce,
                               const std::array<double, 3>& momentPoint,
                               const Teuchos::Comm<int>& comm)
{
  const int d = assembler.space().dim();
  const auto parts = assembly::computeBoundaryForces(assembler, solution, momentPoint, comm);
  const auto body = assembly::computeBodyForceResultant(assembler, data, comm);
  CycleForces out;
  std::array<double, 3> supports{0, 0, 0}, loads{0, 0, 0}, contact{0, 0, 0};
  double largestPart = 0.0;  // supports may cancel each other (rollers at both ends of a bar)
  if (contactForce) contact = *contactForce;
  for (const auto& p : parts) {
    const auto* bc = data.boundaryConditions.find(p.part);
    const auto type = bc ? bc->type : core::BoundaryType::Free;
    if (type == core::BoundaryType::Contact)
      continue;  // the contact force is the summary's (Σ_p ∫_F w_p τ_p, the same integral)
    // A Components part is a support in its displacement components and a load in the others.
    const bool support =
        type == core::BoundaryType::Displacement || type == core::BoundaryType::Symmetry ||
        type == core::BoundaryType::NormalDisplacement || (bc && bc->hasDisplacementComponent());
    for (int i = 0; i < 3; ++i)
      (support &&
               (type != core::BoundaryType::Components || (i < d && bc->displacementComponent(i)))
           ? supports
           : loads)[i] += p.force[i];
    largestPart = std::max(largestPart, norm(p.force));
    if (!support) continue;
    nlohmann::ordered_json r = {{"type", core::toString(type)},
                                {"force", firstComponents(p.force, d)}};
    if (d == 3)
      r["moment"] = std::vector<double>(p.moment.begin(), p.moment.end());
    else
      r["moment"] = p.moment[2];
    out.reactions[p.part] = std::move(r);
  }
  std::array<double, 3> sum{0, 0, 0};
  for (int i = 0; i < 3; ++i)
    sum[i] = supports[i] + loads[i] + contact[i] + body[i];
  const double scale =
      std::max({norm(supports), norm(loads), norm(contact), norm(body), largestPart});
  out.balance = {{"supports", firstComponents(supports, d)},
                 {"loads", firstComponents(loads, d)},
                 {"contact", firstComponents(contact, d)},
                 {"body", firstComponents(body, d)},
                 {"relative_residual", scale > 0.0 ? norm(sum) / scale : 0.0}};
  return out;
}

std::string forcesBrief(const nlohmann::ordered_json& cycle)
{
  std::ostringstream os;
  os.precision(4);
  if (cycle.contains("reactions"))
    for (const auto& [part, r] : cycle["reactions"].items()) {
      if (r.value("type", "") != "Displacement") continue;
      os << "reaction " << part << " (";
      const auto& f = r["force"];
      for (std::size_t i = 0; i < f.size(); ++i)
        os << (i ? ", " : "") << f[i].get<double>();
      os << "), ";
    }
  if (cycle.contains("contact") && cycle["contact"].contains("area")) {
    const auto& c = cycle["contact"];
    os << "contact area " << c["area"].get<double>();
    if (c.value("stick_area", 0.0) > 0.0) os << " (stick " << c["stick_area"].get<double>() << ")";
    os << ", ";
  }
  if (cycle.contains("force_balance") && cycle["force_balance"].contains("relative_residual"))
    os << "force balance " << cycle["force_balance"]["relative_residual"].get<double>() << ", ";
  return os.str();
}

}  // namespace sc::app
