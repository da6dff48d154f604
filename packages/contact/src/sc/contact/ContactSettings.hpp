#pragma once
// "Contact": the rigid obstacle, the contact frame and the friction law (docs/theory.md §"Contact
// and friction"). The contact package owns the whole sublist: getValidParameters() describes these
// keys and the "Newton" sublist of ActiveSetSolver (the semismooth Newton settings, read by the
// solver itself); fromParameters() reads a validated list.
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

/// "Contact": the rigid obstacle and the friction law (docs/theory.md §"Contact and friction").
struct ContactSettings {
  std::string obstacle = "Plane";       ///< Plane, Circle (2D), Sphere (3D) or Cylinder (3D)
  std::vector<double> obstaclePoint;   ///< a point of the plane
  /// Plane: its unit normal, pointing into the body. Indenters: the unit direction in which the
  /// indenter presses into the body (the contact summary's load axis).
  std::vector<double> obstacleNormal;
  std::vector<double> obstacleCenter;  ///< indenters: centre of the circle/sphere, a point of the axis
  double obstacleRadius = 1.0;         ///< indenters: radius
  std::vector<double> obstacleAxis;    ///< Cylinder: unit axis direction
  ContactFrame frame = ContactFrame::ObstacleNormal;
  FrictionLaw frictionLaw = FrictionLaw::None;
  double frictionCoefficient = 0.0;
  double trescaBound = 0.0;

  /// Friction rows are built only when they can be non-zero (no friction machinery otherwise).
  bool needsFriction() const
  {
    return (frictionLaw == FrictionLaw::Coulomb && frictionCoefficient > 0.0) ||
           (frictionLaw == FrictionLaw::Tresca && trescaBound > 0.0);
  }
  /// The valid "Contact" list: obstacle, frame and friction keys, and the "Newton" sublist
  /// (ActiveSetSolver::getValidParameters()).
  static Teuchos::RCP<const Teuchos::ParameterList> getValidParameters();
  /// The obstacle, frame and friction of a validated "Contact" list, checked against the
  /// dimension (InputError); its "Newton" sublist goes to the ActiveSetSolver.
  static ContactSettings fromParameters(const Teuchos::ParameterList& contactList, int dimension);
};

}  // namespace sc::contact
