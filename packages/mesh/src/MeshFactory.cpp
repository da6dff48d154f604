#include <sc/mesh/MeshFactory.hpp>

#include <sc/core/Error.hpp>
#include <sc/core/Parameters.hpp>
#include <sc/mesh/BoundarySimplexSplit.hpp>
#include <sc/mesh/BoxGeometry.hpp>
#include <sc/mesh/GmshMeshIO.hpp>
#include <sc/mesh/HalfBallGeometry.hpp>
#include <sc/mesh/HalfDiscGeometry.hpp>

#include <Teuchos_CommHelpers.hpp>

namespace sc::mesh {

const std::vector<std::string>& MeshFactory::sources()
{
  static const std::vector<std::string> s = {"Half disc", "Half ball", "Unit square",
                                             "Unit cube", "Rectangle", "Gmsh file"};
  return s;
}

Teuchos::RCP<const Teuchos::ParameterList> MeshFactory::getValidParameters()
{
  static Teuchos::RCP<const Teuchos::ParameterList> valid;
  if (valid.is_null()) {
    auto p = Teuchos::rcp(new Teuchos::ParameterList("Mesh"));
    sc::core::declareChoice(*p, "Source", "Half disc", sources(),
                            "Domain: a scene geometry (Half disc, Half ball: Hertz 2D/3D; Unit "
                            "square/cube, Rectangle: manufactured) or a Gmsh .msh file (Mesh/File)");
    sc::core::declareReal(*p, "Initial mesh size", 0.25,
                          "Target element size of the initial Gmsh mesh (Gmsh Mesh.MeshSizeMax)",
                          0.0, /*lowerOpen=*/true);
    sc::core::declareInt(*p, "Uniform refinements", 0,
                         "Uniform bisection levels applied to the initial mesh (x4 elements per "
                         "level in 2D, x8 in 3D)",
                         0, 20);
    sc::core::declareBool(*p, "Project boundary", true,
                          "Project new vertices on curved boundaries (Arc, Cap) onto the exact "
                          "circle/sphere; false keeps the initial polygonal boundary");
    sc::core::declareReal(*p, "Radius", 1.0, "Radius R of the Half disc / Half ball", 0.0, true);
    sc::core::declareString(*p, "File", "",
                            "Gmsh .msh file (format 2.2 or 4.1) for Source = Gmsh file; relative "
                            "paths are taken from the working directory");
    sc::core::declareRealArray(*p, "Lower corner", Teuchos::Array<double>(2, 0.0),
                               "Lower-left corner of the Rectangle", {2});
    sc::core::declareRealArray(*p, "Upper corner", Teuchos::Array<double>(2, 1.0),
                               "Upper-right corner of the Rectangle", {2});
    Teuchos::ParameterList& local = p->sublist(
        "Local refinement", false,
        "Bisection sweeps towards a region, after the uniform refinements (e.g. a contact zone)");
    sc::core::declareInt(local, "Levels", 0,
                         "Number of sweeps; each bisects every selected element once (3 sweeps "
                         "halve h in 3D, 2 in 2D); 0 = off",
                         0, 40);
    sc::core::declareRealArray(local, "Center", Teuchos::Array<double>(),
                               "Centre of the region (Problem/Dimension values; needed when "
                               "Levels > 0)",
                               {0, 2, 3});
    sc::core::declareReal(local, "Radius", 0.25,
                          "Elements whose centroid lies within this distance of Center are "
                          "selected",
                          0.0, true);
    sc::core::declareString(local, "Boundary", "",
                            "If set: select only elements with a face on this boundary part "
                            "whose centroid is within Radius (refines along a surface, e.g. Cap)");
    valid = p;
  }
  return valid;
}

namespace {
// Validate a copy, wrapped as sublist "Mesh" so that errors name 'Mesh/<key>'.
Teuchos::ParameterList validated(const Teuchos::ParameterList& meshList)
{
  Teuchos::ParameterList user, valid;
  user.sublist("Mesh") = meshList;
  user.sublist("Mesh").setName("Mesh");
  valid.sublist("Mesh") = *MeshFactory::getValidParameters();
  sc::core::validateParameters(user, valid, "Mesh parameters");
  return user.sublist("Mesh");
}

int sceneDimension(const std::string& source)
{
  if (source == "Half ball" || source == "Unit cube") return 3;
  if (source == "Gmsh file") return 0;
  return 2;
}
}  // namespace

Teuchos::RCP<const Geometry> MeshFactory::buildGeometry(const Teuchos::ParameterList& meshList,
                                                        int dimension)
{
  const Teuchos::ParameterList p = validated(meshList);
  const std::string source = p.get<std::string>("Source");
  SC_THROW_IF(dimension != 2 && dimension != 3, sc::core::InputError,
              "Problem/Dimension = " << dimension << " is not valid (2 or 3)");
  const int sd = sceneDimension(source);
  SC_THROW_IF(sd != 0 && sd != dimension, sc::core::InputError,
              "'Mesh/Source' = '" << source << "' is a " << sd << "D scene but Problem/Dimension = "
                                  << dimension << "; " << dimension << "D scenes: "
                                  << (dimension == 2 ? "'Half disc', 'Unit square', 'Rectangle'"
                                                     : "'Half ball', 'Unit cube'")
                                  << ", 'Gmsh file'");
  const double R = p.get<double>("Radius");
  if (source == "Half disc") return Teuchos::rcp(new HalfDiscGeometry(R));
  if (source == "Half ball") return Teuchos::rcp(new HalfBallGeometry(R));
  if (source == "Unit square") return Teuchos::rcp(new BoxGeometry({0, 0}, {1, 1}, source));
  if (source == "Unit cube") return Teuchos::rcp(new BoxGeometry({0, 0, 0}, {1, 1, 1}, source));
  if (source == "Rectangle") {
    const auto lo = p.get<Teuchos::Array<double>>("Lower corner");
    const auto hi = p.get<Teuchos::Array<double>>("Upper corner");
    return Teuchos::rcp(new BoxGeometry(std::vector<double>(lo.begin(), lo.end()),
                                        std::vector<double>(hi.begin(), hi.end()), source));
  }
  return Teuchos::null;  // Gmsh file
}

namespace {

Teuchos::RCP<SimplexMesh> initialMesh(const Teuchos::ParameterList& p, int dimension,
                                      const Teuchos::RCP<const Geometry>& geometry)
{
  Teuchos::RCP<SimplexMesh> initial;
  if (geometry.is_null()) {
    const std::string file = p.get<std::string>("File");
    SC_THROW_IF(file.empty(), sc::core::InputError,
                "'Mesh/Source' = 'Gmsh file' needs 'Mesh/File' (path of a .msh file)");
    initial = GmshMeshIO::readFile(file, dimension);
  } else {
    initial = GmshMeshIO::meshGeometry(*geometry, p.get<double>("Initial mesh size"));
  }
  return initial;
}

template <class T>
void broadcastVector(const Teuchos::Comm<int>& comm, std::vector<T>& v)
{
  int n = static_cast<int>(v.size());
  Teuchos::broadcast<int, int>(comm, 0, &n);
  v.resize(n);
  if (n > 0) Teuchos::broadcast<int, T>(comm, 0, n, v.data());
}

void broadcastString(const Teuchos::Comm<int>& comm, std::string& s)
{
  std::vector<char> c(s.begin(), s.end());
  broadcastVector(comm, c);
  s.assign(c.begin(), c.end());
}

Teuchos::RCP<BisectionRefiner> finish(const Teuchos::ParameterList& p,
                                      Teuchos::RCP<const SimplexMesh> initial,
                                      Teuchos::RCP<const Geometry> geometry, bool split)
{
  if (split) initial = splitElementsWithAllVerticesOnBoundary(*initial);
  auto refiner = Teuchos::rcp(new BisectionRefiner(initial, geometry, p.get<bool>("Project boundary")));
  for (int i = 0; i < p.get<int>("Uniform refinements"); ++i) refiner->refineUniformly();
  MeshFactory::refineLocally(*refiner, p.sublist("Local refinement"));
  return refiner;
}

}  // namespace

Teuchos::RCP<BisectionRefiner> MeshFactory::build(const Teuchos::ParameterList& meshList,
                                                  int dimension, const Teuchos::Comm<int>& comm,
                                                  bool splitBoundarySimplices)
{
  if (comm.getSize() == 1) return build(meshList, dimension, splitBoundarySimplices);
  const Teuchos::ParameterList p = validated(meshList);  // same on every rank: throws everywhere
  auto geometry = buildGeometry(p, dimension);
  std::vector<double> coords;
  std::vector<int> elems, bfv, bpart;
  std::string names, origin, error;
  if (comm.getRank() == 0) {
    try {
      auto m = initialMesh(p, dimension, geometry);
      coords = m->coordinates();
      elems = m->elementVertices();
      for (int f : m->boundaryFaces()) {
        bfv.insert(bfv.end(), m->faceVertices(f), m->faceVertices(f) + dimension);
        bpart.push_back(m->faceBoundaryId(f));
      }
      for (const auto& n : m->boundaryNames()) names += n + '\n';
      origin = m->origin();
    } catch (const sc::core::InputError& e) {
      error = std::string("I") + e.what();
    } catch (const std::exception& e) {
      error = std::string("X") + e.what();
    }
  }
  broadcastString(comm, error);
  SC_THROW_IF(!error.empty() && error[0] == 'I', sc::core::InputError, error.substr(1));
  SC_THROW_IF(!error.empty(), sc::core::InternalError, error.substr(1));
  broadcastVector(comm, coords);
  broadcastVector(comm, elems);
  broadcastVector(comm, bfv);
  broadcastVector(comm, bpart);
  broadcastString(comm, names);
  broadcastString(comm, origin);
  std::vector<std::string> nameList;
  for (std::size_t a = 0, b; (b = names.find('\n', a)) != std::string::npos; a = b + 1)
    nameList.push_back(names.substr(a, b - a));
  auto mesh = Teuchos::rcp(new SimplexMesh(dimension, std::move(coords), std::move(elems), bfv,
                                           bpart, nameList, origin));
  return finish(p, mesh, geometry, splitBoundarySimplices);
}

void MeshFactory::refineLocally(BisectionRefiner& refiner, const Teuchos::ParameterList& list)
{
  Teuchos::ParameterList local(list);  // get() with defaults: missing keys mean the defaults
  const int levels = local.get<int>("Levels", 0);
  if (levels == 0) return;
  const int d = refiner.mesh()->dim();
  const auto center = local.get<Teuchos::Array<double>>("Center", Teuchos::Array<double>());
  SC_THROW_IF(static_cast<int>(center.size()) != d, sc::core::InputError,
              "'Mesh/Local refinement/Center' needs " << d << " values (the problem dimension) "
              "when 'Mesh/Local refinement/Levels' = " << levels << " > 0; got "
              << center.size() << ".");
  const double radius = local.get<double>("Radius", 0.25);
  const std::string boundary = local.get<std::string>("Boundary", "");
  // boundaryId() throws an InputError listing the valid part names.
  const int part = boundary.empty() ? -1 : refiner.mesh()->boundaryId(boundary);
  auto within = [&](const SimplexMesh& m, const int* verts, int n) {
    double r2 = 0.0;
    for (int j = 0; j < d; ++j) {
      double c = 0.0;
      for (int i = 0; i < n; ++i) c += m.vertex(verts[i])[j] / n;
      r2 += (c - center[j]) * (c - center[j]);
    }
    return r2 < radius * radius;
  };
  for (int level = 0; level < levels; ++level) {
    const auto m = refiner.mesh();
    std::vector<int> marked;
    if (part < 0) {
      for (int e = 0; e < m->numElements(); ++e)
        if (within(*m, m->elementVertices(e), d + 1)) marked.push_back(e);
    } else {
      for (int f : m->boundaryFaces())
        if (m->faceBoundaryId(f) == part && within(*m, m->faceVertices(f), d))
          marked.push_back(m->faceElements(f)[0]);
    }
    if (marked.empty()) break;  // the region holds no element (or face) centroid any more
    refiner.refine(marked);
  }
}

Teuchos::RCP<BisectionRefiner> MeshFactory::build(const Teuchos::ParameterList& meshList,
                                                  int dimension, bool splitBoundarySimplices)
{
  const Teuchos::ParameterList p = validated(meshList);
  auto geometry = buildGeometry(p, dimension);
  return finish(p, initialMesh(p, dimension, geometry), geometry, splitBoundarySimplices);
}

}  // namespace sc::mesh
