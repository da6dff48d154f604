#pragma once
// Conforming simplicial mesh: triangles in 2D, tetrahedra in 3D, with named boundary parts.
//
// Conventions (the discretisation relies on them, docs/mesh.md "Conventions"):
// - Every element's vertices are ordered with positive signed measure (counter-clockwise
//   triangles; tetrahedra with det[x1-x0, x2-x0, x3-x0] > 0). Intrepid2's orientation tools
//   (docs/theory.md §"Mixed formulation") take the element's vertex global ids in this order.
// - Local face i of an element is the face opposite local vertex i (for tetrahedra: the vertices
//   {0,1,2,3} \ {i} in increasing local order; for triangles: the edge {0,1,2} \ {i}).
// - Intrepid2/shards numbering is available through sideFace() and elementEdges(): shards side s
//   of Triangle<3> is the edge (s, s+1 mod 3), i.e. opposite local vertex {2, 0, 1}[s]; sides of
//   Tetrahedron<4> are {0,1,3}, {1,2,3}, {0,3,2}, {0,2,1}, opposite local vertex {2, 0, 1, 3}[s];
//   edges of Tetrahedron<4> are (0,1), (1,2), (2,0), (0,3), (1,3), (2,3).
// - Faces (edges in 2D, triangles in 3D) and edges store their vertices sorted by increasing
//   global id.
// - faceElements(f)[0] is always a valid element; [1] is -1 on boundary faces. faceNormal(f) is
//   the unit normal pointing out of faceElements(f)[0], hence the outward normal on the boundary.
// - Boundary parts have ids 0..numBoundaryParts()-1 and names (Gmsh physical names, scene names).
//
// The mesh is immutable after construction (refinement builds a new one, see BisectionRefiner) and
// not copyable: share it through Teuchos::RCP<const SimplexMesh>.

#include <array>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace sc::mesh {

class SimplexMesh {
public:
  /// Build connectivity and geometric data and check the mesh. `origin` names where the mesh came
  /// from (file name, scene) and is quoted in every error. Elements with negative signed measure
  /// are reordered (two vertices swapped); degenerate elements, faces shared by more than two
  /// elements, folded (overlapping) neighbours, hanging nodes on edges and tagged boundary faces
  /// that are not on the boundary are sc::core::InputError. Boundary faces not listed get the part
  /// "Unnamed". Optional `labels`: the numbers that errors should quote for vertices and elements
  /// (e.g. the Gmsh node and element tags of a file), indexed like the vertices/elements given
  /// here.
  struct Labels {
    std::vector<std::size_t> vertex, element;
  };
  SimplexMesh(int dim, std::vector<double> coordinates, std::vector<int> elementVertices,
              const std::vector<int>& boundaryFaceVertices,
              const std::vector<int>& boundaryFacePart, std::vector<std::string> boundaryNames,
              std::string origin, const Labels* labels = nullptr);

  SimplexMesh(const SimplexMesh&) = delete;
  SimplexMesh& operator=(const SimplexMesh&) = delete;

  int dim() const { return dim_; }
  int verticesPerElement() const { return dim_ + 1; }
  int verticesPerFace() const { return dim_; }
  int numVertices() const { return static_cast<int>(coords_.size()) / dim_; }
  int numElements() const { return static_cast<int>(elemVerts_.size()) / (dim_ + 1); }
  int numFaces() const { return static_cast<int>(faceVerts_.size()) / dim_; }
  const std::string& origin() const { return origin_; }

  // Vertices ---------------------------------------------------------------------------------
  /// All coordinates, dim() per vertex.
  const std::vector<double>& coordinates() const { return coords_; }
  const double* vertex(int v) const { return &coords_[static_cast<std::size_t>(v) * dim_]; }

  // Elements ---------------------------------------------------------------------------------
  /// All element vertices, dim()+1 per element (positive orientation).
  const std::vector<int>& elementVertices() const { return elemVerts_; }
  const int* elementVertices(int e) const
  {
    return &elemVerts_[static_cast<std::size_t>(e) * (dim_ + 1)];
  }
  /// Faces of element e, dim()+1 entries; entry i is the face opposite local vertex i.
  const int* elementFaces(int e) const
  {
    return &elemFaces_[static_cast<std::size_t>(e) * (dim_ + 1)];
  }
  /// Face on Intrepid2/shards side `side` of element e (see the conventions above).
  int sideFace(int e, int side) const { return elementFaces(e)[oppositeVertexOfSide(dim_, side)]; }
  /// Local vertex opposite shards side `side`: 2D {2, 0, 1}, 3D {2, 0, 1, 3}.
  static int oppositeVertexOfSide(int dim, int side)
  {
    constexpr int tri[3] = {2, 0, 1}, tet[4] = {2, 0, 1, 3};
    return dim == 2 ? tri[side] : tet[side];
  }
  double elementMeasure(int e) const { return elemMeasure_[e]; }
  /// Longest edge of element e.
  double elementDiameter(int e) const { return elemDiameter_[e]; }
  /// Elements around vertex v (compressed rows).
  std::pair<const int*, const int*> vertexElements(int v) const
  {
    return {&vertElems_[vertElemPtr_[v]], &vertElems_[vertElemPtr_[v + 1]]};
  }

