#include "sc/assembly/LoadsAndSupports.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>

#include <Teuchos_LAPACK.hpp>

#include <sc/core/Error.hpp>
#include <sc/mesh/CurvedElements.hpp>
#include <sc/mesh/SimplexMesh.hpp>

namespace sc::assembly {
namespace {

const char* axisName(int i) { return i == 0 ? "x" : i == 1 ? "y" : "z"; }

std::string vectorText(const double* v, int d)
{
  std::ostringstream os;
  os << "(";
  for (int c = 0; c < d; ++c)
    os << (c ? ", " : "") << (std::abs(v[c]) < 1e-12 ? 0.0 : v[c]);
  os << ")";
  return os.str();
}

// The diagonal of the mesh's bounding box, and its centre.
double boundingBox(const mesh::SimplexMesh& m, double* centre)
{
  const int d = m.dim();
  const auto& x = m.coordinates();
  double diag2 = 0.0;
  for (int c = 0; c < d; ++c) {
    double lo = x.empty() ? 0.0 : x[c], hi = lo;
    for (std::size_t i = c; i < x.size(); i += d)
      lo = std::min(lo, x[i]), hi = std::max(hi, x[i]);
    diag2 += (hi - lo) * (hi - lo);
    centre[c] = 0.5 * (lo + hi);
  }
  return std::sqrt(diag2);
}

}  // namespace

std::map<std::string, NormalFramePart> normalFrameParts(const mesh::SimplexMesh& m,
                                                        const core::BoundaryConditions& bcs)
{
  const int d = m.dim();
  double centre[3] = {0, 0, 0};
  const double tolerance = 1e-9 * boundingBox(m, centre);
  std::map<std::string, NormalFramePart> parts;
  for (const auto& bc : bcs.conditions) {
    if (!bc.inNormalFrame() || !m.hasBoundary(bc.boundary)) continue;
    const std::string key =
        "'Boundary Conditions/" + bc.boundary + "/Type' = '" + core::toString(bc.type) + "'";
    const auto faces = m.boundaryFacesOf(bc.boundary);
    double lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0}, mean[3] = {0, 0, 0};
    bool first = true;
    for (int f : faces) {
      const auto nf = m.faceNormal(f);
      for (int c = 0; c < d; ++c)
        mean[c] += m.faceMeasure(f) * nf[c];
      for (int k = 0; k < d; ++k) {
        const double* p = m.vertex(m.faceVertices(f)[k]);
        for (int c = 0; c < d; ++c) {
          lo[c] = first ? p[c] : std::min(lo[c], p[c]);
          hi[c] = first ? p[c] : std::max(hi[c], p[c]);
        }
        first = false;
      }
    }
    NormalFramePart part;
    for (int c = 0; c < d; ++c)
      if (hi[c] - lo[c] <= tolerance &&
          (part.axis < 0 || hi[c] - lo[c] < hi[part.axis] - lo[part.axis]))
        part.axis = c;
    double norm = 0.0;
    for (int c = 0; c < d; ++c)
      norm += mean[c] * mean[c];
    norm = std::sqrt(norm);
    if (part.axis >= 0) {
      part.normal[part.axis] = mean[part.axis] >= 0.0 ? 1.0 : -1.0;
    } else {
      SC_THROW_IF(norm <= 0.0, core::InternalError, "part '" << bc.boundary << "' has no area");
      for (int c = 0; c < d; ++c)
        part.normal[c] = mean[c] / norm;
      // Flat: every vertex within the tolerance of the plane through the first one, and every
      // face facing the same way.
      const double* p0 = m.vertex(m.faceVertices(faces.front())[0]);
      double far = 0.0, worstFace = 1.0;
      for (int f : faces) {
        const auto nf = m.faceNormal(f);
        double dot = 0.0;
        for (int c = 0; c < d; ++c)
          dot += nf[c] * part.normal[c];
        worstFace = std::min(worstFace, dot);
        for (int k = 0; k < d; ++k) {
          const double* p = m.vertex(m.faceVertices(f)[k]);
          double h = 0.0;
          for (int c = 0; c < d; ++c)
            h += (p[c] - p0[c]) * part.normal[c];
          far = std::max(far, std::abs(h));
        }
      }
      SC_THROW_IF(far > tolerance || worstFace < 0.5, core::InputError,
                  key << " needs a flat part (" << (d == 2 ? "a straight line" : "a plane")
                      << ", of any orientation), but '" << bc.boundary << "' is not flat: its "
                      << "vertices are up to " << far << " away from the "
                      << (d == 2 ? "line" : "plane") << " through " << vectorText(p0, d)
                      << " with its mean outward normal " << vectorText(part.normal.data(), d)
                      << " (allowed: " << tolerance << ", 1e-9 of the mesh's size). Conditions in "
                      << "the normal–tangential frame of curved parts are not supported "
                      << "(docs/theory.md §\"Loads and supports\"); split the part into flat "
                      << "parts, or use Type Displacement (with Expression data) or Pressure.");
    }
    parts[bc.boundary] = part;
  }
  return parts;
}

