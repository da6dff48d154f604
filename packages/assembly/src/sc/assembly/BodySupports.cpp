#include "sc/assembly/BodySupports.hpp"

#include <map>
#include <sstream>

#include <sc/assembly/LoadsAndSupports.hpp>
#include <sc/core/Error.hpp>
#include <sc/mesh/MeshBodies.hpp>
#include <sc/mesh/SimplexMesh.hpp>

namespace sc::assembly {

void checkEveryBodyIsHeld(const mesh::SimplexMesh& m, const core::BoundaryConditions& bcs)
{
  const auto bodies = mesh::meshBodies(m);
  if (bodies.size() < 2) return;
  const int d = m.dim();
  const auto frames = normalFrameParts(m, bcs);
  const auto supports = supportDirections(m, bcs, frames);
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    bool held = false;
    std::vector<SupportDirection> bodySupports;  // of the body's Symmetry, Components ... parts
    std::ostringstream parts;
    for (int id : bodies[b].boundaryIds) {
      const std::string& name = m.boundaryName(id);
      const core::BoundaryCondition* bc = bcs.find(name);
      const core::BoundaryType type = bc ? bc->type : core::BoundaryType::Free;
      held = held || type == core::BoundaryType::Displacement;
      parts << "'" << name << "' (" << core::toString(type);
      for (const auto& s : supports)
        if (s.part == name) bodySupports.push_back(s);
      if (bc && bc->inNormalFrame()) parts << ", " << describePlane(frames.at(name), d);
      parts << (bc ? "" : ", not in 'Boundary Conditions'") << ")";
      parts << (id == bodies[b].boundaryIds.back() ? "" : ", ");
    }
    held = held || (!bodySupports.empty() &&
                    freeRigidMotions(m, bodySupports, &bodies[b].elements).empty());
    SC_THROW_IF(!held, core::InputError,
                "the mesh of "
                    << m.origin() << " holds " << bodies.size()
                    << " bodies that share no face, and body " << b + 1 << " of " << bodies.size()
                    << " (" << bodies[b].describe(d) << ") is not held: its boundary parts are "
                    << parts.str() << ". Nothing fixes its rigid-body motions (contact, "
                    << "tractions, pressures and Free parts do not), so the problem is "
                    << "ill-posed. Give one of its parts Type 'Displacement', or give it Symmetry "
                    << "parts that hold every rigid motion (e.g. normal to every axis); a part may "
                    << "span several bodies.");
  }
}

}  // namespace sc::assembly
