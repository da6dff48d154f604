#include "sc/contact/ContactPoint.hpp"

#include <cmath>

#include <sc/core/Error.hpp>
#include <sc/disc/Bernstein.hpp>

namespace sc::contact {

std::string toString(PointStatus s)
{
  switch (s) {
  case PointStatus::Free: return "free";
  case PointStatus::Stick: return "stick";
  case PointStatus::Slip: return "slip";
  }
  return "?";
}

std::array<double, 2> ContactPoint::previousRT() const
{
  double a = 0.0, b = 0.0;
  for (int i = 0; i < 3; ++i) {
    a += history[i] * t1[i];
    b += history[i] * t2[i];
  }
  return {a, b};
}

void commitLoadStep(std::vector<ContactPoint>& points)
{
  for (auto& p : points)
    for (int i = 0; i < 3; ++i)
      p.history[i] = p.rT[0] * p.t1[i] + p.rT[1] * p.t2[i];
  for (auto& p : points)
    p.previousRN = p.rN;
}

std::vector<std::string> csvColumns(int dim)
{
  std::vector<std::string> columns = {"x", "y"};
  if (dim == 3) columns.push_back("z");
  columns.insert(columns.end(), {"sigma_n", "sigma_t"});
  if (dim == 3) columns.push_back("sigma_t2");
  columns.insert(columns.end(), {"weighted_gap", "weighted_slip", "status"});
  return columns;
}

std::vector<double> csvValues(const ContactPoint& p, int dim)
{
  std::vector<double> v(p.x.begin(), p.x.begin() + dim);
  v.push_back(p.sigmaN);
  v.insert(v.end(), p.sigmaT.begin(), p.sigmaT.begin() + (dim - 1));
  v.push_back(p.gap - p.rN);  // G − r_N ≥ 0: the weighted gap left open
  v.push_back(dim == 2 ? p.rT[0] : std::hypot(p.rT[0], p.rT[1]));
  return v;
}

std::vector<PointValues> pointValues(const std::vector<ContactPoint>& points, int dim, int degree,
                                     bool bernsteinCoefficients)
{
  std::vector<PointValues> values(points.size());
  // The points of each face (its block in the solver), by their index within the face.
  std::map<int, std::vector<std::size_t>> faces;
  for (std::size_t i = 0; i < points.size(); ++i) {
    auto& f = faces[points[i].block];
    const auto index = static_cast<std::size_t>(points[i].index);
    if (f.size() <= index) f.resize(index + 1, points.size());
    f[index] = i;
  }
  const auto alphas = bernsteinCoefficients ? disc::bernsteinIndices(degree, dim)
                                            : std::vector<std::array<int, 3>>();
  for (const auto& [block, members] : faces) {
    SC_THROW_IF(bernsteinCoefficients && members.size() != alphas.size(), core::InternalError,
                "contact::pointValues: face block " << block << " has " << members.size()
                                                    << " points, its degree " << degree << " needs "
                                                    << alphas.size());
    for (std::size_t p = 0; p < members.size(); ++p) {
      SC_THROW_IF(members[p] == points.size(), core::InternalError,
                  "contact::pointValues: point " << p << " of face block " << block
                                                 << " is missing");
      const ContactPoint& cp = points[members[p]];
      PointValues& v = values[members[p]];
      if (!bernsteinCoefficients) {
        v.pressure = -cp.sigmaN;
        v.sigmaT = cp.sigmaT;
      } else {
        std::array<double, 3> lambda{};
        for (int i = 0; i < 3; ++i)
          lambda[i] = alphas[p][i] / static_cast<double>(degree);
        double sigmaN = 0.0;
        for (std::size_t q = 0; q < members.size(); ++q) {
          const double b = disc::bernstein(alphas[q], lambda, degree);
          const ContactPoint& cq = points[members[q]];
          sigmaN += b * cq.sigmaN;
          v.sigmaT[0] += b * cq.sigmaT[0];
          v.sigmaT[1] += b * cq.sigmaT[1];
        }
        v.pressure = -sigmaN;
      }
      v.gap = (cp.gap - cp.rN) / cp.weight;
      v.slip = {cp.rT[0] / cp.weight, cp.rT[1] / cp.weight};
    }
  }
  return values;
}

std::map<int, FaceTraction> faceMeans(const std::vector<ContactPoint>& points)
{
  std::map<int, std::array<double, 3>> sums;  // face -> (Σ −σ_N, Σ σ_T1, count)
  for (const auto& p : points) {
    auto& s = sums[p.face];
    s[0] += -p.sigmaN;
    s[1] += p.sigmaT[0];
    s[2] += 1.0;
  }
  std::map<int, FaceTraction> means;
  for (const auto& [face, s] : sums)
    means[face] = {s[0] / s[2], s[1] / s[2]};
  return means;
}

}  // namespace sc::contact
