#include <sc/mesh/CadGeometry.hpp>

#include <sc/core/Error.hpp>
#include <sc/core/FloatingPointTraps.hpp>
#include <sc/mesh/GmshSession.hpp>

#include <gmsh.h>

#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <sstream>

#include <sys/stat.h>

namespace sc::mesh {

CadGeometry::CadGeometry(const std::string& path, int dim)
    : path_(path), dim_(dim), session_(std::make_unique<GmshSession>())
{
  const std::string origin = "Gmsh geometry '" + path + "' (Mesh/File)";
  struct stat st {};
  SC_THROW_IF(::stat(path.c_str(), &st) != 0, core::InputError,
              origin << " cannot be opened: " << std::strerror(errno));
  SC_THROW_IF(!S_ISREG(st.st_mode), core::InputError,
              origin << " is not a regular file; Mesh/File must name a Gmsh .geo script");
  {
    std::ifstream probe(path);
    SC_THROW_IF(!probe, core::InputError, origin << " cannot be opened: no read permission");
  }
  session_->activate();
  try {
    core::FloatingPointTrapsSuspended gmshComputes;  // OpenCASCADE computes with NaNs
    gmsh::merge(path);
  } catch (...) {
    SC_THROW_IF(true, core::InputError,
                origin << " cannot be run by Gmsh: " << GmshSession::lastError());
  }
  SC_THROW_IF(GmshSession::hasError(), core::InputError,
              origin << " cannot be run by Gmsh: " << GmshSession::lastError());
  // A script may mesh its model itself: that mesh is not ours (GmshMeshIO::meshCad meshes it).
  gmsh::model::mesh::clear();
  const int modelDim = gmsh::model::getDimension();
  SC_THROW_IF(modelDim != dim, core::InputError,
              origin << " defines a model of dimension " << modelDim
                     << " but Problem/Dimension = " << dim);
  gmsh::vectorpair groups;
  gmsh::model::getPhysicalGroups(groups, dim - 1);
  SC_THROW_IF(groups.empty(), core::InputError,
              origin << " has no physical group of dimension " << dim - 1 << " ("
                     << (dim == 2 ? "Physical Curve" : "Physical Surface")
                     << "): name the boundary parts that the deck's Boundary Conditions use");
  for (const auto& [d, tag] : groups) {
    std::string name;
    gmsh::model::getPhysicalName(d, tag, name);
    if (name.empty()) name = std::to_string(tag);
    SC_THROW_IF(entities_.count(name), core::InputError,
                origin << ": two physical groups of dimension " << d << " are named '" << name
                       << "'; each boundary part needs a name of its own");
    names_.push_back(name);
    std::vector<int> ents;
    gmsh::model::getEntitiesForPhysicalGroup(d, tag, ents);
    entities_[name] = ents;
    bool curved = false;
    for (int e : ents) {
      std::string type;
      gmsh::model::getType(d, e, type);
      if (type != "Line" && type != "Plane") curved = true;
    }
    curved_[name] = curved;
  }
}

CadGeometry::~CadGeometry() = default;

bool CadGeometry::isCurved(const std::string& boundaryName) const
{
  const auto it = curved_.find(boundaryName);
  return it != curved_.end() && it->second;
}

std::array<double, 3> CadGeometry::project(const std::string& boundaryName,
                                           const std::array<double, 3>& x) const
{
  if (!isCurved(boundaryName)) return x;
  session_->activate();
  core::FloatingPointTrapsSuspended gmshComputes;
  double best = std::numeric_limits<double>::max();
  std::array<double, 3> closest = x;
  const std::vector<double> point{x[0], x[1], dim_ == 2 ? 0.0 : x[2]};
  for (int e : entities_.at(boundaryName)) {
    std::vector<double> c, t;
    gmsh::model::getClosestPoint(dim_ - 1, e, point, c, t);
    if (c.size() < 3) continue;
    const double d2 = (c[0] - x[0]) * (c[0] - x[0]) + (c[1] - x[1]) * (c[1] - x[1]) +
                      (dim_ == 2 ? 0.0 : (c[2] - x[2]) * (c[2] - x[2]));
    if (d2 < best) best = d2, closest = {c[0], c[1], dim_ == 2 ? 0.0 : c[2]};
  }
  SC_THROW_IF(best == std::numeric_limits<double>::max(), core::InputError,
              "Gmsh geometry '" << path_ << "': Gmsh found no closest point on the entities of "
                                << "physical group '" << boundaryName << "' for the new vertex ("
                                << x[0] << ", " << x[1] << ", " << x[2] << ")");
  return closest;
}

void CadGeometry::addToGmshModel() const
{
  SC_THROW_IF(true, core::InternalError, "CadGeometry: the model is the script's own");
}

std::string CadGeometry::classifyBoundaryEntity(const std::array<double, 3>&) const
{
  SC_THROW_IF(true, core::InternalError, "CadGeometry: the boundary parts are the script's groups");
}

}  // namespace sc::mesh
