#pragma once
// Hertz's reference values (Johnson, Contact Mechanics, 1985, §4.2 and §4.3) from a computed
// normal load P: a cylinder (2D, plane strain, P per unit thickness) or a sphere (3D) of radius
// R pressed on a rigid plane, E* = E/(1 − ν²):
//   2D: a = √(4PR/(πE*)),      p₀ = 2P/(πa),   p(x) = p₀√(1 − x²/a²);
//   3D: a = (3PR/(4E*))^{1/3}, p₀ = 3P/(2πa²).
// The Half disc / Half ball scenes are finite, so a and p₀ are compared with the values that
// their own P predicts; friction changes the pressure, so only frictionless runs compare.
#include <optional>

namespace sc::core {
struct Material;
}

namespace sc::contact {

struct ContactSummary;

struct HertzReference {
  double halfWidth = 0.0;    ///< a: half-width (2D) or radius (3D) of the contact zone
  double maxPressure = 0.0;  ///< p₀
};

HertzReference hertzFromLoad(int dim, double load, double youngModulus, double poissonRatio,
                             double radius);

/// A computed contact zone against Hertz's values for its own load.
struct HertzComparison {
  HertzReference reference;  ///< from the normal load (the last component of the force)
  /// zone size / a: the outermost half-width in 2D, the equivalent radius √(A/π) in 3D (it
  /// averages over the ragged edge of a 3D zone, docs/contact.md "Outputs").
  double zoneSizeRatio = 0.0;
  double maxPressureRatio = 0.0;  ///< computed peak pressure / p₀
};

/// The comparison of a frictionless run's `summary` on a cylinder (2D) or ball (3D) of
/// `radius` with Hertz's values for its load, E* from `material` (plane stress: E* = E, the
/// plane-strain E/(1 − ν²) at ν = 0); none when the load does not press (≤ 0).
std::optional<HertzComparison> compareWithHertz(int dim, const ContactSummary& summary,
                                                const core::Material& material, double radius);

}  // namespace sc::contact
