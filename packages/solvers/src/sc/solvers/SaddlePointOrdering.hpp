#pragma once
// A fill-reducing ordering for matrices with zero diagonal entries (saddle points: the u and θ
// rows of the mixed system, docs/theory.md "Unknowns"), computed with METIS and given to MUMPS as
// its pivot order (ICNTL(7) = 1; docs/solvers.md "Ordering").
//
// Nested dissection on the whole graph can put a zero-diagonal unknown where it is no pivot:
// MUMPS delays it to a parent front, and the factors grow 5-10× (docs/solvers.md "Ordering").
// Here each zero-diagonal row is glued to one of its nonzero-diagonal neighbours (its host,
// spread so that few rows share one), METIS orders the graph of A + Aᵀ with every host and its
// rows merged into one weighted vertex, and the rows follow their host in the pivot order, so
// each has a 2 × 2 pivot [[a, b], [b, 0]] at hand. Placing them after the last of their
// neighbours instead gave 2.3× the factor entries of AMF on a 3D contact system: an element's
// displacement rows then join the separator fronts.

#include <cstdint>
#include <vector>

namespace sc::solvers {

/// The graph of an n × n matrix by rows (0-based column indices, any order, the diagonal and
/// duplicates allowed; the pattern need not be symmetric: A + Aᵀ is ordered) and which rows have a
/// zero (or no) diagonal entry. Returns position[i], the 0-based place of unknown i in the pivot
/// order (a permutation of 0..n-1); zero-diagonal rows without a nonzero-diagonal neighbour come
/// last. Throws sc::core::Error if METIS fails or the graph exceeds
/// METIS' 32-bit indices. metisSeconds (if given): the wall time of METIS_NodeND alone.
std::vector<int> saddlePointOrdering(int n, const std::vector<std::int64_t>& rowStart,
                                     const std::vector<int>& columns,
                                     const std::vector<char>& zeroDiagonal,
                                     double* metisSeconds = nullptr);

}  // namespace sc::solvers