void checkNormalFramePartsFlat(const mesh::SimplexMesh& m, const core::BoundaryConditions& bcs,
                               const mesh::CurvedElements& curved)
{
  const int d = m.dim();
  double centre[3] = {0, 0, 0};
  const double tolerance = 1e-9 * boundingBox(m, centre);
  for (const auto& [name, part] : normalFrameParts(m, bcs))
    for (int f : m.boundaryFacesOf(name)) {
      const int e = m.faceElements(f)[0];
      if (!curved.isCurved(e)) continue;
      const int* fv = m.faceVertices(f);
      const double* p0 = m.vertex(fv[0]);
      const int* edges = m.elementEdges(e);
      const int nEdges = d == 2 ? 3 : 6;
      for (int k = 0; k < nEdges; ++k) {
        const int* ev = m.edgeVertices(edges[k]);
        const bool onFace = std::count(fv, fv + d, ev[0]) && std::count(fv, fv + d, ev[1]);
        if (!onFace || !curved.isCurvedEdge(edges[k])) continue;
        const double* mid = curved.edgeMidpoint(edges[k]);
        double h = 0.0;
        for (int c = 0; c < d; ++c)
          h += (mid[c] - p0[c]) * part.normal[c];
        const core::BoundaryCondition* bc = bcs.find(name);
        SC_THROW_IF(
            std::abs(h) > tolerance, core::InputError,
            "'Boundary Conditions/"
                << name << "/Type' = '" << core::toString(bc->type) << "' needs a flat part, but '"
                << name << "' is curved (its quadratic "
                << "faces, Mesh/Geometry order = 2, follow a curved geometry: the "
                << "midpoint " << vectorText(mid, d) << " of one of its edges is " << std::abs(h)
                << " away from the " << (d == 2 ? "line" : "plane") << " of its vertices): "
                << "conditions in the normal–tangential frame of curved parts are not "
                << "supported (docs/theory.md §\"Loads and supports\"); use Mesh/Geometry "
                << "order = 1 with Mesh/Project boundary = false to keep the part straight, "
                << "or Type Displacement or Pressure.");
      }
    }
}

std::vector<SupportDirection>
supportDirections(const mesh::SimplexMesh& m, const core::BoundaryConditions& bcs,
                  const std::map<std::string, NormalFramePart>& frameParts)
{
  std::vector<SupportDirection> out;
  for (const auto& bc : bcs.conditions) {
    if (!m.hasBoundary(bc.boundary)) continue;
    if (bc.inNormalFrame()) out.push_back({bc.boundary, frameParts.at(bc.boundary).normal});
    if (bc.type == core::BoundaryType::Components)
      for (int i = 0; i < m.dim(); ++i)
        if (bc.displacementComponent(i)) {
          SupportDirection s{bc.boundary, {0, 0, 0}};
          s.direction[i] = 1.0;
          out.push_back(s);
        }
  }
  return out;
}

std::vector<std::vector<double>> freeRigidMotions(const mesh::SimplexMesh& m,
                                                  const std::vector<SupportDirection>& supports,
                                                  const std::vector<int>* elements)
{
  const int d = m.dim(), r = d == 2 ? 3 : 6;
  double centre[3] = {0, 0, 0};
  const double scale = std::max(boundingBox(m, centre), 1e-300);
  // Gram matrix of the constraints v(x)·n = 0 at the parts' vertices, in coordinates centred on
  // the bounding box and scaled by its diagonal (translations and rotations of one size).
  std::vector<double> G(static_cast<std::size_t>(r) * r, 0.0);
  for (const auto& support : supports)
    for (int f : m.boundaryFacesOf(support.part)) {
      if (elements && !std::binary_search(elements->begin(), elements->end(), m.faceElements(f)[0]))
        continue;
      for (int k = 0; k < d; ++k) {
        const double* p = m.vertex(m.faceVertices(f)[k]);
        double x[3] = {0, 0, 0};
        for (int c = 0; c < d; ++c)
          x[c] = (p[c] - centre[c]) / scale;
        const double* n = support.direction.data();
        std::vector<double> row(r, 0.0);
        for (int c = 0; c < d; ++c)
          row[c] = n[c];
        if (d == 2) {
          row[2] = -x[1] * n[0] + x[0] * n[1];
        } else {
          // (e_a × x)·n = e_a·(x × n)
          row[3] = x[1] * n[2] - x[2] * n[1];
          row[4] = x[2] * n[0] - x[0] * n[2];
          row[5] = x[0] * n[1] - x[1] * n[0];
        }
        for (int i = 0; i < r; ++i)
          for (int j = 0; j < r; ++j)
            G[i * r + j] += row[i] * row[j];
      }
    }
  std::vector<double> eig(r), work(3 * r);
  int info = 0;
  Teuchos::LAPACK<int, double>().SYEV('V', 'U', r, G.data(), r, eig.data(), work.data(),
                                      static_cast<int>(work.size()), &info);
  SC_THROW_IF(info != 0, core::InternalError,
              "LAPACK SYEV failed in freeRigidMotions (" << info << ")");
  std::vector<std::vector<double>> free;
  const double largest = std::max(eig[r - 1], 0.0);
  for (int i = 0; i < r; ++i)
    if (eig[i] <= 1e-10 * largest || largest == 0.0)
      free.emplace_back(G.begin() + i * r, G.begin() + (i + 1) * r);
  return free;
}

