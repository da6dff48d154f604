#pragma once
// A user's geometry given as a Gmsh script (Mesh/Source = Gmsh geometry, docs/mesh.md "Curved
// boundaries from files"): the script is run by Gmsh (it may merge CAD files: STEP, BRep, IGES)
// into a model that this object keeps for the whole run, on every rank. Its physical groups of
// dimension d−1 name the boundary parts. The model is meshed once (GmshMeshIO::meshCad, rank 0);
// afterwards every vertex that refinement creates on a curved part, and every mid-edge node of
// a curved (quadratic) element, is placed at the closest point of the part's CAD entities
// (Gmsh's getClosestPoint), so that refinement converges to the CAD body.
//
// Running a script is running a program: Gmsh scripts can start other programs (SystemCall).
// This source is an explicit choice in the deck; Mesh/Source = Gmsh file never runs scripts.

#include <sc/mesh/Geometry.hpp>

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace sc::mesh {

class GmshSession;

class CadGeometry : public Geometry {
public:
  /// Run the script `path` in a model of its own. InputError (naming the file) if it is not a
  /// readable regular file, Gmsh reports an error, the model's dimension is not `dim`, or it has
  /// no physical group of dimension dim−1.
  CadGeometry(const std::string& path, int dim);
  ~CadGeometry() override;

  int dim() const override { return dim_; }
  std::string sceneName() const override { return "Gmsh geometry"; }
  /// Physical groups of dimension dim−1 by tag; a group without a name is called by its number.
  std::vector<std::string> boundaryNames() const override { return names_; }
  /// False if every entity of the group is a straight line or a plane, true otherwise.
  bool isCurved(const std::string& boundaryName) const override;
  /// The closest point of the group's entities to x (x itself for a part that is not curved).
  std::array<double, 3> project(const std::string& boundaryName,
                                const std::array<double, 3>& x) const override;
  void addToGmshModel() const override;
  std::string classifyBoundaryEntity(const std::array<double, 3>& centerOfMass) const override;

  const std::string& path() const { return path_; }
  const GmshSession& session() const { return *session_; }

private:
  std::string path_;
  int dim_;
  std::unique_ptr<GmshSession> session_;
  std::vector<std::string> names_;
  std::map<std::string, std::vector<int>> entities_;
  std::map<std::string, bool> curved_;
};

}  // namespace sc::mesh
