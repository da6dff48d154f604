#pragma once
// The estimated error of a quantity a user reads (a load, a contact width, a peak pressure),
// from the run's own history of that quantity and of η (docs/output.md "Error bars"): a
// Richardson-type extrapolation in η. If the quantity's error behaves like C·η^β (η_CF's
// observed rate in DOFs sets the quantity's: β = 1 converges with η, β = 2 like a functional,
// twice η's rate), then for an earlier cycle j and the current cycle n
//     q_j − q_n ≈ C(η_j^β − η_n^β)   so   |q_n − q_∞| ≈ |q_j − q_n| · η_n^β / (η_j^β − η_n^β),
// and the estimate is the largest of these over the last `window` earlier cycles, times a
// safety factor, and at least `floor` (a resolution the caller knows, e.g. the gap between two
// measures of one contact width). β = 0: no extrapolation, the largest change |q_j − q_n| over
// the window (a quantity that moves in steps, such as a width read off the contact points).
// A pure function of the history: no solve, no communication.
#include <vector>

namespace sc::adapt {

/// One solved cycle of a quantity's history.
struct QuantitySample {
  double dofs = 0.0;   ///< unknowns of the cycle (only their order matters: increasing)
  double eta = 0.0;    ///< the cycle's η (> 0)
  double value = 0.0;  ///< the quantity
};

struct QuantityErrorSettings {
  int window = 3;             ///< earlier cycles compared with the current one
  double safetyFactor = 1.5;  ///< multiplies the extrapolated error
  double rate = 1.0;          ///< β ≥ 0: the quantity's error ∝ η^β (0: the largest change)
};

/// The estimate for the last sample of `history` (same units as the quantity), or a negative
/// number when there is none: fewer than two samples, or no earlier cycle in the window with a
/// larger η (η did not decrease: nothing to extrapolate with). `floor` ≥ 0 is a lower bound
/// applied when an estimate exists.
double estimateQuantityError(const std::vector<QuantitySample>& history, double floor = 0.0,
                             const QuantityErrorSettings& settings = {});

}  // namespace sc::adapt
