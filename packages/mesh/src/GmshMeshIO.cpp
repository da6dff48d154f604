#include <sc/mesh/GmshMeshIO.hpp>

#include <sc/core/Error.hpp>
#include <sc/core/FloatingPointTraps.hpp>

#include <gmsh.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <unordered_map>

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

namespace sc::mesh {

namespace {

// Gmsh keeps global state: one session per call, finalised even when we throw.
class GmshSession {
public:
  GmshSession()
  {
    gmsh::initialize(0, nullptr, /*readConfigFiles=*/false);
    gmsh::option::setNumber("General.Terminal", 0);
    gmsh::option::setNumber("General.Verbosity", 1);
    gmsh::option::setNumber("General.NumThreads", 1);
    gmsh::logger::start();  // keeps error messages for our exceptions
  }
  ~GmshSession()
  {
    try {
      gmsh::logger::stop();
      gmsh::finalize();
    } catch (...) {
    }
  }
  GmshSession(const GmshSession&) = delete;
  GmshSession& operator=(const GmshSession&) = delete;
};

std::string lastGmshError()
{
  std::string err;
  try {
    gmsh::logger::getLastError(err);
  } catch (...) {
  }
  return err.empty() ? std::string("(Gmsh gave no message)") : err;
}

// Gmsh 4.8's .msh readers trust the file: a damaged $Nodes or $Elements section can make them
// read out of bounds and crash (found by fuzzing: a SEGV in GModel::getMeshVertexByTag from
// _readMSH4; docs/reliability.md "Fuzzing"). So Gmsh first reads the file in a child process
// that does nothing else; if the child dies, the file is refused with an input error instead of
// the run (every MPI rank) crashing. Returns the child's signal (> 0), or its non-zero exit
// status negated (Gmsh calling exit), or 0 when Gmsh read the file without dying (it may still
// have reported an error, which the real read then gives).
int gmshReaderDies(const std::string& path)
{
  std::fflush(nullptr);
  const pid_t pid = ::fork();
  if (pid < 0)
    return 0;  // no child possible: read in this process, as before
  if (pid == 0) {
    // The child: default handlers, so that a crash ends it at once (no sanitizer or fuzzer
    // report from a copy of this process), output discarded, no MPI, no exit handlers.
    for (int sig : {SIGSEGV, SIGBUS, SIGABRT, SIGFPE, SIGILL})
      std::signal(sig, SIG_DFL);
    if (const int null = ::open("/dev/null", O_WRONLY); null >= 0) {
      ::dup2(null, STDOUT_FILENO);
      ::dup2(null, STDERR_FILENO);
    }
    try {
      GmshSession session;
      sc::core::FloatingPointTrapsSuspended gmshReads;
      gmsh::open(path);
      std::vector<int> types;
      std::vector<std::vector<std::size_t>> elemTags, nodeTags;
      gmsh::model::mesh::getElements(types, elemTags, nodeTags, -1, -1);
      std::vector<std::size_t> tags;
      std::vector<double> coords, params;
      gmsh::model::mesh::getNodes(tags, coords, params, -1, -1, true, false);
    } catch (...) {
    }
    ::_exit(0);
  }
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0)
    if (errno != EINTR)
      return 0;
  if (WIFSIGNALED(status))
    return WTERMSIG(status);
  return WIFEXITED(status) ? -WEXITSTATUS(status) : 0;
}

std::string elementTypeName(int type)
{
  std::string name;
  int d, order, nn, npn;
  std::vector<double> coords;
  try {
    gmsh::model::mesh::getElementProperties(type, name, d, order, nn, coords, npn);
  } catch (...) {
    name = "unknown";
  }
  return "'" + name + "' (Gmsh element type " + std::to_string(type) + ")";
}

// Build a SimplexMesh from the mesh of the current Gmsh model: elements of dimension `dim`,
// boundary parts from the physical groups of dimension dim−1 (in the order of `partOrder` if
// given, else by group tag).
Teuchos::RCP<SimplexMesh> extractMesh(int dim, const std::string& origin,
                                      const std::vector<std::string>& partOrder)
{
  const int linearType = dim == 2 ? 2 : 4;  // 3-node triangle, 4-node tetrahedron
  const int faceType = dim == 2 ? 1 : 2;    // 2-node line, 3-node triangle

  std::vector<int> types;
  std::vector<std::vector<std::size_t>> elemTags, nodeTags;
  gmsh::model::mesh::getElements(types, elemTags, nodeTags, dim, -1);
  std::vector<std::size_t> elemNodes;
  SimplexMesh::Labels labels;  // Gmsh tags, quoted in error messages
  for (std::size_t t = 0; t < types.size(); ++t) {
    SC_THROW_IF(types[t] != linearType, sc::core::InputError,
                origin << ": unsupported element type " << elementTypeName(types[t]) << " (element "
                       << (elemTags[t].empty() ? 0 : elemTags[t][0])
                       << "); StressContact reads linear "
                       << (dim == 2 ? "3-node triangles" : "4-node tetrahedra") << " only");
    elemNodes.insert(elemNodes.end(), nodeTags[t].begin(), nodeTags[t].end());
    labels.element.insert(labels.element.end(), elemTags[t].begin(), elemTags[t].end());
  }
  SC_THROW_IF(elemNodes.empty(), sc::core::InputError,
              origin << ": the file has no " << (dim == 2 ? "triangles" : "tetrahedra")
                     << " (empty or truncated file, or a mesh of another dimension)");

  // Nodes used by elements, numbered 0.. in order of first appearance.
  std::unordered_map<std::size_t, int> index;
  index.reserve(elemNodes.size());
  std::vector<int> elemVerts(elemNodes.size());
  std::vector<std::size_t> usedTags;
  for (std::size_t i = 0; i < elemNodes.size(); ++i) {
    auto [it, inserted] = index.emplace(elemNodes[i], static_cast<int>(usedTags.size()));
    if (inserted) usedTags.push_back(elemNodes[i]);
    elemVerts[i] = it->second;
  }
  std::vector<std::size_t> allTags;
  std::vector<double> allCoords, params;
  gmsh::model::mesh::getNodes(allTags, allCoords, params, -1, -1, true, false);
  std::vector<double> coords(usedTags.size() * dim, std::nan(""));
  // A coordinate "nan" or "inf" in the file (Gmsh's reader accepts both) is refused before any
  // arithmetic: it would make every measure and check of the mesh NaN.
  for (std::size_t i = 0; i < allTags.size(); ++i) {
    const double* x = &allCoords[3 * i];
    SC_THROW_IF(index.count(allTags[i]) &&
                    !(std::isfinite(x[0]) && std::isfinite(x[1]) && std::isfinite(x[2])),
                sc::core::InputError,
                origin << ": node " << allTags[i] << " has a non-finite coordinate (" << x[0]
                       << ", " << x[1] << ", " << x[2] << ")");
  }
  double extent = 0;
  for (std::size_t i = 0; i < allTags.size(); ++i)
    if (index.count(allTags[i]))
      for (int k = 0; k < 3; ++k) extent = std::max(extent, std::abs(allCoords[3 * i + k]));
  for (std::size_t i = 0; i < allTags.size(); ++i) {
    auto it = index.find(allTags[i]);
    if (it == index.end()) continue;
    for (int k = 0; k < dim; ++k) coords[static_cast<std::size_t>(it->second) * dim + k] = allCoords[3 * i + k];
    SC_THROW_IF(dim == 2 && std::abs(allCoords[3 * i + 2]) > 1e-10 * std::max(extent, 1.0),
                sc::core::InputError,
                origin << ": node " << allTags[i] << " has z = " << allCoords[3 * i + 2]
                       << "; a 2D mesh must lie in the plane z = 0");
  }
  for (std::size_t v = 0; v < usedTags.size(); ++v)
    SC_THROW_IF(std::isnan(coords[v * dim]), sc::core::InputError,
                origin << ": node " << usedTags[v]
                       << " is used by an element but has no coordinates (truncated file?)");

  // Boundary parts from physical groups of dimension dim−1.
  gmsh::vectorpair groups;
  gmsh::model::getPhysicalGroups(groups, dim - 1);
  std::vector<std::string> names = partOrder;
  std::vector<int> bfv, bpart;
  for (const auto& [gd, gtag] : groups) {
    std::string name;
    gmsh::model::getPhysicalName(gd, gtag, name);
    if (name.empty()) name = std::to_string(gtag);
    auto pos = std::find(names.begin(), names.end(), name);
    const int part = static_cast<int>(pos - names.begin());
    if (pos == names.end()) names.push_back(name);
    std::vector<int> entities;
    gmsh::model::getEntitiesForPhysicalGroup(gd, gtag, entities);
    for (int ent : entities) {
      std::vector<int> ft;
      std::vector<std::vector<std::size_t>> fTags, fNodes;
      gmsh::model::mesh::getElements(ft, fTags, fNodes, dim - 1, ent);
      for (std::size_t t = 0; t < ft.size(); ++t) {
        SC_THROW_IF(ft[t] != faceType, sc::core::InputError,
                    origin << ": physical group '" << name << "' holds unsupported element type "
                           << elementTypeName(ft[t]));
        for (std::size_t i = 0; i < fNodes[t].size(); ++i) {
          auto it = index.find(fNodes[t][i]);
          SC_THROW_IF(it == index.end(), sc::core::InputError,
                      origin << ": boundary element " << fTags[t][i / dim] << " of physical group '"
                             << name << "' uses node " << fNodes[t][i]
                             << ", which belongs to no " << (dim == 2 ? "triangle" : "tetrahedron"));
          bfv.push_back(it->second);
        }
        bpart.insert(bpart.end(), fTags[t].size(), part);
      }
    }
  }
  labels.vertex = usedTags;
  return Teuchos::rcp(new SimplexMesh(dim, std::move(coords), std::move(elemVerts), bfv, bpart,
                                      names, origin, &labels));
}

void buildGeometryModel(const Geometry& geometry, double meshSize)
{
  // Gmsh's OpenCASCADE kernel and mesh generators compute with NaNs internally (0/0 in
  // MTri3's circumradius of a degenerate candidate, among others: trapped under SC_TRAP_FPE);
  // that is Gmsh's business, so traps are off while it builds the mesh.
  sc::core::FloatingPointTrapsSuspended gmshComputes;
  const int dim = geometry.dim();
  gmsh::model::add("scene");
  geometry.addToGmshModel();
  gmsh::vectorpair bents;
  gmsh::model::getEntities(bents, dim - 1);
  std::map<std::string, std::vector<int>> byName;
  for (const auto& [d, tag] : bents) {
    std::array<double, 3> com;
    gmsh::model::occ::getCenterOfMass(d, tag, com[0], com[1], com[2]);
    byName[geometry.classifyBoundaryEntity(com)].push_back(tag);
  }
  const auto names = geometry.boundaryNames();
  for (std::size_t i = 0; i < names.size(); ++i) {
    auto it = byName.find(names[i]);
    SC_THROW_IF(it == byName.end(), sc::core::InternalError,
                geometry.sceneName() << ": Gmsh model has no boundary entity for '" << names[i]
                                     << "'");
    const int g = gmsh::model::addPhysicalGroup(dim - 1, it->second, static_cast<int>(i) + 1);
    gmsh::model::setPhysicalName(dim - 1, g, names[i]);
  }
  gmsh::vectorpair dents;
  gmsh::model::getEntities(dents, dim);
  std::vector<int> dtags;
  for (const auto& p : dents) dtags.push_back(p.second);
  const int g = gmsh::model::addPhysicalGroup(dim, dtags, 100);
  gmsh::model::setPhysicalName(dim, g, "Domain");
  // The size is MeshSizeMax alone: OpenCASCADE points carry default sizes (about a tenth of the
  // model) that would otherwise cap the element size and make coarse requests ineffective.
  gmsh::option::setNumber("Mesh.MeshSizeMax", meshSize);
  gmsh::option::setNumber("Mesh.MeshSizeFromPoints", 0);
  gmsh::option::setNumber("Mesh.MeshSizeFromCurvature", 0);
  gmsh::model::mesh::generate(dim);
}

}  // namespace

