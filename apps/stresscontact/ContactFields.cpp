#include "ContactFields.hpp"

#include <sc/contact/ActiveSetSolver.hpp>

namespace sc::app {

io::GridPiece contactPointGrid(const contact::ActiveSetSolver& solver, int dim, int degree)
{
  const auto& points = solver.points();
  const auto values = contact::pointValues(points, dim, degree, solver.bernsteinConstraints());
  io::GridPiece grid("contact", io::CellType::Vertex, dim);
  std::vector<int> status;
  std::vector<double> pressure, traction, gap, slip, weight, normal;
  // In 2D the tangential quantities are signed along t1 (one component); in 3D they are vectors
  // in x, y, z: ParaView draws them as arrows and colours by their magnitude.
  auto tangential = [&](std::vector<double>& out, const contact::ContactPoint& p,
                        const std::array<double, 2>& c) {
    if (dim == 2) {
      out.push_back(c[0]);
      return;
    }
    for (int i = 0; i < 3; ++i)
      out.push_back(c[0] * p.t1[i] + c[1] * p.t2[i]);
  };
  for (std::size_t i = 0; i < points.size(); ++i) {
    const auto& p = points[i];
    const auto& v = values[i];
    grid.coordinates.insert(grid.coordinates.end(), p.x.begin(), p.x.begin() + dim);
    status.push_back(static_cast<int>(p.status));
    pressure.push_back(v.pressure);
    tangential(traction, p, v.sigmaT);
    gap.push_back(v.gap);
    tangential(slip, p, v.slip);
    weight.push_back(p.weight);
    normal.insert(normal.end(), p.n.begin(), p.n.begin() + dim);
  }
  const auto tangentialKind = dim == 2 ? io::FieldKind::Scalar : io::FieldKind::Vector;
  grid.addPointField("status", std::move(status));
  grid.addPointField("contact_pressure", io::FieldKind::Scalar, std::move(pressure));
  grid.addPointField("tangential_traction", tangentialKind, std::move(traction));
  grid.addPointField("gap", io::FieldKind::Scalar, std::move(gap));
  grid.addPointField("slip", tangentialKind, std::move(slip));
  grid.addPointField("weight", io::FieldKind::Scalar, std::move(weight));
  grid.addPointField("contact_normal", io::FieldKind::Vector, std::move(normal));
  return grid;
}

}  // namespace sc::app
