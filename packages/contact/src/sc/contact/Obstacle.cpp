#include "sc/contact/Obstacle.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include <sc/core/Error.hpp>
#include <sc/mesh/SimplexMesh.hpp>

namespace sc::contact {

PlaneObstacle::PlaneObstacle(int dim, const std::vector<double>& point,
                             const std::vector<double>& normal)
  : dim_(dim)
{
  for (int i = 0; i < dim; ++i) {
    point_[i] = point.at(i);
    normal_[i] = normal.at(i);
  }
}

double PlaneObstacle::height(const double* x) const
{
  double h = 0.0;
  for (int i = 0; i < dim_; ++i)
    h += (x[i] - point_[i]) * normal_[i];
  return h;
}

double PlaneObstacle::gap(const double* x, const double* n, double cap) const
{
  // x + s n on the plane: (x + s n − p)·ν = 0 → s = −(x − p)·ν / (n·ν). A point behind the plane
  // (height < 0) gets s < 0: an overlap, not a miss.
  double cosine = 0.0;
  for (int i = 0; i < dim_; ++i)
    cosine += n[i] * normal_[i];
  if (cosine > -1e-12)  // parallel to the plane or pointing away from it
    return cap;
  return std::min(-height(x) / cosine, cap);
}

std::array<double, 3> PlaneObstacle::contactNormal(const double* /*x*/) const
{
  // Out of the body, into the obstacle: −ν. (With +ν the solver "converges" in one step with
  // nothing in contact: the sign trap of docs/theory.md §"Contact and friction", pinned by a test.)
  return {-normal_[0], -normal_[1], -normal_[2]};
}

IndenterObstacle::IndenterObstacle(int dim, const std::vector<double>& center, double radius,
                                   const std::vector<double>& axis,
                                   const std::vector<double>& loadDirection)
  : dim_(dim), radius_(radius), cylinder_(!axis.empty())
{
  SC_THROW_IF(!(radius > 0.0) || !std::isfinite(radius), core::InputError,
              "'Contact/Obstacle radius' = " << radius << " must be a positive number.");
  for (int i = 0; i < dim; ++i) {
    center_[i] = center.at(i);
    load_[i] = loadDirection.at(i);
    if (cylinder_)
      axis_[i] = axis.at(i);
  }
}

std::array<double, 3> IndenterObstacle::across(const double* v) const
{
  std::array<double, 3> r{0, 0, 0};
  for (int i = 0; i < dim_; ++i)
    r[i] = v[i];
  if (cylinder_) {
    double along = 0.0;
    for (int i = 0; i < dim_; ++i)
      along += r[i] * axis_[i];
    for (int i = 0; i < dim_; ++i)
      r[i] -= along * axis_[i];
  }
  return r;
}

double IndenterObstacle::height(const double* x) const
{
  double rel[3] = {0, 0, 0};
  for (int i = 0; i < dim_; ++i)
    rel[i] = x[i] - center_[i];
  const auto r = across(rel);
  return std::sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2]) - radius_;
}

std::array<double, 3> IndenterObstacle::contactNormal(const double* x) const
{
  double rel[3] = {0, 0, 0};
  for (int i = 0; i < dim_; ++i)
    rel[i] = x[i] - center_[i];
  const auto r = across(rel);
  const double len = std::sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2]);
  if (!(len > 1e-12 * radius_))  // on the axis/centre: the loading direction decides
    return {load_[0], load_[1], load_[2]};
  return {-r[0] / len, -r[1] / len, -r[2] / len};
}

double IndenterObstacle::gap(const double* x, const double* n, double cap) const
{
  // |r + s m| = R with r = across(x − c), m = across(n): A s² + 2 b s + c0 = 0.
  double rel[3] = {0, 0, 0};
  for (int i = 0; i < dim_; ++i)
    rel[i] = x[i] - center_[i];
  const auto r = across(rel);
  const auto m = across(n);
  double A = 0.0, b = 0.0, c0 = -radius_ * radius_;
  for (int i = 0; i < 3; ++i) {
    A += m[i] * m[i];
    b += r[i] * m[i];
    c0 += r[i] * r[i];
  }
  if (c0 > 0.0 && b >= 0.0)  // outside, and moving away from (or along) the surface
    return cap;
  if (!(A > 1e-24))  // along the cylinder's axis
    return cap;
  const double disc = b * b - A * c0;
  if (disc < 0.0)  // the ray passes beside the indenter
    return cap;
  // The first crossing from outside (s ≥ 0), or, for a point already inside (an overlap), the
  // way back out (s < 0).
  const double s = (-b - std::sqrt(disc)) / A;
  return std::min(s, cap);
}

std::unique_ptr<Obstacle> createObstacle(const ContactSettings& settings, int dim)
{
  if (settings.obstacle == "Plane")
    return std::make_unique<PlaneObstacle>(dim, settings.obstaclePoint, settings.obstacleNormal);
  SC_THROW_IF(settings.obstacle != "Circle" && settings.obstacle != "Sphere" &&
                  settings.obstacle != "Cylinder",
              core::InputError,
              "'Contact/Obstacle' = '" << settings.obstacle
                                       << "': valid obstacles: 'Plane', 'Circle', 'Sphere', 'Cylinder'.");
  return std::make_unique<IndenterObstacle>(
      dim, settings.obstacleCenter, settings.obstacleRadius,
      settings.obstacle == "Cylinder" ? settings.obstacleAxis : std::vector<double>(),
      settings.obstacleNormal);
}

