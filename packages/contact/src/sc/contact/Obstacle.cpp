#include "sc/contact/Obstacle.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
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
    if (cylinder_) axis_[i] = axis.at(i);
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

namespace {

std::string pointText(const double* x, int n)
{
  std::ostringstream os;
  os << std::setprecision(10) << (n > 1 ? "(" : "");
  for (int i = 0; i < n; ++i)
    os << (i ? ", " : "") << x[i];
  os << (n > 1 ? ")" : "");
  return os.str();
}

}  // namespace

HeightFunctionObstacle::HeightFunctionObstacle(int dim, const std::string& formula, double side,
                                               const std::vector<double>& offset,
                                               double lengthScale)
    : dim_(dim), h_(formula, "'Contact/Obstacle height'"), side_(side > 0.0 ? 1.0 : -1.0)
{
  for (int i = 0; i < dim && i < static_cast<int>(offset.size()); ++i)
    offset_[i] = offset[i];
  const double L = lengthScale > 0.0 && std::isfinite(lengthScale) ? lengthScale : 1.0;
  length_ = L;
  // ∇H (4th order): truncation ~ (δ/ℓ)⁴ and rounding ~ ε ℓ/δ of the slope for a surface with
  // features of size ℓ ~ L, both ~1e-13 at δ = 2e-4 L. The Hessian only steers Newton.
  firstStep_ = 2e-4 * L;
  secondStep_ = 1e-3 * L;
}

double HeightFunctionObstacle::surface(const double* xi) const
{
  double p[2] = {0.0, 0.0};
  for (int i = 0; i + 1 < dim_; ++i)
    p[i] = xi[i] - offset_[i];
  return offset_[dim_ - 1] + h_.unchecked(p, dim_ - 1);
}

bool HeightFunctionObstacle::slope(const double* xi, double* g) const
{
  const int m = dim_ - 1;
  for (int i = 0; i < m; ++i) {
    double z[2] = {xi[0], m > 1 ? xi[1] : 0.0};
    auto at = [&](double k) {
      z[i] = xi[i] + k * firstStep_;
      return surface(z);
    };
    const double p1 = at(1), m1 = at(-1), p2 = at(2), m2 = at(-2);
    // Differences first: exactly 0 for a constant h (the Plane's numbers to rounding).
    g[i] = (8.0 * (p1 - m1) - (p2 - m2)) / (12.0 * firstStep_);
    if (!std::isfinite(g[i])) return false;
  }
  return true;
}

bool HeightFunctionObstacle::hessian(const double* xi, double* H) const
{
  const int m = dim_ - 1;
  const double d = secondStep_;
  auto at = [&](double a, double b) {
    const double z[2] = {xi[0] + a * d, m > 1 ? xi[1] + b * d : 0.0};
    return surface(z);
  };
  const double c = at(0, 0);
  H[0] = ((at(1, 0) - c) + (at(-1, 0) - c)) / (d * d);
  if (m > 1) {
    H[3] = ((at(0, 1) - c) + (at(0, -1) - c)) / (d * d);
    H[1] = H[2] = ((at(1, 1) - at(1, -1)) - (at(-1, 1) - at(-1, -1))) / (4.0 * d * d);
  }
  for (int i = 0; i < m * m; ++i)
    if (!std::isfinite(H[i])) return false;
  return true;
}

