#pragma once
// The reactions and the force balance of a solved cycle for summary.json and the cycle's
// progress summary (docs/output.md "summary.json": reactions, force_balance).
#include <array>
#include <string>

#include <Teuchos_Comm.hpp>
#include <nlohmann/json.hpp>

#include <sc/assembly/MixedElasticityAssembler.hpp>

namespace sc::app {

struct CycleForces {
  /// part → {type, force (d), moment (3 components in 3D, the z component in 2D)} for every
  /// part of Type Displacement, Symmetry or Normal displacement, and of Type Components with a
  /// displacement component (its whole force), in the mesh's part order.
  nlohmann::ordered_json reactions = nlohmann::ordered_json::object();
  /// supports, loads, contact, body (d components each) and relative_residual.
  nlohmann::ordered_json balance = nlohmann::ordered_json::object();
};

/// Every term is a force on the body: `supports` the sum of the reactions, `loads` the sum of
/// ∫ σ_h n over the parts of Type Traction, Pressure and Free (and parts the deck does not name;
/// a Components part adds its traction components here and the others to `supports`),
/// `contact` the contact force of the summary (`contactForce`, null without contact), `body`
/// ∫ f dx. Their sum vanishes up to the linear solver's residual; relative_residual is its norm
/// over the largest of the terms' norms (0 when all vanish). Collective.
CycleForces computeCycleForces(const assembly::MixedElasticityAssembler& assembler,
                               const assembly::MultiVector& solution,
                               const assembly::ElasticityData& data,
                               const std::array<double, 3>* contactForce,
                               const std::array<double, 3>& momentPoint,
                               const Teuchos::Comm<int>& comm);

/// The part of the one-line cycle summary on forces, from a cycle entry of summary.json: the force
/// on each Displacement part, the contact area (and stick area with friction), the balance's
/// relative residual; empty when the cycle has none of them.
std::string forcesBrief(const nlohmann::ordered_json& cycle);

}  // namespace sc::app