double missCap(const mesh::SimplexMesh& m)
{
  const int d = m.dim();
  double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300};
  for (int v = 0; v < m.numVertices(); ++v)
    for (int i = 0; i < d; ++i) {
      lo[i] = std::min(lo[i], m.vertex(v)[i]);
      hi[i] = std::max(hi[i], m.vertex(v)[i]);
    }
  double diag = 0.0;
  for (int i = 0; i < d; ++i)
    diag += (hi[i] - lo[i]) * (hi[i] - lo[i]);
  return 10.0 * std::sqrt(diag);
}

void checkObstacle(const mesh::SimplexMesh& m, const ContactSettings& settings,
                   const std::vector<std::string>& contactBoundaries)
{
  const int d = m.dim();
  const auto obstacle = createObstacle(settings, d);
  auto vec = [&](const std::vector<double>& v) {
    std::ostringstream os;
    os << "{";
    for (int i = 0; i < d; ++i)
      os << (i ? ", " : "") << v[i];
    os << "}";
    return os.str();
  };
  // Heights of all vertices (the body) and of the contact boundary's vertices. The mesh is the
  // same on every rank, so every rank reaches the same verdict.
  double lo = 1e300, hi = -1e300, sum = 0.0, contactLo = 1e300;
  for (int v = 0; v < m.numVertices(); ++v) {
    const double h = obstacle->height(m.vertex(v));
    lo = std::min(lo, h);
    hi = std::max(hi, h);
    sum += h;
  }
  std::vector<int> ids;
  for (const auto& name : contactBoundaries)
    ids.push_back(m.boundaryId(name));
  for (int f : m.boundaryFaces()) {
    if (std::find(ids.begin(), ids.end(), m.faceBoundaryId(f)) == ids.end())
      continue;
    for (int i = 0; i < d; ++i)
      contactLo = std::min(contactLo, obstacle->height(m.vertex(m.faceVertices(f)[i])));
  }
  const double mean = sum / std::max(1, m.numVertices());
  if (settings.obstacle != "Plane") {
    // An indenter: the body must lie outside it, and the contact boundary may overlap it by at
    // most the fraction of the body's extent that a plane may (measured radially).
    std::ostringstream where;
    where << "the indenter ('Contact/Obstacle' = '" << settings.obstacle << "', 'Contact/Obstacle "
          << "center' = " << vec(settings.obstacleCenter) << ", 'Contact/Obstacle radius' = "
          << settings.obstacleRadius << ")";
    SC_THROW_IF(mean <= 0.0, core::InputError,
                where.str() << " holds most of the body (mean distance from its surface " << mean
                            << "): the body must lie outside the indenter, which touches its "
                               "contact boundary.");
    const double overlap = std::max(0.0, -contactLo), extent = hi - lo;
    SC_THROW_IF(overlap > kMaxInitialOverlap * extent, core::InputError,
                "the contact boundary starts " << overlap << " deep inside " << where.str()
                    << ", more than " << kMaxInitialOverlap << " of the body's extent " << extent
                    << " measured from the indenter; the small-strain contact model does not "
                       "apply. Move the indenter out of the body (an overlap up to that fraction "
                       "is solved as a prescribed indentation).");
    return;
  }
  // The body mostly behind the plane but partly in front, well beyond the overlap allowed: a
  // plane through the body, which the opposite normal would not mend either.
  const double reach = kMaxInitialOverlap * (hi - lo);
  SC_THROW_IF(mean <= 0.0 && lo < -reach && hi > reach, core::InputError,
              "'Contact/Obstacle point' = " << vec(settings.obstaclePoint) << " and 'Contact/Obstacle "
                  "normal' = " << vec(settings.obstacleNormal) << " give a plane through the body: it "
                  "extends " << -lo << " beyond the plane and " << hi << " in front of it, along the "
                  "normal. Place the plane at the contact boundary ("
                  << (contactBoundaries.empty() ? std::string("the Contact parts") : "'" + contactBoundaries[0] + "'")
                  << "), with the normal pointing from the obstacle towards the body.");
  SC_THROW_IF(mean <= 0.0, core::InputError,
              "'Contact/Obstacle normal' = " << vec(settings.obstacleNormal)
                  << " points away from the body: the body lies on the plane's far side (mean "
                     "height "
                  << mean << " along the normal). The normal must point from the obstacle towards "
                     "the body (here probably the opposite vector).");
  const double extent = hi - lo;
  const double overlap = std::max(0.0, -contactLo);
  SC_THROW_IF(overlap > kMaxInitialOverlap * extent, core::InputError,
              "'Contact/Obstacle point' = " << vec(settings.obstaclePoint)
                  << ": the contact boundary starts " << overlap
                  << " deep inside the obstacle, more than " << kMaxInitialOverlap
                  << " of the body's extent " << extent
                  << " along the obstacle normal; the small-strain contact model does not apply. "
                     "Move the plane out of the body (an overlap up to that fraction is solved "
                     "as a prescribed penetration).");
}

}  // namespace sc::contact
