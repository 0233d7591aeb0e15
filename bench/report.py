#!/usr/bin/python3
"""Builds bench/RESULTS.md and its PNG plots from the raw output that scripts/bench collected in
one run directory (every figure in the report comes from that one run on one machine):

  cpu_<N>.md          thin_ice_bench tables, one process per sheet size N (gpu_<N>.md: --backend cuda)
  rebuild_<N>.md      the same sheet with a contact rebuild at every step (Algorithm 1, N_iter = 1)
  kernels.json        thin_ice_bench_kernels (Google Benchmark JSON)
  liggghts.log        LIGGGHTS output of the 3-D DEM comparison, liggghts.json its set-up
  tim_dem/summary.json  `thin_ice run` on the same sheet for the same simulated time
  rtf_<ID>/summary.json `thin_ice run` of each validation scenario (real-time factor)
  machine.json        machine, date, commands
  busy_threads.csv    bench/busy_threads: the quick run beside a busy loop per core, by thread count and wait policy

  report.py --run DIR --out DIR
"""
import argparse
import csv
import glob
import json
import math
import os
import re
import statistics
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "scripts"))
from thin_ice_study import run_record  # noqa: E402
from thin_ice_study.png_output import save_png  # noqa: E402

import device_results  # noqa: E402  (beside this file)


def read_table(path):
    """Rows of a Markdown table as dicts keyed by the header cells."""
    rows, header = [], None
    with open(path) as f:
        for line in f:
            if not line.startswith("|"):
                continue
            cells = [c.strip() for c in line.strip().strip("|").split("|")]
            if header is None:
                header = cells
            elif not set(cells[0]) <= set("-:"):
                rows.append(dict(zip(header, cells)))
    return rows


def fit_exponent(xs, ys):
    """Least-squares slope of log y against log x."""
    lx, ly = [math.log(x) for x in xs], [math.log(y) for y in ys]
    mx, my = sum(lx) / len(lx), sum(ly) / len(ly)
    return sum((a - mx) * (b - my) for a, b in zip(lx, ly)) / sum((a - mx) ** 2 for a in lx)


def cpu_section(run, out, lines):
    rows = []
    paths = glob.glob(os.path.join(run, "cpu_*.md")) + glob.glob(os.path.join(run, "gpu_*.md"))
    for path in sorted(paths, key=lambda p: (os.path.basename(p)[:3], int(re.findall(r"\d+", p)[-1]))):
        rows += read_table(path)
    if not rows:
        return
    lines += ["## Throughput and scaling (whole time step)", "",
              "M-2 ice (h = 0.051 m, E = 328 MPa), 0.2 m cells, dt = 4e-6 s; a 2:1 sheet of about the given",
              "number of cells, kept away from the structure. \"broken field\": every bond marked broken before",
              "the first step, so that the pieces, still touching edge to edge, are held together by DEM contacts",
              "only (earlier versions of this table set strengths of 1 Pa instead, so the bonds broke in the first step and",
              "pushed the pieces apart: those figures are not comparable with these). Memory: growth of the",
              "process's peak resident set per cell (sheet generation included: an upper bound); on the GPU, the",
              "device memory held after the steps (cudaMemGetInfo), not the peak of a rebuild's temporaries.", ""]
    header = list(rows[0].keys())
    lines += ["| " + " | ".join(header) + " |", "|" + "---:|" * len(header)]
    lines += ["| " + " | ".join(r[h] for h in header) + " |" for r in rows]
    lines.append("")
    # Scaling: time per step against cells, per (sheet, threads).
    series = {}
    for r in rows:
        key = (r["sheet"], r["backend"], r["threads"])
        cells, rate = int(r["cells"]), float(r["cell-steps/s"])
        series.setdefault(key, []).append((cells, cells / rate))
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(11, 4.2))
    lines += ["Fitted exponent p of the time per step, t ~ N^p, over the sizes measured:", ""]
    for (sheet, backend, threads), pts in sorted(series.items()):
        pts.sort()
        xs, ts = [p[0] for p in pts], [p[1] for p in pts]
        label = f"{sheet}, {backend}" + ("" if threads == "-" else f", {threads} thread{'s' if threads != '1' else ''}")
        ax1.loglog(xs, ts, "o-", label=label)
        ax2.semilogx(xs, [x / t for x, t in zip(xs, ts)], "o-", label=label)
        if len(xs) >= 2:
            lines.append(f"- {label}: p = {fit_exponent(xs, ts):.3f} (N = {xs[0]} to {xs[-1]})")
    lines.append("")
    ax1.set_xlabel("cells N")
    ax1.set_ylabel("wall time per step [s]")
    ax1.grid(True, which="both", alpha=0.3)
    ax2.set_xlabel("cells N")
    ax2.set_ylabel("cell-steps per second")
    ax2.axhline(2e7, color="k", ls="--", lw=1, label="target 2e7 (10^4 cells, 2 threads)")
    ax2.grid(True, which="both", alpha=0.3)
    ax2.legend(fontsize=7)
    fig.suptitle("thin_ice_sim CPU backend: scaling with the number of cells")
    fig.tight_layout()
    save_png(fig, os.path.join(out, "scaling.png"), dpi=110)
    plt.close(fig)
    lines += ["![Scaling](scaling.png)", ""]


