#pragma once
// Every body of the mesh must be held (docs/reliability.md, docs/theory.md §"Loads and
// supports"): a mesh of several bodies that share no face (a Gmsh file) is one system with a
// rigid-body kernel per body, and the deck-wide checks (a Displacement part somewhere, or
// Symmetry parts normal to every axis: Simulation, checkLoadsAndSupports) cannot see a body that
// touches none of those parts. Its motion was left to the solver: a MUMPS singularity, or a
// silent zero.
#include <sc/core/ProblemData.hpp>

namespace sc::mesh {
class SimplexMesh;
}

namespace sc::assembly {

/// For a mesh of two or more bodies (mesh::meshBodies), each body must touch a Displacement part
/// or Symmetry parts normal to all d axes (the rule checkLoadsAndSupports applies to a single
/// body; contact, tractions, pressures and Free parts fix no rigid motion). Otherwise an
/// InputError names the body (number, element count, bounding box) and its parts with their
/// types. A mesh of one body is left to the deck-wide checks, which say the same.
void checkEveryBodyIsHeld(const mesh::SimplexMesh& mesh,
                          const core::BoundaryConditions& boundaryConditions);

}  // namespace sc::assembly
