#pragma once
// Rigid obstacles (docs/theory.md §"Contact and friction", docs/contact.md "Contact model"). A
// contact point measures its gap to the obstacle along the unit normal of its contact frame: the
// obstacle's normal (the exact non-penetration direction for a rigid plane, the default) or the
// body's outward face normal (the talk's literal linearisation). A point behind the obstacle
// surface (an initial overlap) has a negative gap, which the linearised Signorini problem handles.
// Only a ray (nearly) parallel to the obstacle, or pointing away from it, misses: it gets a finite
// cap (never ∞, since c·G is formed), so such points stay free.
#include <array>
#include <memory>
#include <vector>

#include <sc/contact/ContactSettings.hpp>

namespace sc::mesh {
class SimplexMesh;
}

namespace sc::contact {

class Obstacle {
public:
  virtual ~Obstacle() = default;
  /// Signed distance from x to the obstacle along the unit vector n (negative: x is behind the
  /// obstacle's surface), or `cap` if the ray misses it.
  virtual double gap(const double* x, const double* n, double cap) const = 0;
  /// The obstacle-normal frame's normal at x: the unit vector from the body towards the
  /// obstacle (for a plane, minus the plane's normal, which points towards the body).
  virtual std::array<double, 3> contactNormal(const double* x) const = 0;
  /// Signed height of x above the obstacle surface (positive on the body's side).
  virtual double height(const double* x) const = 0;
};

/// The plane through `point` with unit normal `normal` pointing towards the body.
class PlaneObstacle : public Obstacle {
public:
  PlaneObstacle(int dim, const std::vector<double>& point, const std::vector<double>& normal);
  double gap(const double* x, const double* n, double cap) const override;
  std::array<double, 3> contactNormal(const double* x) const override;
  double height(const double* x) const override;

private:
  int dim_;
  std::array<double, 3> point_{}, normal_{};
};

/// A rigid indenter (docs/contact.md "Indenters"): the disc/ball of radius R around `center`
/// (Circle in 2D, Sphere in 3D), or, with a unit `axis`, the infinite cylinder of radius R around
/// the line through `center` along `axis` (3D). The body lies outside it. At a point x of the
/// body, with r the part of x − center across the axis (all of it for a ball): height |r| − R,
/// contact normal −r/|r| (towards the indenter's axis/centre, the normal of its surface at the
/// closest point), and the gap along a unit vector n the distance to the surface along the ray
/// x + s n (negative behind the surface; the miss cap for a ray that misses or leaves it).
class IndenterObstacle : public Obstacle {
public:
  IndenterObstacle(int dim, const std::vector<double>& center, double radius,
                   const std::vector<double>& axis, const std::vector<double>& loadDirection);
  double gap(const double* x, const double* n, double cap) const override;
  std::array<double, 3> contactNormal(const double* x) const override;
  double height(const double* x) const override;

private:
  int dim_;
  std::array<double, 3> center_{}, axis_{}, load_{};
  double radius_;
  bool cylinder_;
  std::array<double, 3> across(const double* v) const;  ///< v without its component along the axis
};

std::unique_ptr<Obstacle> createObstacle(const ContactSettings& settings, int dim);

/// The gap given to rays that miss the obstacle: 10 × the mesh's bounding-box diagonal (finite,
/// since c·G is formed; large enough that such points stay free).
double missCap(const mesh::SimplexMesh& mesh);

/// Largest initial overlap accepted, as a fraction of the body's extent along the obstacle
/// normal: beyond it the small-strain, linearised contact model does not apply.
inline constexpr double kMaxInitialOverlap = 0.1;

/// Checks the obstacle against the body before any solve (also for --check): throws InputError
/// naming 'Contact/Obstacle normal' if the body lies on the obstacle's far side (the normal
/// points away from the body: the solver would "converge" with nothing in contact), and naming
/// 'Contact/Obstacle point' if the contact boundary overlaps the obstacle by more than
/// kMaxInitialOverlap of the body's extent. `contactBoundaries`: boundary names of Type Contact.
void checkObstacle(const mesh::SimplexMesh& mesh, const ContactSettings& settings,
                   const std::vector<std::string>& contactBoundaries);

}  // namespace sc::contact