def rebuild_section(run, lines):
    normal = {}
    for path in glob.glob(os.path.join(run, "cpu_*.md")):
        for r in read_table(path):
            normal[(int(r["cells"]), r["sheet"], r["backend"], r["threads"])] = r
    out = []
    for path in sorted(glob.glob(os.path.join(run, "rebuild_*.md")), key=lambda p: int(re.findall(r"\d+", p)[-1])):
        for r in read_table(path):
            cells, backend, threads = int(r["cells"]), r["backend"], r["threads"]
            base_sheet = "intact, bonded" if r["sheet"].startswith("intact") else "broken field"
            base = normal.get((cells, base_sheet, backend, threads))
            if base is None:
                continue
            t_every = float(r["wall [s]"]) / int(r["steps"])
            t_base = float(base["wall [s]"]) / int(base["steps"])
            cost = t_every - t_base
            cost_text = (f"{1e3 * cost:.3f} | {cost / t_base:.2f}" if cost > 0 else "within noise | -")
            out.append(f"| {cells} | {base_sheet} | {backend} | {threads} | {1e3 * t_base:.3f} | {1e3 * t_every:.3f} | "
                       f"{cost_text} |")
    if out:
        lines += ["## Cost of one contact rebuild", "",
                  "The same sheet run with a rebuild at every step (N_iter = 1) and with the scenario's N_iter;",
                  "the difference of the step times is one rebuild (neighbour search, bond filter, S_ref carried,",
                  "incidence lists). The intact sheet gives the clean figure: its own run rebuilds only every",
                  "N_iter steps. The broken field's pieces drift, so its own run already rebuilds often and the",
                  "difference understates a rebuild (at 1e6 cells, 20 steps, it can vanish in the noise).", "",
                  "| cells | sheet | backend | threads | step [ms] | step with rebuild [ms] | rebuild [ms] | rebuild / step |",
                  "|---:|---|---|---:|---:|---:|---:|---:|"] + out + [""]


def kernels_section(run, lines):
    path = os.path.join(run, "kernels.json")
    if not os.path.exists(path):
        return
    with open(path) as f:
        data = json.load(f)
    bench = {b["name"]: b for b in data["benchmarks"]}
    ctx = data.get("context", {})
    lines += ["## Kernel micro-benchmarks (Google Benchmark)", "",
              f"libbenchmark {ctx.get('library_build_type', '?')} build as packaged by Debian; "
              f"{ctx.get('num_cpus', '?')} CPUs at {ctx.get('mhz_per_cpu', '?')} MHz; one thread.", ""]
    ours, boost = bench.get("BM_PolygonOverlap_IntegerClip"), bench.get("BM_PolygonOverlap_BoostGeometry")
    if ours and boost:
        lines += ["### Convex polygon overlap: the integer-grid clip against Boost.Geometry", "",
                  "4096 pairs of bonded Voronoi cells (0.2 m) of a generated sheet, the second pushed 1-30 mm",
                  "into the first and turned by up to 2 degrees. Boost.Geometry: intersection() + area() +",
                  "centroid(); ours also gives the chord and normal of Eq. (1).", "",
                  "| kernel | pairs per second | ratio |", "|---|---:|---:|",
                  f"| integer clip (this project) | {ours['pairs_per_s']:.3g} | {ours['pairs_per_s'] / boost['pairs_per_s']:.1f} |",
                  f"| Boost.Geometry intersection | {boost['pairs_per_s']:.3g} | 1 |", "",
                  f"Agreement: largest overlap-area difference {ours['max_area_diff_m2']:.2e} m^2 over all pairs "
                  f"(largest overlap {ours['largest_overlap_m2']:.2e} m^2).", ""]
    rows = []
    for name, b in bench.items():
        m = re.match(r"BM_NeighbourSearch_(\w+)/(\d+)", name)
        if m:
            rows.append((int(m.group(2)), m.group(1), b))
    if rows:
        lines += ["### Neighbour search: the cell list against nanoflann and brute force", "",
                  "Jittered grid of N centroids at 0.2 m pitch, radius 0.5 m, every pair i < j (the KD-tree: built",
                  "and queried once per point).", "",
                  "| N | search | time [ms] | points per second | same pairs as the KD-tree |", "|---:|---|---:|---:|---|"]
        for n, kind, b in sorted(rows, key=lambda r: (r[0], r[1])):
            same = b.get("same_pairs_as_kdtree")
            same_text = "" if same is None else ("yes" if same == 1 else "NO")
            lines.append(f"| {n} | {kind} | {b['real_time']:.3f} | {b['points_per_s']:.3g} | {same_text} |")
        lines.append("")


