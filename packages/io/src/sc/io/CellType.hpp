#pragma once
// Simplex cell types the writers know, with their XDMF names.

#include <string>

namespace sc::io {

enum class CellType { Line, Triangle, Tetrahedron };

/// Vertices per cell: 2, 3, 4.
int verticesPerCell(CellType type);

/// XDMF 3 TopologyType ("Polyline" with NodesPerElement="2" for lines).
std::string xdmfTopologyName(CellType type);

/// "line", "triangle", "tetrahedron" (for messages).
std::string cellTypeName(CellType type);

}  // namespace sc::io