std::string describeRigidMotion(const std::vector<double>& v, int d)
{
  double rotation = 0.0, translation = 0.0;
  for (std::size_t i = 0; i < v.size(); ++i)
    (static_cast<int>(i) < d ? translation : rotation) += v[i] * v[i];
  if (rotation > 1e-16 * (rotation + translation)) return "against a rotation";
  std::vector<double> t(v.begin(), v.begin() + d);
  const double norm = std::sqrt(translation);
  for (int c = 0; c < d; ++c)
    t[c] /= norm;
  for (int c = 0; c < d; ++c)
    if (std::abs(std::abs(t[c]) - 1.0) < 1e-9) return std::string("along ") + axisName(c);
  // The sign of a null vector is arbitrary: show the one with a positive first large entry.
  int lead = 0;
  while (lead < d - 1 && std::abs(t[lead]) < 1e-9)
    ++lead;
  if (t[lead] < 0)
    for (auto& c : t)
      c = -c;
  return "along " + vectorText(t.data(), d);
}

std::string describePlane(const NormalFramePart& part, int d)
{
  if (part.axis >= 0) return std::string(axisName(part.axis)) + " = const";
  return "normal " + vectorText(part.normal.data(), d);
}

int checkLoadsAndSupports(const mesh::SimplexMesh& m, const ElasticityData& data,
                          const ContactPlane* plane)
{
  const int d = m.dim();
  const auto& bcs = data.boundaryConditions;
  const auto parts = normalFrameParts(m, bcs);
  const auto supports = supportDirections(m, bcs, parts);
  int heldByContact = -1;
  if (bcs.boundariesOfType(core::BoundaryType::Displacement).empty() && !supports.empty()) {
    bool onlySymmetry = true, components = false;
    std::ostringstream names;
    for (const auto& [name, part] : parts) {
      names << (names.tellp() > 0 ? ", " : "") << "'" << name << "' (" << describePlane(part, d)
            << ")";
      onlySymmetry = onlySymmetry && bcs.find(name)->type == core::BoundaryType::Symmetry;
    }
    for (const auto& bc : bcs.conditions) {
      if (!bc.hasDisplacementComponent() || !m.hasBoundary(bc.boundary)) continue;
      components = true;
      names << (names.tellp() > 0 ? ", " : "") << "'" << bc.boundary << "' (";
      for (int i = 0, n = 0; i < d; ++i)
        if (bc.displacementComponent(i)) names << (n++ ? ", " : "") << "u_" << axisName(i);
      names << " given)";
    }
    std::string kinds = onlySymmetry ? "Symmetry" : "Symmetry and Normal displacement";
    if (components)
      kinds = parts.empty()  ? "Components"
              : onlySymmetry ? "Symmetry and Components"
                             : "Symmetry, Normal displacement and Components";
    const auto free = freeRigidMotions(m, supports);
    std::ostringstream missing;
    for (const auto& v : free)
      missing << (missing.tellp() > 0 ? ", " : "") << describeRigidMotion(v, d);
    // What is left may be one translation along a coordinate axis, which a contact plane normal
    // to it holds once any point is in contact (the contact solver starts from the points
    // nearest the plane).
    int planeAxis = -1;
    if (plane && bcs.hasContact())
      for (int c = 0; c < d; ++c)
        if (std::abs(plane->normal[c]) >= 1.0 - 1e-12) planeAxis = c;
    if (free.size() == 1 && planeAxis >= 0 &&
        describeRigidMotion(free[0], d) == std::string("along ") + axisName(planeAxis))
      heldByContact = planeAxis;
    SC_THROW_IF(!free.empty() && heldByContact < 0, core::InputError,
                "the deck has no Displacement part and its "
                    << kinds << " parts " << names.str()
                    << " leave rigid-body motions free (nothing holds the body " << missing.str()
                    << "): the problem is ill-posed. Add a Symmetry part (or a Components part "
                    << "with a displacement component) that holds each missing motion or a "
                    << "Displacement part."
                    << (plane && bcs.hasContact()
                            ? " (The contact with the plane 'Contact/Obstacle normal' holds the "
                              "body along that normal only when it is a coordinate axis and the "
                              "other parts hold every other motion.)"
                            : ""));
  }
  // Formulas: finite at the vertices where they are used (Expression throws otherwise, naming the
  // key, the formula and the point).
  for (const auto& bc : bcs.conditions) {
    if (bc.expression.empty() || !m.hasBoundary(bc.boundary)) continue;
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
