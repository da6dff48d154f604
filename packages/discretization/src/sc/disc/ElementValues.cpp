#include "sc/disc/ElementValues.hpp"

#include <cmath>

#include <Intrepid2_CellTools.hpp>
#include <Intrepid2_DefaultCubatureFactory.hpp>
#include <Intrepid2_OrientationTools.hpp>

#include <sc/core/Error.hpp>
#include <sc/mesh/SimplexMesh.hpp>

#include "sc/disc/MixedElasticitySpace.hpp"
#include "sc/disc/detail/ElementMap.hpp"
#include "sc/disc/detail/Intrepid2Impl.hpp"

namespace sc::disc {
namespace {

using OrtView = Kokkos::DynRankView<Intrepid2::Orientation, Device>;

// Reference values of both bases at a set of reference points, and per-element oriented copies.
struct Tabulation {
  View refPoints;            // (nq, d)
  View rtRef, rtDivRef;      // (nRT, nq, d), (nRT, nq)
  View pkRef;                // (nP, nq)
  View rtOr, rtDivOr, pkOr;  // oriented: (1, nRT, nq, d), (1, nRT, nq), (1, nP, nq)
  OrtView ort{"ort", 1};

  void tabulate(const MixedElasticitySpace::Impl& impl, const View& points)
  {
    const int nq = points.extent(0), d = impl.dim;
    const int nRT = impl.rt->getCardinality(), nP = impl.pk->getCardinality();
    refPoints = points;
    rtRef = View("rtRef", nRT, nq, d);
    rtDivRef = View("rtDivRef", nRT, nq);
    pkRef = View("pkRef", nP, nq);
    impl.rt->getValues(rtRef, points, Intrepid2::OPERATOR_VALUE);
    impl.rt->getValues(rtDivRef, points, Intrepid2::OPERATOR_DIV);
    impl.pk->getValues(pkRef, points, Intrepid2::OPERATOR_VALUE);
    rtOr = View("rtOr", 1, nRT, nq, d);
    rtDivOr = View("rtDivOr", 1, nRT, nq);
    pkOr = View("pkOr", 1, nP, nq);
  }

