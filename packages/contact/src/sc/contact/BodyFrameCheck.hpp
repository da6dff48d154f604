#pragma once
// Contact/Frame = Body normal (docs/theory.md §"Contact frame and gap") measures each contact
// point's gap along its face's outward normal n_F. On a face (nearly) perpendicular to the
// obstacle, that ray is parallel to the obstacle's surface or meets it far away: the point gets
// the miss cap (PlaneObstacle::gap) or a gap many times its height, so it stays free. Where such
// a face touches or crosses the obstacle, the body goes through the obstacle with no force
// (a Rectangle whose Left side is Contact on the plane y = 0: force 5e-14 in the body frame
// against 2.88 in the obstacle frame). Checked before any solve, also under --check.
#include <string>
#include <vector>

#include <sc/contact/ContactSettings.hpp>

namespace sc::mesh {
class SimplexMesh;
}

namespace sc::contact {

/// A contact face counts as perpendicular when the angle between its outward normal and the
/// direction into the obstacle exceeds this: its body-normal ray meets the obstacle more than
/// 1/cos(85°) = 11.5 times the point's height away, or never.
inline constexpr double kBodyFramePerpendicularDegrees = 85.0;

/// With Contact/Frame = Body normal: an InputError naming the part, a face, its angle and the
/// remedies if a vertex at or behind the obstacle's surface (height ≤ 1e-9 of the mesh's
/// bounding-box diagonal) lies on contact faces that are all perpendicular, i.e. no contact
/// face can hold it. A perpendicular face that meets the obstacle only at a vertex held by
/// another contact face (the corner of a punch whose sides are in the Contact part) is accepted.
/// Nothing to check in the obstacle frame. `contactBoundaries`: the parts of Type Contact.
void checkBodyFrameFaces(const mesh::SimplexMesh& mesh, const ContactSettings& settings,
                         const std::vector<std::string>& contactBoundaries);

}  // namespace sc::contact
