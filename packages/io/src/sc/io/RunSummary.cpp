#include <sc/io/RunSummary.hpp>

#include <sc/io/AtomicFile.hpp>
#include <sc/core/Collective.hpp>
#include <sc/io/ParameterListJson.hpp>

#include <sc/core/Error.hpp>

#include <filesystem>

namespace sc::io {

using Json = nlohmann::ordered_json;

RunSummary::RunSummary(Teuchos::RCP<const Teuchos::Comm<int>> comm, const std::string& directory,
                       const std::string& version, const Teuchos::ParameterList& parameters)
    : comm_(std::move(comm)), path_((std::filesystem::path(directory) / "summary.json").string())
{
  SC_THROW_IF(comm_.is_null(), sc::core::InternalError, "RunSummary: null communicator");
  // Key order is the schema order of docs/output.md.
  json_["code"] = Json{{"name", "StressContact"}, {"version", version}};
  json_["parameters"] = toJson(parameters);
  json_["ranks"] = comm_->getSize();
  json_["converged"] = false;
  json_["cycles"] = Json::array();
  json_["error"] = nullptr;
}

Json RunSummary::makeCycleEntry(int cycle)
{
  Json c;
  c["cycle"] = cycle;
  c["elements"] = nullptr;
  c["dofs"] = Json{
      {"stress", nullptr}, {"displacement", nullptr}, {"rotation", nullptr}, {"total", nullptr}};
  c["mesh"] = Json{{"vertices", nullptr},
                   {"elements", nullptr},
                   {"measure", nullptr},
                   {"min_angle_deg", nullptr}};
  c["eta"] = Json::object();
  c["errors"] = Json::object();
  c["contact"] = Json::object();
  c["reactions"] = Json::object();
  c["force_balance"] = Json::object();
  c["nonlinear_iterations"] = nullptr;
  c["linear_solves"] = nullptr;
  c["linear_iterations"] = nullptr;
  c["timings"] = Json::object();
  c["memory"] = Json::object();
  return c;
}

Json& RunSummary::addCycle(int cycle)
{
  json_["cycles"].push_back(makeCycleEntry(cycle));
  return json_["cycles"].back();
}

Json& RunSummary::currentCycle()
{
  SC_THROW_IF(json_["cycles"].empty(), sc::core::InternalError,
              "RunSummary::currentCycle: no cycle added yet");
  return json_["cycles"].back();
}

void RunSummary::setConverged(bool converged) { json_["converged"] = converged; }

void RunSummary::setError(const std::string& message)
{
  json_["converged"] = false;
  json_["error"] = message;
}

void RunSummary::writeLocal() const
{
  if (comm_->getRank() != 0) return;
  // Replace invalid UTF-8 (e.g. from a system error message) instead of throwing: the summary
  // is also written from error handlers and must not fail there.
  writeFileAtomically(path_, json_.dump(2, ' ', false, Json::error_handler_t::replace) + "\n");
}

void RunSummary::write() const
{
  core::runOnRoot(*comm_, [this] { writeLocal(); });
}

}  // namespace sc::io