std::array<double, 2> HeightFunctionObstacle::closestPoint(const double* x) const
{
  const int m = dim_ - 1;
  const double target = x[m];
  std::array<double, 2> xi{x[0], m > 1 ? x[1] : 0.0};
  auto notFinite = [&](const double* where, const char* what) {
    SC_THROW_IF(true, core::InputError,
                "'Contact/Obstacle height' = '"
                    << h_.formula() << "' gives a " << what << " that is not finite at "
                    << pointText(where, m) << " (t = " << core::Expression::loadTime()
                    << "), where the obstacle's surface next to "
                    << "the body point " << pointText(x, dim_) << " is needed: the height "
                    << "function must be finite, with its slope, over the body's span.");
  };
  auto objective = [&](const double* z) {
    double D = std::pow(surface(z) - target, 2);
    for (int i = 0; i < m; ++i)
      D += std::pow(z[i] - x[i], 2);
    return 0.5 * D;
  };
  double D = objective(xi.data());
  if (!std::isfinite(D)) notFinite(xi.data(), "height");
  const double tolerance = 1e-13 * length_;
  for (int iteration = 0; iteration < 100; ++iteration) {
    double g[2] = {0.0, 0.0}, Hs[4] = {0.0, 0.0, 0.0, 0.0};
    if (!slope(xi.data(), g)) notFinite(xi.data(), "slope");
    const double r = surface(xi.data()) - target;
    double grad[2] = {0.0, 0.0};
    for (int i = 0; i < m; ++i)
      grad[i] = (xi[i] - x[i]) + r * g[i];
    if ((m == 1 ? std::abs(grad[0]) : std::hypot(grad[0], grad[1])) == 0.0) break;
    // Newton's matrix I + ∇H∇Hᵀ + (H − x_d)∇²H where it is positive definite, else the
    // Gauss–Newton matrix I + ∇H∇Hᵀ (always positive definite): a descent direction either way.
    double J[4];
    auto gaussNewton = [&] {
      for (int i = 0; i < m; ++i)
        for (int j = 0; j < m; ++j)
          J[i * m + j] = (i == j ? 1.0 : 0.0) + g[i] * g[j];
    };
    gaussNewton();
    if (hessian(xi.data(), Hs)) {
      double N[4];
      for (int k = 0; k < m * m; ++k)
        N[k] = J[k] + r * Hs[k];
      const bool definite = m == 1 ? N[0] > 0.0 : (N[0] > 0.0 && N[0] * N[3] - N[1] * N[2] > 0.0);
      if (definite) std::copy(N, N + m * m, J);
    }
    double step[2];
    if (m == 1) {
      step[0] = -grad[0] / J[0];
    } else {
      const double det = J[0] * J[3] - J[1] * J[2];
      step[0] = -(J[3] * grad[0] - J[1] * grad[1]) / det;
      step[1] = -(-J[2] * grad[0] + J[0] * grad[1]) / det;
    }
    double slopeAlong = 0.0;
    for (int i = 0; i < m; ++i)
      slopeAlong += grad[i] * step[i];
    // Backtracking (Armijo) on the squared distance. Near the solution the distance changes by
    // less than its rounding (it is stationary there: it fixes ξ to √ε only), so a step that
    // halves the stationarity residual is accepted too (that fixes ξ to ε). Neither: converged
    // to rounding.
    const double residual = m == 1 ? std::abs(grad[0]) : std::hypot(grad[0], grad[1]);
    auto residualAt = [&](const double* z) {
      double gz[2] = {0.0, 0.0};
      if (!slope(z, gz)) return std::nan("");
      const double rz = surface(z) - target;
      double q = 0.0;
      for (int i = 0; i < m; ++i)
        q += std::pow((z[i] - x[i]) + rz * gz[i], 2);
      return std::sqrt(q);
    };
    double alpha = 1.0, trialD = D;
    std::array<double, 2> trial = xi;
    bool accepted = false;
    for (int k = 0; k < 40 && !accepted; ++k, alpha *= 0.5) {
      for (int i = 0; i < m; ++i)
        trial[i] = xi[i] + alpha * step[i];
      trialD = objective(trial.data());
      accepted = std::isfinite(trialD) && (trialD <= D + 1e-4 * alpha * slopeAlong ||
                                           residualAt(trial.data()) <= 0.5 * residual);
    }
    if (!accepted) break;
    double moved = 0.0;
    for (int i = 0; i < m; ++i)
      moved = std::max(moved, std::abs(trial[i] - xi[i]));
    xi = trial;
    D = trialD;
    if (moved <= tolerance) break;
  }
  return xi;
}

std::array<double, 3> HeightFunctionObstacle::bodyNormal(const double* xi) const
{
  const int m = dim_ - 1;
  double g[2] = {0.0, 0.0};
  if (!slope(xi, g))
    SC_THROW_IF(
        true, core::InputError,
        "'Contact/Obstacle height' = '"
            << h_.formula() << "' has a slope that is not "
            << "finite at " << pointText(xi, m) << " (t = " << core::Expression::loadTime()
            << "): the height function must be finite, with its slope, over the body's span.");
  double norm = 1.0;
  for (int i = 0; i < m; ++i)
    norm += g[i] * g[i];
  norm = std::sqrt(norm);
  std::array<double, 3> nu{0.0, 0.0, 0.0};
  for (int i = 0; i < m; ++i)
    nu[i] = -side_ * g[i] / norm;
  nu[m] = side_ / norm;
  return nu;
}

