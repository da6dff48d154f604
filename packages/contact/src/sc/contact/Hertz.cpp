#include "sc/contact/Hertz.hpp"

#include <cmath>

#include <sc/core/ProblemData.hpp>

#include "sc/contact/ContactSummary.hpp"

namespace sc::contact {

HertzReference hertzFromLoad(int dim, double P, double E, double nu, double R)
{
  const double estar = E / (1.0 - nu * nu);
  HertzReference h;
  if (dim == 2) {
    h.halfWidth = std::sqrt(4.0 * P * R / (M_PI * estar));
    h.maxPressure = 2.0 * P / (M_PI * h.halfWidth);
  } else {
    h.halfWidth = std::cbrt(3.0 * P * R / (4.0 * estar));
    h.maxPressure = 3.0 * P / (2.0 * M_PI * h.halfWidth * h.halfWidth);
  }
  return h;
}

std::optional<HertzComparison> compareWithHertz(int dim, const ContactSummary& summary,
                                                const core::Material& material, double radius)
{
  const double load = summary.force[dim - 1];
  if (!(load > 0.0)) return std::nullopt;
  HertzComparison c;
  c.reference = hertzFromLoad(dim, load, material.youngModulus,
                              material.planeStress ? 0.0 : material.poissonRatio, radius);
  c.zoneSizeRatio =
      (dim == 2 ? summary.zoneSize : summary.equivalentZoneSize) / c.reference.halfWidth;
  c.maxPressureRatio = summary.maxPressure / c.reference.maxPressure;
  return c;
}

}  // namespace sc::contact
