#include "sc/assembly/BodySupports.hpp"

#include <set>
#include <sstream>

#include <sc/assembly/LoadsAndSupports.hpp>
#include <sc/core/Error.hpp>
#include <sc/mesh/MeshBodies.hpp>
#include <sc/mesh/SimplexMesh.hpp>

namespace sc::assembly {

void checkEveryBodyIsHeld(const mesh::SimplexMesh& m, const core::BoundaryConditions& bcs)
{
  const auto bodies = mesh::meshBodies(m);
  if (bodies.size() < 2)
    return;
  const int d = m.dim();
  const auto axes = symmetryAxes(m, bcs);
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    bool held = false;
    std::set<int> normal;  // axes of the body's Symmetry parts
    std::ostringstream parts;
    for (int id : bodies[b].boundaryIds) {
      const std::string& name = m.boundaryName(id);
      const core::BoundaryCondition* bc = bcs.find(name);
      const core::BoundaryType type = bc ? bc->type : core::BoundaryType::Free;
      held = held || type == core::BoundaryType::Displacement;
      parts << (parts.tellp() > 0 ? ", " : "") << "'" << name << "' (" << core::toString(type);
      if (type == core::BoundaryType::Symmetry) {
        normal.insert(axes.at(name));
        parts << ", " << "xyz"[axes.at(name)] << " = const";
      }
      parts << (bc ? "" : ", not in 'Boundary Conditions'") << ")";
    }
    held = held || static_cast<int>(normal.size()) == d;
    SC_THROW_IF(!held, core::InputError,
                "the mesh of " << m.origin() << " holds " << bodies.size()
                    << " bodies that share no face, and body " << b + 1 << " of "
                    << bodies.size() << " ("
                    << bodies[b].describe(d) << ") is not held: its boundary parts are "
                    << parts.str() << ". Nothing fixes its rigid-body motions (contact, "
                    << "tractions, pressures and Free parts do not), so the problem is "
                    << "ill-posed. Give one of its parts Type 'Displacement', or give it Symmetry "
                    << "parts normal to every axis; a part may span several bodies.");
  }
}

}  // namespace sc::assembly
