#include "sc/contact/ContactPoint.hpp"

#include <cmath>

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

std::vector<std::string> csvColumns(int dim)
{
  std::vector<std::string> columns = {"x", "y"};
  if (dim == 3)
    columns.push_back("z");
  columns.insert(columns.end(), {"sigma_n", "sigma_t"});
  if (dim == 3)
    columns.push_back("sigma_t2");
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
