// The subcommands of the one command-line program, `thin_ice` (thin_ice.cpp dispatches to them).
// Each takes the command line from its own name on: argv[0] is the subcommand's name ("run",
// "edge-check"), its arguments follow, and it returns the program's exit status.
#pragma once

namespace thin_ice::cli {

/// `thin_ice run`: one scenario offline, or `--resume DIR` (run_command.cpp). The caller sets the
/// OpenMP wait policy first (thin_ice_sim/openmp_wait_policy.hpp), with the program's whole argv.
int runCommand(int argc, char** argv);

/// `thin_ice sheet`: a Voronoi ice sheet from a YAML file (sheet_command.cpp).
int sheetCommand(int argc, char** argv);

/// `thin_ice analyse`: a finished run's load statistics again, as JSON (analyse_command.cpp).
int analyseCommand(int argc, char** argv);

/// `thin_ice parameters`: a scenario's resolved parameter set, as a scenario file (parameters_command.cpp).
int parametersCommand(int argc, char** argv);

/// `thin_ice probe edge-check`: cuts near the front edge against P_crit (probe_edge_check.cpp).
int probeEdgeCheck(int argc, char** argv);

/// `thin_ice probe edge-balance`: the front row's vertical force balance (probe_edge_balance.cpp).
int probeEdgeBalance(int argc, char** argv);

/// `thin_ice probe bond-offset`: the bond law under a slope of the sheet (probe_bond_offset.cpp).
int probeBondOffset(int argc, char** argv);

/// `thin_ice probe profiles`: the rubble pile's profiles from a run's snapshot (probe_profiles.cpp).
int probeProfiles(int argc, char** argv);

}  // namespace thin_ice::cli
