#pragma once
// Transfer of data from a mesh to its refinement with the history of one BisectionRefiner call
// (docs/theory.md §"Adaptivity"): vertex fields (P1 interpolation at the new midpoints), element
// fields (children inherit the parent's value) and the parent of every boundary face (to carry
// contact active sets and boundary data over).

#include <sc/mesh/RefinementStep.hpp>
#include <sc/mesh/SimplexMesh.hpp>

#include <vector>

namespace sc::mesh {

/// Values at the vertices of the refined mesh (`components` per vertex, interleaved): old vertices
/// keep theirs, each new vertex gets the mean of its parent edge's endpoints (exact for P1 fields;
/// a projected boundary vertex gets the chord-midpoint value).
std::vector<double> prolongVertexField(const RefinementStep& step, const std::vector<double>& old,
                                       int components = 1);

/// Values per element of the refined mesh (`components` per element): each child gets its parent's.
std::vector<double> prolongElementField(const RefinementStep& step, const std::vector<double>& old,
                                        int components = 1);

/// For every face f of `refined`: the boundary face of `previous` that contains it if f is a
/// boundary face, else -1. Found topologically (no geometry), so it also holds for projected
/// boundary vertices.
std::vector<int> boundaryFaceParents(const SimplexMesh& previous, const SimplexMesh& refined,
                                     const RefinementStep& step);

}  // namespace sc::mesh
