#include "DeckParameters.hpp"

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include <sc/adapt/AdaptivitySettings.hpp>
#include <sc/contact/ContactSettings.hpp>
#include <sc/core/Error.hpp>
#include <sc/core/LoadSteps.hpp>
#include <sc/core/Parameters.hpp>
#include <sc/core/ProblemData.hpp>
#include <sc/estimator/EstimatorSettings.hpp>
#include <sc/io/OutputSettings.hpp>
#include <sc/mesh/MeshFactory.hpp>
#include <sc/solvers/LinearSolverFactory.hpp>

#ifndef SC_SOURCE_INPUT_DIR
#define SC_SOURCE_INPUT_DIR ""
#endif
#ifndef SC_INSTALL_INPUT_DIR
#define SC_INSTALL_INPUT_DIR ""
#endif
#ifndef SC_VERSION
#define SC_VERSION "unknown"
#endif

namespace sc::app {

std::string versionString() { return SC_VERSION; }

Teuchos::RCP<const Teuchos::ParameterList> getValidParameters()
{
  static Teuchos::RCP<const Teuchos::ParameterList> valid = [] {
    auto pl = Teuchos::rcp(new Teuchos::ParameterList("StressContact"));
    auto add = [&](const std::string& name, const Teuchos::RCP<const Teuchos::ParameterList>& sub,
                   const std::string& doc) { pl->set(name, *sub, doc); };
    add("Problem", core::ProblemSettings::getValidParameters(), "The problem: dimension, name.");
    add("Mesh", mesh::MeshFactory::getValidParameters(),
        "Initial mesh: a scene geometry or a Gmsh file, mesh size, refinements (docs/mesh.md).");
    add("Material", core::Material::getValidParameters(), "Isotropic linear elastic material.");
    add("Boundary Conditions", core::BoundaryConditions::getValidParameters(),
        "One sublist per boundary part of the mesh.");
    add("Body Force", core::BodyForce::getValidParameters(),
        "Body force f in div σ + f = 0, e.g. gravity (docs/user-guide.md \"Loads and supports\").");
    add("Contact", contact::ContactSettings::getValidParameters(),
        "Rigid obstacle and friction law, for boundary parts of Type Contact (docs/theory.md "
        "§\"Contact and friction\").");
    add("Load steps", core::LoadSteps::getValidParameters(),
        "Quasi-static load steps with friction on the slip increment (docs/theory.md "
        "§\"Load steps\"); none: one step at t = 1.");
    add("Discretization", core::DiscretizationSettings::getValidParameters(),
        "Finite element spaces (docs/theory.md §\"Mixed formulation\").");
    add("Linear Solver", solvers::LinearSolverFactory::getValidParameters(),
        "Linear solver of each (Newton) step (docs/theory.md §\"Linear solvers\").");
    add("Estimator", estimator::EstimatorSettings::getValidParameters(),
        "Reconstruction-based a posteriori error estimator (docs/theory.md).");
    add("Adaptivity", adapt::AdaptivitySettings::getValidParameters(),
        "Solve-estimate-mark-refine cycles (docs/theory.md).");
    add(io::OutputSettings::sublistName, io::OutputSettings::getValidParameters(),
        "Output files (docs/output.md).");
    return pl;
  }();
  return valid;
}

void printValidParameters(std::ostream& out)
{
  out << "StressContact " << versionString()
      << ": valid parameters of an input deck (Teuchos XML ParameterList).\n"
      << "Each key: type = default, then its documentation and valid values. A sublist\n"
      << "'<name>' stands for any number of sublists named by the user (boundary parts).\n";
  core::printParameterDocumentation(*getValidParameters(), out);
}

std::string defaultDeckPath()
{
  if (const char* env = std::getenv("STRESSCONTACT_DEFAULT_DECK")) return env;
  for (const std::string& dir :
       {std::string(SC_SOURCE_INPUT_DIR), std::string(SC_INSTALL_INPUT_DIR)})
    if (!dir.empty() && std::ifstream(dir + "/hertz2d.xml")) return dir + "/hertz2d.xml";
  SC_THROW_IF(true, core::InputError,
              "no input deck given and the default deck hertz2d.xml was found neither in '"
                  << SC_SOURCE_INPUT_DIR << "' nor in '" << SC_INSTALL_INPUT_DIR
                  << "'. Give a deck: stresscontact INPUT.xml");
  return "";
}

Teuchos::RCP<Teuchos::ParameterList> readAndValidateDeck(const std::string& path,
                                                         const std::vector<std::string>& overrides,
                                                         const std::string& outputDirectory)
{
  auto params = core::readParameterFile(path);
  const auto valid = getValidParameters();
  // Check the deck as written first, so errors name the deck; then the overrides.
  {
    Teuchos::ParameterList copy = *params;
    core::validateParameters(copy, *valid, "'" + path + "'");
  }
  // A mesh or geometry file named in the deck by a relative path is the deck's neighbour: it is
  // resolved against the deck's directory, so that the deck runs from any working directory. A
  // path given by --set is a shell path, relative to the working directory (docs/user-guide.md).
  if (params->isSublist("Mesh") && params->sublist("Mesh").isType<std::string>("File")) {
    const std::filesystem::path file = params->sublist("Mesh").get<std::string>("File");
    if (!file.empty() && file.is_relative())
      params->sublist("Mesh").set(
          "File", (std::filesystem::path(path).parent_path() / file).lexically_normal().string());
  }
  for (const auto& o : overrides)
    core::applyOverride(*params, *valid, o);
  if (!outputDirectory.empty())
    params->sublist(io::OutputSettings::sublistName).set("Directory", outputDirectory);
  core::validateParameters(*params, *valid, "'" + path + "' with command-line overrides");
  return params;
}

}  // namespace sc::app
