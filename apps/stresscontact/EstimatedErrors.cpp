#include "EstimatedErrors.hpp"

#include <cmath>
#include <map>

#include <sc/adapt/QuantityError.hpp>

#include "CycleResults.hpp"

namespace sc::app {

namespace {

using Json = nlohmann::ordered_json;

/// A width: the largest change over the last three cycles, × 1.5, at least the floor.
constexpr adapt::QuantityErrorSettings kWidthRule{3, 1.5, 0.0};

double norm(const std::vector<double>& v)
{
  double s = 0.0;
  for (double x : v)
    s += x * x;
  return std::sqrt(s);
}

/// The quantities of one cycle by name (contact keys of summary.json, "reaction:<part>").
std::map<std::string, double> quantitiesOf(const Json& c)
{
  std::map<std::string, double> q;
  if (c.contains("contact") && c["contact"].contains("force")) {
    const Json& ct = c["contact"];
    q["force"] = norm(ct["force"].get<std::vector<double>>());
    for (const char* key : {"half_width", "radius", "equivalent_half_width", "equivalent_radius",
                            "max_pressure", "stick_half_width", "stick_radius",
                            "equivalent_stick_half_width", "equivalent_stick_radius"})
      if (ct.contains(key) && ct[key].is_number()) q[key] = ct[key].get<double>();
  }
  if (c.contains("reactions"))
    for (const auto& [part, r] : c["reactions"].items())
      q["reaction:" + part] = norm(r["force"].get<std::vector<double>>());
  return q;
}

}  // namespace

EstimatedErrors estimateErrors(const Json& cycles, const CycleResults& r, int dim, bool friction,
                               int loadStep)
{
  EstimatedErrors out;
  if (!r.solved || !r.estimate) return out;
  // This cycle as summary.json will record it (the same names and norms as the history's).
  Json current;
  if (r.contact) {
    const auto& cs = r.contact->summary;
    current["contact"] = {
        {"force", std::vector<double>(cs.force.begin(), cs.force.begin() + dim)},
        {dim == 2 ? "half_width" : "radius", cs.zoneSize},
        {dim == 2 ? "equivalent_half_width" : "equivalent_radius", cs.equivalentZoneSize},
        {"max_pressure", cs.maxPressure},
        {dim == 2 ? "stick_half_width" : "stick_radius", cs.stickZoneSize},
        {dim == 2 ? "equivalent_stick_half_width" : "equivalent_stick_radius",
         cs.equivalentStickZoneSize}};
  }
  if (r.forces) current["reactions"] = r.forces->reactions;
  const auto now = quantitiesOf(current);

  // The earlier cycles of this load step, solved and estimated, in order.
  std::vector<std::pair<double, double>> dofsEta;  // per earlier cycle
  std::vector<std::map<std::string, double>> values;
  for (const Json& c : cycles) {
    const int step = c.contains("load_step") ? c["load_step"]["step"].get<int>() : 0;
    if (step != loadStep || !c.contains("dofs") || !c.contains("eta")) continue;
    dofsEta.emplace_back(c["dofs"]["total"].get<double>(), c["eta"]["total"].get<double>());
    values.push_back(quantitiesOf(c));
  }
  const auto estimate = [&](const std::string& name, double floor,
                            const adapt::QuantityErrorSettings& how) -> std::optional<double> {
    std::vector<adapt::QuantitySample> history;
    for (std::size_t i = 0; i < values.size(); ++i)
      if (const auto it = values[i].find(name); it != values[i].end())
        history.push_back({dofsEta[i].first, dofsEta[i].second, it->second});
    history.push_back({static_cast<double>(r.dofs.total), r.estimate->total(), now.at(name)});
    const double e = adapt::estimateQuantityError(history, floor, how);
    return e >= 0.0 ? std::optional<double>(e) : std::nullopt;
  };

  if (r.contact) {
    const auto& cs = r.contact->summary;
    // The zone's edge is resolved to about the gap between its two measures (the outermost
    // point in contact and the area's equivalent): a floor for both, which a staircase (the
    // width unchanged over cycles while the zone's points move) would otherwise estimate as 0.
    const double zoneFloor = std::abs(cs.zoneSize - cs.equivalentZoneSize);
    const double stickFloor = std::abs(cs.stickZoneSize - cs.equivalentStickZoneSize);
    const std::string width = dim == 2 ? "half_width" : "radius";
    const std::string stick = dim == 2 ? "stick_half_width" : "stick_radius";
    const auto add = [&](const std::string& key, double floor,
                         const adapt::QuantityErrorSettings& how) {
      out.contact.emplace_back(key, estimate(key, floor, how));
      return out.contact.back().second;
    };
    // The rates (docs/adaptivity.md "Error bars", chosen on the Hertz 2D runs of
    // docs/verification.md): the force, an integral of σ_h n, converges like η² (twice η's
    // rate in DOFs); the peak pressure, a point value, like η; the widths move in steps of the
    // contact faces at the zone's edge: their largest recent change, and the floor.
    const auto force = add("force", 0.0, {3, 2.0, 2.0});
    const auto zone = add(width, zoneFloor, kWidthRule);
    add("equivalent_" + width, zoneFloor, kWidthRule);
    const auto pressure = add("max_pressure", 0.0, {3, 2.0, 1.0});
    std::optional<double> stickError;
    if (friction) {
      stickError = add(stick, stickFloor, kWidthRule);
      add("equivalent_" + stick, stickFloor, kWidthRule);
    }
    const auto target = [&](const char* name, double value, const std::optional<double>& e) {
      out.targets.push_back({name, value, e ? *e : -1.0});
    };
    target("force", now.at("force"), force);
    target("width", cs.zoneSize, zone);
    target("pressure", cs.maxPressure, pressure);
    if (friction) target("stick width", cs.stickZoneSize, stickError);
  }
  for (const auto& [name, value] : now)
    if (name.rfind("reaction:", 0) == 0)
      out.reactions.emplace_back(name.substr(9), estimate(name, 0.0, {3, 2.0, 2.0}));
  return out;
}

}  // namespace sc::app
