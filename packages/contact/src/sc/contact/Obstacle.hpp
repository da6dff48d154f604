#pragma once
// Rigid obstacles (DESIGN §3): the gap g(p) is the distance from p to the obstacle along the
// face's outward normal n. A ray parallel to the obstacle or hitting it behind p is a miss and
// gets a finite cap (never ∞ or a negative value: c·G is formed), so such points stay free.
// A sphere or cylinder implements the same interface.
#include <array>
#include <memory>

#include <sc/core/ProblemData.hpp>

namespace sc::contact {

class Obstacle {
public:
  virtual ~Obstacle() = default;
  /// Distance along the unit vector n from x to the obstacle, or `cap` if the ray misses it.
  virtual double gap(const double* x, const double* n, double cap) const = 0;
};

/// The plane through `point` with unit normal `normal` pointing towards the body.
class PlaneObstacle : public Obstacle {
public:
  PlaneObstacle(int dim, const std::vector<double>& point, const std::vector<double>& normal);
  double gap(const double* x, const double* n, double cap) const override;

private:
  int dim_;
  std::array<double, 3> point_{}, normal_{};
};

std::unique_ptr<Obstacle> createObstacle(const core::ContactSettings& settings, int dim);

}  // namespace sc::contact
