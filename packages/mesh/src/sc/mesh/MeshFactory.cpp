#include <sc/mesh/MeshFactory.hpp>

#include <sc/core/Error.hpp>
#include <sc/core/Parameters.hpp>
#include <sc/mesh/BoundarySimplexSplit.hpp>
#include <sc/mesh/BoxGeometry.hpp>
#include <sc/mesh/CadGeometry.hpp>
#include <sc/mesh/GmshMeshIO.hpp>
#include <sc/mesh/HalfBallGeometry.hpp>
#include <sc/mesh/HalfDiscGeometry.hpp>
#include <sc/mesh/ResourceEstimate.hpp>

#include <sc/core/Collective.hpp>

#include <cmath>
#include <sstream>

namespace sc::mesh {

const std::vector<std::string>& MeshFactory::sources()
{
  static const std::vector<std::string> s = {"Half disc", "Half ball", "Unit square",  "Unit cube",
                                             "Rectangle", "Gmsh file", "Gmsh geometry"};
  return s;
}

Teuchos::RCP<const Teuchos::ParameterList> MeshFactory::getValidParameters()
{
  static Teuchos::RCP<const Teuchos::ParameterList> valid;
  if (valid.is_null()) {
    auto p = Teuchos::rcp(new Teuchos::ParameterList("Mesh"));
    sc::core::declareChoice(*p, "Source", "Half disc", sources(),
                            "Domain: a scene geometry (Half disc, Half ball: Hertz 2D/3D; Unit "
                            "square/cube, Rectangle: manufactured), a Gmsh .msh mesh file read as "
                            "data (Gmsh file; linear, or quadratic for curved boundaries), or a "
                            "Gmsh .geo script that Gmsh runs and meshes (Gmsh geometry: the script "
                            "is a program and may merge CAD files; refinement places new boundary "
                            "vertices on its CAD entities). Mesh/File names the file "
                            "(docs/mesh.md 'Curved boundaries from files')");
    sc::core::declareReal(*p, "Initial mesh size", 0.25,
                          "Target element size of the initial Gmsh mesh (Gmsh Mesh.MeshSizeMax)",
                          0.0, /*lowerOpen=*/true);
    sc::core::declareInt(*p, "Uniform refinements", 0,
                         "Uniform bisection levels applied to the initial mesh (x4 elements per "
                         "level in 2D, x8 in 3D)",
                         0, 20);
    sc::core::declareReal(*p, "Memory limit (GB)", 0.0,
                          "Memory the run may use, in GB (1e9 bytes), summed over ranks; 0 = the "
                          "memory available when the run starts (MemAvailable in /proc/meminfo). "
                          "Meshes and refinements whose estimated memory exceeds it are refused "
                          "before they are made; an adaptive run stops before such a cycle "
                          "(docs/mesh.md, 'Resource limits')",
                          0.0, /*lowerOpen=*/false);
    sc::core::declareBool(*p, "Project boundary", true,
                          "Project new vertices on curved boundaries onto the exact boundary: the "
                          "circle/sphere of Arc, Cap; a Gmsh geometry's CAD entities; a quadratic "
                          "Gmsh file's curved faces. false keeps the initial polygonal boundary");
    sc::core::declareInt(*p, "Geometry order", 2,
                         "2: quadratic (isoparametric) elements at the scene's curved boundaries "
                         "(Arc, Cap, a Gmsh geometry's or a quadratic Gmsh file's curved parts), "
                         "their edge midpoints on the exact boundary, mapped by the "
                         "non-affine Piola maps (docs/mesh.md, 'Curved elements'); needs Project "
                         "boundary = true; no effect on scenes without curved parts or on linear "
                         "Gmsh files. 1: straight-sided (affine) elements everywhere (the talk's "
                         "'straight boundaries' study, with Project boundary = false)",
                         1, 2);
    sc::core::declareReal(*p, "Radius", 1.0,
                          "Radius R of the Half disc / Half ball. At least 1e-5: OpenCASCADE, "
                          "which builds the scene, works to an absolute tolerance of 1e-7 (R = "
                          "1e-6 could not be meshed); scale the length unit for smaller bodies",
                          1e-5, false);
    sc::core::declareString(*p, "File", "",
                            "Source = Gmsh file: a .msh file (format 2.2 or 4.1), read as data. "
                            "Source = Gmsh geometry: a .geo script, run by Gmsh. A relative path "
                            "in a deck is taken from the deck's directory, one given by --set from "
                            "the working directory");
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

// The "Local refinement" sublist checked against its declaration, with its declared defaults.
Teuchos::ParameterList validatedLocal(const Teuchos::ParameterList& list)
{
  Teuchos::ParameterList user, valid;
  user.sublist("Mesh").sublist("Local refinement") = list;
  user.sublist("Mesh").sublist("Local refinement").setName("Local refinement");
  valid.sublist("Mesh").set("Local refinement",
                            MeshFactory::getValidParameters()->sublist("Local refinement"));
  sc::core::validateParameters(user, valid, "Mesh parameters");
  return user.sublist("Mesh").sublist("Local refinement");
}

std::vector<double> toVector(const Teuchos::Array<double>& a) { return {a.begin(), a.end()}; }

int sceneDimension(const std::string& source)
{
  if (source == "Half ball" || source == "Unit cube") return 3;
  if (source == "Gmsh file" || source == "Gmsh geometry") return 0;
  return 2;
}
}  // namespace

LocalRefinementSettings LocalRefinementSettings::fromParameters(const Teuchos::ParameterList& l)
{
  LocalRefinementSettings s;
  s.levels = l.get<int>("Levels");
  s.center = toVector(l.get<Teuchos::Array<double>>("Center"));
  s.radius = l.get<double>("Radius");
  s.boundary = l.get<std::string>("Boundary");
  return s;
}

LocalRefinementSettings
LocalRefinementSettings::fromUncheckedParameters(const Teuchos::ParameterList& local)
{
  return fromParameters(validatedLocal(local));
}

MeshSettings MeshSettings::fromParameters(const Teuchos::ParameterList& p)
{
  MeshSettings s;
  s.source = p.get<std::string>("Source");
  s.initialMeshSize = p.get<double>("Initial mesh size");
  s.uniformRefinements = p.get<int>("Uniform refinements");
  s.memoryLimitGB = p.get<double>("Memory limit (GB)");
  s.projectBoundary = p.get<bool>("Project boundary");
  s.geometryOrder = p.get<int>("Geometry order");
  s.radius = p.get<double>("Radius");
  s.file = p.get<std::string>("File");
  s.lowerCorner = toVector(p.get<Teuchos::Array<double>>("Lower corner"));
  s.upperCorner = toVector(p.get<Teuchos::Array<double>>("Upper corner"));
  s.local = LocalRefinementSettings::fromParameters(p.sublist("Local refinement"));
  return s;
}

MeshSettings MeshSettings::fromUncheckedParameters(const Teuchos::ParameterList& meshList)
{
  return fromParameters(validated(meshList));
}

Teuchos::RCP<const Geometry> MeshFactory::buildGeometry(const MeshSettings& s, int dimension)
{
  const std::string& source = s.source;
  SC_THROW_IF(dimension != 2 && dimension != 3, sc::core::InputError,
              "Problem/Dimension = " << dimension << " is not valid (2 or 3)");
  const int sd = sceneDimension(source);
  SC_THROW_IF(sd != 0 && sd != dimension, sc::core::InputError,
              "'Mesh/Source' = '" << source << "' is a " << sd << "D scene but Problem/Dimension = "
                                  << dimension << "; " << dimension << "D scenes: "
                                  << (dimension == 2 ? "'Half disc', 'Unit square', 'Rectangle'"
                                                     : "'Half ball', 'Unit cube'")
                                  << ", 'Gmsh file', 'Gmsh geometry'");
  const double R = s.radius;
  if (source == "Half disc") return Teuchos::rcp(new HalfDiscGeometry(R));
  if (source == "Half ball") return Teuchos::rcp(new HalfBallGeometry(R));
  if (source == "Unit square") return Teuchos::rcp(new BoxGeometry({0, 0}, {1, 1}, source));
  if (source == "Unit cube") return Teuchos::rcp(new BoxGeometry({0, 0, 0}, {1, 1, 1}, source));
  if (source == "Rectangle")
    return Teuchos::rcp(new BoxGeometry(s.lowerCorner, s.upperCorner, source));
  if (source == "Gmsh geometry") {
    SC_THROW_IF(s.file.empty(), sc::core::InputError,
                "'Mesh/Source' = 'Gmsh geometry' needs 'Mesh/File' (path of a .geo script)");
    return Teuchos::rcp(new CadGeometry(s.file, dimension));
  }
  return Teuchos::null;  // Gmsh file: its boundary comes with the file (initialMesh)
}

Teuchos::RCP<const Geometry> MeshFactory::buildGeometry(const Teuchos::ParameterList& meshList,
                                                        int dimension)
{
  return buildGeometry(MeshSettings::fromUncheckedParameters(meshList), dimension);
}

namespace {

// The local-refinement selection of one sweep (Levels > 0; validated Center).
struct LocalSelection {
  int d = 0, part = -1;
  std::vector<double> center;
  double radius = 0.0;
  bool within(const SimplexMesh& m, const int* verts, int n) const
  {
    double r2 = 0.0;
    for (int j = 0; j < d; ++j) {
      double c = 0.0;
      for (int i = 0; i < n; ++i)
        c += m.vertex(verts[i])[j] / n;
      r2 += (c - center[j]) * (c - center[j]);
    }
    return r2 < radius * radius;
  }
  std::vector<int> marked(const SimplexMesh& m) const
  {
    std::vector<int> marked;
    if (part < 0) {
      for (int e = 0; e < m.numElements(); ++e)
        if (within(m, m.elementVertices(e), d + 1)) marked.push_back(e);
    } else {
      for (int f : m.boundaryFaces())
        if (m.faceBoundaryId(f) == part && within(m, m.faceVertices(f), d))
          marked.push_back(m.faceElements(f)[0]);
    }
    return marked;
  }
};

LocalSelection localSelection(const SimplexMesh& mesh, const LocalRefinementSettings& local)
{
  LocalSelection s;
  s.d = mesh.dim();
  s.center = local.center;
  SC_THROW_IF(static_cast<int>(s.center.size()) != s.d, sc::core::InputError,
              "'Mesh/Local refinement/Center' needs " << s.d
                                                      << " values (the problem dimension) "
                                                         "when 'Mesh/Local refinement/Levels' = "
                                                      << local.levels << " > 0; got "
                                                      << s.center.size() << ".");
  s.radius = local.radius;
  // boundaryId() throws an InputError listing the valid part names.
  s.part = local.boundary.empty() ? -1 : mesh.boundaryId(local.boundary);
  return s;
}

// Stage 1, before Gmsh runs: the initial mesh of a scene from its measure and the target size.
void checkInitialEstimate(const MeshSettings& p, int dimension, const ResourceLimit& limit)
{
  if (!limit.active()) return;
  const double measure = sceneMeasure(p, dimension);
  if (measure <= 0.0) return;  // Gmsh file: checked once read (its size is the file's)
  const double h = p.initialMeshSize;
  const double n = estimateInitialElements(measure, h, dimension);
  if (limit.fits(n)) return;
  const double hMin = h * std::pow(n / limit.maxElements(), 1.0 / dimension);
  SC_THROW_IF(true, sc::core::InputError,
              "'Mesh/Initial mesh size' = "
                  << h << " is too small: the initial mesh of the '" << p.source << "' ("
                  << (dimension == 2 ? "area " : "volume ") << measure << ") would have "
                  << limit.describe(n) << ". Make 'Mesh/Initial mesh size' at least about " << hMin
                  << " or raise 'Mesh/Memory limit (GB)' on a larger machine.");
}

// Stage 2, on the initial mesh (all ranks): uniform levels (×2^d each) and the local sweeps.
void checkRefinementEstimate(const MeshSettings& p, const SimplexMesh& initial,
                             const ResourceLimit& limit)
{
  if (!limit.active()) return;
  const int d = initial.dim();
  const double n0 = initial.numElements();
  const double maxN = limit.maxElements();
  if (!limit.fits(n0))
    SC_THROW_IF(true, sc::core::InputError,
                "the initial mesh (" << initial.origin() << ") has " << limit.describe(n0)
                                     << ". Use a coarser mesh.");
  const int uniform = p.uniformRefinements;
  const double nU = n0 * std::pow(2.0, d * uniform);
  if (!limit.fits(nU)) {
    const int fit = static_cast<int>(std::floor(std::log2(maxN / n0) / d));
    SC_THROW_IF(true, sc::core::InputError,
                "'Mesh/Uniform refinements' = " << uniform << " is too many: the initial mesh's "
                                                << initial.numElements() << " elements times "
                                                << (1 << d) << " per level would give "
                                                << limit.describe(nU) << ". At most "
                                                << std::max(fit, 0) << " uniform levels fit.");
  }
  const int levels = p.local.levels;
  if (levels == 0) return;
  const auto est = MeshFactory::estimateRefinement(p, initial);
  if (!limit.fits(est.local)) {
    MeshSettings q(p);
    int fit = 0;
    for (; fit < levels; ++fit) {
      q.local.levels = fit + 1;
      if (!limit.fits(MeshFactory::estimateRefinement(q, initial).local)) break;
    }
    SC_THROW_IF(true, sc::core::InputError,
                "'Mesh/Local refinement/Levels' = "
                    << levels << " is too many: " << static_cast<long long>(est.selected)
                    << " selected elements, growing about "
                    << std::round(est.growth * 100.0) / 100.0
                    << " times per sweep, each with about " << est.closure
                    << " new elements with the closure, would give " << limit.describe(est.local)
                    << ". At most " << fit
                    << " sweeps fit; fewer sweeps or a smaller 'Mesh/Local refinement/Radius'.");
  }
}

}  // namespace

double MeshFactory::estimateInitialElements(const Teuchos::ParameterList& meshList, int dimension)
{
  const MeshSettings p = MeshSettings::fromUncheckedParameters(meshList);
  const double measure = sceneMeasure(p, dimension);
  if (measure <= 0.0) return -1.0;
  return sc::mesh::estimateInitialElements(measure, p.initialMeshSize, dimension);
}

MeshEstimate MeshFactory::estimateRefinement(const Teuchos::ParameterList& meshList,
                                             const SimplexMesh& initial)
{
  return estimateRefinement(MeshSettings::fromUncheckedParameters(meshList), initial);
}

MeshEstimate MeshFactory::estimateRefinement(const MeshSettings& p, const SimplexMesh& initial)
{
  const int d = initial.dim();
  MeshEstimate e;
  e.initial = initial.numElements();
  const int uniform = p.uniformRefinements;
  e.uniform = e.initial * std::pow(2.0, d * uniform);
  e.local = e.uniform;
  const int levels = p.local.levels;
  if (levels == 0) return e;
  const LocalSelection sel = localSelection(initial, p.local);
  // Selected elements after the uniform levels: ×2^d (volume) or ×2^(d-1) (faces on a part).
  const bool surface = sel.part >= 0;
  e.selected = static_cast<double>(sel.marked(initial).size()) *
               std::pow(2.0, (surface ? d - 1 : d) * uniform);
  // A volume region keeps its measure while h halves every d sweeps: its elements double per
  // sweep; along a surface they grow by 2^((d-1)/d). Each selected element brings `closure` new
  // ones with the conforming closure (calibrated: docs/mesh.md "Resource limits").
  e.growth = surface ? std::pow(2.0, (d - 1.0) / d) : 2.0;
  e.closure = closureFactor(d, surface);
  e.local =
      e.uniform + e.closure * e.selected * (std::pow(e.growth, levels) - 1.0) / (e.growth - 1.0);
  return e;
}

namespace {

// The initial mesh, and for a Gmsh file the boundary it gives (null otherwise).
GmshMeshIO::MeshFile initialMesh(const MeshSettings& p, int dimension,
                                 const Teuchos::RCP<const Geometry>& geometry)
{
  if (geometry.is_null()) {
    SC_THROW_IF(p.file.empty(), sc::core::InputError,
                "'Mesh/Source' = 'Gmsh file' needs 'Mesh/File' (path of a .msh file)");
    return GmshMeshIO::readMeshFile(p.file, dimension);
  }
  const double h = p.initialMeshSize;
  if (const auto* cad = dynamic_cast<const CadGeometry*>(geometry.get()))
    return {GmshMeshIO::meshCad(*cad, h, p.geometryOrder), Teuchos::null};
  return {GmshMeshIO::meshGeometry(*geometry, h), Teuchos::null};
}

Teuchos::RCP<BisectionRefiner> finish(const MeshSettings& p,
                                      Teuchos::RCP<const SimplexMesh> initial,
                                      Teuchos::RCP<const Geometry> geometry, bool split,
                                      const ResourceLimit& limit)
{
  if (split) initial = splitElementsWithAllVerticesOnBoundary(*initial);
  checkRefinementEstimate(p, *initial, limit);
  SC_THROW_IF(p.geometryOrder == 2 && !p.projectBoundary, core::InputError,
              "'Mesh/Geometry order' = 2 places the curved elements' nodes on the exact boundary, "
              "but 'Mesh/Project boundary' = false keeps the initial polygon: set 'Mesh/Geometry "
              "order' = 1 for the straight-boundaries study, or 'Mesh/Project boundary' = true.");
  auto refiner = Teuchos::rcp(new BisectionRefiner(initial, geometry, p.projectBoundary));
  for (int i = 0; i < p.uniformRefinements; ++i)
    refiner->refineUniformly();
  MeshFactory::refineLocally(*refiner, p.local, limit);
  return refiner;
}

}  // namespace

Teuchos::RCP<BisectionRefiner> MeshFactory::build(const MeshSettings& p, int dimension,
                                                  const Teuchos::Comm<int>& comm,
                                                  bool splitBoundarySimplices,
                                                  const ResourceLimit& limit)
{
  if (comm.getSize() == 1) return build(p, dimension, splitBoundarySimplices, limit);
  auto geometry =
      buildGeometry(p, dimension);            // the same settings on every rank: throws everywhere
  checkInitialEstimate(p, dimension, limit);  // the same limit on every rank: throws everywhere
  std::vector<double> coords, boundaryNodes;
  std::vector<int> elems, bfv, bpart, boundaryPart;
  std::string names, origin;
  // Rank 0 meshes (Gmsh); an error there is thrown on every rank (InputError stays one).
  core::runOnRoot(comm, [&] {
    const auto file = initialMesh(p, dimension, geometry);
    const auto& m = file.mesh;
    if (!file.boundary.is_null()) {
      boundaryNodes = file.boundary->faceNodes();
      boundaryPart = file.boundary->facePart();
    }
    coords = m->coordinates();
    elems = m->elementVertices();
    for (int f : m->boundaryFaces()) {
      bfv.insert(bfv.end(), m->faceVertices(f), m->faceVertices(f) + dimension);
      bpart.push_back(m->faceBoundaryId(f));
    }
    for (const auto& n : m->boundaryNames())
      names += n + '\n';
    origin = m->origin();
  });
  core::broadcast(comm, 0, coords);
  core::broadcast(comm, 0, elems);
  core::broadcast(comm, 0, bfv);
  core::broadcast(comm, 0, bpart);
  core::broadcast(comm, 0, names);
  core::broadcast(comm, 0, origin);
  core::broadcast(comm, 0, boundaryNodes);
  core::broadcast(comm, 0, boundaryPart);
  std::vector<std::string> nameList;
  for (std::size_t a = 0, b; (b = names.find('\n', a)) != std::string::npos; a = b + 1)
    nameList.push_back(names.substr(a, b - a));
  auto mesh = Teuchos::rcp(new SimplexMesh(dimension, std::move(coords), std::move(elems), bfv,
                                           bpart, nameList, origin));
  if (geometry.is_null())  // a Gmsh file: the boundary it gives, the same on every rank
    geometry = Teuchos::rcp(new MeshBoundaryGeometry(dimension, mesh->boundaryNames(),
                                                     std::move(boundaryNodes),
                                                     std::move(boundaryPart), origin));
  return finish(p, mesh, geometry, splitBoundarySimplices, limit);
}

Teuchos::RCP<BisectionRefiner> MeshFactory::build(const Teuchos::ParameterList& meshList,
                                                  int dimension, const Teuchos::Comm<int>& comm,
                                                  bool splitBoundarySimplices,
                                                  const ResourceLimit& limit)
{
  // Validated on every rank alike: an error is thrown everywhere.
  return build(MeshSettings::fromUncheckedParameters(meshList), dimension, comm,
               splitBoundarySimplices, limit);
}

void MeshFactory::refineLocally(BisectionRefiner& refiner, const Teuchos::ParameterList& list,
                                const ResourceLimit& limit)
{
  refineLocally(refiner, LocalRefinementSettings::fromUncheckedParameters(list), limit);
}

void MeshFactory::refineLocally(BisectionRefiner& refiner, const LocalRefinementSettings& local,
                                const ResourceLimit& limit)
{
  const int levels = local.levels;
  if (levels == 0) return;
  const LocalSelection sel = localSelection(*refiner.mesh(), local);
  for (int level = 0; level < levels; ++level) {
    const auto m = refiner.mesh();
    const std::vector<int> marked = sel.marked(*m);
    if (marked.empty()) break;  // the region holds no element (or face) centroid any more
    // The estimate of build() is checked again with the real counts before each sweep.
    const double next = m->numElements() +
                        closureFactor(m->dim(), sel.part >= 0) * static_cast<double>(marked.size());
    SC_THROW_IF(limit.active() && !limit.fits(next), sc::core::InputError,
                "'Mesh/Local refinement/Levels' = "
                    << levels << " is too many: sweep " << level + 1 << " would bisect "
                    << marked.size() << " of " << m->numElements() << " elements, giving "
                    << limit.describe(next) << ". At most " << level << " sweeps fit.");
    refiner.refine(marked);
  }
}

Teuchos::RCP<BisectionRefiner> MeshFactory::build(const MeshSettings& p, int dimension,
                                                  bool splitBoundarySimplices,
                                                  const ResourceLimit& limit)
{
  auto geometry = buildGeometry(p, dimension);
  checkInitialEstimate(p, dimension, limit);
  auto file = initialMesh(p, dimension, geometry);
  if (geometry.is_null()) geometry = file.boundary;
  return finish(p, file.mesh, geometry, splitBoundarySimplices, limit);
}

Teuchos::RCP<BisectionRefiner> MeshFactory::build(const Teuchos::ParameterList& meshList,
                                                  int dimension, bool splitBoundarySimplices,
                                                  const ResourceLimit& limit)
{
  return build(MeshSettings::fromUncheckedParameters(meshList), dimension, splitBoundarySimplices,
               limit);
}

bool MeshFactory::hasCurvedElements(const MeshSettings& settings, const BisectionRefiner& refiner)
{
  return settings.geometryOrder >= 2 && !refiner.geometry().is_null() &&
         refiner.projectsBoundary() && !refiner.geometry()->curvedBoundaryNames().empty();
}

Teuchos::RCP<const CurvedElements> MeshFactory::curvedElements(const MeshSettings& settings,
                                                               const BisectionRefiner& refiner)
{
  if (!hasCurvedElements(settings, refiner)) return Teuchos::null;
  return Teuchos::rcp(new CurvedElements(refiner.mesh(), *refiner.geometry()));
}

}  // namespace sc::mesh
