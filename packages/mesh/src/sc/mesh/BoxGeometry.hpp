#pragma once
// Axis-aligned rectangle (2D) or box (3D): the "Unit square", "Unit cube" and "Rectangle" scenes.
// All boundary parts are flat. Names and part ids:
//   2D: "Left" x = x0 (0), "Right" x = x1 (1), "Bottom" y = y0 (2), "Top" y = y1 (3);
//   3D: "Left" x = x0 (0), "Right" x = x1 (1), "Front" y = y0 (2), "Back" y = y1 (3),
//       "Bottom" z = z0 (4), "Top" z = z1 (5).

#include <sc/mesh/Geometry.hpp>

namespace sc::mesh {

class BoxGeometry : public Geometry {
public:
  /// lower/upper: dim entries each (the corners); sceneName as reported by sceneName().
  BoxGeometry(std::vector<double> lower, std::vector<double> upper, std::string sceneName);
  int dim() const override { return static_cast<int>(lower_.size()); }
  std::string sceneName() const override { return sceneName_; }
  std::vector<std::string> boundaryNames() const override;
  bool isCurved(const std::string&) const override { return false; }
  std::array<double, 3> project(const std::string&, const std::array<double, 3>& x) const override
  {
    return x;
  }
  double exactMeasure() const override;
  void addToGmshModel() const override;
  std::string classifyBoundaryEntity(const std::array<double, 3>& com) const override;

private:
  std::vector<double> lower_, upper_;
  std::string sceneName_;
};

}  // namespace sc::mesh
