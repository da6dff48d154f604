#include "FieldWriter.hpp"

#include <cmath>
#include <map>
#include <string>

#include <sc/core/Error.hpp>
#include <sc/io/XdmfWriter.hpp>
#include <sc/mesh/SimplexMesh.hpp>

namespace sc::app {

void writeCycleFields(io::XdmfWriter& writer, const mesh::SimplexMesh& mesh,
                      const std::vector<int>& elementOwner, int rank, const CycleResults& results)
{
  SC_THROW_IF(!results.fields, core::InternalError,
              "cycle " << results.cycle << " has no fields to write");
  const CycleFields& fields = *results.fields;
  const int dim = mesh.dim();
  const std::size_t ne = mesh.numElements();
  const int nodesPerElement = dim + 1;
  // Every rank's owned vertices form one contiguous block of the numbering, as the writer
  // requires (mesh::vertexOwnership).
  const auto& newId = fields.vertices.number;

  io::GridPiece domain("domain", dim == 2 ? io::CellType::Triangle : io::CellType::Tetrahedron,
                       dim);
  const auto& x = mesh.coordinates();
  for (int v : fields.vertices.owned)
    for (int d = 0; d < dim; ++d)
      domain.coordinates.push_back(x[static_cast<std::size_t>(v) * dim + d]);
  std::vector<double> measure;
  for (std::size_t e = 0; e < ne; ++e) {
    if (elementOwner[e] != rank) continue;
    const int* ev = mesh.elementVertices(static_cast<int>(e));
    for (int i = 0; i < nodesPerElement; ++i)
      domain.connectivity.push_back(newId[ev[i]]);
    measure.push_back(mesh.elementMeasure(static_cast<int>(e)));
  }
  domain.addCellField("element_measure", io::FieldKind::Scalar, std::move(measure));
  if (results.estimate) {
    // η_T of the owned elements (same order as the loop above: ownedElements() is ascending),
    // and u^R at the owned vertices as a point field (ParaView: Warp By Vector).
    std::vector<double> etaT;
    for (double v : results.estimate->indicators)
      etaT.push_back(std::sqrt(v));
    domain.addCellField("eta", io::FieldKind::Scalar, std::move(etaT));
    domain.addPointField("reconstructed_displacement", io::FieldKind::Vector,
                         fields.reconstructedDisplacement);
  }
  if (fields.averages) {
    // Cell averages, in the order of the rank's owned elements (the loop above).
    const auto& avg = *fields.averages;
    domain.addCellField("stress", io::FieldKind::Tensor, avg.stress);
    domain.addCellField("von_mises", io::FieldKind::Scalar, avg.vonMises);
    domain.addCellField("pressure", io::FieldKind::Scalar, avg.pressure);
    domain.addCellField("displacement", io::FieldKind::Vector, avg.displacement);
    domain.addCellField("rotation", dim == 2 ? io::FieldKind::Scalar : io::FieldKind::Vector,
                        avg.rotation);
  }

  io::GridPiece boundary("boundary", dim == 2 ? io::CellType::Line : io::CellType::Triangle, dim);
  boundary.geometryFrom = "domain";
  std::vector<int> boundaryId;
  for (int f : mesh.boundaryFaces()) {
    if (elementOwner[mesh.faceElements(f)[0]] != rank) continue;
    const int* fv = mesh.faceVertices(f);
    for (int i = 0; i < dim; ++i)
      boundary.connectivity.push_back(newId[fv[i]]);
    boundaryId.push_back(mesh.faceBoundaryId(f));
  }
  if (results.contact) {
    // Mean contact pressure −σ_N and tangential traction of each contact face's points.
    const auto means = contact::faceMeans(results.contact->points);
    std::vector<double> pressure, shear;
    for (int f : mesh.boundaryFaces()) {
      if (elementOwner[mesh.faceElements(f)[0]] != rank) continue;
      auto it = means.find(f);
      pressure.push_back(it == means.end() ? 0.0 : it->second.pressure);
      shear.push_back(it == means.end() ? 0.0 : it->second.shear);
    }
    boundary.addCellField("contact_pressure", io::FieldKind::Scalar, std::move(pressure));
    boundary.addCellField("tangential_traction", io::FieldKind::Scalar, std::move(shear));
  }
  boundary.addCellField("boundary_id", std::move(boundaryId));
  std::map<int, std::string> names;
  const auto& bn = mesh.boundaryNames();
  for (std::size_t i = 0; i < bn.size(); ++i)
    names[static_cast<int>(i)] = bn[i];
  boundary.setBoundaryNames(names);

  std::vector<io::GridPiece> grids;
  grids.push_back(std::move(domain));
  grids.push_back(std::move(boundary));
  if (fields.contactPoints)  // the contact points with their point values (ContactFields.hpp)
    grids.push_back(*fields.contactPoints);
  writer.writeStep(results.cycle, grids);
}

}  // namespace sc::app
