#pragma once
// Quadratic (isoparametric) geometry of the elements at a curved boundary (Mesh/Geometry order
// = 2, docs/mesh.md "Curved elements"): every edge of a boundary face on a curved part of the
// scene's Geometry gets a midpoint node on the exact curve/surface (the projection of the chord
// midpoint), and an element with such an edge is described by the shards Triangle<6> /
// Tetrahedron<10> node set (vertices, then edge midpoints in shards edge order; chord midpoints
// on its straight edges). All other elements stay affine. Interior edges are straight, so two
// neighbours always agree on their common face. Built from the replicated mesh, identical on
// every rank.

#include <vector>

#include <Teuchos_RCP.hpp>

namespace sc::mesh {

class SimplexMesh;
class Geometry;

class CurvedElements {
public:
  /// Curved edges of all boundary faces on the geometry's curved parts. (The discretisation
  /// checks that each curved element's map stays invertible at its quadrature points.)
  CurvedElements(Teuchos::RCP<const SimplexMesh> mesh, const Geometry& geometry);

  const SimplexMesh& mesh() const { return *mesh_; }
  int dim() const;
  bool isCurved(int element) const { return curvedElement_[element] != 0; }
  int numCurvedElements() const { return numCurved_; }
  int numCurvedEdges() const { return static_cast<int>(midpoints_.size() / 3); }
  /// Nodes per element of the quadratic map: 6 (Triangle<6>) or 10 (Tetrahedron<10>).
  int nodesPerElement() const;
  /// The quadratic nodes of element e (curved or not), 3 coordinates each (z = 0 in 2D).
  void nodes(int element, double* xyz) const;
  /// True if mesh edge `edge` is curved; its midpoint node (3 coordinates).
  bool isCurvedEdge(int edge) const { return edgeSlot_[edge] >= 0; }
  const double* edgeMidpoint(int edge) const
  {
    return &midpoints_[3 * static_cast<std::size_t>(edgeSlot_[edge])];
  }
  /// Largest distance of a midpoint node from its chord midpoint, relative to the edge length
  /// (≈ h/(8R) for a circle of radius R): how much the geometry differs from the straight mesh.
  double maxRelativeBulge() const { return maxBulge_; }

private:
  Teuchos::RCP<const SimplexMesh> mesh_;
  std::vector<int> edgeSlot_;
  std::vector<double> midpoints_;
  std::vector<char> curvedElement_;
  int numCurved_ = 0;
  double maxBulge_ = 0.0;
};

}  // namespace sc::mesh
