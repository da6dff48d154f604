#pragma once
// "Contact": the rigid obstacle, the contact frame and the friction law (docs/theory.md §"Contact
// and friction"), and the semismooth Newton settings of its "Newton" sublist. The contact package
// owns the whole sublist: getValidParameters() describes these keys (the Newton keys are declared
// by ActiveSetSolver::getValidParameters()); fromParameters() reads a validated list once. The
// members carry no defaults of their own: the declarations are the only place a key gets one.
#include <string>
#include <vector>

#include <Teuchos_ParameterList.hpp>
#include <Teuchos_RCP.hpp>

namespace sc::contact {

enum class FrictionLaw { None, Tresca, Coulomb };
/// The contact frame at a contact point (docs/theory.md §"Contact and friction", docs/contact.md
/// "Contact model"): gap, normal stress and friction along the obstacle's normal (exact
/// non-penetration direction for a rigid plane) or along the body's outward face normal (the talk's
/// literal linearisation).
enum class ContactFrame { ObstacleNormal, BodyNormal };

/// "Contact/Newton": the limits and variants of the semismooth Newton (active-set) solver.
struct NewtonSettings {
  int maxIterations{};            ///< Maximum iterations
  double penaltyFactor{};         ///< Penalty factor (on c = 2μ/(h_F |F|))
  int maxRemedies{};              ///< Maximum remedies
  bool hueberStadlerWohlmuth{};   ///< 3D slip linearisation: HSW (true) or Frozen direction
  std::string coulombMethod;      ///< Newton, fixed point fallback | Newton | Fixed point
  int maxFixedPointIterations{};  ///< Maximum fixed-point iterations
  double fixedPointTolerance{};   ///< Fixed-point tolerance

  /// The values of a validated "Newton" list.
  static NewtonSettings fromParameters(const Teuchos::ParameterList& validatedNewton);
  /// The same for a list not yet checked (tests): a copy is validated (errors name
  /// 'Contact/Newton/<key>') and completed with the declared defaults.
  static NewtonSettings fromUncheckedParameters(const Teuchos::ParameterList& newtonList);
};

/// "Contact": the rigid obstacle and the friction law (docs/theory.md §"Contact and friction").
struct ContactSettings {
  std::string obstacle;  ///< Plane, Circle (2D), Sphere (3D), Cylinder (3D), Height function
  std::vector<double> obstaclePoint;  ///< a point of the plane
  /// Plane: its unit normal, pointing into the body. Indenters: the unit direction in which the
  /// indenter presses into the body (the contact summary's load axis).
  std::vector<double> obstacleNormal;
  std::vector<double>
      obstacleCenter;       ///< indenters: centre of the circle/sphere, a point of the axis
  double obstacleRadius{};  ///< indenters: radius
  std::vector<double> obstacleAxis;  ///< Cylinder: unit axis direction
  /// Height function: the formula h of the surface x_d = h(x_1, ..., x_{d-1}) (y = h(x) in 2D,
  /// z = h(x, y) in 3D; the key 'Contact/Obstacle height'); obstacleNormal is ±e_d.
  std::string obstacleHeight;
  /// Height function: the obstacle's displacement at the current load step (d components, or
  /// empty: none); the surface is x_d = o_d + h(x' − o'). The other obstacles move their point or
  /// centre instead.
  std::vector<double> obstacleOffset;
  /// The body's size (its bounding-box diagonal), set with the mesh: the height function's
  /// finite-difference steps are fractions of it.
  double lengthScale = 1.0;
  ContactFrame frame{};
  FrictionLaw frictionLaw{};
  double frictionCoefficient{};
  double trescaBound{};
  NewtonSettings newton;  ///< the "Newton" sublist

  /// Friction rows are built only when they can be non-zero (no friction machinery otherwise).
  bool needsFriction() const
  {
    return (frictionLaw == FrictionLaw::Coulomb && frictionCoefficient > 0.0) ||
           (frictionLaw == FrictionLaw::Tresca && trescaBound > 0.0);
  }
  /// The valid "Contact" list: obstacle, frame and friction keys, and the "Newton" sublist
  /// (ActiveSetSolver::getValidParameters()).
  static Teuchos::RCP<const Teuchos::ParameterList> getValidParameters();
  /// The obstacle, frame, friction and Newton settings of a validated "Contact" list, checked
  /// against the dimension (InputError).
  static ContactSettings fromParameters(const Teuchos::ParameterList& contactList, int dimension);
};

}  // namespace sc::contact
