// Scene geometries (docs/theory.md §"Scenes") and their Gmsh (OpenCASCADE) models.
#include <sc/mesh/BoxGeometry.hpp>
#include <sc/mesh/HalfBallGeometry.hpp>
#include <sc/mesh/HalfDiscGeometry.hpp>

#include <sc/core/Error.hpp>

#include <gmsh.h>

#include <cmath>

namespace sc::mesh {

namespace {
constexpr double kPi = 3.14159265358979323846;

// Radial projection onto the sphere/circle of radius r around c: the closest point.
std::array<double, 3> radial(const std::array<double, 3>& x, const std::array<double, 3>& c,
                             double r)
{
  const double d[3] = {x[0] - c[0], x[1] - c[1], x[2] - c[2]};
  const double len = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
  SC_THROW_IF(!(len > 0), sc::core::InternalError, "projection of the centre onto a sphere");
  return {c[0] + r * d[0] / len, c[1] + r * d[1] / len, c[2] + r * d[2] / len};
}
}  // namespace

std::vector<std::string> Geometry::curvedBoundaryNames() const
{
  std::vector<std::string> out;
  for (const auto& n : boundaryNames())
    if (isCurved(n)) out.push_back(n);
  return out;
}

// Half disc --------------------------------------------------------------------------------------
HalfDiscGeometry::HalfDiscGeometry(double radius) : radius_(radius)
{
  SC_THROW_IF(!(radius > 0), sc::core::InputError, "Mesh/Radius = " << radius << " must be > 0");
}

std::array<double, 3> HalfDiscGeometry::project(const std::string& name,
                                                const std::array<double, 3>& x) const
{
  if (name != "Arc") return x;
  return radial(x, {0.0, 1.0, 0.0}, radius_);
}

double HalfDiscGeometry::exactMeasure() const { return 0.5 * kPi * radius_ * radius_; }

void HalfDiscGeometry::addToGmshModel() const
{
  const double R = radius_;
  const int disk = gmsh::model::occ::addDisk(0, 1, 0, R, R);
  const int cutter = gmsh::model::occ::addRectangle(-2 * R, 1, 0, 4 * R, 2 * R);
  std::vector<std::pair<int, int>> out;
  std::vector<std::vector<std::pair<int, int>>> map;
  gmsh::model::occ::cut({{2, disk}}, {{2, cutter}}, out, map);
  gmsh::model::occ::synchronize();
}

std::string HalfDiscGeometry::classifyBoundaryEntity(const std::array<double, 3>& com) const
{
  return std::abs(com[1] - 1.0) < 1e-8 * radius_ ? "Top" : "Arc";
}

// Half ball --------------------------------------------------------------------------------------
HalfBallGeometry::HalfBallGeometry(double radius) : radius_(radius)
{
  SC_THROW_IF(!(radius > 0), sc::core::InputError, "Mesh/Radius = " << radius << " must be > 0");
}

std::array<double, 3> HalfBallGeometry::project(const std::string& name,
                                                const std::array<double, 3>& x) const
{
  if (name != "Cap") return x;
  return radial(x, {0.0, 0.0, 1.0}, radius_);
}

double HalfBallGeometry::exactMeasure() const { return 2.0 / 3.0 * kPi * std::pow(radius_, 3); }

void HalfBallGeometry::addToGmshModel() const
{
  const double R = radius_;
  const int ball = gmsh::model::occ::addSphere(0, 0, 1, R);
  const int cutter = gmsh::model::occ::addBox(-2 * R, -2 * R, 1, 4 * R, 4 * R, 2 * R);
  std::vector<std::pair<int, int>> out;
  std::vector<std::vector<std::pair<int, int>>> map;
  gmsh::model::occ::cut({{3, ball}}, {{3, cutter}}, out, map);
  gmsh::model::occ::synchronize();
}

std::string HalfBallGeometry::classifyBoundaryEntity(const std::array<double, 3>& com) const
{
  return std::abs(com[2] - 1.0) < 1e-8 * radius_ ? "Top" : "Cap";
}

// Box
// ----------------------------------------------------------------------------------------------
BoxGeometry::BoxGeometry(std::vector<double> lower, std::vector<double> upper,
                         std::string sceneName)
    : lower_(std::move(lower)), upper_(std::move(upper)), sceneName_(std::move(sceneName))
{
  SC_THROW_IF(lower_.size() != upper_.size() || (lower_.size() != 2 && lower_.size() != 3),
              sc::core::InputError,
              sceneName_ << ": corners must both have 2 (2D) or 3 (3D) coordinates");
  for (std::size_t i = 0; i < lower_.size(); ++i)
    SC_THROW_IF(!(upper_[i] > lower_[i]), sc::core::InputError,
                sceneName_ << ": Mesh/Upper corner must exceed Mesh/Lower corner in every "
                              "coordinate (coordinate "
                           << i << ": " << lower_[i] << " >= " << upper_[i] << ")");
}

std::vector<std::string> BoxGeometry::boundaryNames() const
{
  if (dim() == 2) return {"Left", "Right", "Bottom", "Top"};
  return {"Left", "Right", "Front", "Back", "Bottom", "Top"};
}

double BoxGeometry::exactMeasure() const
{
  double m = 1;
  for (std::size_t i = 0; i < lower_.size(); ++i)
    m *= upper_[i] - lower_[i];
  return m;
}

void BoxGeometry::addToGmshModel() const
{
  if (dim() == 2)
    gmsh::model::occ::addRectangle(lower_[0], lower_[1], 0, upper_[0] - lower_[0],
                                   upper_[1] - lower_[1]);
  else
    gmsh::model::occ::addBox(lower_[0], lower_[1], lower_[2], upper_[0] - lower_[0],
                             upper_[1] - lower_[1], upper_[2] - lower_[2]);
  gmsh::model::occ::synchronize();
}

std::string BoxGeometry::classifyBoundaryEntity(const std::array<double, 3>& com) const
{
  const auto names = boundaryNames();
  for (int k = 0; k < dim(); ++k) {
    const double tol = 1e-8 * (upper_[k] - lower_[k]);
    if (std::abs(com[k] - lower_[k]) < tol) return names[2 * k];
    if (std::abs(com[k] - upper_[k]) < tol) return names[2 * k + 1];
  }
  SC_THROW_IF(true, sc::core::InternalError,
              sceneName_ << ": a Gmsh boundary entity is on no side of the box");
}

}  // namespace sc::mesh