def window_text(run, sim_time):
    """What happened in thin_ice_sim's comparison window, read off its loads.csv (through the run
    record's reader, scripts/thin_ice_study/run_record.py)."""
    tim_dem = os.path.join(run, "tim_dem")
    contact, broken = None, 0
    if os.path.exists(os.path.join(tim_dem, run_record.LOADS_FILE)):
        for r in run_record.read_load_rows(tim_dem):
            if contact is None and float(r[run_record.HORIZONTAL_RAW]) > 0.0:
                contact = float(r[run_record.TIME])
            broken = int(r[run_record.BROKEN_BONDS])
    if contact is None:
        return (f"The window is the first {sim_time:.3g} s of pushing: thin_ice_sim's sheet has not reached the "
                "structure in it, so this is the cost of the intact sheet being pushed, before any breaking or piling.")
    return (f"The window is the first {sim_time:.3g} s of pushing: thin_ice_sim's sheet reaches the structure "
            f"at t = {contact:.2f} s and has {broken} broken bonds at the end, so the window holds the structure "
            "contact (its sub-steps included)" + (" and the first failure of the sheet." if broken > 0 else
                                                   ", but no failure of the sheet yet."))


def liggghts_build_text(vector_instructions):
    """What objdump found in LIGGGHTS's library (scripts/bench counts AVX and FMA instructions)."""
    if vector_instructions is None:
        return "its instruction set was not checked (no objdump, or no library found)"
    if vector_instructions == 0:
        return "built for the x86-64 baseline (objdump finds no AVX or FMA instruction in its library)"
    return f"its library holds {vector_instructions} AVX or FMA instructions"


