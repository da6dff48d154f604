#pragma once
// Simplex cell types the writers know, with their XDMF names.

#include <string>

namespace sc::io {

/// Vertex: a point cloud (XDMF "Polyvertex"), one cell per vertex of the grid's own, which the
/// writer numbers itself (GridPiece: no connectivity), e.g. the contact points of a cycle.
enum class CellType { Line, Triangle, Tetrahedron, Vertex };

/// Vertices per cell: 2, 3, 4, 1.
int verticesPerCell(CellType type);

/// XDMF 3 TopologyType ("Polyline" with NodesPerElement="2" for lines, "Polyvertex" with
/// NodesPerElement="1" for vertices).
std::string xdmfTopologyName(CellType type);

/// "line", "triangle", "tetrahedron", "vertex" (for messages).
std::string cellTypeName(CellType type);

}  // namespace sc::io
