// `thin_ice run` (and `thin_ice resume DIR`, the same as `thin_ice run --resume DIR`): runs one
// scenario offline and writes its load history, the paper's load statistics (Section 5.1, Table 6)
// and optional cell snapshots (its command line: run_options.hpp).
//   thin_ice run --scenario FILE [--set section.key=value]... (--until-length L|end | --until-time T)
//                [--backend cpu|cuda|auto] [--output-interval S] [--snapshots N] --out DIR
//   thin_ice run --resume DIR [--accept-changed-scenario] [--set section.key=value]...
//                (--until-length L|end | --until-time T) [--backend cpu|cuda|auto] [--snapshots N] [--profiles]
// Writes DIR/loads.csv (one row per output interval, through loads.csv.partial), DIR/load_bins.csv
// (the kept record: the rows in 35 mm bins of pushed length, load_bins.hpp), DIR/summary.json,
// DIR/checkpoint.bin (the state at the end, unless the run became unhealthy) and with --snapshots
// DIR/snapshots/cells_RRRRRR.csv (RRRRRR: loads.csv data row, 1-based; 000000: the sheet at rest)
// listed in snapshots/index.csv; with --profiles DIR/profiles.csv (the rubble pile's side and top
// profiles at the end).
// --until-length end runs to the end of the pusher's travel, where its face reaches the
// structure's toe (structure.toe_x - sheet.x_min); a length beyond the travel is refused.
// --resume goes on from DIR/checkpoint.bin with DIR's scenario and output interval to the new
// target (the whole run's L or T), on any backend: the rows are appended to DIR/loads.csv (the old
// file stays whole until the new one is complete; where DIR has no loads.csv, as a clone keeps a
// run, the new rows start one and the summary's loads_csv_from_s says where), the bins continue
// DIR/load_bins.csv, the statistics, worked out on the bins, cover the whole history, and the
// summary's wall time is the sum of the segments. --snapshots N then spreads N snapshots over
// the new segment, the last at its end. --set with --resume switches a law on from the resumption
// (e.g. ice.friction_ice_ice=0.6): the override joins the run's, and the summary's overrides_from_m
// says from which L it holds. Only the keys the scenario registry marks switchable are taken there,
// and not a value under which the run's time step is unstable, nor a false bottom raised through
// the ice over it.
// Exit status: 0 done; 1 I/O or backend failure; 2 bad arguments or scenario, or a run directory
// that cannot be resumed (nothing written); 3 the simulation became unhealthy (rows up to then and
// the summary are kept; a resumed run is left as it was and the segment's rows go to
// DIR/unhealthy_segment.csv); 4 stopped by
// SIGINT or SIGTERM before the target: the output interval in progress is finished, and its rows,
// the summary (status "interrupted"), the profiles and a last snapshot are written as at the
// target (a second signal kills at once, unless it comes within 1 s of the first: the same
// request delivered twice, as GNU timeout does).
#include <unistd.h>


#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <limits>
#include <memory>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "commands.hpp"
#include "progress_line.hpp"
#include "run_options.hpp"
#include "stop_signal.hpp"
#include "resume_switch.hpp"
#include "thin_ice_sim/built_backends.hpp"
#include "thin_ice_sim/checkpoint.hpp"
#include "thin_ice_sim/study/load_bins.hpp"
#include "thin_ice_sim/study/load_statistics.hpp"
#include "thin_ice_sim/study/rubble_profiles.hpp"
#include "thin_ice_sim/study/run_directory.hpp"
#include "thin_ice_sim/study/run_record.hpp"
#include "thin_ice_sim/study/run_report.hpp"
#include "thin_ice_sim/study/stall_watch.hpp"
#include "thin_ice_sim/scenario.hpp"
#include "thin_ice_sim/sheet_io.hpp"
#include "thin_ice_sim/simulation.hpp"

