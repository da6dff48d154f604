// Uses three installed StressContact components from outside the source tree: validates a
// Material sublist, builds the half-disc scene mesh and writes a summary. Exit 0 only if the
// numbers are right: c_d = ν for plane strain (analytic), mesh measure within 5% of π/2.
#include <cmath>
#include <iostream>

#include <Teuchos_DefaultComm.hpp>
#include <Teuchos_GlobalMPISession.hpp>

#include <sc/core/Parameters.hpp>
#include <sc/core/ProblemData.hpp>
#include <sc/io/RunSummary.hpp>
#include <sc/mesh/MeshFactory.hpp>
#include <sc/mesh/SimplexMesh.hpp>

int main(int argc, char* argv[])
{
  Teuchos::GlobalMPISession session(&argc, &argv, nullptr);
  auto comm = Teuchos::DefaultComm<int>::getComm();
  Teuchos::ParameterList material;
  material.set("Poisson ratio", 0.28);
  sc::core::validateParameters(material, *sc::core::Material::getValidParameters(), "consumer");
  const auto m = sc::core::Material::fromParameters(material);
  if (std::abs(m.complianceCoefficient(2) - 0.28) > 1e-15) {
    std::cerr << "wrong compliance coefficient\n";
    return 1;
  }
  Teuchos::ParameterList meshList;
  meshList.set("Source", std::string("Half disc"));
  meshList.set("Initial mesh size", 0.2);
  sc::core::validateParameters(meshList, *sc::mesh::MeshFactory::getValidParameters(), "consumer");
  auto mesh = sc::mesh::MeshFactory::build(meshList, 2)->mesh();
  const double measure = mesh->measure();
  std::cout << "consumer: half disc with " << mesh->numElements() << " triangles, measure "
            << measure << " (pi/2 = " << M_PI / 2 << ")" << std::endl;
  if (std::abs(measure - M_PI / 2) > 0.05 * M_PI / 2) return 1;
  sc::io::RunSummary summary(comm, ".", "consumer", material);
  summary.addCycle(0)["elements"] = mesh->numElements();
  summary.setConverged(true);
  summary.write();
  return 0;
}