double HeightFunctionObstacle::height(const double* x) const
{
  const auto xi = closestPoint(x);
  const auto nu = bodyNormal(xi.data());
  const int m = dim_ - 1;
  double h = (x[m] - surface(xi.data())) * nu[m];
  for (int i = 0; i < m; ++i)
    h += (x[i] - xi[i]) * nu[i];
  return h;
}

std::array<double, 3> HeightFunctionObstacle::contactNormal(const double* x) const
{
  const auto xi = closestPoint(x);
  const auto nu = bodyNormal(xi.data());
  return {-nu[0], -nu[1], -nu[2]};
}

double HeightFunctionObstacle::gap(const double* x, const double* n, double cap) const
{
  // φ(s) = side (x_d + s n_d − H(x' + s n')): positive on the body's side, decreasing along a ray
  // that enters the obstacle. For a flat h this is the plane's −height/(n·ν), to rounding.
  const int m = dim_ - 1;
  auto base = [&](double s, double* z) {
    for (int i = 0; i < m; ++i)
      z[i] = x[i] + s * n[i];
  };
  auto phi = [&](double s) {
    double z[2] = {0.0, 0.0};
    base(s, z);
    return side_ * (x[m] + s * n[m] - surface(z));
  };
  auto dphi = [&](double s, double* value) {
    double z[2] = {0.0, 0.0}, g[2] = {0.0, 0.0};
    base(s, z);
    if (!slope(z, g)) return false;
    double along = n[m];
    for (int i = 0; i < m; ++i)
      along -= g[i] * n[i];
    *value = side_ * along;
    return true;
  };
  auto notFinite = [&](double s) {
    double z[2] = {0.0, 0.0};
    base(s, z);
    SC_THROW_IF(
        true, core::InputError,
        "'Contact/Obstacle height' = '"
            << h_.formula() << "' is not finite, with its "
            << "slope, at " << pointText(z, m) << " (t = " << core::Expression::loadTime()
            << "), on the ray from the body point " << pointText(x, dim_)
            << " to the obstacle: the height function must be finite over the body's span.");
  };
  const double f0 = phi(0.0);
  double g0 = 0.0;
  if (!std::isfinite(f0) || !dphi(0.0, &g0)) notFinite(0.0);
  if (!(g0 < -1e-12))  // parallel to the surface or leaving it (as for the plane)
    return cap;
  if (f0 == 0.0) return 0.0;
  const double dir = f0 > 0.0 ? 1.0 : -1.0;  // the root lies ahead (outside) or behind (inside)
  const double stepMax = 0.1 * cap, tolerance = 1e-13 * length_;
  auto same = [&](double f) { return (f > 0.0) == (f0 > 0.0); };
  // Newton from s = 0 towards the surface until it crosses it or converges on one side.
  double s = 0.0, f = f0, lo = 0.0, hi = 0.0;
  bool bracketed = false;
  for (int iteration = 0; iteration < 100 && !bracketed; ++iteration) {
    double g = 0.0;
    double step = dphi(s, &g) && g < 0.0 ? -f / g : dir * stepMax;
    if (std::abs(step) > stepMax) step = dir * stepMax;
    double sNew = s + step, fNew = phi(sNew);
    for (int k = 0; k < 50 && !std::isfinite(fNew); ++k) {
      step *= 0.5;
      sNew = s + step;
      fNew = phi(sNew);
    }
    if (!std::isfinite(fNew)) notFinite(sNew);
    if (std::abs(sNew) > cap) return cap;
    if (fNew == 0.0) return sNew;
    if (!same(fNew)) {
      lo = s, hi = sNew, bracketed = true;
      s = sNew, f = fNew;
      break;
    }
    if (std::abs(sNew - s) <= tolerance) return sNew;
    s = sNew, f = fNew;
  }
  if (!bracketed) return std::min(s, cap);
  // Safeguarded Newton in the bracket [lo, hi] (φ(lo) on f0's side, φ(hi) across).
  for (int iteration = 0; iteration < 200 && std::abs(hi - lo) > tolerance; ++iteration) {
    double g = 0.0;
    double sNew = dphi(s, &g) && g != 0.0 ? s - f / g : 0.5 * (lo + hi);
    if (!(sNew > std::min(lo, hi) && sNew < std::max(lo, hi))) sNew = 0.5 * (lo + hi);
    const double fNew = phi(sNew);
    if (!std::isfinite(fNew)) notFinite(sNew);
    if (fNew == 0.0) return sNew;
    (same(fNew) ? lo : hi) = sNew;
    const bool converged = std::abs(sNew - s) <= tolerance;
    s = sNew, f = fNew;
    if (converged) break;
  }
  return std::min(s, cap);
}

