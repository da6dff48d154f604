#pragma once
// Internal to the discretization package: the Intrepid2 objects behind MixedElasticitySpace.
// Only the package's .cpp files include this (Intrepid2 headers are slow to compile).
#include <array>

#include <Intrepid2_Basis.hpp>
#include <Intrepid2_Orientation.hpp>
#include <Intrepid2_Types.hpp>
#include <Kokkos_DynRankView.hpp>
#include <Shards_CellTopology.hpp>
#include <Teuchos_RCP.hpp>

#include "sc/disc/MixedElasticitySpace.hpp"

namespace sc::disc {

using Device = Kokkos::DefaultExecutionSpace::device_type;  // Serial: the only backend here
using View = Kokkos::DynRankView<double, Device>;
using Basis = Intrepid2::Basis<Device, double, double>;

struct MixedElasticitySpace::Impl {
  Impl(int dim, int degree);
  int dim;
  shards::CellTopology topology;
  /// RT_k: Intrepid2 HDIV In_FEM of order k+1. Its face DOFs are normal fluxes at a lattice of
  /// the face: equispaced for k = 1, warp-blend (Gauss–Lobatto in 2D) for k >= 2, where the
  /// interpolatory face weights of the equispaced open lattice change sign (docs/contact.md).
  Teuchos::RCP<Basis> rt;
  Intrepid2::EPointType rtPoints = Intrepid2::POINTTYPE_EQUISPACED;
  Teuchos::RCP<Basis> pk;  ///< P_k Lagrange: DP_k element-locally, CP_k globally
  /// Intrepid2 side ordinal <-> mesh local face (the face opposite local vertex i).
  std::array<int, 4> sideToMeshFace{}, meshFaceToSide{};

  /// Orientation of an element from the global ids of its vertices (Intrepid2 convention).
  Intrepid2::Orientation orientation(const int* globalVertices) const;
};

}  // namespace sc::disc
