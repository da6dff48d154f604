#pragma once
// docs/theory.md §"Mixed formulation": the 3D RT_k x DP_k x CP_k discretisation rests on 3D
// Taylor–Hood stability, which asks for no tetrahedron with all four vertices on the boundary. Gmsh
// meshes of the half ball have some (85 of 850 at h = 0.25). Splitting each such element at its
// barycentre (1 -> 4, faces unchanged, so the mesh stays conforming) removes them, and bisection
// never creates new ones: a child has all its vertices on the boundary only if its parent has (the
// new vertex of a bisected edge is on the boundary only if the edge is).

#include <sc/mesh/SimplexMesh.hpp>

#include <Teuchos_RCP.hpp>

namespace sc::mesh {

/// A copy of `mesh` in which every element with all vertices on the boundary is split into dim+1
/// elements at its barycentre (the barycentre is appended to the vertices; split elements' first
/// child keeps the index, the others are appended). Boundary faces and names are unchanged.
Teuchos::RCP<SimplexMesh> splitElementsWithAllVerticesOnBoundary(const SimplexMesh& mesh);

}  // namespace sc::mesh