std::unique_ptr<Obstacle> createObstacle(const ContactSettings& settings, int dim)
{
  if (settings.obstacle == "Plane")
    return std::make_unique<PlaneObstacle>(dim, settings.obstaclePoint, settings.obstacleNormal);
  if (settings.obstacle == "Height function")
    return std::make_unique<HeightFunctionObstacle>(dim, settings.obstacleHeight,
                                                    settings.obstacleNormal.at(dim - 1),
                                                    settings.obstacleOffset, settings.lengthScale);
  SC_THROW_IF(
      settings.obstacle != "Circle" && settings.obstacle != "Sphere" &&
          settings.obstacle != "Cylinder",
      core::InputError,
      "'Contact/Obstacle' = '"
          << settings.obstacle
          << "': valid obstacles: 'Plane', 'Circle', 'Sphere', 'Cylinder', 'Height function'.");
  return std::make_unique<IndenterObstacle>(dim, settings.obstacleCenter, settings.obstacleRadius,
                                            settings.obstacle == "Cylinder" ? settings.obstacleAxis
                                                                            : std::vector<double>(),
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
  const bool graph = settings.obstacle == "Height function";
  if (graph) {
    // The height function and its slope must be finite over the body's span (the projection
    // of its bounding box onto the plane of the graph): at every vertex's foot and on a grid.
    const HeightFunctionObstacle surface(d, settings.obstacleHeight, settings.obstacleNormal[d - 1],
                                         settings.obstacleOffset, settings.lengthScale);
    const int e = d - 1;  // the graph's dimension
    double lo[2] = {1e300, 1e300}, hi[2] = {-1e300, -1e300};
    for (int v = 0; v < m.numVertices(); ++v)
      for (int i = 0; i < e; ++i) {
        lo[i] = std::min(lo[i], m.vertex(v)[i]);
        hi[i] = std::max(hi[i], m.vertex(v)[i]);
      }
    auto probe = [&](const double* xi) {
      const double H = surface.surface(xi);
      double g[2];
      const bool finite = std::isfinite(H);
      if (finite && surface.slope(xi, g)) return;
      std::ostringstream span;
      for (int i = 0; i < e; ++i)
        span << (i ? " × " : "") << "[" << lo[i] << ", " << hi[i] << "]";
      SC_THROW_IF(true, core::InputError,
                  "'Contact/Obstacle height' = '"
                      << settings.obstacleHeight << "' is not finite"
                      << (finite ? " in its slope" : "") << " at " << (e == 1 ? "x" : "(x, y)")
                      << " = " << pointText(xi, e) << " (t = " << core::Expression::loadTime()
                      << "), inside the body's span " << (e == 1 ? "x" : "(x, y)") << " ∈ "
                      << span.str()
                      << ": the height function must be finite, with its slope, "
                         "over the whole span of the body, beyond the contact zone too (continue "
                         "it there, e.g. with a conditional a ? b : c).");
    };
    for (int v = 0; v < m.numVertices(); ++v)
      probe(m.vertex(v));
    const int n = e == 1 ? 400 : 40;
    for (int i = 0; i <= n; ++i)
      for (int j = 0; j <= (e == 1 ? 0 : n); ++j) {
        const double xi[2] = {lo[0] + (hi[0] - lo[0]) * i / n,
                              e == 1 ? 0.0 : lo[1] + (hi[1] - lo[1]) * j / n};
        probe(xi);
      }
  }
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
    if (std::find(ids.begin(), ids.end(), m.faceBoundaryId(f)) == ids.end()) continue;
    for (int i = 0; i < d; ++i)
      contactLo = std::min(contactLo, obstacle->height(m.vertex(m.faceVertices(f)[i])));
  }
  const double mean = sum / std::max(1, m.numVertices());
  if (graph) {
    const bool above = settings.obstacleNormal[d - 1] < 0.0;  // the obstacle above the body
    std::ostringstream where;
    where << "the obstacle " << (above ? "above" : "below") << " the surface "
          << (d == 2 ? "y = h(x)" : "z = h(x, y)") << " of 'Contact/Obstacle height' = '"
          << settings.obstacleHeight << "'";
    SC_THROW_IF(mean <= 0.0, core::InputError,
                where.str() << " holds most of the body (mean signed distance " << mean
                            << " along 'Contact/Obstacle normal' = " << vec(settings.obstacleNormal)
                            << "): the body must lie " << (above ? "below" : "above")
                            << " the surface, or the normal is the opposite vector (it points "
                               "from the obstacle towards the body).");
    const double overlap = std::max(0.0, -contactLo), extent = hi - lo;
    SC_THROW_IF(overlap > kMaxInitialOverlap * extent, core::InputError,
                "'Contact/Obstacle height': the contact boundary starts "
                    << overlap << " deep inside " << where.str() << ", more than "
                    << kMaxInitialOverlap << " of the body's extent " << extent
                    << " measured from the surface; the small-strain contact model does not "
                       "apply. Move the surface out of the body (an overlap up to that fraction "
                       "is solved as a prescribed indentation).");
    return;
  }
  if (settings.obstacle != "Plane") {
    // An indenter: the body must lie outside it, and the contact boundary may overlap it by at
    // most the fraction of the body's extent that a plane may (measured radially).
    std::ostringstream where;
    where << "the indenter ('Contact/Obstacle' = '" << settings.obstacle << "', 'Contact/Obstacle "
          << "center' = " << vec(settings.obstacleCenter)
          << ", 'Contact/Obstacle radius' = " << settings.obstacleRadius << ")";
    SC_THROW_IF(mean <= 0.0, core::InputError,
                where.str() << " holds most of the body (mean distance from its surface " << mean
                            << "): the body must lie outside the indenter, which touches its "
                               "contact boundary.");
    const double overlap = std::max(0.0, -contactLo), extent = hi - lo;
    SC_THROW_IF(overlap > kMaxInitialOverlap * extent, core::InputError,
                "the contact boundary starts "
                    << overlap << " deep inside " << where.str() << ", more than "
                    << kMaxInitialOverlap << " of the body's extent " << extent
                    << " measured from the indenter; the small-strain contact model does not "
                       "apply. Move the indenter out of the body (an overlap up to that fraction "
                       "is solved as a prescribed indentation).");
    return;
  }
  // The body mostly behind the plane but partly in front, well beyond the overlap allowed: a
  // plane through the body, which the opposite normal would not mend either.
  const double reach = kMaxInitialOverlap * (hi - lo);
  SC_THROW_IF(mean <= 0.0 && lo < -reach && hi > reach, core::InputError,
              "'Contact/Obstacle point' = "
                  << vec(settings.obstaclePoint)
                  << " and 'Contact/Obstacle "
                     "normal' = "
                  << vec(settings.obstacleNormal)
                  << " give a plane through the body: it "
                     "extends "
                  << -lo << " beyond the plane and " << hi
                  << " in front of it, along the "
                     "normal. Place the plane at the contact boundary ("
                  << (contactBoundaries.empty() ? std::string("the Contact parts")
                                                : "'" + contactBoundaries[0] + "'")
                  << "), with the normal pointing from the obstacle towards the body.");
  SC_THROW_IF(mean <= 0.0, core::InputError,
              "'Contact/Obstacle normal' = "
                  << vec(settings.obstacleNormal)
                  << " points away from the body: the body lies on the plane's far side (mean "
                     "height "
                  << mean
                  << " along the normal). The normal must point from the obstacle towards "
                     "the body (here probably the opposite vector).");
  const double extent = hi - lo;
  const double overlap = std::max(0.0, -contactLo);
  SC_THROW_IF(overlap > kMaxInitialOverlap * extent, core::InputError,
              "'Contact/Obstacle point' = "
                  << vec(settings.obstaclePoint) << ": the contact boundary starts " << overlap
                  << " deep inside the obstacle, more than " << kMaxInitialOverlap
                  << " of the body's extent " << extent
                  << " along the obstacle normal; the small-strain contact model does not apply. "
                     "Move the plane out of the body (an overlap up to that fraction is solved "
                     "as a prescribed penetration).");
}

}  // namespace sc::contact
