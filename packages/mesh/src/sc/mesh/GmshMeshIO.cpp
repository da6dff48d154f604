#include <sc/mesh/GmshMeshIO.hpp>

#include <sc/core/Error.hpp>
#include <sc/core/FloatingPointTraps.hpp>
#include <sc/mesh/CadGeometry.hpp>
#include <sc/mesh/GmshSession.hpp>
#include <sc/mesh/MeshBoundaryGeometry.hpp>

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
#include <sstream>
#include <unordered_map>

#include <fcntl.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

namespace sc::mesh {

namespace {

std::string lastGmshError() { return GmshSession::lastError(); }

// Gmsh 4.8's .msh readers trust the file: a damaged $Nodes or $Elements section can make them
// read out of bounds and crash (found by fuzzing: a SEGV in GModel::getMeshVertexByTag from
// _readMSH4; docs/reliability.md "Fuzzing"). So Gmsh first reads the file in a child process
// that does nothing else; if the child dies, the file is refused with an input error instead of
// the run (every MPI rank) crashing. Returns the child's signal (> 0), or its non-zero exit
// status negated (Gmsh calling exit), or 0 when Gmsh read the file without dying (it may still
// have reported an error, which the real read then gives).
int gmshReaderDies(const std::string& path, unsigned timeLimitSeconds)
{
  std::fflush(nullptr);
  const pid_t pid = ::fork();
  if (pid < 0) return 0;  // no child possible: read in this process, unprotected
  if (pid == 0) {
    // The child: default handlers, so that a crash ends it at once (no sanitizer or fuzzer
    // report from a copy of this process), output discarded, no MPI, no exit handlers.
    for (int sig : {SIGSEGV, SIGBUS, SIGABRT, SIGFPE, SIGILL})
      std::signal(sig, SIG_DFL);
    if (const int null = ::open("/dev/null", O_WRONLY); null >= 0) {
      ::dup2(null, STDOUT_FILENO);
      ::dup2(null, STDERR_FILENO);
    }
    // A reader that spins (a huge or pathological file) is ended by SIGALRM, whose default
    // action terminates the child: the parent reports the time limit.
    std::signal(SIGALRM, SIG_DFL);
    ::alarm(timeLimitSeconds);
    try {
      GmshSession session;
      sc::core::FloatingPointTrapsSuspended gmshReads;
      gmsh::merge(path);
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
    if (errno != EINTR) return 0;
  if (WIFSIGNALED(status)) return WTERMSIG(status);
  return WIFEXITED(status) ? -WEXITSTATUS(status) : 0;
}

// The mesh file, checked to be data and copied where nothing else is (docs/mesh.md "Gmsh files"):
// - it must be a regular file (not a directory, device, pipe or socket: /dev/zero would make the
//   reader spin forever);
// - its first line must be Gmsh's MSH header `$MeshFormat`. gmsh::open decides what a file is
//   from its first line, not from its name, and interprets anything that is not a mesh or
//   another data format as a .geo script, which can run shell commands (`SystemCall`): a file
//   called mesh.msh holding a script would be executed. Checking the header ourselves keeps
//   every script away from Gmsh;
// - Gmsh also merges an option file `<file>.opt` beside the file it opens, and option files are
//   scripts too. The copy lives alone in a fresh directory, so there is none, and the file that
//   was checked is the file that Gmsh reads (it cannot change in between).
class PrivateMeshCopy {
public:
  PrivateMeshCopy(const std::string& path, const std::string& origin)
  {
    const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    SC_THROW_IF(fd < 0, sc::core::InputError,
                origin << " (Mesh/File) cannot be opened: " << std::strerror(errno));
    struct FdCloser {
      int fd;
      ~FdCloser() { ::close(fd); }
    } closer{fd};
    struct stat st {};
    SC_THROW_IF(::fstat(fd, &st) != 0, sc::core::InputError,
                origin << " (Mesh/File) cannot be read: " << std::strerror(errno));
    SC_THROW_IF(S_ISDIR(st.st_mode), sc::core::InputError,
                origin << " (Mesh/File) is a directory, not a .msh file");
    SC_THROW_IF(!S_ISREG(st.st_mode), sc::core::InputError,
                origin << " (Mesh/File) is not a regular file (a device, pipe or socket); "
                          "Mesh/File must name a Gmsh .msh file");
    size_ = static_cast<std::uintmax_t>(st.st_size);

    std::string tmpl =
        (std::filesystem::temp_directory_path() / "stresscontact-mesh-XXXXXX").string();
    SC_THROW_IF(::mkdtemp(tmpl.data()) == nullptr, sc::core::Error,
                "cannot create a temporary directory for reading "
                    << origin << ": " << std::strerror(errno)
                    << " (set TMPDIR to a writable directory)");
    dir_.path = tmpl;
    path_ = dir_.path + "/mesh.msh";
    std::ofstream copy(path_, std::ios::binary);
    SC_THROW_IF(!copy, sc::core::Error,
                "cannot write the temporary copy '" << path_ << "' of " << origin);
    std::vector<char> buffer(1 << 20);
    std::string head;
    bool headerChecked = false;  // a file that is not a mesh is refused before it is copied
    for (;;) {
      const ssize_t n = ::read(fd, buffer.data(), buffer.size());
      if (n < 0 && errno == EINTR) continue;
      SC_THROW_IF(n < 0, sc::core::InputError,
                  origin << " (Mesh/File) cannot be read: " << std::strerror(errno));
      if (n == 0) break;
      if (!headerChecked) {
        head.append(buffer.data(), std::min<std::size_t>(static_cast<std::size_t>(n), 256));
        checkHeader(head, origin, false);
        headerChecked = headerComplete(head);
      }
      copy.write(buffer.data(), n);
      SC_THROW_IF(!copy, sc::core::Error,
                  "cannot write the temporary copy '" << path_ << "' of " << origin
                                                      << " (disk full?)");
    }
    checkHeader(head, origin, true);
  }
  PrivateMeshCopy(const PrivateMeshCopy&) = delete;
  PrivateMeshCopy& operator=(const PrivateMeshCopy&) = delete;

  const std::string& path() const { return path_; }
  std::uintmax_t size() const { return size_; }

private:
  // The header is complete once its first two lines are there ("$MeshFormat", "4.1 0 8").
  static bool headerComplete(const std::string& head)
  {
    const auto first = head.find('\n');
    return first != std::string::npos && head.find('\n', first + 1) != std::string::npos;
  }
  // Throws unless `head` starts with the MSH header of format 2 or 4. With `final` = false (more
  // bytes may follow) only what is already there is checked.
  static void checkHeader(const std::string& head, const std::string& origin, bool final)
  {
    const std::string tag = "$MeshFormat";
    auto fail = [&](const std::string& why) {
      SC_THROW_IF(true, sc::core::InputError,
                  origin << " (Mesh/File) is not a Gmsh MSH file: " << why
                         << ". StressContact reads MSH files of format 2.2 and 4.1 (ASCII or "
                            "binary), which start with the line '$MeshFormat'; it never hands "
                            "other files to Gmsh, since Gmsh runs anything else as a .geo "
                            "script (docs/mesh.md \"Gmsh files\")");
    };
    if (head.compare(0, 3, "\xEF\xBB\xBF") == 0)
      fail("it starts with a UTF-8 byte-order mark; save it without one");
    const std::size_t n = std::min(head.size(), tag.size());
    if (head.compare(0, n, tag, 0, n) != 0 || (final && head.size() < tag.size())) {
      std::string line = head.substr(0, head.find_first_of("\r\n"));
      if (line.size() > 60) line = line.substr(0, 60) + "...";
      for (char& c : line)
        if (static_cast<unsigned char>(c) < 32 || static_cast<unsigned char>(c) > 126) c = '?';
      fail(head.empty() ? std::string("the file is empty")
                        : "its first line is '" + line + "', not '$MeshFormat'");
    }
    if (!headerComplete(head)) {
      if (final) fail("the $MeshFormat section is incomplete");
      return;
    }
    const auto first = head.find('\n');
    std::string rest = head.substr(tag.size(), first - tag.size());
    SC_THROW_IF(rest.find_first_not_of(" \t\r") != std::string::npos, sc::core::InputError,
                origin << " (Mesh/File): the first line has text after '$MeshFormat'");
    std::istringstream version(head.substr(first + 1));
    double v = 0;
    version >> v;
    SC_THROW_IF(!version || !((v >= 2.0 && v < 3.0) || (v >= 4.0 && v < 5.0)), sc::core::InputError,
                origin << " (Mesh/File) has MSH format version '"
                       << head.substr(first + 1, head.find_first_of("\r\n", first + 1) - first - 1)
                       << "'; StressContact reads MSH formats 2.2 and 4.1");
  }

  // Removed with its content when the copy goes, also when the constructor throws.
  struct TemporaryDirectory {
    std::string path;
    ~TemporaryDirectory()
    {
      std::error_code ec;
      if (!path.empty()) std::filesystem::remove_all(path, ec);
    }
  } dir_;
  std::string path_;
  std::uintmax_t size_ = 0;
};

// The $PhysicalNames entries of an MSH file (ASCII in both the ASCII and the binary formats).
// Gmsh keeps one group per name: of two groups given the same name, one silently loses its name
// (and becomes a part called by its number), so duplicates are found in the file itself.
void checkPhysicalNames(const std::string& path, const std::string& origin, int dim)
{
  std::ifstream in(path, std::ios::binary);
  std::string line;
  std::map<std::string, int> tagOfName;  // boundary groups (dimension dim − 1)
  while (std::getline(in, line)) {
    if (line.rfind("$PhysicalNames", 0) != 0) continue;
    int count = 0;
    if (!(in >> count) || !std::getline(in, line)) return;  // Gmsh's reader reports it
    for (int i = 0; i < count && std::getline(in, line); ++i) {
      std::istringstream entry(line);
      int d = -1, tag = 0;
      entry >> d >> tag;
      std::string name;
      std::getline(entry, name);
      const auto a = name.find('"'), b = name.rfind('"');
      if (a == std::string::npos || b <= a) continue;
      name = name.substr(a + 1, b - a - 1);
      if (d != dim - 1) continue;
      const auto [it, inserted] = tagOfName.emplace(name, tag);
      SC_THROW_IF(!inserted && it->second != tag, sc::core::InputError,
                  origin << ": physical groups " << it->second << " and " << tag << " (dimension "
                         << d << ") are both named '" << name
                         << "'; each boundary part needs a name of its own (merge the groups "
                            "in Gmsh, or rename one)");
    }
  }
}

// Time limit of the child that test-reads a mesh file: generous for any real file (Gmsh reads
// about 10 MB/s of ASCII MSH here), finite for a reader that spins.
unsigned readerTimeLimit(std::uintmax_t bytes)
{
  return static_cast<unsigned>(std::min<std::uintmax_t>(60 + bytes / 100000, 3600));
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

// Nodes of a Gmsh element type and whether StressContact reads it: linear or quadratic simplices
// of the mesh's dimension (elements) and of one less (boundary faces).
struct TypeInfo {
  int nodes = 0;     // nodes per element
  int vertices = 0;  // of which vertices (listed first)
  bool supported = false;
};
TypeInfo typeInfo(int type, int dim, bool face)
{
  const int d = face ? dim - 1 : dim;
  switch (type) {
  case 1: return {2, 2, d == 1};    // 2-node line
  case 8: return {3, 2, d == 1};    // 3-node line
  case 2: return {3, 3, d == 2};    // 3-node triangle
  case 9: return {6, 3, d == 2};    // 6-node triangle
  case 4: return {4, 4, d == 3};    // 4-node tetrahedron
  case 11: return {10, 4, d == 3};  // 10-node tetrahedron
  default: return {};
  }
}

// Build a SimplexMesh from the mesh of the current Gmsh model: elements of dimension `dim`
// (linear or quadratic; a quadratic element contributes its vertices), boundary parts from the
// physical groups of dimension dim−1 (in the order of `partOrder` if given, else by group tag),
// and the boundary's geometry from the groups' faces (their mid-edge nodes for quadratic faces).
GmshMeshIO::MeshFile extractMesh(int dim, const std::string& origin,
                                 const std::vector<std::string>& partOrder)
{
  std::vector<int> types;
  std::vector<std::vector<std::size_t>> elemTags, nodeTags;
  gmsh::model::mesh::getElements(types, elemTags, nodeTags, dim, -1);
  std::vector<std::size_t> elemNodes;
  SimplexMesh::Labels labels;  // Gmsh tags, quoted in error messages
  for (std::size_t t = 0; t < types.size(); ++t) {
    const TypeInfo info = typeInfo(types[t], dim, false);
    SC_THROW_IF(!info.supported, sc::core::InputError,
                origin << ": unsupported element type " << elementTypeName(types[t]) << " (element "
                       << (elemTags[t].empty() ? 0 : elemTags[t][0])
                       << "); StressContact reads linear or quadratic "
                       << (dim == 2 ? "triangles (3 or 6 nodes)" : "tetrahedra (4 or 10 nodes)")
                       << " only");
    for (std::size_t e = 0; e < elemTags[t].size(); ++e)
      elemNodes.insert(elemNodes.end(), nodeTags[t].begin() + e * info.nodes,
                       nodeTags[t].begin() + e * info.nodes + info.vertices);
    labels.element.insert(labels.element.end(), elemTags[t].begin(), elemTags[t].end());
  }
  SC_THROW_IF(elemNodes.empty(), sc::core::InputError,
              origin << ": the file has no " << (dim == 2 ? "triangles" : "tetrahedra")
                     << " (empty or truncated file, or a mesh of another dimension)");

  // Vertices used by elements, numbered 0.. in order of first appearance.
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
  std::unordered_map<std::size_t, std::size_t> position;  // node tag -> its index in allTags
  position.reserve(allTags.size());
  for (std::size_t i = 0; i < allTags.size(); ++i)
    position.emplace(allTags[i], i);
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
      for (int k = 0; k < 3; ++k)
        extent = std::max(extent, std::abs(allCoords[3 * i + k]));
  for (std::size_t i = 0; i < allTags.size(); ++i) {
    auto it = index.find(allTags[i]);
    if (it == index.end()) continue;
    for (int k = 0; k < dim; ++k)
      coords[static_cast<std::size_t>(it->second) * dim + k] = allCoords[3 * i + k];
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
  // A group without a name is called by its number; a name that is another group's number
  // would merge two groups into one part.
  {
    std::map<std::string, int> named;
    for (const auto& [gd, gtag] : groups) {
      std::string name;
      gmsh::model::getPhysicalName(gd, gtag, name);
      if (!name.empty()) named.emplace(name, gtag);
    }
    for (const auto& [gd, gtag] : groups) {
      std::string name;
      gmsh::model::getPhysicalName(gd, gtag, name);
      const auto clash = named.find(std::to_string(gtag));
      SC_THROW_IF(
          name.empty() && clash != named.end() && clash->second != gtag, sc::core::InputError,
          origin << ": physical group " << gtag << " has no name, so it is called '" << gtag
                 << "', but physical group " << clash->second << " is named '" << clash->first
                 << "' too; name group " << gtag << " or rename group " << clash->second);
    }
  }
  std::vector<std::string> names = partOrder;
  std::vector<int> bfv, bpart;
  const int faceNodes = MeshBoundaryGeometry::nodesPerFace(dim);
  std::vector<double> boundaryNodes;      // the faces' nodes for the boundary geometry
  std::vector<std::size_t> boundaryTags;  // and their Gmsh tags (messages)
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
        const TypeInfo info = typeInfo(ft[t], dim, true);
        SC_THROW_IF(!info.supported, sc::core::InputError,
                    origin << ": physical group '" << name << "' holds unsupported element type "
                           << elementTypeName(ft[t]));
        for (std::size_t e = 0; e < fTags[t].size(); ++e) {
          const std::size_t* n = &fNodes[t][e * info.nodes];
          std::array<double, 18> x{};  // up to 6 nodes
          for (int i = 0; i < info.nodes; ++i) {
            auto it = index.find(n[i]);
            SC_THROW_IF(i < info.vertices && it == index.end(), sc::core::InputError,
                        origin << ": boundary element " << fTags[t][e] << " of physical group '"
                               << name << "' uses node " << n[i] << ", which belongs to no "
                               << (dim == 2 ? "triangle" : "tetrahedron"));
            if (i < info.vertices) bfv.push_back(it->second);
            const auto p = position.find(n[i]);
            SC_THROW_IF(p == position.end(), sc::core::InputError,
                        origin << ": boundary element " << fTags[t][e] << " of physical group '"
                               << name << "' uses node " << n[i] << ", which has no coordinates");
            for (int k = 0; k < 3; ++k)
              x[3 * i + k] = allCoords[3 * p->second + k];
            SC_THROW_IF(!(std::isfinite(x[3 * i]) && std::isfinite(x[3 * i + 1]) &&
                          std::isfinite(x[3 * i + 2])),
                        sc::core::InputError,
                        origin << ": node " << n[i] << " has a non-finite coordinate");
          }
          if (info.nodes == info.vertices) {  // linear face: midpoints on the chords
            constexpr int kEdges[3][2] = {{0, 1}, {1, 2}, {2, 0}};
            for (int s = 0; s < (dim == 2 ? 1 : 3); ++s)
              for (int k = 0; k < 3; ++k)
                x[3 * (info.vertices + s) + k] =
                    0.5 * (x[3 * kEdges[s][0] + k] + x[3 * kEdges[s][1] + k]);
          }
          boundaryNodes.insert(boundaryNodes.end(), x.begin(), x.begin() + 3 * faceNodes);
          for (int i = 0; i < faceNodes; ++i)
            boundaryTags.push_back(i < info.nodes ? n[i] : 0);
        }
        bpart.insert(bpart.end(), fTags[t].size(), part);
      }
    }
  }
  labels.vertex = usedTags;
  GmshMeshIO::MeshFile result;
  result.mesh = Teuchos::rcp(new SimplexMesh(dim, std::move(coords), std::move(elemVerts), bfv,
                                             bpart, names, origin, &labels));
  // Parts as the mesh names them (a mesh adds 'Unnamed' for faces in no group: flat, no faces).
  result.boundary = Teuchos::rcp(new MeshBoundaryGeometry(
      dim, result.mesh->boundaryNames(), std::move(boundaryNodes), bpart, origin, &boundaryTags));
  return result;
}

void buildGeometryModel(const Geometry& geometry, double meshSize)
{
  // Gmsh's OpenCASCADE kernel and mesh generators compute with NaNs internally (0/0 in
  // MTri3's circumradius of a degenerate candidate, among others: trapped under SC_TRAP_FPE);
  // that is Gmsh's business, so traps are off while it builds the mesh.
  sc::core::FloatingPointTrapsSuspended gmshComputes;
  const int dim = geometry.dim();
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
                geometry.sceneName()
                    << ": Gmsh model has no boundary entity for '" << names[i] << "'");
    const int g = gmsh::model::addPhysicalGroup(dim - 1, it->second, static_cast<int>(i) + 1);
    gmsh::model::setPhysicalName(dim - 1, g, names[i]);
  }
  gmsh::vectorpair dents;
  gmsh::model::getEntities(dents, dim);
  std::vector<int> dtags;
  for (const auto& p : dents)
    dtags.push_back(p.second);
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
  return extractMesh(geometry.dim(), origin, geometry.boundaryNames()).mesh;
}

void GmshMeshIO::writeGeometryMesh(const Geometry& geometry, double meshSize,
                                   const std::string& path, double version, int order)
{
  GmshSession session;
  buildGeometryModel(geometry, meshSize);
  if (order > 1) {
    sc::core::FloatingPointTrapsSuspended gmshComputes;
    gmsh::model::mesh::setOrder(order);
  }
  gmsh::option::setNumber("Mesh.MshFileVersion", version);
  gmsh::write(path);
}

Teuchos::RCP<SimplexMesh> GmshMeshIO::readFile(const std::string& path, int dim)
{
  return readMeshFile(path, dim).mesh;
}

GmshMeshIO::MeshFile GmshMeshIO::readMeshFile(const std::string& path, int dim)
{
  const std::string origin = "Gmsh file '" + path + "'";
  const PrivateMeshCopy copy(path, origin);
  checkPhysicalNames(copy.path(), origin, dim);
  const unsigned limit = readerTimeLimit(copy.size());
  if (const int died = gmshReaderDies(copy.path(), limit); died != 0) {
    std::ostringstream why;
    if (died == SIGALRM)
      why << "Gmsh's reader did not finish within " << limit << " s";
    else if (died > 0)
      why << "Gmsh's reader crashed on it (signal " << died << " (" << strsignal(died) << "))";
    else
      why << "Gmsh's reader crashed on it (exit status " << -died << ")";
    SC_THROW_IF(true, sc::core::InputError,
                origin << " cannot be read: " << why.str()
                       << "; the file is damaged or not a .msh file of format 2.2 or 4.1");
  }
  GmshSession session;
  try {
    sc::core::FloatingPointTrapsSuspended gmshReads;  // Gmsh's reader, as in buildGeometryModel
    gmsh::merge(copy.path());
  } catch (...) {
    SC_THROW_IF(true, sc::core::InputError, origin << " cannot be read: " << lastGmshError());
  }
  SC_THROW_IF(GmshSession::hasError(), sc::core::InputError,
              origin << " cannot be read: " << lastGmshError());
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

Teuchos::RCP<SimplexMesh> GmshMeshIO::meshCad(const CadGeometry& cad, double meshSize, int order)
{
  SC_THROW_IF(!(meshSize > 0), sc::core::InputError,
              "Mesh/Initial mesh size = " << meshSize << " must be > 0");
  const std::string origin = "Gmsh geometry '" + cad.path() + "'";
  cad.session().activate();
  GmshSession::clearErrors();
  try {
    sc::core::FloatingPointTrapsSuspended gmshComputes;
    // Mesh/Initial mesh size caps the element size; sizes that the script gives its points
    // (grading towards a contact zone, say) still apply.
    gmsh::option::setNumber("Mesh.MeshSizeMax", meshSize);
    gmsh::option::setNumber("Mesh.MeshSizeFromPoints", 1);
    gmsh::option::setNumber("Mesh.MeshSizeFromCurvature", 0);
    gmsh::model::mesh::clear();
    gmsh::model::mesh::generate(cad.dim());
    if (order > 1) gmsh::model::mesh::setOrder(order);
  } catch (...) {
    gmsh::model::mesh::clear();
    SC_THROW_IF(true, sc::core::InputError,
                origin << ": Gmsh cannot mesh the geometry: " << lastGmshError());
  }
  SC_THROW_IF(GmshSession::hasError(), sc::core::InputError,
              origin << ": Gmsh cannot mesh the geometry: " << lastGmshError());
  auto mesh = extractMesh(cad.dim(), origin, cad.boundaryNames()).mesh;
  gmsh::model::mesh::clear();  // the model stays for the projections, its mesh goes
  return mesh;
}

}  // namespace sc::mesh
