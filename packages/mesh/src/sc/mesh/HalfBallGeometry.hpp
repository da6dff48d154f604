#pragma once
// Hertz 3D scene (docs/theory.md §"Scenes"): x² + y² + (z−1)² < R², z < 1. Boundary parts: "Top"
// (the flat disc z = 1, part id 0) and "Cap" (the lower hemisphere, curved, part id 1).

#include <sc/mesh/Geometry.hpp>

namespace sc::mesh {

class HalfBallGeometry : public Geometry {
public:
  explicit HalfBallGeometry(double radius = 1.0);
  int dim() const override { return 3; }
  std::string sceneName() const override { return "Half ball"; }
  std::vector<std::string> boundaryNames() const override { return {"Top", "Cap"}; }
  bool isCurved(const std::string& name) const override { return name == "Cap"; }
  std::array<double, 3> project(const std::string& name,
                                const std::array<double, 3>& x) const override;
  double exactMeasure() const override;
  void addToGmshModel() const override;
  std::string classifyBoundaryEntity(const std::array<double, 3>& com) const override;
  double radius() const { return radius_; }

private:
  double radius_;
};

}  // namespace sc::mesh