  // Edges (in 2D the same entities as the faces, numbered alike) ------------------------------
  int numEdges() const { return static_cast<int>(edgeVerts_.size()) / 2; }
  const int* edgeVertices(int ed) const { return &edgeVerts_[static_cast<std::size_t>(ed) * 2]; }
  /// Edges of element e in shards order: 3 (2D, edge s = side s) or 6 (3D).
  const int* elementEdges(int e) const
  {
    return &elemEdges_[static_cast<std::size_t>(e) * (dim_ == 2 ? 3 : 6)];
  }

  // Faces ------------------------------------------------------------------------------------
  const int* faceVertices(int f) const { return &faceVerts_[static_cast<std::size_t>(f) * dim_]; }
  /// The (one or two) elements of face f; second entry -1 on the boundary.
  std::array<int, 2> faceElements(int f) const { return faceElems_[f]; }
  bool isBoundaryFace(int f) const { return faceElems_[f][1] < 0; }
  double faceMeasure(int f) const { return faceMeasure_[f]; }
  /// Unit normal of face f pointing out of faceElements(f)[0] (outward on the boundary).
  std::array<double, 3> faceNormal(int f) const;

  // Boundary parts -----------------------------------------------------------------------------
  int numBoundaryParts() const { return static_cast<int>(boundaryNames_.size()); }
  /// Part names indexed by part id.
  const std::vector<std::string>& boundaryNames() const { return boundaryNames_; }
  const std::string& boundaryName(int id) const { return boundaryNames_.at(id); }
  /// Part id of a name; sc::core::InputError listing the valid names if unknown.
  int boundaryId(const std::string& name) const;
  bool hasBoundary(const std::string& name) const;
  /// All boundary faces (ascending) and the part id of face f (-1 for interior faces).
  const std::vector<int>& boundaryFaces() const { return boundaryFaces_; }
  int faceBoundaryId(int f) const { return faceBoundary_[f]; }
  /// Boundary faces of one part (ascending).
  std::vector<int> boundaryFacesOf(const std::string& name) const;
  /// True if vertex v lies on a boundary face.
  bool isBoundaryVertex(int v) const { return boundaryVertex_[v] != 0; }
  /// Elements all of whose vertices are on the boundary (3D Taylor–Hood stability, docs/theory.md
  /// §"Mixed formulation", asks to avoid such tetrahedra; in 2D: triangles with three boundary
  /// vertices).
  std::vector<int> elementsWithAllVerticesOnBoundary() const;
  /// Total measure (length/area) of one boundary part.
  double boundaryMeasure(const std::string& name) const;

  // Whole-mesh quantities ----------------------------------------------------------------------
  /// Area (2D) / volume (3D) of the domain.
  double measure() const;
  /// Largest element diameter.
  double meshSize() const;
  /// 2D: smallest interior angle of any triangle; 3D: smallest dihedral angle of any tetrahedron.
  double minAngleDeg() const;
  /// Angles of element e in degrees: 3 interior angles (2D) or 6 dihedral angles (3D, at edges
  /// 01,02,03,12,13,23).
  std::vector<double> elementAnglesDeg(int e) const;
  /// Euler characteristic V - E + F (2D, faces = triangles) or V - E + F - T (3D): 1 for a mesh
  /// of a disc or a ball, whatever the refinement.
  long eulerCharacteristic() const;

private:
  void orientAndMeasureElements();
  void buildFaces();
  void assignBoundaryParts(const std::vector<int>& boundaryFaceVertices,
                           const std::vector<int>& boundaryFacePart);
  void checkFolds() const;
  void checkHangingNodes() const;
  void buildVertexElements();
  void buildEdges();
  double signedMeasure(const int* v) const;
  std::string describeElement(int e) const;
  std::string describeFace(const int* v) const;
  std::string vertexLabel(int v) const;
  std::string elementLabel(int e) const;

  int dim_;
  std::string origin_;
  std::vector<double> coords_;
  std::vector<int> elemVerts_;
  std::vector<int> elemFaces_;
  std::vector<double> elemMeasure_, elemDiameter_;
  std::vector<int> faceVerts_;
  std::vector<std::array<int, 2>> faceElems_;
  std::vector<double> faceMeasure_;
  std::vector<double> faceNormal_;  // dim per face
  std::vector<int> faceBoundary_;
  std::vector<int> boundaryFaces_;
  std::vector<std::string> boundaryNames_;
  std::vector<int> vertElemPtr_, vertElems_;
  std::vector<int> edgeVerts_, elemEdges_;
  std::vector<char> boundaryVertex_;
  const Labels* labels_ = nullptr;  // only during construction (error messages)
};

}  // namespace sc::mesh
