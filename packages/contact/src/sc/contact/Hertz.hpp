#pragma once
// Hertz's reference values (Johnson, Contact Mechanics, 1985, §4.2 and §4.3) from a computed
// normal load P: a cylinder (2D, plane strain, P per unit thickness) or a sphere (3D) of radius
// R pressed on a rigid plane, E* = E/(1 − ν²):
//   2D: a = √(4PR/(πE*)),      p₀ = 2P/(πa),   p(x) = p₀√(1 − x²/a²);
//   3D: a = (3PR/(4E*))^{1/3}, p₀ = 3P/(2πa²).
// The Half disc / Half ball scenes are finite, so a and p₀ are compared with the values that
// their own P predicts; friction changes the pressure, so only frictionless runs compare.
namespace sc::contact {

struct HertzReference {
  double halfWidth = 0.0;    ///< a: half-width (2D) or radius (3D) of the contact zone
  double maxPressure = 0.0;  ///< p₀
};

HertzReference hertzFromLoad(int dim, double load, double youngModulus, double poissonRatio,
                             double radius);

}  // namespace sc::contact
