#pragma once
// Least-squares fits of values given at points of one face (an edge in 2D, a triangle in 3D): the
// contact state transfer places a face's per-weight friction history at the weights' centroids and
// evaluates its affine fit on the refined faces (docs/theory.md §"Load steps").
#include <array>
#include <vector>

namespace sc::disc {

/// The affine function of the position on a face that fits the values v[q] (d components) at the
/// points c[q] in the least-squares sense, evaluated at x. The face's coordinates are orthonormal
/// directions spanned by the points; with fewer points than the face needs for an affine fit (or
/// degenerate ones), the mean value.
std::array<double, 3> fitAffineOnFace(const std::vector<const double*>& c,
                                      const std::vector<const double*>& v, int d, const double* x);

}  // namespace sc::disc