def dem_section(run, out, lines):
    log, setup, tim = (os.path.join(run, p) for p in ("liggghts.log", "liggghts.json", "tim_dem/summary.json"))
    if not (os.path.exists(log) and os.path.exists(setup) and os.path.exists(tim)):
        return
    with open(setup) as f:
        s = json.load(f)
    with open(tim) as f:
        t = json.load(f)
    base_path = os.path.join(run, "tim_dem_baseline", "summary.json")
    base = None
    if os.path.exists(base_path):
        with open(base_path) as f:
            base = json.load(f)
    loop = None
    with open(log) as f:
        for line in f:
            m = re.match(r"Loop time of ([\d.eE+-]+) on (\d+) procs for (\d+) steps with (\d+) atoms", line)
            if m:
                loop = (float(m.group(1)), int(m.group(2)), int(m.group(3)), int(m.group(4)))
    if loop is None:
        lines += ["## Side by side with 3-D DEM (LIGGGHTS)", "", "LIGGGHTS did not finish: see its log.", ""]
        return
    wall, procs, steps, atoms = loop
    sim_time = steps * s["dt"]
    lig_per_sim = wall / sim_time
    tim_per_sim = t["wall_time_s"] / t["simulated_time_s"]
    tim_steps = round(t["simulated_time_s"] / t["time_step_s"])
    isa = t.get("cpu_instruction_set", "instruction set not recorded")
    table = ["| model | bodies | time step [s] | steps | simulated [s] | wall [s] | wall per simulated second [s] |",
             "|---|---:|---:|---:|---:|---:|---:|",
             f"| LIGGGHTS 3.8 (3-D DEM) | {atoms} spheres | {s['dt']:.3g} | {steps} | {sim_time:.4g} | {wall:.2f} | {lig_per_sim:.4g} |",
             f"| thin_ice_sim CPU ({isa}) | {t['cells']} cells | {t['time_step_s']:.3g} | {tim_steps} | {t['simulated_time_s']:.4g} | "
             f"{t['wall_time_s']:.2f} | {tim_per_sim:.4g} |"]
    if base is not None:
        base_per_sim = base["wall_time_s"] / base["simulated_time_s"]
        table.append(f"| thin_ice_sim CPU (baseline) | {base['cells']} cells | {base['time_step_s']:.3g} | "
                     f"{round(base['simulated_time_s'] / base['time_step_s'])} | {base['simulated_time_s']:.4g} | "
                     f"{base['wall_time_s']:.2f} | {base_per_sim:.4g} |")
    lines += ["## Side by side with 3-D DEM (LIGGGHTS 3.8)", "",
              f"The M-2 sheet ({s['length']} m x {s['width']} m, h = {s['diameter']} m) pushed at {s['velocity']} m/s",
              "against the 60-degree face between side walls, for the same simulated time on the same machine",
              f"and cores. LIGGGHTS: one layer of {atoms} spheres of diameter h (Hertz, tangential history,",
              "buoyancy, unbonded: the Debian build has no bonds), dt = a fraction of the Rayleigh time,",
              f"{procs} MPI processes. thin_ice_sim: the M-2 scenario, {t['cells']} cells, its own dt, 2 threads.",
              "Inputs: bench/liggghts/sheet.in, bench/liggghts/make_meshes.py; the exact command is below.",
              window_text(run, sim_time), ""] + table + ["",
              f"**Ratio: thin_ice_sim is {lig_per_sim / tim_per_sim:.1f} times faster per simulated second** "
              f"(per time step: {wall / steps / (t['wall_time_s'] / tim_steps):.1f} times). thin_ice_sim steps at the",
              f"{t['time_step_s']:.3g} s its ice's springs allow (critical step {t['critical_time_step_s']:.3g} s); the structure",
              f"contact (K_struct of Eq. 17; critical step {t['structure_critical_time_step_s']:.3g} s with it counted) is stepped",
              f"in {t['structure_substeps']} sub-step(s) for the cells that can reach the face (docs/model.md, Time stepping).", "",
              f"Compiled code: thin_ice_sim as this machine builds it, for {isa} (CMake's THIN_ICE_CPU_LEVEL),",
              "and LIGGGHTS as Debian ships it: " + liggghts_build_text(s.get("avx_or_fma_instructions")) + "."]
    if base is not None:
        lines += ["Like for like, thin_ice_sim built for the baseline too (\"baseline\" above): "
                  f"**{lig_per_sim / base_per_sim:.1f} times faster per simulated second**; the {isa} build is "
                  f"{base_per_sim / tim_per_sim:.2f} times as fast as the baseline build in this window."]
    lines += [""]
    lines += ["LIGGGHTS command (its files named from the repository root): `" + s["command"] + "`", ""]
    fig, ax = plt.subplots(figsize=(6, 3.2))
    names, values, colours = ["LIGGGHTS 3-D DEM", f"thin_ice_sim CPU\n({isa})"], [lig_per_sim, tim_per_sim], ["tab:gray", "tab:blue"]
    if base is not None:
        names.insert(1, "thin_ice_sim CPU\n(baseline)")
        values.insert(1, base_per_sim)
        colours.insert(1, "tab:cyan")
    ax.barh(names, values, color=colours)
    for k, v in enumerate(values):
        ax.text(v, k, f" {v:.0f} s", va="center", fontsize=8)
    ax.set_xlim(min(values) / 3, max(values) * 3)
    ax.set_xscale("log")
    ax.set_xlabel("wall seconds per simulated second (log)")
    title = f"M-2 sheet, same machine and cores: ratio {lig_per_sim / tim_per_sim:.1f}"
    if base is not None:
        title += f" ({isa} build),\n{lig_per_sim / base_per_sim:.1f} (baseline build, as LIGGGHTS's)"
    ax.set_title(title, fontsize=10)
    fig.tight_layout()
    save_png(fig, os.path.join(out, "dem_comparison.png"), dpi=110)
    plt.close(fig)
    lines += ["![3-D DEM comparison](dem_comparison.png)", ""]


