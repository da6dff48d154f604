#pragma once
// Hertz 2D scene (docs/theory.md §"Scenes"): x² + (y−1)² < R², y < 1. Boundary parts: "Top" (the
// flat edge y = 1, part id 0) and "Arc" (the lower half circle, curved, part id 1).

#include <sc/mesh/Geometry.hpp>

namespace sc::mesh {

class HalfDiscGeometry : public Geometry {
public:
  explicit HalfDiscGeometry(double radius = 1.0);
  int dim() const override { return 2; }
  std::string sceneName() const override { return "Half disc"; }
  std::vector<std::string> boundaryNames() const override { return {"Top", "Arc"}; }
  bool isCurved(const std::string& name) const override { return name == "Arc"; }
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