  void orient(const MixedElasticitySpace::Impl& impl, const int* globalVertices)
  {
    ort(0) = impl.orientation(globalVertices);
    using OT = Intrepid2::OrientationTools<Device>;
    OT::modifyBasisByOrientation(rtOr, rtRef, ort, impl.rt.get());
    OT::modifyBasisByOrientation(rtDivOr, rtDivRef, ort, impl.rt.get());
    if (impl.pk->requireOrientation()) {
      OT::modifyBasisByOrientation(pkOr, pkRef, ort, impl.pk.get());
    } else {
      // Intrepid2 13.2 deep_copies input to output here, which mis-copies when the input has
      // no cell dimension (rank 2 into rank 3): copy by hand.
      for (std::size_t a = 0; a < pkRef.extent(0); ++a)
        for (std::size_t q = 0; q < pkRef.extent(1); ++q)
          pkOr(0, a, q) = pkRef(a, q);
    }
  }
};

}  // namespace

// ------------------------------------------------------------------------------- ElementValues
struct ElementValues::Impl {
  Tabulation tab;
  View refWeights;
  std::unique_ptr<ElementMap> map;
  bool atPoints = false;  // tabulated at reinitAtPoints' points (no weights)
};

ElementValues::ElementValues(const MixedElasticitySpace& space, int cubatureDegree)
    : space_(space), impl_(std::make_unique<Impl>())
{
  const auto& si = space.impl();
  auto cub = Intrepid2::DefaultCubatureFactory::create<Device>(si.topology, cubatureDegree);
  nq_ = cub->getNumPoints();
  View pts("points", nq_, si.dim);
  impl_->refWeights = View("weights", nq_);
  cub->getCubature(pts, impl_->refWeights);
  impl_->tab.tabulate(si, pts);
  impl_->map = std::make_unique<ElementMap>(space, pts);
  points_.assign(nq_ * 3, 0.0);
  weights_.assign(nq_, 0.0);
  rt_.assign(static_cast<std::size_t>(space.stressBasisSize()) * nq_ * 3, 0.0);
  rtDiv_.assign(static_cast<std::size_t>(space.stressBasisSize()) * nq_, 0.0);
  dp_.assign(static_cast<std::size_t>(space.displacementBasisSize()) * nq_, 0.0);
  cp_.assign(static_cast<std::size_t>(space.rotationBasisSize()) * nq_, 0.0);
}

ElementValues::~ElementValues() = default;

void ElementValues::reinitAtPoints(int e, const std::vector<double>& physicalPoints)
{
  const auto& si = space_.impl();
  const int d = space_.dim();
  const int n = static_cast<int>(physicalPoints.size() / 3);
  const auto xh = ElementMap::toReference(space_, e, physicalPoints);
  View pts("points", n, d);
  for (int q = 0; q < n; ++q)
    for (int i = 0; i < d; ++i)
      pts(q, i) = xh[q * d + i];
  nq_ = n;
  impl_->tab.tabulate(si, pts);
  impl_->map = std::make_unique<ElementMap>(space_, pts);
  impl_->atPoints = true;
  points_.assign(static_cast<std::size_t>(n) * 3, 0.0);
  weights_.assign(n, 0.0);
  rt_.assign(static_cast<std::size_t>(space_.stressBasisSize()) * n * 3, 0.0);
  rtDiv_.assign(static_cast<std::size_t>(space_.stressBasisSize()) * n, 0.0);
  dp_.assign(static_cast<std::size_t>(space_.displacementBasisSize()) * n, 0.0);
  cp_.assign(static_cast<std::size_t>(space_.rotationBasisSize()) * n, 0.0);
  fill(e);
}

void ElementValues::reinit(int e)
{
  SC_THROW_IF(impl_->atPoints, core::InternalError,
              "ElementValues::reinit after reinitAtPoints: use a separate object for cubature");
  fill(e);
}

void ElementValues::fill(int e)
{
  const auto& m = space_.mesh();
  const auto& si = space_.impl();
  const int d = space_.dim(), nRT = space_.stressBasisSize(), nP = space_.displacementBasisSize();
  ElementMap& F = *impl_->map;
  F.reinit(e);
  Tabulation& t = impl_->tab;
  t.orient(si, m.elementVertices(e));
  // Affine: |T| = det J / d!; curved: ∫ det J (the cubature is exact for the P2 map's det J).
  measure_ = F.curved() ? 0.0 : F.det(0) / (d == 2 ? 2.0 : 6.0);
  for (int q = 0; q < nq_; ++q) {
    for (int i = 0; i < 3; ++i)
      points_[q * 3 + i] = F.x(q)[i];
    weights_[q] = impl_->atPoints ? 0.0 : impl_->refWeights(q) * F.det(q);
    if (F.curved()) measure_ += weights_[q];
  }
  // Contravariant Piola: φ = J φ̂ / det J, div φ = div̂ φ̂ / det J (also for the quadratic map, with
  // J and det J at each point).
  for (int a = 0; a < nRT; ++a)
    for (int q = 0; q < nq_; ++q) {
      const double* J = F.jacobian(q);
      for (int i = 0; i < d; ++i) {
        double v = 0.0;
        for (int j = 0; j < d; ++j)
          v += J[3 * i + j] * t.rtOr(0, a, q, j);
        rt_[(a * nq_ + q) * 3 + i] = v / F.det(q);
      }
      rtDiv_[a * nq_ + q] = t.rtDivOr(0, a, q) / F.det(q);
    }
  // DP_k is element-local: the unoriented reference basis serves; CP_k needs the oriented one.
  for (int a = 0; a < nP; ++a)
    for (int q = 0; q < nq_; ++q) {
      dp_[a * nq_ + q] = t.pkRef(a, q);
      cp_[a * nq_ + q] = t.pkOr(0, a, q);
    }
}

// ------------------------------------------------------------------------------- FaceValues
struct FaceValues::Impl {
  std::vector<Tabulation> sides;                  // one per Intrepid2 side ordinal
  std::vector<std::unique_ptr<ElementMap>> maps;  // one per side
  View paramWeights;
  double paramMeasure = 0.0;
};

FaceValues::FaceValues(const MixedElasticitySpace& space, int cubatureDegree)
    : space_(space), impl_(std::make_unique<Impl>())
{
  const auto& si = space.impl();
  const int d = si.dim;
  const shards::CellTopology sideTopo = si.topology.getCellTopologyData(d - 1, 0);
  auto cub = Intrepid2::DefaultCubatureFactory::create<Device>(sideTopo, cubatureDegree);
  nq_ = cub->getNumPoints();
  View param("param", nq_, d - 1);
  impl_->paramWeights = View("paramWeights", nq_);
  cub->getCubature(param, impl_->paramWeights);
  for (int q = 0; q < nq_; ++q)
    impl_->paramMeasure += impl_->paramWeights(q);
  impl_->sides.resize(d + 1);
  for (int s = 0; s <= d; ++s) {
    View refPts("refPts", nq_, d);
    Intrepid2::CellTools<Device>::mapToReferenceSubcell(refPts, param, d - 1, s, si.topology);
    impl_->sides[s].tabulate(si, refPts);
    impl_->maps.push_back(std::make_unique<ElementMap>(space, refPts));
  }
  points_.assign(nq_ * 3, 0.0);
  weights_.assign(nq_, 0.0);
  normals_.assign(nq_, {0.0, 0.0, 0.0});
  rt_.assign(static_cast<std::size_t>(space.stressBasisSize()) * nq_ * 3, 0.0);
  dp_.assign(static_cast<std::size_t>(space.displacementBasisSize()) * nq_, 0.0);
  cp_.assign(static_cast<std::size_t>(space.rotationBasisSize()) * nq_, 0.0);
}

FaceValues::~FaceValues() = default;

void FaceValues::reinit(int e, int localFace)
{
  const auto& m = space_.mesh();
  const auto& si = space_.impl();
  const int d = space_.dim(), nRT = space_.stressBasisSize(), nP = space_.displacementBasisSize();
  const int side = si.meshFaceToSide[localFace];
  Tabulation& t = impl_->sides[side];
  ElementMap& F = *impl_->maps[side];
  F.reinit(e);
  t.orient(si, m.elementVertices(e));
  const int f = m.elementFaces(e)[localFace];
  curved_ = F.curved();
  if (!curved_) {
    const auto n = m.faceNormal(f);
    const double sign = m.faceElements(f)[0] == e ? 1.0 : -1.0;
    measure_ = m.faceMeasure(f);
    const double scale = measure_ / impl_->paramMeasure;
    for (int q = 0; q < nq_; ++q) {
      for (int i = 0; i < 3; ++i)
        normals_[q][i] = sign * n[i];
      weights_[q] = impl_->paramWeights(q) * scale;
    }
  } else {
    // Curved: the normal and the surface element vary along the face.
    measure_ = 0.0;
    for (int q = 0; q < nq_; ++q) {
      double stretch = 0.0;
      F.sideFrame(q, side, normals_[q], stretch);
      weights_[q] = impl_->paramWeights(q) * stretch;
      measure_ += weights_[q];
    }
  }
  for (int q = 0; q < nq_; ++q)
    for (int i = 0; i < 3; ++i)
      points_[q * 3 + i] = F.x(q)[i];
  for (int a = 0; a < nRT; ++a)
    for (int q = 0; q < nq_; ++q) {
      const double* J = F.jacobian(q);
      for (int i = 0; i < d; ++i) {
        double v = 0.0;
        for (int j = 0; j < d; ++j)
          v += J[3 * i + j] * t.rtOr(0, a, q, j);
        rt_[(a * nq_ + q) * 3 + i] = v / F.det(q);
      }
    }
  for (int a = 0; a < nP; ++a)
    for (int q = 0; q < nq_; ++q) {
      dp_[a * nq_ + q] = t.pkRef(a, q);
      cp_[a * nq_ + q] = t.pkOr(0, a, q);
    }
}

double FaceValues::stressNormal(int a, int q) const
{
  double v = 0.0;
  for (int i = 0; i < space_.dim(); ++i)
    v += stress(a, q, i) * normals_[q][i];
  return v;
}

double ownedMeasure(const MixedElasticitySpace& space)
{
  ElementValues ev(space, 4);  // exact for det J of the quadratic map (degree 2 in 2D, 3 in 3D)
  double sum = 0.0;
  for (int e : space.ownedElements()) {
    if (space.isCurved(e)) {
      ev.reinit(e);
      sum += ev.measure();
    } else {
      sum += space.mesh().elementMeasure(e);
    }
  }
  return sum;
}

}  // namespace sc::disc
