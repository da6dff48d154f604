#include "sc/contact/Obstacle.hpp"

#include <sc/core/Error.hpp>

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

double PlaneObstacle::gap(const double* x, const double* n, double cap) const
{
  // x + s n on the plane: (x + s n − p)·ν = 0 → s = −(x − p)·ν / (n·ν).
  double height = 0.0, cosine = 0.0;
  for (int i = 0; i < dim_; ++i) {
    height += (x[i] - point_[i]) * normal_[i];
    cosine += n[i] * normal_[i];
  }
  if (cosine > -1e-12)  // parallel or pointing away from the plane
    return cap;
  const double s = -height / cosine;
  return (s < 0.0 || s > cap) ? cap : s;
}

std::unique_ptr<Obstacle> createObstacle(const core::ContactSettings& settings, int dim)
{
  SC_THROW_IF(settings.obstacle != "Plane", core::InputError,
              "'Contact/Obstacle' = '" << settings.obstacle << "': valid obstacles: 'Plane'.");
  return std::make_unique<PlaneObstacle>(dim, settings.obstaclePoint, settings.obstacleNormal);
}

}  // namespace sc::contact