Teuchos::RCP<SimplexMesh> GmshMeshIO::meshGeometry(const Geometry& geometry, double meshSize)
{
  SC_THROW_IF(!(meshSize > 0), sc::core::InputError,
              "Mesh/Initial mesh size = " << meshSize << " must be > 0");
  GmshSession session;
  const std::string origin = "scene '" + geometry.sceneName() + "'";
  try {
    buildGeometryModel(geometry, meshSize);
  } catch (const sc::core::Error&) {
    throw;
  } catch (...) {
    SC_THROW_IF(true, sc::core::InternalError,
                origin << ": Gmsh failed to mesh the scene: " << lastGmshError());
  }
  return extractMesh(geometry.dim(), origin, geometry.boundaryNames());
}

void GmshMeshIO::writeGeometryMesh(const Geometry& geometry, double meshSize,
                                   const std::string& path, double version)
{
  GmshSession session;
  buildGeometryModel(geometry, meshSize);
  gmsh::option::setNumber("Mesh.MshFileVersion", version);
  gmsh::write(path);
}

Teuchos::RCP<SimplexMesh> GmshMeshIO::readFile(const std::string& path, int dim)
{
  const std::string origin = "Gmsh file '" + path + "'";
  {
    std::error_code ec;
    SC_THROW_IF(std::filesystem::is_directory(path, ec), sc::core::InputError,
                origin << " (Mesh/File) is a directory, not a .msh file");
    std::ifstream probe(path);
    SC_THROW_IF(!probe, sc::core::InputError,
                origin << " (Mesh/File) cannot be opened: no such file or no read permission");
  }
  if (const int died = gmshReaderDies(path); died != 0) {
    std::ostringstream why;
    if (died > 0)
      why << "signal " << died << " (" << strsignal(died) << ")";
    else
      why << "exit status " << -died;
    SC_THROW_IF(true, sc::core::InputError,
                origin << " cannot be read: Gmsh's reader crashed on it (" << why.str()
                       << "); the file is damaged or not a .msh file of format 2.2 or 4.1");
  }
  GmshSession session;
  try {
    sc::core::FloatingPointTrapsSuspended gmshReads;  // Gmsh's reader, as in buildGeometryModel
    gmsh::open(path);
  } catch (...) {
    SC_THROW_IF(true, sc::core::InputError, origin << " cannot be read: " << lastGmshError());
  }
  std::string err;
  gmsh::logger::getLastError(err);
  SC_THROW_IF(!err.empty(), sc::core::InputError, origin << " cannot be read: " << err);
  const int modelDim = gmsh::model::getDimension();
  SC_THROW_IF(modelDim != dim, sc::core::InputError,
              origin << " holds a mesh of dimension " << modelDim << " but Problem/Dimension = "
                     << dim << (modelDim < 0 ? " (empty, truncated or not a .msh file?)" : ""));
  try {
    return extractMesh(dim, origin, {});
  } catch (const sc::core::Error&) {
    throw;
  } catch (...) {
    SC_THROW_IF(true, sc::core::InputError, origin << " cannot be read: " << lastGmshError());
  }
}

}  // namespace sc::mesh
