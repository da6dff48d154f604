#include <sc/io/OutputSettings.hpp>

#include <sc/core/Error.hpp>
#include <sc/core/Parameters.hpp>

#include <algorithm>
#include <exception>

namespace sc::io {

Teuchos::RCP<const Teuchos::ParameterList> OutputSettings::getValidParameters()
{
  static Teuchos::RCP<const Teuchos::ParameterList> valid = [] {
    auto pl = Teuchos::rcp(new Teuchos::ParameterList(sublistName));
    pl->set<std::string>(
        "Directory", "output",
        "Directory for all output files (summary.json, XDMF/HDF5, CSV); created "
        "with its parents if missing. The command line option --output overrides it.");
    pl->set<std::string>("Base name", "solution",
                         "File name stem of the field output: <Base name>.xdmf and "
                         "<Base name>_c<NNNN>.h5 per adaptive cycle. No '/'.");
    pl->set<bool>("Write XDMF", true,
                  "Write the fields (stress, displacement, rotation, estimator, partition) as "
                  "XDMF + parallel HDF5 for ParaView, one step per adaptive cycle.");
    pl->set<bool>("Write contact CSV", true,
                  "Write contact_cycle<N>.csv with the contact-boundary quantities of each cycle.");
    sc::core::declareRealArray(
        *pl, "Moment point", Teuchos::tuple<double>(0.0, 0.0, 0.0),
        "The point x0 about which summary.json gives the moment of each reaction, the integral "
        "of (x - x0) x sigma n over the part (3 components x, y, z; in 2D z is not used and the "
        "moment is its z component).",
        {3});
    return Teuchos::RCP<const Teuchos::ParameterList>(pl);
  }();
  return valid;
}

OutputSettings::OutputSettings() : OutputSettings(Teuchos::ParameterList(sublistName)) {}

OutputSettings::OutputSettings(const Teuchos::ParameterList& outputSublist)
{
  Teuchos::ParameterList pl(outputSublist);
  try {
    pl.validateParametersAndSetDefaults(*getValidParameters());
  } catch (const std::exception& e) {
    // Teuchos' message names the key, the sublist and the valid keys.
    SC_THROW_IF(true, sc::core::InputError,
                "Invalid parameter in sublist \"" << sublistName << "\":\n"
                                                  << e.what());
  }
  *this = fromParameters(pl);
}

OutputSettings OutputSettings::fromParameters(const Teuchos::ParameterList& validatedOutput)
{
  const Teuchos::ParameterList& pl = validatedOutput;
  OutputSettings s{Unread{}};
  s.directory = pl.get<std::string>("Directory");
  s.baseName = pl.get<std::string>("Base name");
  s.writeXdmf = pl.get<bool>("Write XDMF");
  s.writeContactCsv = pl.get<bool>("Write contact CSV");
  const auto point = pl.get<Teuchos::Array<double>>("Moment point");
  std::copy(point.begin(), point.end(), s.momentPoint.begin());
  SC_THROW_IF(s.directory.empty(), sc::core::InputError,
              "Output/Directory is empty; give a directory such as \"output\"");
  SC_THROW_IF(s.baseName.empty() || s.baseName.find('/') != std::string::npos, sc::core::InputError,
              "Output/Base name = \"" << s.baseName
                                      << "\" is not valid: give a non-empty file name without '/'");
  return s;
}

}  // namespace sc::io
