// The contact constraints of a cycle's space (docs/contact.md "Constraint points"): which basis
// they use (DOF points or Bernstein coefficients), the degrees and frames verified with contact,
// and the construction of the contact faces and their points (frames, weighted gaps, dual
// weights, Newton constants).
#include "sc/contact/ContactConstraints.hpp"

#include <algorithm>
#include <cmath>

#include <sc/core/Collective.hpp>
#include <sc/core/Error.hpp>
#include <sc/disc/Bernstein.hpp>
#include <sc/disc/ElementValues.hpp>
#include <sc/disc/FaceDofPoints.hpp>
#include <sc/disc/MixedElasticitySpace.hpp>
#include <sc/mesh/SimplexMesh.hpp>

#include "sc/contact/Obstacle.hpp"

namespace sc::contact {

bool useBernsteinConstraints(int dim, int /*degree*/, bool curvedFaces)
{
  // Curved faces (Mesh/Geometry order = 2): the gap is not linear along a face, and ∫ g ℓ_p
  // can be negative next to a vertex that touches the obstacle although g ≥ 0 on the face (a
  // zero load gave a contact force of 6% of the loaded one on the deck's mesh); B_p ≥ 0 gives
  // G_p ≥ 0 for any g ≥ 0 (docs/contact.md "Curved contact faces").
  if (curvedFaces) return true;
  // 2D: the DOF points' dual weights ℓ_p have non-negative moments against the face's
  // barycentric coordinates (min 0 at k = 1, 0.067, 0.013, 0.017 at k = 2, 3, 4), so a
  // non-negative linear gap has a non-negative weighted gap; the point constraints are verified
  // against Hertz at k = 1..4. 3D: at k = 1 the moments reach 0 and at k = 2 the weights are
  // small (0.042), and the point constraints left spurious contact outside the zone (active
  // points up to 1.26 a with up to 14% of p0 on Hertz 3D, docs/contact.md): Bernstein
  // coefficients, whose dual weights B_p are non-negative, remove it.
  return dim == 3;
}

void checkContactDegree(int dim, int degree)
{
  const double w = disc::minRelativeFaceDofWeight(dim, degree);
  SC_THROW_IF(w <= 1e-10, core::InputError,
              "'Discretization/Degree' = "
                  << degree << " with contact in " << dim << "D: a contact point of RT_" << degree
                  << " has a non-positive quadrature weight (min ∫_F L_p / |F| = " << w
                  << "), so tractions that are non-positive at the points could pull on average: "
                     "the contact conditions would not bound the load. Valid with contact: "
                  << (dim == 2 ? "1, 2, 3, 4" : "1, 2") << " (docs/contact.md, 'Degree').");
  // 3D k = 4 has positive weights but no verification (a Hertz 3D run at k = 4 that resolves the
  // zone needs millions of DOFs): rejected rather than trusted untested.
  SC_THROW_IF(dim == 3 && degree > 2, core::InputError,
              "'Discretization/Degree' = "
                  << degree
                  << " with contact in 3D is not verified "
                     "(the Hertz 3D tests cover k = 1, 2). Valid with contact: 1, 2 "
                     "(docs/contact.md, 'Degree').");
}

void checkCurvedContact(int dim, int degree, ContactFrame frame)
{
  // Curved contact faces are verified at k = 1, 2 in 2D and k = 1 in 3D (docs/contact.md).
  SC_THROW_IF((dim == 2 && degree > 2) || (dim == 3 && degree > 1), core::InputError,
              "'Discretization/Degree' = "
                  << degree
                  << " with contact on curved faces "
                     "('Mesh/Geometry order' = 2) in "
                  << dim
                  << "D is not verified (the Hertz tests "
                     "cover k = "
                  << (dim == 2 ? "1, 2" : "1")
                  << " there). Set 'Mesh/Geometry "
                     "order' = 1 (straight faces, verified for this degree) or a degree of "
                  << (dim == 2 ? "1 or 2" : "1") << " (docs/contact.md, 'Curved contact faces').");
  SC_THROW_IF(frame == ContactFrame::BodyNormal, core::InputError,
              "'Contact/Frame' = 'Body normal' is not available on curved contact faces "
              "('Mesh/Geometry order' = 2): the body normal varies along a curved face, and the "
              "constraints (Bernstein coefficients of the face's traction) need one frame per "
              "face. Use 'Contact/Frame' = 'Obstacle normal', or 'Mesh/Geometry order' = 1 for "
              "the talk's body-normal model on straight faces (docs/contact.md).");
}

ContactConstraints buildContactConstraints(const disc::MixedElasticitySpace& space,
                                           const ContactSettings& settings,
                                           const core::Material& material,
                                           const std::vector<std::string>& contactBoundaries,
                                           const Obstacle& obstacle, const Teuchos::Comm<int>& comm)
{
  ContactConstraints c;
  const auto& m = space.mesh();
  const int d = m.dim();
  const double cap = missCap(m);
  const double twoMu = 2.0 * material.shearModulus();

  std::vector<int> contactIds;
  for (const auto& name : contactBoundaries)
    contactIds.push_back(m.boundaryId(name));
  const bool obstacleFrame = settings.frame == ContactFrame::ObstacleNormal;
  c.bernstein = useBernsteinConstraints(d, space.degree(), space.geometryOrder() == 2);
  // Curved contact faces: the degrees and the frame verified there (the mesh is replicated, so
  // every rank sees all contact faces and decides alike; a rank-local throw would leave the other
  // ranks waiting in the collectives below).
  if (space.curvedElements()) {
    bool curvedContact = false;
    for (int f : m.boundaryFaces())
      curvedContact = curvedContact || (std::find(contactIds.begin(), contactIds.end(),
                                                  m.faceBoundaryId(f)) != contactIds.end() &&
                                        space.isCurved(m.faceElements(f)[0]));
    if (curvedContact) checkCurvedContact(d, space.degree(), settings.frame);
  }
  double minRelativeWeight = 1.0;  // min over points of ∫_F L_p / |F| (affine-invariant)
  disc::FaceValues fv(space, 2 * space.degree() + 2);
  for (int e : space.ownedElements()) {
    for (int lf = 0; lf <= d; ++lf) {
      const int f = m.elementFaces(e)[lf];
      if (!m.isBoundaryFace(f) ||
          std::find(contactIds.begin(), contactIds.end(), m.faceBoundaryId(f)) == contactIds.end())
        continue;
      const auto dofPoints = disc::stressFaceDofPoints(space, e, lf);
      fv.reinit(e, lf);
      // The contact frame (n, t1[, t2]) of each point: n along the obstacle's normal (out of the
      // body) or the body's outward normal at the point (constant on a straight face, varying
      // on a curved one).
      auto frameAt = [&](const disc::FaceDofPoint& dp) {
        std::array<std::array<double, 3>, 3> fr{};
        auto& n = fr[0];
        auto& t1 = fr[1];
        auto& t2 = fr[2];
        n = obstacleFrame ? obstacle.contactNormal(dp.x.data()) : dp.normal;
        if (d == 2) {
          t1 = {-n[1], n[0], 0.0};
        } else {
          // t1 ⟂ n from the coordinate axis least aligned with n; t2 = n × t1.
          int axis = 0;
          for (int i = 1; i < 3; ++i)
            if (std::abs(n[i]) < std::abs(n[axis])) axis = i;
          std::array<double, 3> a{0, 0, 0};
          a[axis] = 1.0;
          const double an = a[0] * n[0] + a[1] * n[1] + a[2] * n[2];
          double norm = 0.0;
          for (int i = 0; i < 3; ++i) {
            t1[i] = a[i] - an * n[i];
            norm += t1[i] * t1[i];
          }
          for (double& c : t1)
            c /= std::sqrt(norm);
          t2 = {n[1] * t1[2] - n[2] * t1[1], n[2] * t1[0] - n[0] * t1[2],
                n[0] * t1[1] - n[1] * t1[0]};
        }
        return fr;
      };
      // Face-wide frame for the (3D degree 2) Bernstein constraints: that of the first point.
      const auto faceFrame = frameAt(dofPoints.front());
      const double area = fv.measure();
      const double hF = d == 2 ? area : std::sqrt(area);
      const int nq = static_cast<int>(dofPoints.size());
      ContactFace cf;
      cf.m = nq;
      for (const auto& dp : dofPoints) {
        std::array<long long, 3> g{};
        for (int i = 0; i < d; ++i)
          g[i] = space.elementDofs(e)[space.stressOffset(i) + dp.localDof];
        cf.gids.push_back(g);
        cf.scale.push_back(dp.scale);
        cf.meanScale += std::abs(dp.scale) / nq;
      }
      // V(q, p): the constraint basis at the DOF points — the identity for point constraints,
      // the Bernstein polynomials of the face (via barycentric coordinates) otherwise.
      std::array<const double*, 3> fvx{};
      for (int i = 0; i < d; ++i)
        fvx[i] = m.vertex(m.faceVertices(f)[i]);
      const auto alphas = disc::bernsteinIndices(space.degree(), d);
      cf.V.assign(static_cast<std::size_t>(nq) * nq, 0.0);
      for (int q = 0; q < nq; ++q)
        for (int pp = 0; pp < nq; ++pp)
          cf.V[q * nq + pp] =
              c.bernstein
                  ? disc::bernstein(alphas[pp],
                                    disc::faceBarycentric(fvx, dofPoints[q].xAffine.data(), d),
                                    space.degree())
                  : (q == pp ? 1.0 : 0.0);
      cf.Vinv = c.bernstein ? disc::invertCollocation(cf.V, nq) : cf.V;
      for (int pp = 0; pp < nq; ++pp) {
        ContactPoint p;
        p.face = f;
        p.block = static_cast<int>(c.faces.size());
        p.index = pp;
        if (c.bernstein) {
          for (int i = 0; i < d; ++i)
            for (int c = 0; c < d; ++c)
              p.x[c] += alphas[pp][i] / static_cast<double>(space.degree()) * fvx[i][c];
        } else {
          p.x = dofPoints[pp].x;
        }
        const auto fr = c.bernstein ? faceFrame : frameAt(dofPoints[pp]);
        p.n = fr[0];
        p.t1 = fr[1];
        p.t2 = fr[2];
        p.c = settings.newton.penaltyFactor * twoMu / (hF * area);
        // The dual weight w_p = Σ_q V(q, p) ℓ_q (ℓ_q = ψ_q·n_F / s_q, the Lagrange function of the
        // normal trace at q): ℓ_p itself, or B_p. Weighted gap with face quadrature (not lumped).
        for (int q = 0; q < fv.numPoints(); ++q) {
          double w = 0.0;
          for (int j = 0; j < nq; ++j)
            w += cf.V[j * nq + pp] * fv.stressNormal(dofPoints[j].localDof, q) / dofPoints[j].scale;
          // The gap along the point's constraint direction: ν (obstacle frame), or the face's
          // outward normal (body frame, straight faces only).
          p.gap += fv.weight(q) * obstacle.gap(fv.point(q), p.n.data(), cap) * w;
          p.weight += fv.weight(q) * w;
          for (int i = 0; i < d; ++i)
            p.centroid[i] += fv.weight(q) * w * fv.point(q)[i];
        }
        for (int i = 0; i < d; ++i)
          p.centroid[i] /= p.weight;
        minRelativeWeight = std::min(minRelativeWeight, p.weight / area);
        c.points.push_back(p);
      }
      c.faces.push_back(std::move(cf));
    }
  }
  // The contact conditions hold at the points; the load is Σ_p ∫_F L_p σ_N(p). With a negative
  // weight ∫_F L_p, tractions that are non-positive at every point can pull on average, and the
  // solver returns nonsense (degree 2 on the equispaced lattice did: a force of −40404). Reject
  // such a degree on every rank together.
  // checkContactDegree() rejects such degrees up front; this is the same check on the actual
  // faces (they must agree: the ratio is affine-invariant).
  const double globalMin = core::minOverRanks(comm, minRelativeWeight);
  SC_THROW_IF(globalMin <= 1e-10, core::InternalError,
              "a contact point of RT_"
                  << space.degree() << " in " << d
                  << "D has a non-positive weight (min ∫_F L_p / |F| = " << globalMin
                  << ") although checkContactDegree accepted the degree.");
  return c;
}

}  // namespace sc::contact
