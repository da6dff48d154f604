#include "sc/disc/ElementValues.hpp"

#include <cmath>

#include <Intrepid2_CellTools.hpp>
#include <Intrepid2_DefaultCubatureFactory.hpp>
#include <Intrepid2_OrientationTools.hpp>

#include <sc/core/Error.hpp>
#include <sc/mesh/SimplexMesh.hpp>

#include "sc/disc/MixedElasticitySpace.hpp"
#include "sc/disc/detail/AffineMap.hpp"
#include "sc/disc/detail/Intrepid2Impl.hpp"

namespace sc::disc {
namespace {

using OrtView = Kokkos::DynRankView<Intrepid2::Orientation, Device>;

// Reference values of both bases at a set of reference points, and per-element oriented copies.
struct Tabulation {
  View refPoints;             // (nq, d)
  View rtRef, rtDivRef;       // (nRT, nq, d), (nRT, nq)
  View pkRef;                 // (nP, nq)
  View rtOr, rtDivOr, pkOr;   // oriented: (1, nRT, nq, d), (1, nRT, nq), (1, nP, nq)
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
  const auto& m = space_.mesh();
  const auto& si = space_.impl();
  const int d = space_.dim();
  const int n = static_cast<int>(physicalPoints.size() / 3);
  AffineMap F(m, e);
  // x̂ = J⁻¹ (x − x0)
  double inv[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
  F.inverse(d, inv);
  View pts("points", n, d);
  for (int q = 0; q < n; ++q)
    for (int i = 0; i < d; ++i) {
      double v = 0.0;
      for (int j = 0; j < d; ++j)
        v += inv[i][j] * (physicalPoints[q * 3 + j] - F.x0[j]);
      pts(q, i) = v;
    }
  nq_ = n;
  impl_->tab.tabulate(si, pts);
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
  AffineMap F(m, e);
  measure_ = F.det / (d == 2 ? 2.0 : 6.0);
  Tabulation& t = impl_->tab;
  t.orient(si, m.elementVertices(e));
  for (int q = 0; q < nq_; ++q) {
    double xh[3] = {0, 0, 0};
    for (int i = 0; i < d; ++i)
      xh[i] = t.refPoints(q, i);
    F.map(xh, d, &points_[q * 3]);
    weights_[q] = impl_->atPoints ? 0.0 : impl_->refWeights(q) * F.det;
  }
  // Contravariant Piola: φ = J φ̂ / det J, div φ = div̂ φ̂ / det J.
  for (int a = 0; a < nRT; ++a)
    for (int q = 0; q < nq_; ++q) {
      for (int i = 0; i < d; ++i) {
        double v = 0.0;
        for (int j = 0; j < d; ++j)
          v += F.J[i][j] * t.rtOr(0, a, q, j);
        rt_[(a * nq_ + q) * 3 + i] = v / F.det;
      }
      rtDiv_[a * nq_ + q] = t.rtDivOr(0, a, q) / F.det;
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
  std::vector<Tabulation> sides;  // one per Intrepid2 side ordinal
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
  }
  points_.assign(nq_ * 3, 0.0);
  weights_.assign(nq_, 0.0);
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
  AffineMap F(m, e);
  Tabulation& t = impl_->sides[si.meshFaceToSide[localFace]];
  t.orient(si, m.elementVertices(e));
  const int f = m.elementFaces(e)[localFace];
  const auto n = m.faceNormal(f);
  const double sign = m.faceElements(f)[0] == e ? 1.0 : -1.0;
  for (int i = 0; i < 3; ++i)
    normal_[i] = sign * n[i];
  const double scale = m.faceMeasure(f) / impl_->paramMeasure;
  for (int q = 0; q < nq_; ++q) {
    double xh[3] = {0, 0, 0};
    for (int i = 0; i < d; ++i)
      xh[i] = t.refPoints(q, i);
    F.map(xh, d, &points_[q * 3]);
    weights_[q] = impl_->paramWeights(q) * scale;
  }
  for (int a = 0; a < nRT; ++a)
    for (int q = 0; q < nq_; ++q)
      for (int i = 0; i < d; ++i) {
        double v = 0.0;
        for (int j = 0; j < d; ++j)
          v += F.J[i][j] * t.rtOr(0, a, q, j);
        rt_[(a * nq_ + q) * 3 + i] = v / F.det;
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
    v += stress(a, q, i) * normal_[i];
  return v;
}

}  // namespace sc::disc
