#pragma once
// One rank's piece of one grid of an output step, in plain arrays so that io does not depend on
// the mesh package. Vertices are numbered globally so that each rank's owned vertices form a
// contiguous block in rank order (rank 0 first); a rank passes the coordinates of its owned
// vertices and its owned cells with GLOBAL vertex indices. Empty pieces are fine.

#include <sc/io/CellType.hpp>
#include <sc/io/FieldKind.hpp>

#include <map>
#include <string>
#include <vector>

namespace sc::io {

/// A field with double values, interleaved per entity (layout: FieldKind.hpp).
struct Field {
  std::string name;
  FieldKind kind = FieldKind::Scalar;
  std::vector<double> values;
};

/// A scalar field with integer values (ids, flags, states), stored as 32-bit integers.
struct IntegerField {
  std::string name;
  std::vector<int> values;
};

struct GridPiece {
  /// Name of the grid in the step ("domain", "boundary"); also the HDF5 group name.
  std::string name;
  CellType cellType = CellType::Triangle;
  /// Space dimension of the coordinates and of vector/tensor fields: 2 or 3.
  int spaceDim = 2;

  /// Owned vertices' coordinates, spaceDim values per vertex. Leave empty and set geometryFrom
  /// to reuse the vertices of an earlier grid of the same step (e.g. a boundary grid whose
  /// connectivity refers to the domain's vertices); its point fields then live on those vertices.
  std::vector<double> coordinates;
  std::string geometryFrom;

  /// Owned cells, verticesPerCell(cellType) global vertex indices each. Empty for
  /// CellType::Vertex: a point cloud has one cell per owned vertex, numbered by the writer.
  std::vector<long long> connectivity;

  std::vector<Field> pointFields;
  std::vector<Field> cellFields;
  std::vector<IntegerField> integerPointFields;
  std::vector<IntegerField> integerCellFields;

  /// Name/value pairs written as XDMF <Information> elements and as string attributes of the
  /// grid's HDF5 group. Must be identical on all ranks.
  std::map<std::string, std::string> information;

  GridPiece() = default;
  GridPiece(std::string name, CellType cellType, int spaceDim)
      : name(std::move(name)), cellType(cellType), spaceDim(spaceDim)
  {
  }

  void addPointField(std::string fieldName, FieldKind kind, std::vector<double> values)
  {
    pointFields.push_back({std::move(fieldName), kind, std::move(values)});
  }
  void addCellField(std::string fieldName, FieldKind kind, std::vector<double> values)
  {
    cellFields.push_back({std::move(fieldName), kind, std::move(values)});
  }
  void addPointField(std::string fieldName, std::vector<int> values)
  {
    integerPointFields.push_back({std::move(fieldName), std::move(values)});
  }
  void addCellField(std::string fieldName, std::vector<int> values)
  {
    integerCellFields.push_back({std::move(fieldName), std::move(values)});
  }

  /// Record the boundary id -> name map as information "boundary_names" (a JSON object text,
  /// e.g. {"1":"contact","2":"clamped"}); pair it with an integer cell field "boundary_id".
  void setBoundaryNames(const std::map<int, std::string>& names);

  /// Owned vertices of this piece (0 if geometryFrom is set).
  std::size_t localVertexCount() const
  {
    return coordinates.size() / static_cast<std::size_t>(spaceDim);
  }
  /// Owned cells (the owned vertices for CellType::Vertex).
  std::size_t localCellCount() const
  {
    return cellType == CellType::Vertex
               ? localVertexCount()
               : connectivity.size() / static_cast<std::size_t>(verticesPerCell(cellType));
  }
};

}  // namespace sc::io
