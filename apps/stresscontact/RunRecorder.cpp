#include "RunRecorder.hpp"

#include <cmath>
#include <cstdio>
#include <iomanip>
#include <sstream>

#include <sc/io/CsvWriter.hpp>
#include <sc/io/HistoryTable.hpp>
#include <sc/io/RunSummary.hpp>

namespace sc::app {

RunRecorder::RunRecorder(const Teuchos::Comm<int>& comm, const core::Progress& progress,
                         io::RunSummary& summary, std::string directory, int dim, bool hasContact)
    : comm_(comm), progress_(progress), summary_(summary), directory_(std::move(directory)),
      dim_(dim), hasContact_(hasContact)
{
}

void RunRecorder::writeContactTable(const CycleResults& results) const
{
  if (!results.contact) return;
  const auto header = contact::csvColumns(dim_);
  io::CsvWriter csv(header);
  for (const auto& p : results.contact->points) {
    // Filled by index, not push_back: GCC 12 warns (-Wmaybe-uninitialized, a false positive)
    // about moving std::variant<double, std::string> when a vector of them grows.
    io::CsvWriter::Row row(header.size());
    std::size_t col = 0;
    for (double v : contact::csvValues(p, dim_))
      row[col++] = v;
    row[col] = contact::toString(p.status);
    csv.addRow(std::move(row));
  }
  char name[64];
  std::snprintf(name, sizeof(name), "/contact_cycle%d.csv", results.cycle);
  csv.writeGathered(comm_, directory_ + name);
}

void RunRecorder::recordCycle(const CycleResults& results, const adapt::Marking& marking,
                              const std::string& stopReason)
{
  const int d = dim_;
  nlohmann::ordered_json& c = summary_.addCycle(results.cycle);
  c["elements"] = results.mesh.elements;
  if (results.contact) {
    const auto& cs = results.contact->summary;
    const auto& st = results.contact->statistics;
    std::vector<double> force(cs.force.begin(), cs.force.begin() + d);
    c["contact"] = {
        {"force", force},
        {d == 2 ? "half_width" : "radius", cs.zoneSize},
        {"max_pressure", cs.maxPressure},
        {"min_pressure", cs.minPressure},
        {"area", cs.area},
        {"stick_area", cs.stickArea},
        {d == 2 ? "stick_half_width" : "stick_radius", cs.stickZoneSize},
        {d == 2 ? "equivalent_half_width" : "equivalent_radius", cs.equivalentZoneSize},
        {d == 2 ? "equivalent_stick_half_width" : "equivalent_stick_radius",
         cs.equivalentStickZoneSize},
        {"points", {{"free", cs.numFree}, {"stick", cs.numStick}, {"slip", cs.numSlip}}},
        {"newton_iterations", st.newtonIterations},
        {"cycle_remedies", st.remedies},
        {"fixed_point_iterations", st.fixedPointIterations}};
    // 2D: the resolution of the outermost-point widths (docs/output.md "Error bars"; in 3D the
    // gap to the next point outside does not bound a ragged edge's radius).
    if (d == 2) {
      c["contact"]["half_width_resolution"] = cs.zoneResolution;
      c["contact"]["stick_half_width_resolution"] = cs.stickZoneResolution;
      // The half-width from the pressure profile at the zone's ends (contact::ContactSummary).
      c["contact"]["fitted_half_width"] = cs.fittedZoneSize > 0.0
                                              ? nlohmann::ordered_json(cs.fittedZoneSize)
                                              : nlohmann::ordered_json(nullptr);
    }
    // Hertz's values from the computed load (contact/Hertz.hpp): the ratios say how close the
    // run is.
    if (const auto& h = results.contact->hertz)
      c["contact"]["hertz"] = {{d == 2 ? "half_width" : "radius", h->reference.halfWidth},
                               {"max_pressure", h->reference.maxPressure},
                               {d == 2 ? "half_width_ratio" : "radius_ratio", h->zoneSizeRatio},
                               {"max_pressure_ratio", h->maxPressureRatio}};
    // Contact/Newton/Stopping = Balanced (contact/BalancedStopping.hpp), when the rule applied.
    if (st.balancedBound > 0.0)
      c["contact"]["balanced"] = {{"bound", st.balancedBound},
                                  {"krylov_tolerance", st.krylovTolerance},
                                  {"algebraic_error", st.algebraicError}};
    c["nonlinear_iterations"] = st.newtonIterations;
    std::ostringstream os;
    os << "force (" << force[0] << ", " << force[1]
       << (d == 3 ? ", " + std::to_string(force[2]) : "") << "), "
       << (d == 2 ? "half-width " : "radius ") << cs.zoneSize << " (from the area "
       << cs.equivalentZoneSize << "), max pressure " << cs.maxPressure << ", stick "
       << cs.stickZoneSize << " (" << cs.numStick << " stick, " << cs.numSlip << " slip points)";
    progress_.report("contact", os.str());
    // The error bars (docs/output.md "Error bars"): null until the history has an estimate.
    if (const auto& ee = results.estimatedErrors) {
      auto& j = c["contact"]["estimated_error"];
      j = nlohmann::ordered_json::object();
      std::ostringstream eb;
      eb.precision(3);
      for (const auto& [key, e] : ee->contact) {
        j[key] = e ? nlohmann::ordered_json(*e) : nlohmann::ordered_json(nullptr);
        if (key.rfind("equivalent_", 0) == 0) continue;  // in summary.json only
        eb << (eb.tellp() > 0 ? ", " : "") << key;
        if (e)
          eb << " ± " << *e;
        else
          eb << " (none yet)";
      }
      progress_.report("error bars", eb.str());
    }
  }
  if (const auto& estimate = results.estimate) {
    auto& eta = c["eta"];
    eta["total"] = estimate->total();
    for (const auto& p : estimate->parts)
      eta[p.first] = std::sqrt(p.second);
    for (const auto& p : estimate->diagnostics)
      eta[p.first] = p.second;  // signed, in the units of η² (not a root)
    eta["stress_energy_norm"] = estimate->stressEnergyNorm;
    eta["relative"] =
        estimate->stressEnergyNorm > 0.0 ? estimate->total() / estimate->stressEnergyNorm : 0.0;
    if (results.stressEnergyError >= 0.0) {
      eta["stress_energy_error"] = results.stressEnergyError;
      eta["efficiency_index"] = estimate->total() / results.stressEnergyError;
    }
    if (!marking.uniform && stopReason.empty()) eta["marked_elements"] = marking.elements.size();
  }
  if (!stopReason.empty()) c["stop_reason"] = stopReason;
  // The accuracy targets against this cycle's error bars (docs/adaptivity.md).
  if (!results.targets.empty()) {
    auto& t = c["accuracy_targets"];
    t = nlohmann::ordered_json::array();
    for (const auto& s : results.targets)
      t.push_back({{"quantity", s.name},
                   {"key", s.key},
                   {"target", s.target},
                   {"estimated_relative_error", s.relativeError >= 0.0
                                                    ? nlohmann::ordered_json(s.relativeError)
                                                    : nlohmann::ordered_json(nullptr)},
                   {"met", s.met}});
  }
  if (results.solved) {
    // Reactions and the force balance, with the contact force recorded above (docs/output.md).
    c["reactions"] = results.forces->reactions;
    if (const auto& ee = results.estimatedErrors)
      for (const auto& [part, e] : ee->reactions)
        c["reactions"][part]["estimated_error"] = {
            {"force", e ? nlohmann::ordered_json(*e) : nlohmann::ordered_json(nullptr)}};
    c["force_balance"] = results.forces->balance;
    c["dofs"] = {{"stress", results.dofs.stress},
                 {"displacement", results.dofs.displacement},
                 {"rotation", results.dofs.rotation},
                 {"total", results.dofs.total}};
    const auto& ls = *results.linearSolve;
    // One linear solve per Newton step (1 without contact); Krylov iterations per solve.
    c["linear_solves"] = ls.solves;
    if (ls.iterative) {
      long long total = ls.finalSolveIterations;
      for (int it : ls.iterationsPerSolve)
        total += it;
      c["linear_iterations"] = {{"per_solve", ls.iterationsPerSolve},
                                {"final_solve", ls.finalSolveIterations},
                                {"total", total}};
    } else {
      c["linear_iterations"] = nullptr;
    }
    c["linear_solver"] = {{"type", ls.name},
                          {"relative_residual", ls.last.relativeResidual},
                          {"symbolic_reuses", ls.symbolicReuses},
                          {"factor_nonzeros", ls.last.factorNonzeros}};
    if (!ls.iterative)
      c["linear_solver"]["seconds"] = {{"equilibration", ls.cycleEquilibrationSeconds},
                                       {"analysis", ls.cycleSymbolicSeconds},
                                       {"factorization", ls.cycleNumericSeconds},
                                       {"triangular_solves", ls.cycleSolveSeconds}};
    if (ls.last.mumpsMemoryMaxMB >= 0.0)
      c["linear_solver"]["mumps_memory_mb"] = {
          {"estimated_max", ls.last.mumpsEstimatedMemoryMaxMB},
          {"estimated_sum", ls.last.mumpsEstimatedMemoryTotalMB},
          {"used_max", ls.last.mumpsMemoryMaxMB},
          {"used_sum", ls.last.mumpsMemoryTotalMB}};
    if (ls.iterative) {
      c["linear_solver"]["preconditioner_setups"] = ls.preconditionerSetups;
      c["linear_solver"]["preconditioner_seconds_last"] = ls.last.preconditionerSeconds;
    }
    if (const auto& e = results.errors) {
      c["errors"] = {{"stress_l2", e->stress},
                     {"stress_div_l2", e->stressDiv},
                     {"displacement_l2", e->displacement},
                     {"rotation_l2", e->rotation},
                     {"stress_l2_relative", e->stress / e->stressNorm},
                     {"displacement_l2_relative", e->displacement / e->displacementNorm}};
      std::ostringstream os;
      os << "|σ−σh| = " << e->stress << ", |div(σ−σh)| = " << e->stressDiv
         << ", |u−uh| = " << e->displacement << ", |θ−θh| = " << e->rotation;
      progress_.report("errors", os.str());
    }
  }
  const auto& m = results.mesh;
  c["mesh"] = {{"vertices", m.vertices},
               {"elements", m.elements},
               {"measure", m.measure},
               {"geometry_order", m.geometryOrder},
               {"curved_elements", m.curvedElements},
               {"min_angle_deg", m.minAngleDeg}};
  c["mesh"]["elements_per_rank"] = m.elementsPerRank;
}

void RunRecorder::recordCost(const CycleResults& results,
                             const std::map<std::string, double>& timings,
                             const core::PhaseTimers::PeakMemory& memory)
{
  auto& c = summary_.currentCycle();
  c["timings"] = timings;
  c["memory"] = {{"peak_rss_max_mb", memory.maxMB}, {"peak_rss_sum_mb", memory.sumMB}};
  // The cycle's one-line summary: size, η, Newton steps, seconds per phase, peak memory.
  std::ostringstream os;
  os << std::setprecision(4);
  if (results.solved) os << results.dofs.total << " DOFs, ";
  if (results.estimate) os << "eta " << results.estimate->total() << ", ";
  if (results.contact) os << results.contact->statistics.newtonIterations << " Newton steps, ";
  os << forcesBrief(c);
  os << std::fixed << std::setprecision(3);
  double total = 0.0;
  for (const auto& [phase, seconds] : timings)
    total += seconds;
  os << "seconds " << total << " (";
  bool first = true;
  for (const char* phase :
       {"solve", "reconstruct", "estimate", "mark", "refine", "transfer", "output"}) {
    const auto it = timings.find(phase);
    if (it == timings.end()) continue;
    os << (first ? "" : ", ") << phase << " " << it->second;
    first = false;
  }
  os << "), peak memory " << std::setprecision(0) << memory.maxMB << " MB";
  if (comm_.getSize() > 1)
    os << " per rank, " << memory.sumMB << " MB on all " << comm_.getSize() << " ranks";
  progress_.report("cycle summary", os.str());
}

void RunRecorder::write()
{
  summary_.write();
  io::writeHistory(comm_, directory_, summary_.json()["cycles"], dim_, hasContact_);
}

std::string RunRecorder::recordStop(const std::string& stopReason,
                                    const adapt::AdaptivitySettings& adaptivity)
{
  // Why the run stopped, and with accuracy targets or a time budget whether the targets were
  // met (docs/adaptivity.md "Accuracy targets and a time budget").
  auto& stop = summary_.json()["stop"];
  stop = {{"reason", stopReason}};
  std::string outcome;
  if (adaptivity.hasQuantityTargets() || adaptivity.timeBudget > 0.0) {
    const bool met = stopReason.rfind("accuracy targets met", 0) == 0;
    const bool budget = stopReason.rfind("time budget", 0) == 0;
    stop["accuracy_targets_met"] = adaptivity.hasQuantityTargets()
                                       ? nlohmann::ordered_json(met)
                                       : nlohmann::ordered_json(nullptr);
    stop["time_budget_reached"] = budget;
    outcome = met      ? " (accuracy targets met)"
              : budget ? (adaptivity.hasQuantityTargets()
                              ? " (best within the time budget; accuracy targets not met)"
                              : " (best within the time budget)")
                       : (adaptivity.hasQuantityTargets() ? " (accuracy targets not met)" : "");
  }
  return outcome;
}

}  // namespace sc::app
