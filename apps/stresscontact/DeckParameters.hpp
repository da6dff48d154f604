#pragma once
// The master parameter list of the application: one sublist per component, each taken from that
// component's getValidParameters(). This file is the only place that knows which components
// make up a run.
#include <ostream>
#include <string>
#include <vector>

#include <Teuchos_ParameterList.hpp>
#include <Teuchos_RCP.hpp>

namespace sc::app {

std::string versionString();

/// The complete valid list (cached): Problem, Mesh, Material, Boundary Conditions, Contact,
/// Discretization, Linear Solver, Estimator, Adaptivity, Output.
Teuchos::RCP<const Teuchos::ParameterList> getValidParameters();

/// `stresscontact --print-parameters`.
void printValidParameters(std::ostream& out);

/// The deck run without arguments: $STRESSCONTACT_DEFAULT_DECK, else the source tree's
/// input/hertz2d.xml, else the installed share/stresscontact/input/hertz2d.xml.
std::string defaultDeckPath();

/// Read `path`, apply `--set` overrides and `--output`, validate everything and fill defaults.
/// Throws sc::core::InputError naming the file, the key, the value and what would be valid.
Teuchos::RCP<Teuchos::ParameterList> readAndValidateDeck(const std::string& path,
                                                         const std::vector<std::string>& overrides,
                                                         const std::string& outputDirectory);

}  // namespace sc::app
