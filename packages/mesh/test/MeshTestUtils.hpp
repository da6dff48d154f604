#pragma once
// Helpers shared by the mesh tests.
#include <sc/core/Error.hpp>
#include <sc/mesh/SimplexMesh.hpp>

#include <algorithm>
#include <functional>
#include <cmath>
#include <set>
#include <string>
#include <vector>

namespace sc::mesh::test {

/// The message of the InputError that f throws, or "(no InputError)".
inline std::string errorOf(const std::function<void()>& f)
{
  try {
    f();
  } catch (const sc::core::InputError& e) {
    return e.what();
  }
  return "(no InputError)";
}

inline bool contains(const std::string& text, const std::string& what)
{
  return text.find(what) != std::string::npos;
}

/// Conformity: every face has one (boundary, with a part id) or two (interior) elements, faces of
/// the elements are consistent. Returns an empty string if fine, else what is wrong.
inline std::string conformityProblem(const SimplexMesh& m, bool allowUnnamed = false)
{
  std::vector<int> count(m.numFaces(), 0);
  for (int e = 0; e < m.numElements(); ++e)
    for (int i = 0; i <= m.dim(); ++i)
      ++count[m.elementFaces(e)[i]];
  long nb = 0;
  for (int f = 0; f < m.numFaces(); ++f) {
    const bool boundary = m.isBoundaryFace(f);
    if (count[f] != (boundary ? 1 : 2))
      return "face " + std::to_string(f) + " has " + std::to_string(count[f]) + " elements";
    if (boundary != (m.faceBoundaryId(f) >= 0))
      return "face " + std::to_string(f) + " boundary id mismatch";
    nb += boundary;
  }
  if (nb != static_cast<long>(m.boundaryFaces().size())) return "boundary face count";
  // A hanging face would show up as an untagged boundary face.
  if (!allowUnnamed && m.hasBoundary("Unnamed")) return "untagged boundary faces (hanging faces?)";
  if (m.eulerCharacteristic() != 1)
    return "Euler characteristic " + std::to_string(m.eulerCharacteristic());
  return "";
}

/// Least-squares slope of log(y) against log(x).
inline double fittedSlope(const std::vector<double>& x, const std::vector<double>& y)
{
  const int n = static_cast<int>(x.size());
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (int i = 0; i < n; ++i) {
    const double lx = std::log(x[i]), ly = std::log(y[i]);
    sx += lx, sy += ly, sxx += lx * lx, sxy += lx * ly;
  }
  return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

/// Number of distinct element shapes up to similarity, by sorted angles rounded to 1e-4 degree.
inline std::size_t similarityClasses(const SimplexMesh& m)
{
  std::set<std::vector<long>> classes;
  for (int e = 0; e < m.numElements(); ++e) {
    auto a = m.elementAnglesDeg(e);
    std::sort(a.begin(), a.end());
    std::vector<long> key;
    for (double x : a)
      key.push_back(std::lround(x * 1e4));
    classes.insert(key);
  }
  return classes.size();
}

}  // namespace sc::mesh::test
