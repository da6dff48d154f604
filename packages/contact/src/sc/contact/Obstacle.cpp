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

std::unique_ptr<Obstacle> createObstacle(const ContactSettings& settings, int dim)
{
  SC_THROW_IF(settings.obstacle != "Plane", core::InputError,
              "'Contact/Obstacle' = '" << settings.obstacle << "': valid obstacles: 'Plane'.");
  return std::make_unique<PlaneObstacle>(dim, settings.obstaclePoint, settings.obstacleNormal);
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
