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
#include <string>
#include <vector>

#include <sc/contact/ContactSettings.hpp>
#include <sc/core/Expression.hpp>

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

/// A rigid obstacle bounded by the graph of a height function (docs/contact.md "Height
/// function"): the surface x_d = H(x') = o_d + h(x' − o'), x' = (x_1, ..., x_{d−1}) (y = h(x) in
/// 2D, z = h(x, y) in 3D), h the deck's formula and o the obstacle's displacement at the load
/// step; the body lies on the side `side` e_d of it (side = ±1, the Obstacle normal). At a point x:
/// the closest point P = (ξ, H(ξ)) of the graph (Newton on the stationarity of ½|ξ − x'|² +
/// ½(H(ξ) − x_d)², backtracking, started from the vertical projection ξ = x'), the body-side
/// normal ν = side (−∇H, 1)/√(1 + |∇H|²) at P, height (x − P)·ν (the signed distance), contact
/// normal −ν (into the obstacle), and the gap along n the root of side (x_d + s n_d − H(x' + s n'))
/// nearest to s = 0 on the side the ray meets the surface (Newton with bracketing). ∇H and the
/// Hessian are central finite differences (4th and 2nd order) with steps that are fixed
/// fractions of the body's size: exact for an affine h, within ~1e-12 of the slope otherwise.
/// A flat h reproduces the Plane's numbers (the same formulas to rounding).
class HeightFunctionObstacle : public Obstacle {
public:
  HeightFunctionObstacle(int dim, const std::string& formula, double side,
                         const std::vector<double>& offset, double lengthScale);
  double gap(const double* x, const double* n, double cap) const override;
  std::array<double, 3> contactNormal(const double* x) const override;
  double height(const double* x) const override;

  /// H at the surface point ξ (d − 1 coordinates), NaN or ±inf where the formula is not finite.
  double surface(const double* xi) const;
  /// ∇H at ξ by 4th-order central differences; false if a stencil value is not finite.
  bool slope(const double* xi, double* gradient) const;
  /// The closest point's ξ of the graph to x (see the class comment).
  std::array<double, 2> closestPoint(const double* x) const;

private:
  int dim_;
  core::Expression h_;
  double side_;
  std::array<double, 3> offset_{};
  double length_;                  ///< the body's size: the searches' tolerances are 1e-13 of it
  double firstStep_, secondStep_;  ///< finite-difference steps of ∇H and of the Hessian
  bool hessian(const double* xi, double* H) const;
  std::array<double, 3> bodyNormal(const double* xi) const;  ///< ν at the surface point over ξ
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
