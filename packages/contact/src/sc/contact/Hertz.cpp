#include "sc/contact/Hertz.hpp"

#include <cmath>

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

}  // namespace sc::contact
