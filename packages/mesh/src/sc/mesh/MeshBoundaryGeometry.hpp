#pragma once
// The boundary of a mesh read from a file, as the file describes it (docs/mesh.md "Curved
// boundaries from files"): every boundary face of a physical group is a quadratic curve (3-node
// line, 2D) or surface patch (6-node triangle, 3D) through its vertices and mid-edge nodes, or a
// straight segment / flat triangle when the file is linear. It serves as the Geometry of a Gmsh
// file: refinement places each new boundary vertex at the closest point of its part's patches,
// and curved (quadratic) elements take their edge midpoints from there, so that the body stays
// the one of the file under refinement: its quadratic surface for a second-order file, its
// polygon for a linear one (then warning() says so, with the largest angle between
// neighbouring faces of a part).

#include <sc/mesh/Geometry.hpp>

#include <array>
#include <memory>
#include <string>
#include <vector>

namespace sc::mesh {

class MeshBoundaryGeometry : public Geometry {
public:
  /// Nodes per face: 3 in 2D (v0, v1, midpoint of v0v1) and 6 in 3D (v0, v1, v2, then the
  /// midpoints of v0v1, v1v2, v2v0), as Gmsh's 3-node line and 6-node triangle.
  static int nodesPerFace(int dim) { return dim == 2 ? 3 : 6; }

  /// `faceNodes`: nodesPerFace(dim) points of 3 coordinates per face; `facePart`: the index of
  /// each face's part in `names`. A linear face has its midpoints at the chord midpoints.
  /// `origin` names the file in messages. Throws InputError for a face whose quadratic map
  /// folds (a mid-edge node outside the middle half of its chord, or a patch normal that turns
  /// against the flat triangle's), naming the part and `faceLabels` (3 or 6 node tags per face,
  /// optional).
  MeshBoundaryGeometry(int dim, std::vector<std::string> names, std::vector<double> faceNodes,
                       std::vector<int> facePart, std::string origin,
                       const std::vector<std::size_t>* faceLabels = nullptr);

  int dim() const override { return dim_; }
  std::string sceneName() const override { return "Gmsh file"; }
  std::vector<std::string> boundaryNames() const override { return names_; }
  /// True if a face of the part bends: in 2D a midpoint node off its chord midpoint, in 3D a
  /// midpoint node off the plane of its face's vertices (by more than 1e-10 of the face's size).
  /// A flat part whose edges bend within its plane is not curved: its bent edges are another
  /// part's too, whose patches place their new vertices.
  bool isCurved(const std::string& boundaryName) const override;
  /// Closest point of the part's faces (their quadratic patches); x itself for a part that is
  /// not curved or unknown.
  std::array<double, 3> project(const std::string& boundaryName,
                                const std::array<double, 3>& x) const override;
  void addToGmshModel() const override;
  std::string classifyBoundaryEntity(const std::array<double, 3>& centerOfMass) const override;
  std::string warning() const override { return warning_; }

  /// The largest angle (degrees) between the outward normals of two faces of `part` that share
  /// a vertex (2D) or an edge (3D), evaluated at the shared points; 0 for a flat part.
  double maxKinkAngleDegrees(int part) const;
  bool quadratic() const { return quadratic_; }

  const std::vector<double>& faceNodes() const { return nodes_; }
  const std::vector<int>& facePart() const { return part_; }
  const std::string& origin() const { return origin_; }

private:
  struct Bins;
  int dim_;
  std::vector<std::string> names_;
  std::vector<double> nodes_;
  std::vector<int> part_;
  std::string origin_;
  std::vector<char> partCurved_;
  bool quadratic_ = false;
  std::string warning_;
  std::vector<std::shared_ptr<Bins>> bins_;  // per part: a uniform grid of the faces' boxes

  int partIndex(const std::string& name) const;
  /// Closest point on face f and its squared distance to x.
  std::array<double, 3> closestOnFace(int f, const std::array<double, 3>& x, double& dist2) const;
};

}  // namespace sc::mesh
