// Checkpoint/restart of adaptive runs (docs/adaptivity.md "Checkpoint and
// restart"). After every complete cycle N the run writes <output>/checkpoint.h5 (atomically):
// the mesh of cycle N with the refiner's bisection state, the elements marked for cycle N+1, the
// contact points of cycle N (the next cycle's start), the summary's cycle records, the XDMF
// steps, the run's parameters, and the load step of cycle N (docs/theory.md §"Load steps") with
// the contact points' friction history. Besides after every cycle that goes on, it is written
// after the last cycle of every load step but the last, so that a run stopped after a step
// continues with the next. `--restart DIR` reads it, checks the parameters, and goes on with
// cycle N+1, which then refines (or, first in its load step, commits the friction history),
// solves and writes as the uninterrupted run would have.
#include "Simulation.hpp"

#include <algorithm>
#include <cmath>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <map>
#include <sstream>

#include <Teuchos_CommHelpers.hpp>

#include <nlohmann/json.hpp>

#include <sc/solvers/StressHierarchy.hpp>
#include <sc/contact/ActiveSetSolver.hpp>
#include <sc/contact/ContactProblem.hpp>
#include <sc/contact/ContactSummary.hpp>
#include <sc/core/Collective.hpp>
#include <sc/core/Error.hpp>
#include <sc/io/CheckpointFile.hpp>
#include <sc/io/HistoryTable.hpp>
#include <sc/io/ParameterListJson.hpp>
#include <sc/io/RunSummary.hpp>
#include <sc/io/XdmfWriter.hpp>
#include <sc/mesh/BisectionRefiner.hpp>
#include <sc/mesh/SimplexMesh.hpp>

#include "DeckParameters.hpp"