namespace {

using thin_ice::jsonNumber;
using thin_ice::jsonString;
using thin_ice::LoadSample;
using thin_ice::Simulation;
using Clock = std::chrono::steady_clock;
using thin_ice_tools::kUsage;
using thin_ice_tools::Options;
using thin_ice_tools::UsageError;

using thin_ice::run_record::loadsHeader;
using thin_ice::run_record::loadsRow;

/// One CSV per snapshot: cell pose, whether it is bonded, the size of its bonded piece (cells) and
/// its world polygon as "x0 y0 x1 y1 ..." [m] in one field.
/// Writes snapshots/cells_ROW.csv and its line in snapshots/index.csv; returns the file's name.
std::string writeSnapshot(const Simulation& sim, const std::string& dir, long row) {
  const std::vector<thin_ice::CellSnapshot> cells = sim.cells();
  std::vector<std::vector<thin_ice::Vec2>> polygons;
  polygons.reserve(cells.size());
  for (std::size_t k = 0; k < cells.size(); ++k) polygons.push_back(sim.cellPolygon(static_cast<int>(k), cells[k]));
  const std::string name = thin_ice::run_record::snapshotFileName(row);
  thin_ice::writeFileAtomically(dir + "/" + name, thin_ice::run_record::snapshotText(cells, polygons));
  std::ofstream index(dir + "/" + thin_ice::run_record::kSnapshotIndexFile, std::ios::app);
  index << thin_ice::run_record::snapshotIndexRow(name, sim.time(), sim.pushedLength());
  return name;
}

/// What a resumed run takes over from its directory (inactive for a fresh run).
struct Continuation {
  bool active = false;
  std::string previous_csv;           ///< loads.csv as it was, header included (the header alone where it had none)
  double loads_csv_from = 0.0;        ///< [s] where loads.csv's first row begins (0: the whole run)
  long rows = 0;                      ///< its rows, those of loads.csv absent here included
  std::vector<thin_ice::LoadBin> bins;  ///< its kept record (load_bins.csv)
  double first_failure_length = std::numeric_limits<double>::infinity();  ///< [m] its first broken bond, +infinity: none yet
  LoadSample last;                    ///< its last row (time, length, bond counts)
  double previous_wall = 0.0;         ///< [s] of the segments before
  std::vector<double> resumed_at;     ///< [m] where each resumption began, this one last
  std::vector<thin_ice::SwitchedOverride> switched;  ///< overrides given at resumptions, this one's last
  double start_fraction = 0.0;        ///< progress towards the target at the resumption
};

struct RunResult {
  thin_ice::LoadBinner bins;         // the history analysed (load_bins.hpp)
  double first_failure_length = std::numeric_limits<double>::infinity();  // [m] L of the first row with a broken bond, +infinity: none
  double wall = 0.0;                 // [s] of stepping and output
  LoadSample last;                   // the last row written (zero loads before the first)
  std::string error;                 // empty when the run reached its target
  int interrupted_by = 0;            // the signal that stopped the run early, 0 if none
};

/// The stall watch's line on stderr: what the run was doing, for how long nothing moved, where it
/// last was, and whether a stop request waits for the step to return (it is acted on after a row).
void reportStall(const thin_ice::StallReport& r) {
  std::string where = r.moved_before ? "; the last row: t = " + jsonNumber(r.last_time) + " s, L = " +
                                           jsonNumber(r.last_length) + " m"
                                     : "; no row finished yet";
  const int stop = thin_ice_tools::stopSignal();
  if (stop != 0) {
    timespec now{};
    clock_gettime(CLOCK_MONOTONIC, &now);
    const long long ago_ns = static_cast<long long>(now.tv_sec) * 1000000000LL + now.tv_nsec -
                             thin_ice_tools::stop_detail::g_first_stop_ns.load();
    where += "; stop signal " + std::to_string(stop) + " came " + thin_ice_tools::formatDuration(1e-9 * ago_ns) +
             " ago and is acted on when the step returns";
  }
  std::fprintf(stderr, "%sthin_ice run: nothing has moved for %s while %s%s\n", ::isatty(STDERR_FILENO) ? "\n" : "",
               thin_ice_tools::formatDuration(r.silent_seconds).c_str(), r.phase.c_str(), where.c_str());
}

RunResult runSimulation(Simulation& sim, const Options& o, const Continuation& cont, thin_ice::StallWatch& watch) {
  watch.phase("stepping");
  RunResult r;
  r.bins = thin_ice::LoadBinner(cont.bins);
  r.first_failure_length = cont.first_failure_length;
  r.last = cont.last;
  const double dt = sim.timeStep(), velocity = sim.pusherVelocity();
  const long steps_per_row = std::max(1L, std::lround(o.output_interval / dt));
  const bool by_length = o.until_length > 0.0;
  auto stepsLeft = [&]() -> long {  // whole steps until the target, rounded up
    // A target at the end of the pusher's travel is reached when the plate stops there (within a
    // step of it: Simulation::step).
    if (by_length && sim.pusherAtTravelEnd()) return 0;
    const double left = by_length ? (o.until_length - sim.pushedLength()) / (velocity * dt)
                                  : (o.until_time - sim.time()) / dt;
    return static_cast<long>(std::ceil(left - 1e-6));  // 1e-6 step: rounding in t or L
  };
  auto fraction = [&]() {
    const double f = by_length ? sim.pushedLength() / o.until_length : sim.time() / o.until_time;
    return std::clamp(f, 0.0, 1.0);
  };
  const std::string csv_path = o.out + "/" + thin_ice::run_record::kLoadsFile;
  std::ofstream csv(csv_path + ".partial", std::ios::trunc);
  if (!csv) throw std::runtime_error("cannot write '" + csv_path + ".partial'");
  const std::string snapshot_dir = o.out + "/" + thin_ice::run_record::kSnapshotDir;
  const std::string snapshot_index = snapshot_dir + "/" + thin_ice::run_record::kSnapshotIndexFile;
  if (o.snapshots > 0 && !(cont.active && std::filesystem::exists(snapshot_index))) {
    std::ofstream(snapshot_index) << thin_ice::run_record::headerLine(thin_ice::run_record::kSnapshotIndexColumns);
  }
  // Snapshot k (0-based) is due at progress k / (N - 1): the first shows the sheet at rest, the
  // last the end (N = 1: the end only). Several due in one row give one file. A resumed run's
  // snapshots are due at k / N of its own segment, k = 1..N: its start is the last run's end.
  int snapshots_taken = 0;
  auto snapshotDue = [&](double f, bool last) {
    const double segment = (f - cont.start_fraction) / std::max(1e-12, 1.0 - cont.start_fraction);
    const int due = last ? o.snapshots
                    : cont.active ? int(std::floor(segment * o.snapshots + 1e-9))
                    : o.snapshots == 1 ? 0 : int(std::floor(f * (o.snapshots - 1) + 1e-9)) + 1;
    if (std::min(due, o.snapshots) <= snapshots_taken) return false;
    snapshots_taken = std::min(due, o.snapshots);
    return true;
  };

  // Row r (1-based) holds the loads averaged over output interval r (Simulation::loads()),
  // stamped with the time at its end; there is no row at t = 0 (nothing averaged yet).
  const int panels = std::max(0, sim.params().structure.panels);
  if (cont.active) {
    csv << cont.previous_csv;
  } else {
    csv << loadsHeader(panels);
    if (snapshotDue(0.0, false)) writeSnapshot(sim, snapshot_dir, 0);  // the sheet at rest
  }
  // A resumed segment that goes wrong is taken back whole, its snapshots too: the index as it was
  // before the segment, and the files the segment wrote.
  std::error_code no_index;
  const std::uintmax_t index_size_before = std::filesystem::file_size(snapshot_index, no_index);
  std::vector<std::string> segment_snapshots;
  thin_ice_tools::Progress progress(sim.time(), cont.start_fraction);
  const Clock::time_point start = Clock::now();
  for (long row = cont.rows + 1, left = stepsLeft(); left > 0; ++row) {
    const double pushed_before = sim.pushedLength();
    // Rows end on multiples of steps_per_row counted from t = 0, so that a run resumed after a
    // short last row (a target between rows) writes the same rows from there on as a run made in
    // one go; in a fresh run every row but the last is whole.
    const long to_boundary = steps_per_row - sim.stepCount() % steps_per_row;
    try {
      sim.step(std::min(to_boundary, left));
    } catch (const std::exception& e) {
      r.error = std::string("step failed: ") + e.what();
    }
    if (r.error.empty() && !sim.healthy()) r.error = sim.lastError();
    if (r.error.empty() && by_length && !(sim.pushedLength() > pushed_before)) {
      r.error = "pushed length stopped advancing at L = " + jsonNumber(pushed_before) + " m";
    }
    if (!r.error.empty()) {  // keep the rows so far; the state now is not worth a row
      std::fprintf(stderr, "%sthin_ice run: simulation stopped at t = %.6g s: %s\n",
                   ::isatty(STDERR_FILENO) ? "\n" : "", sim.time(), r.error.c_str());
      break;
    }
    r.last = sim.loads();
    watch.moved(r.last.time, r.last.pushed_length);
    csv << loadsRow(r.last, panels) << std::flush;
    r.bins.add(r.last);
    if (std::isinf(r.first_failure_length) && r.last.broken_bonds > 0) r.first_failure_length = r.last.pushed_length;
    // A signal in the interval that reached the target changes nothing: the run is complete.
    r.interrupted_by = stepsLeft() > 0 ? thin_ice_tools::stopSignal() : 0;
    const bool last_row = stepsLeft() <= 0 || r.interrupted_by != 0;
    left = r.interrupted_by != 0 ? 0 : stepsLeft();
    const double wall = std::chrono::duration<double>(Clock::now() - start).count();
    progress.report(fraction(), r.last, wall, last_row);
    if (snapshotDue(fraction(), last_row)) segment_snapshots.push_back(writeSnapshot(sim, snapshot_dir, row));
  }
  if (r.interrupted_by != 0) {
    std::fprintf(stderr, "thin_ice run: stopped by signal %d at t = %.6g s, L = %.6g m; writing what was reached\n",
                 r.interrupted_by, sim.time(), sim.pushedLength());
  }
  r.wall = std::chrono::duration<double>(Clock::now() - start).count();
  watch.phase("writing the results");
  csv.close();
  // A resumed segment that went wrong leaves the run as it was: its rows go to a file of their own.
  const std::string kept = cont.active && !r.error.empty() ? o.out + "/unhealthy_segment.csv" : csv_path;
  if (!csv || std::rename((csv_path + ".partial").c_str(), kept.c_str()) != 0) {
    throw std::runtime_error("cannot finish '" + kept + "'");
  }
  if (kept == csv_path) {
    thin_ice::writeFileAtomically(o.out + "/" + thin_ice::run_record::kLoadBinsFile,
                                  thin_ice::run_record::loadBinsText(r.bins.bins()));
  }
  if (kept != csv_path && !segment_snapshots.empty()) {
    for (const std::string& name : segment_snapshots) std::filesystem::remove(snapshot_dir + "/" + name);
    if (no_index) {
      std::filesystem::remove(snapshot_index);  // the segment made the index: it goes with it
      std::error_code not_empty;
      std::filesystem::remove(snapshot_dir, not_empty);  // and the folder, where nothing else is in it
    } else {
      std::filesystem::resize_file(snapshot_index, index_size_before);
    }
  }
  return r;
}

/// The rubble pile's side profile (height against x, 0.1 m bins from 4 m in front of the toe) and
/// top profile (distance from the toe against y), as the paper's Figs. 13 and 15.
void writeProfiles(const Simulation& sim, const std::string& path) {
  thin_ice::writeFileAtomically(path, thin_ice::rubbleProfilesCsv(thin_ice::computeRubbleProfiles(sim.cells(), sim.params())));
}

/// What summary.json records of this run (run_record.hpp owns the file's layout and writes it).
thin_ice::run_record::SummaryRecord summaryRecord(const Simulation& sim, const Options& o, const RunResult& r,
                                                  const Continuation& cont, const thin_ice::LoadStatistics& s,
                                                  double setup_wall) {
  const double wall = cont.previous_wall + r.wall;  // [s] of every segment
  const thin_ice::Scenario& sc = sim.scenario();
  const thin_ice::Params& p = sim.params();
  const LoadSample& last = r.last;  // after a blow-up sim.loads() is not to be trusted
  const double cell_steps = double(sim.cellCount()) * double(sim.stepCount());
  thin_ice::run_record::SummaryRecord record;
  record.status = !r.error.empty() ? "unhealthy" : r.interrupted_by != 0 ? "interrupted" : "completed";
  record.error = r.error;
  record.scenario_name = sc.name;
  record.scenario_file = sc.source;
  record.scenario_hash = sc.hash;
  record.overrides = sc.overrides;
  record.parameters = thin_ice::scenarioParameters(p);
  record.backend = sim.backendName();
  record.backend_note = sim.backendNote();
  record.cpu_instruction_set = Simulation::cpuInstructionSet();
  record.cells = sim.cellCount();
  record.time_step = sim.timeStep();
  record.critical_time_step = sim.criticalTimeStep();
  record.structure_substeps = sim.structureSubsteps();
  record.structure_critical_time_step = sim.structureCriticalTimeStep();
  record.output_interval = o.output_interval;
  record.loads_csv_from = cont.loads_csv_from;
  record.load_bin_length = thin_ice::kLoadBinLength;
  record.target_is_length = o.until_length > 0.0;
  record.target = record.target_is_length ? o.until_length : o.until_time;
  record.steps = sim.stepCount();
  record.simulated_time = sim.time();
  record.pushed_length = sim.pushedLength();
  record.setup_wall_time = setup_wall;
  record.wall_time = wall;
  record.cell_steps_per_second = wall > 0.0 ? cell_steps / wall : NAN;
  record.real_time_factor = wall > 0.0 ? sim.time() / wall : NAN;
  record.resumed_at = cont.resumed_at;
  for (const thin_ice::SwitchedOverride& w : cont.switched) record.overrides_from.push_back({w.set, w.from_length});
  record.intact_bonds = last.intact_bonds;
  record.broken_bonds = last.broken_bonds;
  record.calibration_factor = sc.params.structure.calibration_factor;
  record.load_json = thin_ice::loadJson(s, r.first_failure_length);
  record.structure_width = p.structure.width;
  record.toe_x = p.structure.toe_x;
  record.angle_deg = p.structure.angle_deg;
  record.structure_height = p.structure.height;
  record.panels = p.structure.panels;
  record.false_bottom = p.bottom.enabled;
  record.bottom_depth = p.bottom.depth;
  record.bottom_distance_from_structure = p.bottom.distance_from_structure;
  record.experiment_json = thin_ice::experimentJson(sc.name, p.structure.width, s);
  return record;
}

void printReport(const Simulation& sim, const Options& o, const thin_ice::LoadStatistics& s) {
  std::printf("%s (%s): t = %.4g s, L = %.4g m, %ld steps\n  peak %.5g N at L = %.4g m; phase-1 "
              "slope %.5g N/m\n  %s\n", sim.scenario().name.c_str(), sim.backendName().c_str(),
              sim.time(), sim.pushedLength(), sim.stepCount(), s.peak_load, s.peak_length,
              s.phase1_slope, s.steady_rule.c_str());
  const thin_ice::ExperimentComparison c =
      thin_ice::compareWithExperiment(sim.scenario().name, sim.params().structure.width, s);
  if (c.experiment) {
    std::printf("  experiment (%s, x %.3g for a %.3g m structure): mean %.0f N (%+.1f%%), peak %.0f N (%+.1f%%)\n",
                c.experiment->source.c_str(), c.width_scale, sim.params().structure.width, c.mean, c.mean_error_percent,
                c.peak, c.peak_error_percent);
  }
  std::printf("wrote %s/loads.csv, %s/load_bins.csv and %s/summary.json\n", o.out.c_str(), o.out.c_str(), o.out.c_str());
}

/// A run directory that cannot be resumed: exit status 2, nothing written.
struct ResumeError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// Runs `read` and turns what goes wrong into a ResumeError naming the directory (exit status 2).
template <typename Read>
auto aboutTheDirectory(const std::string& dir, Read read) -> decltype(read()) {
  try {
    return read();
  } catch (const ResumeError&) {
    throw;
  } catch (const thin_ice::ScenarioError&) {
    throw;
  } catch (const std::exception& e) {  // unreadable files, a checkpoint that does not fit
    throw ResumeError(dir + ": cannot resume: " + e.what());
  }
}

/// `--until-length end` becomes the pusher's travel (structure.toe_x - sheet.x_min), which only
/// the built model knows: a run of any sheet length can be asked to go as far as it can.
void resolveTravelEnd(Options& o, const Simulation& sim) {
  if (o.until_travel_end) o.until_length = sim.pusherTravel();
}

/// --resume: the run's scenario and output interval, its checkpoint put into a new simulation, and
/// its loads.csv read back, checked against each other. Creates nothing on disk. What is wrong
/// with the directory is a ResumeError; a backend that cannot start fails as for a fresh run.

std::unique_ptr<Simulation> prepareResume(Options& o, Continuation& cont) {
  const std::string& dir = o.resume;
  thin_ice::RunSummary summary;
  thin_ice::Checkpoint checkpoint;
  std::string run_hash;  // the scenario hash of the run so far (before any override switched on here)
  thin_ice::Scenario unswitched;  // the run's scenario as it reads now, without the overrides given here
  const thin_ice::Scenario scenario = aboutTheDirectory(dir, [&] {
    summary = thin_ice::readRunSummary(dir);
    if (summary.status == "unhealthy") {
      throw ResumeError(dir + " ended unhealthy (summary.json); its state is not worth going on from");
    }
    std::string warning;
    bool parameters_recorded = false;
    thin_ice::Scenario loaded = thin_ice::loadRunScenario(dir, o.accept_changed_scenario, warning, &parameters_recorded);
    if (!warning.empty()) std::fprintf(stderr, "thin_ice run: warning: %s\n", warning.c_str());
    run_hash = loaded.hash;
    unswitched = loaded;
    if (!o.overrides.empty()) {  // switched on from here: after the run's own, so they win
      for (const std::string& set : o.overrides) {
        const std::string why = thin_ice_tools::whyNotSwitchable(set, loaded.source);
        if (!why.empty()) throw ResumeError(why);
      }
      std::vector<std::string> overrides = loaded.overrides;
      overrides.insert(overrides.end(), o.overrides.begin(), o.overrides.end());
      loaded = thin_ice::loadScenario(loaded.source, overrides);
    }
    const std::string checkpoint_path = dir + "/" + thin_ice::run_record::kCheckpointFile;
    if (!std::filesystem::exists(checkpoint_path)) {
      throw ResumeError(dir + " has no checkpoint.bin (`thin_ice run` writes one at the end of every healthy run; "
                        "a run that failed, or one recorded before checkpoints existed, has none)");
    }
    checkpoint = thin_ice::readCheckpoint(checkpoint_path);
    if (!checkpoint.checksummed) {
      std::fprintf(stderr, "thin_ice run: warning: %s is of format 1 and carries no checksum: damage to it cannot be "
                   "told; the next one written is checksummed\n", checkpoint_path.c_str());
    }
    if (checkpoint.state.steps != summary.steps) {
      throw ResumeError(checkpoint_path + " is at step " + std::to_string(checkpoint.state.steps) +
                        " but summary.json says the run ended at step " + std::to_string(summary.steps));
    }
    // A changed scenario file changed its hash too; loadRunScenario has already said so. Overrides
    // switched on here change it by design, so the checkpoint is held against the run's own. A run
    // that recorded its parameters is held to them instead (loadRunScenario), and a file whose
    // comments changed, or that now states a value the run keeps, changes the hash alone.
    if (!parameters_recorded && !o.accept_changed_scenario && checkpoint.scenario_hash != run_hash) {
      throw ResumeError(checkpoint_path + " is of scenario hash " + checkpoint.scenario_hash +
                        ", the run's (summary.json) is " + run_hash);
    }
    return loaded;
  });
  std::unique_ptr<Simulation> sim;
  try {
    sim = std::make_unique<Simulation>(scenario, o.backend);  // no device: exit status 1
    resolveTravelEnd(o, *sim);
  } catch (const thin_ice::ScenarioError&) {
    // The model refuses a time step made unstable by a switch (a stiffer E, say) or by the scenario
    // file changed under --accept-changed-scenario, and its message offers a smaller
    // numerics.time_step, which a run under way cannot take.
    const std::string why =
        thin_ice_tools::whyTheStepCannotHold(thin_ice_tools::whatWasRefused(unswitched, scenario, o.overrides), dir);
    if (why.empty()) throw;  // not the time step: the model's own message says what
    throw ResumeError(why);
  }
  aboutTheDirectory(dir, [&] {
    thin_ice::restoreCheckpoint(*sim, checkpoint, true);  // its hash checked above
    const std::string cut = thin_ice_tools::whyBottomCutsIce(*sim, o.overrides, scenario.source);
    if (!cut.empty()) throw ResumeError(cut);
    o.output_interval = summary.output_interval;

    // The history so far, which must end where the checkpoint is: the kept record (load_bins.csv,
    // or the bins of loads.csv for a run made before it) and, where this directory has it,
    // loads.csv, whose rows the new ones follow. Without loads.csv (a fresh clone keeps the
    // checkpoint, load_bins.csv and the summary) the segment's rows start a new loads.csv.
    const std::string csv_path = dir + "/" + thin_ice::run_record::kLoadsFile;
    const std::string bins_path = dir + "/" + thin_ice::run_record::kLoadBinsFile;
    const int panels = std::max(0, sim->params().structure.panels);
    const std::string header = loadsHeader(panels);
    const bool has_csv = std::filesystem::exists(csv_path);
    if (!has_csv && !std::filesystem::exists(bins_path)) throw ResumeError("no " + bins_path + " nor " + csv_path);
    if (has_csv) {
      std::ifstream csv(csv_path);
      if (!csv) throw ResumeError("cannot read " + csv_path);
      cont.previous_csv.assign(std::istreambuf_iterator<char>(csv), std::istreambuf_iterator<char>());
      if (cont.previous_csv.compare(0, header.size(), header) != 0) {
        throw ResumeError(csv_path + ": its first line is not the header `thin_ice run` writes for " + std::to_string(panels) +
                          " panels (" + header.substr(0, header.size() - 1) + ")");
      }
      if (cont.previous_csv.back() != '\n') throw ResumeError(csv_path + ": its last row is cut short (no line end)");
      const thin_ice::LoadHistory history = thin_ice::readLoadHistory(csv_path);
      // Where it ends first: a loads.csv behind the checkpoint is an older copy of the record (the
      // kept record, pulled, may have gone on), one past it a record whose checkpoint was not
      // written after it.
      const double t_end = history.time.empty() ? 0.0 : history.time.back();
      const double tolerance = 1e-8 * std::max(1.0, sim->time());  // [s] rows hold nine digits
      if (history.time.empty() || t_end < sim->time() - tolerance) {
        throw ResumeError(csv_path + " ends at t = " + (history.time.empty() ? std::string("(no rows)") : jsonNumber(t_end)) +
                          " s, before checkpoint.bin's t = " + jsonNumber(sim->time()) +
                          " s: an older copy of the record (remove it to go on from load_bins.csv alone)");
      }
      if (t_end > sim->time() + tolerance) {
        throw ResumeError(csv_path + " ends at t = " + jsonNumber(t_end) + " s, after checkpoint.bin's t = " +
                          jsonNumber(sim->time()) + " s: the checkpoint is older than the record, which cannot be taken back");
      }
      // Rows come one output interval apart (or closer: a short row at an earlier target), from
      // where the file begins on: a row deleted at the start or in the middle leaves a wider gap,
      // which would stay in the history and its statistics.
      const double interval = summary.output_interval;  // [s]
      for (std::size_t k = 0; k < history.time.size(); ++k) {
        const double previous = k == 0 ? summary.loads_csv_from : history.time[k - 1];
        const double gap = history.time[k] - previous;
        if (!(gap > 0.0) || gap > interval * (1.0 + 1e-6) + 1e-9) {
          throw ResumeError(csv_path + ": row " + std::to_string(k + 1) + " (t = " + jsonNumber(history.time[k]) +
                            " s) comes " + jsonNumber(gap) + " s after " +
                            (k == 0 ? "t = " + jsonNumber(summary.loads_csv_from) + " s, where the file begins"
                                    : std::string("the row before it")) +
                            "; allowed: more than 0 and at most the output interval, " + jsonNumber(interval) +
                            " s (a row is missing or out of order: the record is damaged)");
        }
      }
      cont.loads_csv_from = summary.loads_csv_from;
      // A loads.csv of the whole history: its rows are the exact record; the first failure is
      // taken from them, and the kept record must hold as many rows (two continuations of one run
      // to the same time, say one pulled and one made here, are not mixed).
      cont.bins = thin_ice::readRunLoadBins(dir);  // load_bins.csv, or the bins of a whole loads.csv
      const long kept = thin_ice::LoadBinner(cont.bins).samples();
      if (summary.loads_csv_from == 0.0 && kept != static_cast<long>(history.time.size())) {
        throw ResumeError(bins_path + " holds " + std::to_string(kept) + " rows but " + csv_path + " " +
                          std::to_string(history.time.size()) + ": they are not one record");
      }
      cont.first_failure_length = summary.loads_csv_from == 0.0
                                      ? thin_ice::firstFailureLength(history.pushed_length, history.broken_bonds)
                                      : summary.first_failure_length;
    } else {
      cont.previous_csv = header;
      cont.loads_csv_from = sim->time();
      cont.bins = thin_ice::readLoadBins(bins_path);
      cont.first_failure_length = summary.first_failure_length;
    }
    if (cont.bins.empty()) throw ResumeError(bins_path + " holds no rows to go on from");
    const thin_ice::LoadBin& last = cont.bins.back();
    cont.rows = thin_ice::LoadBinner(cont.bins).samples();
    cont.last.time = last.time;
    cont.last.pushed_length = last.pushed_length;
    cont.last.intact_bonds = last.intact_bonds;
    cont.last.broken_bonds = last.broken_bonds;
    // Bins and rows hold nine significant digits; the step count above is the exact check.
    if (std::fabs(cont.last.time - sim->time()) > 1e-8 * std::max(1.0, sim->time())) {
      throw ResumeError(bins_path + " ends at t = " + jsonNumber(cont.last.time) + " s but checkpoint.bin is at t = " +
                        jsonNumber(sim->time()) + " s");
    }
    const double reached = o.until_length > 0.0 ? sim->pushedLength() : sim->time();
    const double target = o.until_length > 0.0 ? o.until_length : o.until_time;
    if (!(target > reached + 1e-9)) {
      throw ResumeError(dir + " is already at " + (o.until_length > 0.0 ? "L = " : "t = ") + jsonNumber(reached) +
                        (o.until_length > 0.0 ? " m" : " s") + "; give a target beyond it");
    }
    cont.active = true;
    cont.previous_wall = summary.wall_time;
    cont.resumed_at = summary.resumed_at;
    cont.resumed_at.push_back(sim->pushedLength());
    cont.switched = summary.switched;
    for (const std::string& set : o.overrides) cont.switched.push_back({set, sim->pushedLength()});
    cont.start_fraction = reached / target;
  });
  return sim;
}

/// Most time steps a run may be asked for (far beyond any run; a long holds 9.2e18).
constexpr double kMaxStepCount = 1e15;

/// A fresh run writes loads.csv, summary.json, checkpoint.bin and maybe snapshots/ and
/// profiles.csv: into a directory that holds another run's files, the two runs' outputs would mix
/// (old snapshots beside new loads). Refused, naming what is there.
void refuseDirectoryWithRun(const std::string& dir) {
  namespace record = thin_ice::run_record;
  for (const char* name : {record::kSummaryFile, record::kLoadsFile, record::kLoadBinsFile, record::kLoadsPartialFile,
                           record::kCheckpointFile, record::kSnapshotDir, "profiles.csv", "unhealthy_segment.csv"}) {
    if (std::filesystem::exists(std::filesystem::path(dir) / name)) {
      throw UsageError("--out " + dir + " already holds a run (" + name +
                       "); allowed: a new or empty directory (remove it, or carry the run on with --resume " + dir + ")");
    }
  }
}

/// Loads the scenario and builds the simulation (or takes over a run to resume); creates nothing
/// on disk.
std::unique_ptr<Simulation> prepare(Options& o, Continuation& cont) {
  std::unique_ptr<Simulation> sim;
  if (!o.resume.empty()) {
    sim = prepareResume(o, cont);
  } else {
    refuseDirectoryWithRun(o.out);
    sim = std::make_unique<Simulation>(thin_ice::loadScenario(o.scenario, o.overrides), o.backend);
    resolveTravelEnd(o, *sim);
  }
  if (o.until_length > 0.0 && !(sim->pusherVelocity() > 0.0)) {
    throw UsageError("--until-length needs pusher.velocity > 0 m/s; the scenario has " +
                     jsonNumber(sim->pusherVelocity()) + " m/s (use --until-time)");
  }
  if (o.until_length > sim->pusherTravel()) {
    throw UsageError("--until-length " + jsonNumber(o.until_length) + " m is beyond the pusher's travel: its face reaches " +
                     "the structure's toe after " + jsonNumber(sim->pusherTravel()) +
                     " m (structure.toe_x - sheet.x_min); allowed: at most that");
  }
  // Step counts are longs made from these quotients: a value whose count a long cannot hold would
  // overflow into a run that ends at once and says "completed".
  const double dt = sim->timeStep();
  const double target_steps = o.until_length > 0.0 ? o.until_length / (sim->pusherVelocity() * dt) : o.until_time / dt;
  if (!(target_steps <= kMaxStepCount)) {
    throw UsageError(std::string(o.until_length > 0.0 ? "--until-length " : "--until-time ") +
                     jsonNumber(o.until_length > 0.0 ? o.until_length : o.until_time) + " is " +
                     jsonNumber(target_steps) + " time steps of " + jsonNumber(dt) + " s; allowed: at most " +
                     jsonNumber(kMaxStepCount) + " steps");
  }
  if (!(o.output_interval / dt <= kMaxStepCount)) {
    throw UsageError("--output-interval " + jsonNumber(o.output_interval) + " is " + jsonNumber(o.output_interval / dt) +
                     " time steps of " + jsonNumber(dt) + " s; allowed: at most " + jsonNumber(kMaxStepCount) + " steps");
  }
  return sim;
}

}  // namespace

