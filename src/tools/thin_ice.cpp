// thin_ice: the project's one command-line program. Its first argument names what to do:
//   thin_ice run ARGS             run a scenario offline (run_command.cpp)
//   thin_ice resume DIR [ARGS]    the same as thin_ice run --resume DIR [ARGS]
//   thin_ice sheet ARGS           a Voronoi ice sheet from a YAML file (sheet_command.cpp)
//   thin_ice analyse RUN_DIR      a finished run's load statistics again (analyse_command.cpp)
//   thin_ice parameters ARGS      a scenario's resolved parameters, as a scenario file (parameters_command.cpp)
//   thin_ice probe PROBE ARGS     the investigation probes (probe_*.cpp)
//   thin_ice [help | --help]      the list of commands
// `thin_ice COMMAND --help` gives a command's own usage, `thin_ice probe --help` the probes.
// Exit status: the command's; 0 after help; 2 without a command (the list goes to stderr) or for
// an unknown one (one line naming those allowed).
#include <cstdio>
#include <string>
#include <vector>

#include "commands.hpp"
#include "thin_ice_sim/openmp_wait_policy.hpp"

namespace {

struct Command {
  const char* name;
  const char* arguments;  ///< shown after the name in the list
  const char* summary;    ///< one line of the list
  int (*function)(int argc, char** argv);  ///< given the command line from the command's name on
  bool steps_simulation;  ///< takes the passive OpenMP wait policy (openmp_wait_policy.hpp)
};

int resumeCommand(int argc, char** argv);
int probeCommand(int argc, char** argv);

const std::vector<Command> kCommands = {
    {"run", "ARGS", "run a scenario offline: loads.csv, summary.json, checkpoint.bin, snapshots",
     thin_ice::cli::runCommand, true},
    {"resume", "DIR [ARGS]", "go on with the run in DIR to a new target (thin_ice run --resume DIR [ARGS])",
     resumeCommand, true},
    {"sheet", "ARGS", "generate a Voronoi ice sheet from a YAML file: picture, polygons, statistics",
     thin_ice::cli::sheetCommand, false},
    {"analyse", "RUN_DIR [--write-bins]", "a finished run's load statistics worked out again from its load record (JSON)",
     thin_ice::cli::analyseCommand, false},
    {"parameters", "--scenario FILE [--set K=V]", "a scenario's whole parameter set as resolved (bases, overrides, rules)",
     thin_ice::cli::parametersCommand, false},
    {"probe", "PROBE ARGS", "the investigation probes of the model (thin_ice probe --help lists them)",
     probeCommand, false},
};

const std::vector<Command> kProbes = {
    {"edge-check", "ARGS", "cuts near the sheet's front edge against the floating plate's P_crit (table)",
     thin_ice::cli::probeEdgeCheck, false},
    {"edge-balance", "RUN_DIR", "the front row's vertical force balance in a run, snapshot by snapshot (table)",
     thin_ice::cli::probeEdgeBalance, false},
    {"bond-offset", "ARGS", "what the bond law makes of a slope of the sheet alone (JSON)",
     thin_ice::cli::probeBondOffset, false},
    {"profiles", "RUN_DIR", "the rubble pile's side and top profiles from one of a run's snapshots",
     thin_ice::cli::probeProfiles, false},
};

/// main's argv: the restart that sets the OpenMP wait policy needs the whole command line.
char** g_program_argv = nullptr;

bool asksForHelp(const std::string& arg) { return arg == "help" || arg == "--help" || arg == "-h"; }

void printList(std::FILE* stream, const char* usage, const std::vector<Command>& commands) {
  std::fprintf(stream, "%s", usage);
  for (const Command& c : commands) {
    const std::string call = std::string(c.name) + " " + c.arguments;
    std::fprintf(stream, "  %-24s %s\n", call.c_str(), c.summary);
  }
}

std::string names(const std::vector<Command>& commands) {
  std::string list;
  for (const Command& c : commands) list += (list.empty() ? "" : " ") + std::string(c.name);
  return list;
}

/// Runs the command of `commands` that argv[0] names, given the command line from its name on;
/// an unknown name is one line on stderr, exit status 2. `program` is what the messages begin
/// with, `what` the kind of name ("command", "probe").
int dispatch(const char* program, const char* what, const std::vector<Command>& commands, int argc, char** argv) {
  const std::string name = argv[0];
  for (const Command& c : commands) {
    if (name != c.name) continue;
    // libgomp reads the wait policy before main runs: the program starts again with it set.
    if (c.steps_simulation) thin_ice::restartWithPassiveOpenMpWaitUnlessSet(g_program_argv);
    return c.function(argc, argv);
  }
  std::fprintf(stderr, "%s: unknown %s '%s'; allowed: %s\n", program, what, name.c_str(), names(commands).c_str());
  return 2;
}

/// `thin_ice resume DIR [ARGS]`: `thin_ice run --resume DIR [ARGS]`, messages and all.
int resumeCommand(int argc, char** argv) {
  const std::string dir = argc > 1 ? argv[1] : "";
  static char run_name[] = "run";
  if (dir == "--help" || dir == "-h") {  // not "help": that may be a run directory's name
    static char help[] = "--help";
    char* run_help[] = {run_name, help, nullptr};
    return thin_ice::cli::runCommand(2, run_help);
  }
  if (dir.empty() || dir[0] == '-') {
    std::fprintf(stderr, "thin_ice resume: the run directory comes first: thin_ice resume DIR [ARGS], ARGS as for "
                         "thin_ice run --resume DIR (thin_ice run --help)\n");
    return 2;
  }
  static char resume_flag[] = "--resume";
  std::vector<char*> run_argv = {run_name, resume_flag};
  for (int k = 1; k < argc; ++k) run_argv.push_back(argv[k]);
  run_argv.push_back(nullptr);
  return thin_ice::cli::runCommand(static_cast<int>(run_argv.size()) - 1, run_argv.data());
}

/// `thin_ice probe PROBE ARGS`.
int probeCommand(int argc, char** argv) {
  const char* usage = "usage: thin_ice probe PROBE [ARGS]   (thin_ice probe PROBE --help: its usage)\n";
  if (argc < 2) {
    printList(stderr, usage, kProbes);
    return 2;
  }
  if (asksForHelp(argv[1])) {
    printList(stdout, usage, kProbes);
    return 0;
  }
  return dispatch("thin_ice probe", "probe", kProbes, argc - 1, argv + 1);
}

}  // namespace

int main(int argc, char** argv) {
  const char* usage = "usage: thin_ice COMMAND [ARGS]   (thin_ice COMMAND --help: its usage)\n";
  if (argc < 2) {
    printList(stderr, usage, kCommands);
    return 2;
  }
  if (asksForHelp(argv[1])) {
    printList(stdout, usage, kCommands);
    return 0;
  }
  g_program_argv = argv;
  return dispatch("thin_ice", "command", kCommands, argc - 1, argv + 1);
}
