#include "sc/contact/BodyFrameCheck.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

#include <sc/contact/Obstacle.hpp>
#include <sc/core/Error.hpp>
#include <sc/mesh/SimplexMesh.hpp>

namespace sc::contact {

void checkBodyFrameFaces(const mesh::SimplexMesh& m, const ContactSettings& settings,
                         const std::vector<std::string>& contactBoundaries)
{
  if (settings.frame != ContactFrame::BodyNormal) return;
  const int d = m.dim();
  const auto obstacle = createObstacle(settings, d);
  const double tolerance = 1e-9 * missCap(m) / 10.0;  // of the bounding-box diagonal
  const double cosLimit = std::cos(kBodyFramePerpendicularDegrees * M_PI / 180.0);
  std::vector<int> ids;
  for (const auto& name : contactBoundaries)
    ids.push_back(m.boundaryId(name));
  // Per vertex at or behind the surface: is it on a contact face that can hold it, and the first
  // perpendicular face on it (to name). The mesh is the same on every rank: a collective verdict.
  struct Touch {
    bool held = false;
    int face = -1;
    double cosine = 0.0;
  };
  std::map<int, Touch> touched;
  for (int f : m.boundaryFaces()) {
    if (std::find(ids.begin(), ids.end(), m.faceBoundaryId(f)) == ids.end()) continue;
    const int* fv = m.faceVertices(f);
    double centroid[3] = {0, 0, 0};
    for (int i = 0; i < d; ++i)
      for (int c = 0; c < d; ++c)
        centroid[c] += m.vertex(fv[i])[c] / d;
    const auto nF = m.faceNormal(f);
    const auto into = obstacle->contactNormal(centroid);
    double cosine = 0.0;
    for (int c = 0; c < d; ++c)
      cosine += nF[c] * into[c];
    const bool perpendicular = cosine < cosLimit;
    for (int i = 0; i < d; ++i) {
      if (obstacle->height(m.vertex(fv[i])) > tolerance) continue;
      Touch& t = touched[fv[i]];
      t.held = t.held || !perpendicular;
      if (perpendicular && t.face < 0) t.face = f, t.cosine = cosine;
    }
  }
  int count = 0, vertex = -1;
  for (const auto& [v, t] : touched)
    if (!t.held && count++ == 0) vertex = v;
  if (count == 0) return;
  const Touch& t = touched.at(vertex);
  auto point = [&](const double* x) {
    std::ostringstream os;
    os << "(";
    for (int c = 0; c < d; ++c)
      os << (c ? ", " : "") << x[c];
    os << ")";
    return os.str();
  };
  std::ostringstream face;
  for (int i = 0; i < d; ++i)
    face << (i ? (i + 1 == d ? " and " : ", ") : "") << point(m.vertex(m.faceVertices(t.face)[i]));
  const double* x = m.vertex(vertex);
  const double h = obstacle->height(x);
  const double angle = std::acos(std::clamp(t.cosine, -1.0, 1.0)) * 180.0 / M_PI;
  SC_THROW_IF(
      true, core::InputError,
      "'Contact/Frame' = 'Body normal' cannot hold the contact part '"
          << m.boundaryName(m.faceBoundaryId(t.face)) << "' where it meets the obstacle: "
          << "its face through " << face.str() << " has its outward normal at "
          << std::round(angle * 10.0) / 10.0 << " degrees to the direction into the "
          << "obstacle (more than " << kBodyFramePerpendicularDegrees << "), and its "
          << "vertex " << point(x) << (h < -tolerance ? " lies behind" : " lies on")
          << " the obstacle's surface (height " << h << "), on no contact face that "
          << "faces the obstacle (" << count << (count == 1 ? " such vertex" : " such vertices")
          << "). Along the face's normal the ray " << (t.cosine <= 1e-12 ? "never meets" : "meets")
          << " the obstacle" << (t.cosine <= 1e-12 ? "" : " only far away") << ", so its "
          << "points stay free and the body would go through the obstacle there without "
          << "a force. Use 'Contact/Frame' = 'Obstacle normal' (the default), or add the "
          << "faces that meet the obstacle to a Contact part.");
}

}  // namespace sc::contact
