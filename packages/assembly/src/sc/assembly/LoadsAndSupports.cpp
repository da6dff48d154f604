#include "sc/assembly/LoadsAndSupports.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>

#include <sc/core/Error.hpp>
#include <sc/mesh/SimplexMesh.hpp>

namespace sc::assembly {
namespace {

const char* axisName(int i) { return i == 0 ? "x" : i == 1 ? "y" : "z"; }

}  // namespace

std::map<std::string, int> symmetryAxes(const mesh::SimplexMesh& m,
                                        const core::BoundaryConditions& bcs)
{
  const int d = m.dim();
  const auto& x = m.coordinates();
  double diag2 = 0.0;
  for (int c = 0; c < d; ++c) {
    double lo = x.empty() ? 0.0 : x[c], hi = lo;
    for (std::size_t i = c; i < x.size(); i += d)
      lo = std::min(lo, x[i]), hi = std::max(hi, x[i]);
    diag2 += (hi - lo) * (hi - lo);
  }
  const double tolerance = 1e-9 * std::sqrt(diag2);
  std::map<std::string, int> axes;
  for (const auto& bc : bcs.conditions) {
    if (bc.type != core::BoundaryType::Symmetry || !m.hasBoundary(bc.boundary))
      continue;
    double lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
    bool first = true;
    for (int f : m.boundaryFacesOf(bc.boundary))
      for (int k = 0; k < d; ++k) {
        const double* p = m.vertex(m.faceVertices(f)[k]);
        for (int c = 0; c < d; ++c) {
          lo[c] = first ? p[c] : std::min(lo[c], p[c]);
          hi[c] = first ? p[c] : std::max(hi[c], p[c]);
        }
        first = false;
      }
    int axis = -1;
    for (int c = 0; c < d; ++c)
      if (hi[c] - lo[c] <= tolerance && (axis < 0 || hi[c] - lo[c] < hi[axis] - lo[axis]))
        axis = c;
    if (axis < 0) {
      std::ostringstream extent;
      for (int c = 0; c < d; ++c)
        extent << (c ? ", " : "") << axisName(c) << " in [" << lo[c] << ", " << hi[c] << "]";
      SC_THROW_IF(true, core::InputError,
                  "'Boundary Conditions/" << bc.boundary << "/Type' = 'Symmetry' needs a part that "
                      << (d == 2 ? "lies on a line x = const or y = const"
                                 : "lies in a plane x = const, y = const or z = const")
                      << " (its normal along a coordinate axis), but the vertices of '"
                      << bc.boundary << "' span " << extent.str()
                      << ". Use Type Displacement (with Expression data) on other parts.");
    }
    axes[bc.boundary] = axis;
  }
  return axes;
}

int checkLoadsAndSupports(const mesh::SimplexMesh& m, const ElasticityData& data,
                          const ContactPlane* plane)
{
  const int d = m.dim();
  const auto& bcs = data.boundaryConditions;
  const auto axes = symmetryAxes(m, bcs);
  int heldByContact = -1;
  if (bcs.boundariesOfType(core::BoundaryType::Displacement).empty() && !axes.empty()) {
    std::set<int> normal;
    std::ostringstream parts;
    for (const auto& [name, axis] : axes) {
      normal.insert(axis);
      parts << (parts.tellp() > 0 ? ", " : "") << "'" << name << "' (" << axisName(axis) << " = const)";
    }
    std::ostringstream missing;
    for (int c = 0; c < d; ++c)
      if (!normal.count(c))
        missing << (missing.tellp() > 0 ? ", " : "") << axisName(c);
    // A Symmetry part in x_i = const fixes the rigid motions' u_i on a set spanning the other
    // directions: the translation along x_i and the rotations that move x_i. All d axes fix all.
    // With d − 1 axes every rotation and d − 1 translations are fixed: what is left is the
    // translation along the last axis, which a contact plane normal to it holds once any point
    // is in contact (the contact solver starts from the points nearest the plane).
    int planeAxis = -1;
    if (plane && bcs.hasContact())
      for (int c = 0; c < d; ++c)
        if (std::abs(plane->normal[c]) >= 1.0 - 1e-12)
          planeAxis = c;
    if (static_cast<int>(normal.size()) == d - 1 && planeAxis >= 0 && !normal.count(planeAxis))
      heldByContact = planeAxis;
    SC_THROW_IF(static_cast<int>(normal.size()) < d && heldByContact < 0, core::InputError,
                "the deck has no Displacement part and its Symmetry parts " << parts.str()
                    << " leave rigid-body motions free (nothing holds the body along "
                    << missing.str() << "): the problem is ill-posed. Add a Symmetry part normal "
                    << "to each missing axis or a Displacement part."
                    << (plane && bcs.hasContact()
                            ? " (The contact with the plane 'Contact/Obstacle normal' holds the "
                              "body along that normal only when it is a coordinate axis and the "
                              "Symmetry parts are normal to every other axis.)"
                            : ""));
  }
  // Formulas: finite at the vertices where they are used (Expression throws otherwise, naming the
  // key, the formula and the point).
  for (const auto& bc : bcs.conditions) {
    if (bc.expression.empty() || !m.hasBoundary(bc.boundary))
      continue;
    for (int f : m.boundaryFacesOf(bc.boundary))
      for (int k = 0; k < d; ++k)
        for (const auto& e : bc.expression)
          e(m.vertex(m.faceVertices(f)[k]), d);
  }
  if (!data.exactSolution)
    for (const auto& e : data.bodyForce.expression)
      for (int v = 0; v < m.numVertices(); ++v)
        e(m.vertex(v), d);
  return heldByContact;
}

}  // namespace sc::assembly