// The OpenMP wait policy is set by thin_ice.cpp's main before it gets here: the restart needs the
// program's whole command line, which this function no longer sees.
int thin_ice::cli::runCommand(int argc, char** argv) {
  thin_ice::registerBuiltBackends();
  const Clock::time_point setup_start = Clock::now();
  Options options;
  Continuation continuation;
  std::unique_ptr<Simulation> sim;
  std::unique_ptr<thin_ice::StallWatch> watch;  // from the end of the command line's parsing
  try {
    options = thin_ice_tools::parseOptions(argc, argv);
    if (options.help) return std::printf("%s", kUsage) < 0;
    watch = std::make_unique<thin_ice::StallWatch>(
        options.stall_seconds, "setting up (the scenario, the model, the backend, the checkpoint)", reportStall);
    sim = prepare(options, continuation);
  } catch (const UsageError& e) {
    std::cerr << "thin_ice run: " << e.what() << "\n" << kUsage;
    return 2;
  } catch (const ResumeError& e) {
    std::cerr << "thin_ice run: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {  // ScenarioError: 2; e.g. no CUDA device: 1
    std::cerr << "thin_ice run: " << e.what() << "\n";
    return dynamic_cast<const thin_ice::ScenarioError*>(&e) ? 2 : 1;
  }
  try {
    const double setup_wall = std::chrono::duration<double>(Clock::now() - setup_start).count();
    std::filesystem::create_directories(options.out +
                                        (options.snapshots > 0 ? std::string("/") + thin_ice::run_record::kSnapshotDir : ""));
    thin_ice_tools::stopOnSigintAndSigterm();
    const RunResult result = runSimulation(*sim, options, continuation, *watch);
    if (continuation.active && !result.error.empty()) {
      std::fprintf(stderr, "thin_ice run: the resumed segment became unhealthy; %s is left as it was (its rows are in "
                   "unhealthy_segment.csv there)\n", options.out.c_str());
      return 3;
    }
    const auto stats = thin_ice::analyseLoadBins(result.bins.bins(), thin_ice::SteadyStateRule(),
                                                 result.first_failure_length);
    // The checkpoint first: a summary that says "completed" or "interrupted" has one beside it
    // that matches its loads.csv. An unhealthy state is not worth going on from.
    const std::string checkpoint_path = options.out + "/" + thin_ice::run_record::kCheckpointFile;
    if (result.error.empty()) {
      thin_ice::writeCheckpoint(checkpoint_path, thin_ice::takeCheckpoint(*sim));
    } else {
      std::filesystem::remove(checkpoint_path);
    }
    const thin_ice::run_record::SummaryRecord record =
        summaryRecord(*sim, options, result, continuation, stats, setup_wall);
    thin_ice::writeFileAtomically(options.out + "/" + thin_ice::run_record::kSummaryFile,
                                  thin_ice::run_record::summaryJson(record));
    if (options.profiles) writeProfiles(*sim, options.out + "/profiles.csv");
    printReport(*sim, options, stats);
    return !result.error.empty() ? 3 : result.interrupted_by != 0 ? 4 : 0;
  } catch (const std::exception& e) {
    std::cerr << "thin_ice run: " << e.what() << "\n";
    return 1;
  }
}
