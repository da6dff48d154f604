#include "EstimatedErrors.hpp"

#include <cmath>
#include <map>

#include <sc/adapt/QuantityError.hpp>

#include "CycleResults.hpp"

namespace sc::app {

namespace {

using Json = nlohmann::ordered_json;

/// A width in 3D, or in 2D without a resolution (no point outside the zone): the largest change
/// over the last three cycles, × 1.5, at least the floor.
constexpr adapt::QuantityErrorSettings kWidthRule{3, 1.5, 0.0};
/// A 2D width with a resolution r (contact::ContactSummary: half the gap between the outermost
/// point in the zone and the next point outside, the mean of the two ends): 1.5 r. The midpoint
/// is within r of an edge anywhere between the two points; the factor covers the edge's own
/// discretisation error, calibrated on Hertz 2D Coulomb ν = 0.28 (its largest true error over r
/// in cycles 3–16 is 1.34, the stick zone's) and validated on the other scenes
/// (docs/verification.md "Error bars"). Not in 3D: the next point outside the outermost one lies
/// on another ray of a ragged edge, and r does not bound the radius's error there (Hertz 3D:
/// true errors up to 21 r).
constexpr double kResolutionFactor = 1.5;
/// A load (the contact force, a reaction): extrapolated like η² over the last five cycles, × 2.
/// Five, not three: under Dörfler marking a load's error can stay on a plateau for a few cycles
/// while η decreases (the manufactured solution's Bottom reaction: −2.5e-4 from cycle 3 to 7),
/// which three cycles' changes do not see; calibrated there (the smallest window with at most
/// one of its 20 ratios below 1) and validated on the Hertz scenes (docs/verification.md "Error
/// bars").
constexpr adapt::QuantityErrorSettings kLoadRule{5, 2.0, 2.0};
/// The fitted half-width (2D, contact::ContactSummary::fittedZoneSize): not bound to the point
/// spacing, it moves by less than the outermost point; extrapolated like η over the last three
/// cycles, × 2, as the peak pressure (like η², as the load, it fell under the true error in 4
/// Coulomb cycles, where the fit's own bias at the slip zone's edge decays slowly; validated on
/// the four Hertz 2D scenes, docs/verification.md "Error bars").
constexpr adapt::QuantityErrorSettings kFittedRule{3, 2.0, 1.0};

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
    for (const char* key :
         {"half_width", "radius", "equivalent_half_width", "equivalent_radius", "max_pressure",
          "stick_half_width", "stick_radius", "equivalent_stick_half_width",
          "equivalent_stick_radius", "fitted_half_width"})
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
    if (cs.fittedZoneSize > 0.0) current["contact"]["fitted_half_width"] = cs.fittedZoneSize;
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
    // A width: in 2D from its resolution where it has one, once the history gives error bars at
    // all (from cycle 1 on, as every other quantity).
    const auto addWidth = [&](const std::string& key, double floor, double resolution) {
      auto e = estimate(key, floor, kWidthRule);
      if (e && dim == 2 && resolution > 0.0) e = kResolutionFactor * resolution;
      out.contact.emplace_back(key, e);
      return e;
    };
    // The rates (docs/output.md "Error bars", chosen on the Hertz 2D runs of
    // docs/verification.md): the force, an integral of σ_h n, converges like η² (twice η's
    // rate in DOFs; kLoadRule); the peak pressure, a point value, like η; the widths move in steps
    // of the points at the zone's edge: in 2D 1.5 × their resolution (both measures of a zone: the
    // area's moves by the same points' shares), else their largest recent change and the floor.
    const auto force = add("force", 0.0, kLoadRule);
    const auto zone = addWidth(width, zoneFloor, cs.zoneResolution);
    addWidth("equivalent_" + width, zoneFloor, cs.zoneResolution);
    const auto pressure = add("max_pressure", 0.0, {3, 2.0, 1.0});
    // 2D: the half-width fitted to the pressure profile at the zone's ends (kFittedRule).
    std::optional<double> fitted;
    if (now.count("fitted_half_width")) fitted = add("fitted_half_width", 0.0, kFittedRule);
    std::optional<double> stickError;
    if (friction) {
      stickError = addWidth(stick, stickFloor, cs.stickZoneResolution);
      addWidth("equivalent_" + stick, stickFloor, cs.stickZoneResolution);
    }
    const auto target = [&](const char* name, double value, const std::optional<double>& e) {
      out.targets.push_back({name, value, e ? *e : -1.0});
    };
    target("force", now.at("force"), force);
    // The width target: the half-width measure the run knows best (the smaller relative error
    // bar of the outermost-point and the fitted half-width, docs/adaptivity.md).
    if (fitted && (!zone || *fitted / cs.fittedZoneSize < *zone / cs.zoneSize))
      target("width", cs.fittedZoneSize, fitted);
    else
      target("width", cs.zoneSize, zone);
    target("pressure", cs.maxPressure, pressure);
    if (friction) target("stick width", cs.stickZoneSize, stickError);
  }
  for (const auto& [name, value] : now)
    if (name.rfind("reaction:", 0) == 0)
      out.reactions.emplace_back(name.substr(9), estimate(name, 0.0, kLoadRule));
  return out;
}

}  // namespace sc::app