def rtf_section(run, lines):
    rows = []
    for path in sorted(glob.glob(os.path.join(run, "rtf_*", "summary.json"))):
        with open(path) as f:
            t = json.load(f)
        name = os.path.basename(os.path.dirname(path))[4:]
        rows.append(f"| {name} | {t['cells']} | {t['time_step_s']:.3g} | {t['simulated_time_s']:.3g} | "
                    f"{t['wall_time_s']:.2f} | {t['real_time_factor']:.3g} | {t['cell_steps_per_second']:.3g} |")
    if rows:
        lines += ["## Real-time factor of the validation scenarios (CPU, 2 threads)", "",
                  "The first stretch of each full-width scenario: the intact sheet being pushed, before it reaches",
                  "the structure (first contact at about 0.3 s). The factor falls as the sheet breaks and contacts",
                  "multiply; the whole validation runs are below.", "",
                  "| scenario | cells | dt [s] | simulated [s] | wall [s] | real-time factor | cell-steps/s |",
                  "|---|---:|---:|---:|---:|---:|---:|"] + rows + [""]
    validation = []
    docs = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "docs", "validation")
    for path in sorted(glob.glob(os.path.join(docs, "strips", "*", "summary.json")) +
                       glob.glob(os.path.join(docs, "full", "*", "summary.json"))):
        with open(path) as f:
            v = json.load(f)
        if v.get("backend") != "cpu":
            continue
        validation.append(f"| {os.path.relpath(os.path.dirname(path), docs)} | {v['cells']} | {v['time_step_s']:.3g} / "
                          f"{v.get('structure_substeps', 1)} | {v['pushed_length_m']:.2f} | {v['wall_time_s']:.0f} | "
                          f"{v['real_time_factor']:.3g} |")
    if validation:
        lines += ["Whole validation runs on the CPU (docs/validation/, made by `scripts/study validate`, not in this bench",
                  "run, on the same machine; a run that shared the machine with other work is slower):", "",
                  "| run | cells | dt [s] / structure sub-steps | pushed length [m] | wall [s] | real-time factor |",
                  "|---|---:|---:|---:|---:|---:|"] + validation + [""]


def pile_section(run, lines):
    """The grown M-2 pile (bench/states/m2-pile: 6000 cells, 4362 pairs of touching slabs) stepped from its
    saved state on one and two threads: where a validation run spends its time."""
    rows = []
    for threads in (1, 2):
        path = os.path.join(run, f"pile_{threads}.md")
        if os.path.exists(path):
            rows += read_table(path)
    if rows:
        lines += ["## The grown pile (CPU)", "",
                  "`thin_ice_bench --state bench/states/m2-pile`: full-width M-2 at L = 7.82 m with its rubble pile,",
                  "stepped from the saved state (docs/performance.md says where the step's time goes).", "",
                  "| threads | cells | contacts | steps | step [us] | real-time factor |",
                  "|---:|---:|---:|---:|---:|---:|"]
        lines += [f"| {r['threads']} | {r['cells']} | {r['contacts']} | {r['steps']} | {r['step [us]']} | "
                  f"{r['real-time factor']} |" for r in rows]
        lines.append("")
    pile_against_reference(run, lines)


def pile_against_reference(run, lines):
    """The pile on one thread, this tree against the reference commit, timed in turn (scripts/bench):
    the ratio of each turn's two steps, and their median."""
    path = os.path.join(run, "pile_against_reference.csv")
    if not os.path.exists(path):
        return
    with open(path) as f:
        rows = list(csv.DictReader(f))
    reference = [r for r in rows if r["build"] == "reference"]
    current = [r for r in rows if r["build"] == "current"]
    if not reference or len(reference) != len(current):
        fail(f"{path}: {len(reference)} reference and {len(current)} current timings; allowed: as many of each, at least one")
    before = [float(r["step_us"]) for r in reference]
    after = [float(r["step_us"]) for r in current]
    ratios = [b / a for b, a in zip(before, after)]
    lines += [f"The same state on one thread, this tree ({current[0]['commit']}) against {reference[0]['commit']}, both built",
              "alike (plain CMake, no ROS, no CUDA) and timed in turn:", "",
              "| turn | step before [us] | step now [us] | times faster |", "|---:|---:|---:|---:|"]
    lines += [f"| {k + 1} | {b:.0f} | {a:.0f} | {r:.2f} |" for k, (b, a, r) in enumerate(zip(before, after, ratios))]
    lines += ["", f"Median: **{statistics.median(ratios):.2f} times faster** than {reference[0]['commit']}.", ""]