namespace sc::app {

namespace {

using Json = nlohmann::ordered_json;

// Bumped when the content changes meaning; a checkpoint of another version is refused.
// 3: a contact point's face by its vertices (face numbers of the initial mesh and of the same
// mesh rebuilt from the refiner's state differ).
// 4: the load step of the cycle (load_step, load_step_time, load_step_first_cycle,
// load_step_complete) and each contact point's weight, centroid, friction history, r_T and
// tangents (what the next cycle's transfer and the next step's commit read).
// 5: each contact point's r_N (the next step's commit makes it the previous step's r_N, from
// which the step's first Newton update measures penetration).
constexpr long long kCheckpointVersion = 5;

// A contact point in the checkpoint (d = dimension): x (d), status, slip direction (2), index in
// its face, the face's sorted vertices (d), weight, centroid (d), history (d), r_T (2), r_N,
// t1 (d), t2 (d).
int contactPointStride(int d) { return 6 * d + 8; }

std::string checkpointPath(const std::string& directory)
{
  return (std::filesystem::path(directory) / "checkpoint.h5").string();
}

void flatten(const Json& j, const std::string& prefix, std::map<std::string, std::string>& out)
{
  if (j.is_object() && !j.empty()) {
    for (const auto& item : j.items())
      flatten(item.value(), prefix.empty() ? item.key() : prefix + "/" + item.key(), out);
  } else {
    out[prefix] = j.dump();
  }
}

// The parameters in which two runs differ, "" if none. Output/Directory may differ (the run is
// restarted in the directory it wrote, however that was named).
std::string parameterDifferences(const Json& saved, const Json& current)
{
  std::map<std::string, std::string> a, b;
  flatten(saved, "", a);
  flatten(current, "", b);
  a.erase("Output/Directory");
  b.erase("Output/Directory");
  std::ostringstream os;
  int count = 0;
  auto note = [&](const std::string& key, const std::string& there, const std::string& here) {
    if (count++ < 8)
      os << (count > 1 ? "; " : "") << "'" << key << "' is " << there << " in the checkpoint and "
         << here << " in this run";
  };
  for (const auto& [key, value] : a) {
    auto it = b.find(key);
    if (it == b.end())
      note(key, value, "absent");
    else if (it->second != value)
      note(key, value, it->second);
  }
  for (const auto& [key, value] : b)
    if (!a.count(key)) note(key, "absent", value);
  if (count > 8) os << "; and " << (count - 8) << " more";
  return os.str();
}

template <class T>
std::vector<T> narrow(const std::vector<long long>& v)
{
  return std::vector<T>(v.begin(), v.end());
}

}  // namespace

void Simulation::writeCheckpoint(int cycle, const std::vector<int>& marked, bool stepComplete)
{
  // Timed by checkpoint() as the cycle's "checkpoint" phase, which summary.json shows from its next
  // write on (the checkpoint copies the cycle's record before its own time is known).
  // The contact points of this cycle, every rank's in rank order, with their face (in the mesh
  // of this cycle, which the checkpoint holds) and index in it: on restart rank 0 holds them all,
  // and ActiveSetSolver::transferState carries them to cycle N+1 through the refinement of the
  // restored mesh, as in the uninterrupted run, whatever the rank count. The face is stored by
  // its sorted vertices, which the restored mesh keeps: its face numbers are its own (the mesh
  // of cycle 0, straight from Gmsh, numbers its faces otherwise than the same mesh rebuilt from
  // the refiner's state, which made every contact run killed in cycle 1 unrestartable).
  // With load steps a point also carries what friction on the slip increment needs: its history
  // r_T^{n-1} with its weight and centroid (ActiveSetSolver::transferState places it on refined
  // faces), and its r_T, r_N and tangents (contact::commitLoadStep makes them the next step's
  // history, and r_N its previousRN). All exact doubles: the restarted run computes the same
  // numbers.
  const int d = settings_.problem.dimension;
  std::vector<double> mine;
  static const std::vector<contact::ContactPoint> none;
  for (const auto& p : contactProblem_ ? contactProblem_->points() : none) {
    mine.insert(mine.end(), p.x.begin(), p.x.begin() + d);
    mine.push_back(static_cast<double>(p.status));
    mine.push_back(p.direction[0]);
    mine.push_back(p.direction[1]);
    mine.push_back(static_cast<double>(p.index));
    std::vector<int> v(mesh_->faceVertices(p.face), mesh_->faceVertices(p.face) + d);
    std::sort(v.begin(), v.end());
    for (int x : v)
      mine.push_back(static_cast<double>(x));
    mine.push_back(p.weight);
    mine.insert(mine.end(), p.centroid.begin(), p.centroid.begin() + d);
    mine.insert(mine.end(), p.history.begin(), p.history.begin() + d);
    mine.push_back(p.rT[0]);
    mine.push_back(p.rT[1]);
    mine.push_back(p.rN);
    mine.insert(mine.end(), p.t1.begin(), p.t1.begin() + d);
    mine.insert(mine.end(), p.t2.begin(), p.t2.begin() + d);
  }
  std::vector<double> points = core::gatherAllConcatenated(*comm_, mine);

  core::runOnRoot(*comm_, [&] {
    io::CheckpointFile cp;
    cp.setInts("checkpoint_version", {kCheckpointVersion});
    cp.setString("code_version", versionString());
    cp.setString("deck", deckPath_);
    cp.setString("parameters", io::toJson(*params_).dump());
    cp.setInts("ranks", {comm_->getSize()});
    cp.setInts("cycle", {cycle});
    // The load step of this cycle (0-based), its time, the number of its first cycle, and
    // whether this cycle was its last (the next cycle starts the next step).
    cp.setInts("load_step", {loadStep_});
    cp.setDoubles("load_step_time", {settings_.loadSteps.times[loadStep_]});
    cp.setInts("load_step_first_cycle", {stepFirstCycle_});
    cp.setInts("load_step_complete", {stepComplete ? 1 : 0});

    const auto s = refiner_->state();
    cp.setInts("mesh_dimension", {s.dim});
    cp.setInts("mesh_elements", {mesh_->numElements()});
    cp.setInts("mesh_vertices", {mesh_->numVertices()});
    cp.setString("mesh_boundary_names", Json(mesh_->boundaryNames()).dump());
    cp.setDoubles("mesh_coordinates", s.coordinates);
    cp.setInts("mesh_element_vertices", {s.elementVertices.begin(), s.elementVertices.end()});
    cp.setInts("mesh_generations", {s.generations.begin(), s.generations.end()});
    cp.setInts("mesh_codes", {s.codes.begin(), s.codes.end()});
    cp.setInts("mesh_boundary_edges", {s.boundaryEdges.begin(), s.boundaryEdges.end()});
    cp.setInts("mesh_boundary_edge_parts",
               {s.boundaryEdgeParts.begin(), s.boundaryEdgeParts.end()});
    cp.setInts("mesh_boundary_faces", {s.boundaryFaces.begin(), s.boundaryFaces.end()});
    cp.setInts("mesh_boundary_face_parts",
               {s.boundaryFaceParts.begin(), s.boundaryFaceParts.end()});
    cp.setInts("mesh_curved_edges", {s.curvedEdges.begin(), s.curvedEdges.end()});
    cp.setInts("mesh_curved_edge_parts", {s.curvedEdgeParts.begin(), s.curvedEdgeParts.end()});

    cp.setInts("marked_elements", {marked.begin(), marked.end()});
    cp.setInts("contact_point_stride", {contactPointStride(d)});
    cp.setDoubles("contact_points", std::move(points));

    cp.setString("summary_cycles", summary_->json()["cycles"].dump());
    Json steps = Json::array();
    if (writer_)
      for (const auto& st : writer_->steps())
        steps.push_back({{"cycle", st.cycle}, {"time", st.time}, {"xml", st.xml}});
    cp.setString("xdmf_steps", steps.dump());
    cp.write(checkpointPath(settings_.output.directory));
  });
}

int Simulation::readCheckpoint(std::vector<int>& marked)
{
  const std::string path = checkpointPath(restartDirectory_);
  // A run killed in cycle 0 wrote no checkpoint (none is written before a cycle is complete) but
  // may have written that cycle's fields: nothing to continue, so the restart is the run itself,
  // from cycle 0, which replaces those files as any run replaces an earlier run's. A directory
  // without any file of a run is still an error (a mistyped --restart DIR).
  {
    namespace fs = std::filesystem;
    const fs::path dir(restartDirectory_);
    std::error_code ec;
    const bool killedInCycleZero =
        !fs::exists(path, ec) &&
        (fs::exists(dir / (settings_.output.baseName + "_c0000.h5"), ec) ||
         fs::exists(dir / (settings_.output.baseName + ".xdmf"), ec) ||
         fs::exists(dir / "contact_cycle0.csv", ec) || fs::exists(dir / "summary.json", ec));
    if (killedInCycleZero) {
      progress_.message("restart: " + restartDirectory_ +
                        " holds no checkpoint.h5 but files of a run "
                        "killed in cycle 0, before its first complete cycle: running from cycle 0");
      marked.clear();
      return 0;
    }
  }
  // Every rank reads the file (read-only): the data are global.
  checkpoint_ = std::make_unique<io::CheckpointFile>(io::CheckpointFile::read(path));
  const io::CheckpointFile& cp = *checkpoint_;
  auto bad = [&](const std::string& why) {
    SC_THROW_IF(true, core::InputError, "the checkpoint '" << path << "' " << why);
  };
  auto scalar = [&](const std::string& name) {
    const auto& v = cp.ints(name);
    if (v.size() != 1) bad("has a dataset '" + name + "' that is not a single number (damaged)");
    return v[0];
  };
  if (scalar("checkpoint_version") != kCheckpointVersion)
    bad("has 'checkpoint_version' = " + std::to_string(scalar("checkpoint_version")) +
        "; this build reads version " + std::to_string(kCheckpointVersion) +
        (scalar("checkpoint_version") < 4
             ? " (from version 4 on the checkpoint keeps the load step "
               "and the contact points' friction history)"
             : "") +
        ": restart with the build that wrote it, or run the deck again from the start");
  if (cp.string("code_version") != versionString())
    bad("was written by StressContact " + cp.string("code_version") + ", this is " +
        versionString() + ": restart with the version that wrote it, or run the deck again");

  Json saved;
  try {
    saved = Json::parse(cp.string("parameters"));
  } catch (const std::exception&) {
    bad("has parameters that are not valid JSON (damaged)");
  }
  const std::string diff = parameterDifferences(saved, io::toJson(*params_));
  if (!diff.empty())
    bad("belongs to a run with other parameters: " + diff + ". A restart takes the deck and the " +
        "--set options of the run it continues (only the output directory may differ).");

  const int cycle = static_cast<int>(scalar("cycle"));
  const int ranksBefore = static_cast<int>(scalar("ranks"));
  if (cycle < 0) bad("has a negative cycle (damaged)");
  // The load step of that cycle. The deck's Load steps equal the checkpoint's (the parameters
  // were compared above); the step and its time are checked against them all the same.
  const int step = static_cast<int>(scalar("load_step"));
  const int stepFirstCycle = static_cast<int>(scalar("load_step_first_cycle"));
  const bool stepComplete = scalar("load_step_complete") != 0;
  if (step < 0 || step >= settings_.loadSteps.numSteps())
    bad("is of load step " + std::to_string(step + 1) + ", but 'Load steps/Times' has " +
        std::to_string(settings_.loadSteps.numSteps()) + " step(s)");
  if (cp.doubles("load_step_time").size() != 1 ||
      cp.doubles("load_step_time")[0] != settings_.loadSteps.times[step])
    bad("is of load step " + std::to_string(step + 1) +
        " at another time than 'Load steps/Times' gives it");
  if (stepFirstCycle < 0 || stepFirstCycle > cycle || (step == 0 && stepFirstCycle != 0) ||
      (stepComplete && step + 1 >= settings_.loadSteps.numSteps()))
    bad("has load step records that do not fit together (damaged)");

  // The mesh of that cycle, with the state the refiner needs to go on exactly as before.
  mesh::BisectionRefiner::State s;
  s.dim = static_cast<int>(scalar("mesh_dimension"));
  s.coordinates = cp.doubles("mesh_coordinates");
  s.elementVertices = narrow<int>(cp.ints("mesh_element_vertices"));
  s.generations = narrow<int>(cp.ints("mesh_generations"));
  s.codes = narrow<unsigned char>(cp.ints("mesh_codes"));
  s.boundaryEdges = narrow<std::uint64_t>(cp.ints("mesh_boundary_edges"));
  s.boundaryEdgeParts = narrow<int>(cp.ints("mesh_boundary_edge_parts"));
  s.boundaryFaces = narrow<int>(cp.ints("mesh_boundary_faces"));
  s.boundaryFaceParts = narrow<int>(cp.ints("mesh_boundary_face_parts"));
  s.curvedEdges = narrow<std::uint64_t>(cp.ints("mesh_curved_edges"));
  s.curvedEdgeParts = narrow<int>(cp.ints("mesh_curved_edge_parts"));
  // The part ids of the state refer to the initial mesh's boundary names (a Gmsh file changed
  // since the run was started could number them otherwise).
  const std::string names = Json(mesh_->boundaryNames()).dump();
  if (cp.string("mesh_boundary_names") != names)
    bad("has the boundary parts " + cp.string("mesh_boundary_names") +
        ", the deck's initial mesh " + names + " (was the mesh file changed?)");
  refiner_->restore(s, "checkpoint '" + path + "'");
  mesh_ = refiner_->mesh();
  if (hierarchy_) {
    // The meshes before the checkpoint are not stored: the hierarchy restarts from this one.
    hierarchy_ = std::make_unique<solvers::StressHierarchy>(settings_.discretization.degree, comm_);
    hierarchy_->addMesh(mesh_, {});
  }
  if (mesh_->numElements() != scalar("mesh_elements") ||
      mesh_->numVertices() != scalar("mesh_vertices"))
    bad("holds a mesh that does not rebuild to its recorded size (damaged)");

  marked = narrow<int>(cp.ints("marked_elements"));
  for (int e : marked)
    if (e < 0 || e >= mesh_->numElements())
      bad("marks an element that its mesh does not have (damaged)");

  const int d = settings_.problem.dimension;
  const auto& points = cp.doubles("contact_points");
  const int stride = contactPointStride(d);
  if (scalar("contact_point_stride") != stride || points.size() % stride != 0)
    bad("has contact points of another dimension (damaged)");
  // The restored mesh's boundary faces by their sorted vertices.
  std::map<std::vector<int>, int> faceOf;
  for (int f : mesh_->boundaryFaces()) {
    std::vector<int> v(mesh_->faceVertices(f), mesh_->faceVertices(f) + d);
    std::sort(v.begin(), v.end());
    faceOf.emplace(std::move(v), f);
  }
  std::vector<contact::ContactPoint> restored;
  for (std::size_t k = 0; k < points.size(); k += stride) {
    // Each point's face must be a boundary face of the restored mesh (the mesh of its cycle).
    std::vector<int> v;
    for (int i = 0; i < d; ++i) {
      const double x = points[k + d + 4 + i];
      if (!(x >= 0 && x < mesh_->numVertices() && x == std::floor(x)))
        bad("has a contact point on a face with a vertex its mesh does not have (damaged)");
      v.push_back(static_cast<int>(x));
    }
    const auto face = faceOf.find(v);
    if (face == faceOf.end())
      bad("has a contact point on a face that its mesh does not have on the boundary (damaged)");
    if (comm_->getRank() != 0) continue;
    contact::ContactPoint p;
    for (int i = 0; i < d; ++i)
      p.x[i] = points[k + i];
    p.status = static_cast<contact::PointStatus>(static_cast<int>(points[k + d]));
    p.direction = {points[k + d + 1], points[k + d + 2]};
    p.face = face->second;
    p.index = static_cast<int>(points[k + d + 3]);
    std::size_t at = k + 2 * d + 4;
    p.weight = points[at++];
    for (auto* v : {&p.centroid, &p.history})
      for (int i = 0; i < d; ++i)
        (*v)[i] = points[at++];
    p.rT = {points[at], points[at + 1]};
    at += 2;
    p.rN = points[at++];
    for (auto* v : {&p.t1, &p.t2})
      for (int i = 0; i < d; ++i)
        (*v)[i] = points[at++];
    restored.push_back(p);
  }
  if (contactProblem_) contactProblem_->restorePoints(std::move(restored));

  Json cycles, steps;
  try {
    cycles = Json::parse(cp.string("summary_cycles"));
    steps = Json::parse(cp.string("xdmf_steps"));
  } catch (const std::exception&) {
    bad("has summary or XDMF records that are not valid JSON (damaged)");
  }
  if (!steps.is_array()) bad("has XDMF records that are not a list (damaged)");
  if (!cycles.is_array() || static_cast<int>(cycles.size()) != cycle + 1 ||
      cycles.back().value("cycle", -1) != cycle)
    bad("does not hold the summary records of cycles 0 to " + std::to_string(cycle) + " (damaged)");
  // summary.json counts the linear solver's symbolic reuses and preconditioner set-ups over the
  // run: the restarted run's solver starts from zero.
  const Json& last = cycles.back();
  auto count = [&](const char* key) -> long long {
    if (last.contains("linear_solver") && last["linear_solver"].is_object() &&
        last["linear_solver"].contains(key) && last["linear_solver"][key].is_number_integer())
      return last["linear_solver"][key].get<long long>();
    return 0;
  };
  symbolicReusesBefore_ = count("symbolic_reuses");
  preconditionerSetupsBefore_ = count("preconditioner_setups");

  // Where the load steps go on: the next step from its start, or this step from cycle + 1.
  resume_.step = stepComplete ? step + 1 : step;
  resume_.stepFirstCycle = stepComplete ? cycle + 1 : stepFirstCycle;
  resume_.startsStep = stepComplete;
  lastCycle_ = cycle;

  std::ostringstream os;
  os << "restart from " << path << ": cycle " << cycle << " complete (" << mesh_->numElements()
     << " elements, " << marked.size() << " marked), continuing with cycle " << cycle + 1;
  if (settings_.loadSteps.numSteps() > 1)
    os << (stepComplete ? ", which starts load step " : " in load step ") << resume_.step + 1
       << " of " << settings_.loadSteps.numSteps();
  if (ranksBefore != comm_->getSize())
    os << "; written on " << ranksBefore << " rank(s), now " << comm_->getSize()
       << ": the cycles after it match a run on " << comm_->getSize()
       << " rank(s) only to rounding (the partition changes)";
  progress_.message(os.str());
  return cycle + 1;
}

void Simulation::restoreOutputs()
{
  const io::CheckpointFile& cp = *checkpoint_;
  Json cycles = Json::parse(cp.string("summary_cycles"));
  const int cycle = static_cast<int>(cp.ints("cycle")[0]);
  // Stopping = Fixed: the final Krylov solve's bound is a fraction of the last cycle's η
  // (contact/BalancedStopping.hpp), as in the uninterrupted run. (Balanced keeps the fixed
  // tolerance in a restarted run's first cycle, docs/theory.md.)
  if (!balancedStopping_.isBalanced() && !settings_.loadSteps.given && !cycles.empty()) {
    const auto& last = cycles.back();
    const auto eta = last.contains("eta") ? last.at("eta") : Json();
    if (eta.is_object() && eta.contains("total") && eta.at("total").is_number() &&
        eta.contains("stress_energy_norm") && eta.at("stress_energy_norm").is_number()) {
      const double total = eta.at("total").get<double>();
      const double norm = eta.at("stress_energy_norm").get<double>();
      balancedStopping_.setDiscretisationError(total, norm > 0.0 ? total / norm : 0.0);
    }
  }
  summary_->json()["cycles"] = std::move(cycles);
  summary_->json()["restart"] = {{"checkpoint_cycle", cycle},
                                 {"ranks_before", cp.ints("ranks")[0]}};
  if (settings_.loadSteps
          .given)  // the load step of the checkpoint's cycle (1-based, as load_step/step)
    summary_->json()["restart"]["checkpoint_load_step"] = cp.ints("load_step")[0] + 1;
  if (writer_) {
    std::vector<io::XdmfWriter::Step> steps;
    for (const auto& s : Json::parse(cp.string("xdmf_steps")))
      steps.push_back(
          {s.at("cycle").get<int>(), s.at("time").get<double>(), s.at("xml").get<std::string>()});
    writer_->restoreSteps(steps);
  }
  // history.csv holds the restored cycles only (the killed run may have written a row after its
  // last checkpoint).
  io::writeHistory(*comm_, settings_.output.directory, summary_->json()["cycles"],
                   settings_.problem.dimension, boundaryConditions_.hasContact());
  checkpoint_.reset();
}

void Simulation::killIfAsked(int cycle) const
{
  // Test only (docs/reliability.md): simulates a run killed during a cycle, after the cycle's
  // fields and CSV are written but before its summary record and checkpoint.
  const char* value = std::getenv("SC_KILL_IN_CYCLE");
  if (!value || std::string(value).empty()) return;
  char* end = nullptr;
  const long k = std::strtol(value, &end, 10);
  if (*end != '\0' || k != cycle) return;
  comm_->barrier();
  if (comm_->getRank() == 0)
    std::cerr << "stresscontact: SC_KILL_IN_CYCLE=" << k << ": killing the run in cycle " << cycle
              << " (test only)" << std::endl;
  comm_->barrier();
  std::raise(SIGKILL);
}

}  // namespace sc::app
