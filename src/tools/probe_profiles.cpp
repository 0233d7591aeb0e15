// `thin_ice probe profiles`: the rubble pile's side and top profiles
// (thin_ice_sim/study/rubble_profiles.hpp) of a finished run, from one of its snapshots, written as
// RUN_DIR/profiles.csv (the file `thin_ice run --profiles` writes at the end of a run).
//   thin_ice probe profiles RUN_DIR [--snapshot cells_RRRRRR.csv] [--out FILE] [--accept-changed-scenario]
// Default: the last snapshot, which `thin_ice run` takes at the end of the run. The scenario is the
// one RUN_DIR/summary.json names (run from the directory the run was started in).
// Exit status: 0 done; 2 bad arguments, run directory or scenario.
#include <cstdio>
#include <exception>
#include <stdexcept>
#include <string>
#include <vector>

#include "commands.hpp"
#include "thin_ice_sim/study/rubble_profiles.hpp"
#include "thin_ice_sim/study/run_directory.hpp"
#include "thin_ice_sim/sheet_io.hpp"
#include "run_tool_args.hpp"

namespace {

constexpr const char* kTool = "thin_ice probe profiles";

}  // namespace

int thin_ice::cli::probeProfiles(int argc, char** argv) {
  const char* usage =
      "usage: thin_ice probe profiles RUN_DIR [--snapshot cells_RRRRRR.csv] [--out FILE] [--accept-changed-scenario]\n";
  thin_ice_tools::RunToolArgs args;
  const int status = thin_ice_tools::parseRunToolArgs(argc, argv, kTool, usage, {"--snapshot", "--out"}, args);
  if (status >= 0) return status;
  const std::string& run = args.run;
  const std::string snapshot = args.values.count("--snapshot") ? args.values.at("--snapshot") : "";
  const std::string out = args.values.count("--out") ? args.values.at("--out") : "";
  try {
    const thin_ice::Scenario scenario = thin_ice_tools::loadRunScenario(args, kTool);
    const std::vector<thin_ice::SnapshotEntry> index = thin_ice::readSnapshotIndex(run);
    if (index.empty()) throw std::runtime_error("snapshots/index.csv lists no snapshot");
    const thin_ice::SnapshotEntry* chosen = &index.back();
    if (!snapshot.empty()) {
      chosen = nullptr;
      for (const thin_ice::SnapshotEntry& e : index) {
        if (e.file == run + "/snapshots/" + snapshot) chosen = &e;
      }
      if (!chosen) throw std::runtime_error("--snapshot " + snapshot + ": not in snapshots/index.csv");
    }
    const thin_ice::RubbleProfiles profiles =
        thin_ice::computeRubbleProfiles(thin_ice::readCellSnapshot(chosen->file), scenario.params);
    const std::string path = out.empty() ? run + "/profiles.csv" : out;
    thin_ice::writeFileAtomically(path, thin_ice::rubbleProfilesCsv(profiles));
    std::printf("wrote %s from %s (L = %.4g m)\n", path.c_str(), chosen->file.c_str(), chosen->pushed_length);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s: %s: %s\n", kTool, run.c_str(), e.what());
    return 2;
  }
  return 0;
}