def busy_threads_section(run, lines):
    """The quick run on a machine whose every core is taken (bench/busy_threads), per thread count and
    OpenMP wait policy: the median wall time of the turns and their range, and how many ran out of time."""
    path = os.path.join(run, "busy_threads.csv")
    if not os.path.exists(path):
        return
    with open(path) as f:
        rows = list(csv.DictReader(f))
    cases = {}
    for r in rows:
        cases.setdefault((int(r["threads"]), r["wait_policy"]), []).append(r)
    if not cases:
        fail(f"{path}: no rows; allowed: the file bench/busy_threads writes")
    single = cases.get((1, "passive"))
    single_median = statistics.median(float(r["wall_s"]) for r in single) if single else None
    lines += ["## Threads on a busy machine (CPU)", "",
              "`bench/busy_threads`: the quick scenario (about 75 cells) for 1 s of simulated time (0.2 s with --quick) while a busy loop",
              "per core, at the same priority, keeps every core taken; the cases in turn. Threads 0 is the default",
              "(`numerics.threads: 0`: one thread below 2000 cells, all cores above). `thin_ice` sets the passive",
              "wait policy (a waiting thread sleeps) unless the environment names one; active is libgomp's own",
              "default (a waiting thread spins), named here through OMP_WAIT_POLICY.", "",
              "| threads | wait policy | runs | wall time, median [s] | range [s] | against one thread | stopped at the limit |",
              "|---:|---|---:|---:|---:|---:|---:|"]
    for (threads, policy), rs in sorted(cases.items(), key=lambda kv: (kv[0][0], kv[0][1] != "passive")):
        walls = [float(r["wall_s"]) for r in rs]
        median = statistics.median(walls)
        against = f"{median / single_median:.2f}" if single_median else "-"
        stopped = sum(r["exit_status"] == "124" for r in rs)
        lines.append(f"| {threads}{' (default)' if threads == 0 else ''} | {policy} | {len(rs)} | {median:.2f} | "
                     f"{min(walls):.2f}-{max(walls):.2f} | {against} | {stopped} |")
    lines.append("")


def fail(message):
    print(f"bench/report.py: {message}", file=sys.stderr)
    sys.exit(2)


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--run", required=True)
    p.add_argument("--out", required=True)
    a = p.parse_args()
    if not os.path.isdir(a.out):
        fail(f"--out {a.out}: no such folder; allowed: the folder RESULTS.md and its plots go to (bench)")
    try:
        with open(os.path.join(a.run, "machine.json")) as f:
            machine = json.load(f)
    except (OSError, ValueError) as e:
        fail(f"--run {a.run}: no readable machine.json ({e}); allowed: the folder scripts/bench wrote its run into")
    lines = ["# Benchmark results", "",
             "Regenerated from scratch by `scripts/bench`; every figure below comes from one run on one machine.", "",
             f"- machine: {machine['cpu']}, {machine['cores']} cores, {machine['memory_gib']} GiB",
             f"- date: {machine['date']}",
             f"- command: `{machine['command']}`",
             f"- GPU: {machine['gpu']}", ""]
    cpu_section(a.run, a.out, lines)
    rebuild_section(a.run, lines)
    kernels_section(a.run, lines)
    dem_section(a.run, a.out, lines)
    rtf_section(a.run, lines)
    pile_section(a.run, lines)
    busy_threads_section(a.run, lines)
    # The GPU figures come from the committed device runs (a GPU is lent to some sessions only).
    lines += [""] + device_results.device_section(os.path.dirname(os.path.abspath(__file__))) + [""]
    path = os.path.join(a.out, "RESULTS.md")
    with open(path + ".partial", "w") as f:
        f.write("\n".join(lines))
    os.replace(path + ".partial", path)


if __name__ == "__main__":
    main()
