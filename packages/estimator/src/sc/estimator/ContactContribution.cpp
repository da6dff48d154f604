#include "sc/estimator/ContactContribution.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "sc/core/Collective.hpp"

#include <sc/assembly/ElementSolution.hpp>
#include <sc/contact/Obstacle.hpp>
#include <sc/disc/ElementValues.hpp>
#include <sc/disc/MixedElasticitySpace.hpp>
#include <sc/mesh/SimplexMesh.hpp>

#include "sc/estimator/DisplacementReconstruction.hpp"

namespace sc::estimator {

std::string largeFrictionWarning(const contact::ContactSettings& settings)
{
  if (settings.frictionLaw != contact::FrictionLaw::Coulomb ||
      !(settings.frictionCoefficient > kLargeFrictionCoefficient))
    return "";
  std::ostringstream os;
  os << "'Contact/Friction coefficient' = " << settings.frictionCoefficient << " is above "
     << kLargeFrictionCoefficient << ": the estimator's friction part bounds the tangential work "
     << "in the stick zone by mu_F |sigma_N| |u^R_T|, so at a given mesh eta grows like "
     << "sqrt(mu_F) and it, and the adaptive marking, are dominated by that part; the solution "
     << "and the forces are not (hertz2d.xml, cycle 0: eta/|A^1/2 sigma_h| = 0.19 at mu_F = 0.4, "
     << "0.42 at 10, 122 at 1e6, the same force 108.787; docs/theory.md \"Friction part for "
     << "large mu_F\").";
  return os.str();
}

ContactContribution::ContactContribution(const disc::MixedElasticitySpace& space,
                                         const contact::ContactSettings& settings,
                                         const core::Material& material,
                                         std::vector<std::string> contactBoundaries)
    : space_(space), settings_(settings), material_(material),
      boundaries_(std::move(contactBoundaries))
{
}

void ContactContribution::addTo(ErrorEstimate& est, assembly::ElementSolution& sol,
                                const DisplacementReconstruction& rec,
                                const Teuchos::Comm<int>& comm) const
{
  const auto& m = space_.mesh();
  const int d = space_.dim();
  const double twoMu = 2.0 * material_.shearModulus();
  const auto obstacle = contact::createObstacle(settings_, d);
  const bool obstacleFrame = settings_.frame == contact::ContactFrame::ObstacleNormal;
  const bool coulomb = settings_.frictionLaw == contact::FrictionLaw::Coulomb;
  const bool tresca = settings_.frictionLaw == contact::FrictionLaw::Tresca;
  const double cap = contact::missCap(m);  // as the contact solver
  std::vector<int> ids;
  for (const auto& name : boundaries_)
    ids.push_back(m.boundaryId(name));

  disc::FaceValues fv(space_, rec.cubatureDegree());
  // complementarity, penetration, tension, friction, signed normal part
  double local[5] = {0, 0, 0, 0, 0}, global[5];
  const auto& owned = space_.ownedElements();
  for (std::size_t idx = 0; idx < owned.size(); ++idx) {
    const int e = owned[idx];
    const int* faces = m.elementFaces(e);
    bool gathered = false;
    for (int lf = 0; lf <= d; ++lf) {
      const int f = faces[lf];
      if (!m.isBoundaryFace(f) ||
          std::find(ids.begin(), ids.end(), m.faceBoundaryId(f)) == ids.end())
        continue;
      if (!gathered) {
        sol.gather(e);
        gathered = true;
      }
      fv.reinit(e, lf);
      const double hF = d == 2 ? m.faceMeasure(f) : std::sqrt(m.faceMeasure(f));
      double compl_ = 0.0, pen = 0.0, tension = 0.0, fric = 0.0, signedNormal = 0.0;
      for (int q = 0; q < fv.numPoints(); ++q) {
        const double* x = fv.point(q);
        const double w = fv.weight(q);
        const auto& nF = fv.normal(q);  // the body's outward normal (varies on a curved face)
        const std::array<double, 3> n = obstacleFrame ? obstacle->contactNormal(x) : nF;
        const double g = obstacle->gap(x, n.data(), cap);
        double sigma[9], t[3] = {0, 0, 0}, u[3] = {0, 0, 0};
        sol.stress(fv, q, sigma);
        for (int i = 0; i < d; ++i)
          for (int j = 0; j < d; ++j)
            t[i] += sigma[i * d + j] * nF[j];
        rec.valueAt(e, x, u);
        double sN = 0.0, uN = 0.0;
        for (int i = 0; i < d; ++i) {
          sN += n[i] * t[i];
          uN += n[i] * u[i];
        }
        double sTuT = 0.0, uT2 = 0.0;
        for (int i = 0; i < d; ++i) {
          const double sT = t[i] - sN * n[i], uT = u[i] - uN * n[i];
          sTuT += sT * uT;
          uT2 += uT * uT;
        }
        compl_ += w * std::max(0.0, g - uN) * std::max(0.0, -sN);
        pen += w * std::max(0.0, uN - g) * std::abs(sN);
        tension += w * std::pow(std::max(0.0, sN), 2);
        const double bound = coulomb  ? settings_.frictionCoefficient * std::abs(sN)
                             : tresca ? settings_.trescaBound
                                      : 0.0;
        if (settings_.needsFriction()) fric += w * (bound * std::sqrt(uT2) + sTuT);
        signedNormal += w * (uN - g) * sN;
      }
      tension *= hF / twoMu;
      // The trace can break Coulomb between the points: the absolute value per face.
      fric = std::abs(fric);
      est.indicators[idx] += compl_ + pen + tension + fric;
      local[0] += compl_;
      local[1] += pen;
      local[2] += tension;
      local[3] += fric;
      local[4] += signedNormal;
    }
  }
  core::sumOverRanks(comm, 5, local, global);
  est.addPart("contact_complementarity", global[0]);
  est.addPart("contact_penetration", global[1]);
  est.addPart("contact_tension", global[2]);
  est.addPart("friction", global[3]);
  est.addDiagnostic("contact_normal_signed", global[4]);
}

}  // namespace sc::estimator
