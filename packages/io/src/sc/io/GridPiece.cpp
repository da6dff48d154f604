// Small helpers of GridPiece, CellType and FieldKind.
#include <sc/io/GridPiece.hpp>

#include <sc/core/Error.hpp>

#include <nlohmann/json.hpp>

namespace sc::io {

int verticesPerCell(CellType type)
{
  switch (type) {
  case CellType::Line: return 2;
  case CellType::Triangle: return 3;
  case CellType::Tetrahedron: return 4;
  case CellType::Vertex: return 1;
  }
  throw sc::core::InternalError("verticesPerCell: unknown CellType");
}

std::string xdmfTopologyName(CellType type)
{
  switch (type) {
  case CellType::Line: return "Polyline";
  case CellType::Triangle: return "Triangle";
  case CellType::Tetrahedron: return "Tetrahedron";
  case CellType::Vertex: return "Polyvertex";
  }
  throw sc::core::InternalError("xdmfTopologyName: unknown CellType");
}

std::string cellTypeName(CellType type)
{
  switch (type) {
  case CellType::Line: return "line";
  case CellType::Triangle: return "triangle";
  case CellType::Tetrahedron: return "tetrahedron";
  case CellType::Vertex: return "vertex";
  }
  throw sc::core::InternalError("cellTypeName: unknown CellType");
}

int inputComponents(FieldKind kind, int dim)
{
  switch (kind) {
  case FieldKind::Scalar: return 1;
  case FieldKind::Vector: return dim;
  case FieldKind::Tensor: return dim * dim;
  case FieldKind::SymmetricTensor: return dim == 2 ? 3 : 6;
  }
  throw sc::core::InternalError("inputComponents: unknown FieldKind");
}

int storedComponents(FieldKind kind)
{
  switch (kind) {
  case FieldKind::Scalar: return 1;
  case FieldKind::Vector: return 3;
  case FieldKind::Tensor:
  case FieldKind::SymmetricTensor: return 9;
  }
  throw sc::core::InternalError("storedComponents: unknown FieldKind");
}

std::string xdmfAttributeType(FieldKind kind)
{
  switch (kind) {
  case FieldKind::Scalar: return "Scalar";
  case FieldKind::Vector: return "Vector";
  case FieldKind::Tensor:
  case FieldKind::SymmetricTensor: return "Tensor";
  }
  throw sc::core::InternalError("xdmfAttributeType: unknown FieldKind");
}

std::string fieldKindName(FieldKind kind)
{
  switch (kind) {
  case FieldKind::Scalar: return "scalar";
  case FieldKind::Vector: return "vector";
  case FieldKind::Tensor: return "tensor";
  case FieldKind::SymmetricTensor: return "symmetric tensor";
  }
  throw sc::core::InternalError("fieldKindName: unknown FieldKind");
}

void GridPiece::setBoundaryNames(const std::map<int, std::string>& names)
{
  nlohmann::ordered_json j = nlohmann::ordered_json::object();
  for (const auto& [id, label] : names)
    j[std::to_string(id)] = label;
  information["boundary_names"] = j.dump();
}

}  // namespace sc::io
