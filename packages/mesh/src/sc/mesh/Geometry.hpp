#pragma once
// Exact description of a scene's domain (docs/theory.md §"Scenes"): its boundary part names, which
// parts are curved, the projection of a point onto a curved part (used to place new boundary
// vertices during refinement, docs/theory.md §"Adaptivity"), and how to build the domain in Gmsh
// for the initial mesh.

#include <array>
#include <cmath>
#include <string>
#include <vector>

namespace sc::mesh {

class Geometry {
public:
  virtual ~Geometry() = default;

  virtual int dim() const = 0;
  /// Scene name as in Mesh/Source ("Half disc", ...).
  virtual std::string sceneName() const = 0;
  /// Boundary part names, in part-id order of the meshes built from this geometry.
  virtual std::vector<std::string> boundaryNames() const = 0;
  /// True if the named part is curved (its vertices must be projected after bisection).
  virtual bool isCurved(const std::string& boundaryName) const = 0;
  std::vector<std::string> curvedBoundaryNames() const;
  /// Closest point of the exact (curved) boundary part to x; x itself for flat parts. 2D points
  /// have x[2] = 0.
  virtual std::array<double, 3> project(const std::string& boundaryName,
                                        const std::array<double, 3>& x) const = 0;
  /// Exact area/volume of the domain (quiet NaN if not known).
  virtual double exactMeasure() const { return std::nan(""); }

  /// A note on how faithful this description of the domain is, for the run's progress output and
  /// summary.json (e.g. a file's curved part that is only its polygon); empty if there is none.
  virtual std::string warning() const { return {}; }

  /// Add the domain to the current Gmsh model (OpenCASCADE kernel) and synchronise. Requires an
  /// initialised Gmsh (see GmshMeshIO).
  virtual void addToGmshModel() const = 0;
  /// Name of the boundary part that a Gmsh boundary entity with this centre of mass belongs to.
  virtual std::string classifyBoundaryEntity(const std::array<double, 3>& centerOfMass) const = 0;
};

}  // namespace sc::mesh
