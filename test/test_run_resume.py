#!/usr/bin/python3
"""`thin_ice run --resume` (and `thin_ice resume`, the same): a run stopped at t = 0.4 s and resumed
to 0.8 s writes the same loads.csv, byte for byte, as the run made in one go, and a summary whose
statistics cover the whole history (and one resumed from its checkpoint, load_bins.csv and summary
alone, as a clone keeps a run in progress, the same bins and statistics); one stopped between rows (t = 0.41 s) writes the same rows
again from the second row boundary on;
the first failure, which starts phase 1, is found whether it lies before or after the resumption;
an override given with --resume holds from the resumption on (rows before it unchanged, after it
changed, the summary saying from which L) and stays through a later resumption; a directory that
cannot be resumed, an override of a key a run under way cannot change, or a false bottom raised
through the ice over it, is refused with exit status 2 and the directory left as it was.

    test_run_resume.py THIN_ICE SOURCE_DIR   (THIN_ICE: the thin_ice program)
"""
import csv
import json
import os
import re
import shutil
import signal
import subprocess
import sys
import tempfile
import time

from quick_strip import refusal_problem, strip_scenario


def command(thin_ice, args):
    """`thin_ice resume ARGS...` where `args` begin with "resume", else `thin_ice run ARGS`."""
    return [thin_ice] + args if args[:1] == ["resume"] else [thin_ice, "run"] + args


def run(thin_ice, args):
    return subprocess.run(command(thin_ice, args), stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                          timeout=600)


def stopped_early(thin_ice, args, out):
    """Runs `thin_ice run` with `args`, sends SIGTERM once out/loads.csv.partial exists (or after 60
    s), and returns its exit status and the summary it wrote ({} if none)."""
    proc = subprocess.Popen(command(thin_ice, args), stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    deadline = time.monotonic() + 60
    while proc.poll() is None and time.monotonic() < deadline and \
            not os.path.exists(os.path.join(out, "loads.csv.partial")):
        time.sleep(0.02)
    if proc.poll() is None:
        proc.send_signal(signal.SIGTERM)
    code = proc.wait(timeout=600)
    try:
        with open(os.path.join(out, "summary.json")) as f:
            return code, json.load(f)
    except (OSError, ValueError):
        return code, {}


def main():
    thin_ice, source = sys.argv[1], sys.argv[2]
    scenario = strip_scenario(source) + ["--output-interval", "0.02"]
    failures = []
    with tempfile.TemporaryDirectory() as tmp:
        whole, split, off_grid, early, switched, floating, no_bottom, kept_only = (
            os.path.join(tmp, d) for d in ("whole", "split", "off_grid", "early", "switched", "floating", "no_bottom",
                                           "kept_only"))
        for args in (scenario + ["--until-time", "0.8", "--out", whole],
                     scenario + ["--until-time", "0.4", "--out", split],
                     ["resume", split, "--until-time", "0.8"],  # the same as run --resume
                     scenario + ["--until-time", "0.2", "--out", early],  # before contact: no bond broken yet
                     ["--resume", early, "--until-time", "0.8"],
                     scenario + ["--until-time", "0.41", "--out", off_grid],
                     ["--resume", off_grid, "--until-time", "0.8"],
                     # twice the ice-ice friction from 0.4 s (L = 0.08 m) on, kept through a second resumption
                     scenario + ["--until-time", "0.4", "--out", switched],
                     ["--resume", switched, "--set", "ice.friction_ice_ice=0.6", "--until-time", "0.8"],
                     ["--resume", switched, "--until-time", "0.9"],
                     # the strip afloat over the false bottom (by 0.8 s it has ridden up the face)
                     scenario + ["--until-time", "0.25", "--snapshots", "1", "--out", floating],
                     scenario + ["--set", "bottom.enabled=false", "--until-time", "0.05", "--out", no_bottom]):
            done = run(thin_ice, args)
            if done.returncode != 0:
                sys.exit(f"FAIL: {' '.join(args)}: exit status {done.returncode}: {done.stderr.strip()}")
        # What a clone keeps of a run in progress: its checkpoint, load_bins.csv and summary, not
        # loads.csv. Resumed from those alone, then once more with the segment's own loads.csv.
        for args in (scenario + ["--until-time", "0.4", "--out", kept_only],
                     ["resume", kept_only, "--snapshots", "1", "--until-time", "0.8"],
                     ["resume", kept_only, "--until-time", "0.9"]):
            if args[0] == "resume" and args[-1] == "0.8":
                os.remove(os.path.join(kept_only, "loads.csv"))
            done = run(thin_ice, args)
            if done.returncode != 0:
                sys.exit(f"FAIL: {' '.join(args)}: exit status {done.returncode}: {done.stderr.strip()}")
            if args[-1] == "0.8":
                kept_rows = open(os.path.join(kept_only, "loads.csv")).read().splitlines()
                sk = json.load(open(os.path.join(kept_only, "summary.json")))
                bins_kept = list(csv.DictReader(open(os.path.join(kept_only, "load_bins.csv"))))
        with open(os.path.join(whole, "loads.csv")) as a, open(os.path.join(split, "loads.csv")) as b:
            if a.read() != b.read():
                failures.append("the resumed loads.csv differs from the run made in one go")
        sw, ss = (json.load(open(os.path.join(d, "summary.json"))) for d in (whole, split))
        if ss["status"] != "completed" or ss["resumed_at_m"] != [0.08] or sw["resumed_at_m"] != []:
            failures.append(f"status {ss['status']}, resumed_at_m {ss['resumed_at_m']} (whole: {sw['resumed_at_m']}), "
                            "expected completed, [0.08] ([])")
        if ss["steps"] != sw["steps"] or ss["broken_bonds"] != sw["broken_bonds"]:
            failures.append(f"steps {ss['steps']} / {sw['steps']}, broken bonds {ss['broken_bonds']} / {sw['broken_bonds']}")
        # The old rows are read back from their nine significant digits. The first failure (which
        # starts phase 1) lies before the split at 0.4 s and after the one at 0.2 s.
        se = json.load(open(os.path.join(early, "summary.json")))
        if sw["load"]["first_failure_m"] is None:
            failures.append("no bond broke in the strip run: the first failure is not tested")
        for name, resumed in (("resumed at 0.4 s", ss), ("resumed at 0.2 s", se)):
            for key in ("peak_N", "steady_mean_N", "phase1_slope_N_per_m", "first_failure_m"):
                a, b = sw["load"][key], resumed["load"][key]
                if (a is None) != (b is None) or (a is not None and abs(a - b) > 1e-7 * max(1.0, abs(a))):
                    failures.append(f"load.{key} {b} {name}, {a} in one go")
            if resumed["load"]["phase1_range_m"] != sw["load"]["phase1_range_m"]:
                failures.append(f"phase-1 range {resumed['load']['phase1_range_m']} {name}, "
                                f"{sw['load']['phase1_range_m']} in one go")
        # Resumed from the kept record alone: the same bins and statistics as in one go, a loads.csv
        # of the segment's rows (those of the one-go run after 0.4 s) that says where it begins.
        bins_whole = list(csv.DictReader(open(os.path.join(whole, "load_bins.csv"))))
        if len(bins_kept) != len(bins_whole) or any(
                a["bin"] != b["bin"] or a["samples"] != b["samples"] or
                abs(float(a[k]) - float(b[k])) > 1e-8 * max(1.0, abs(float(b[k])))
                for a, b in zip(bins_kept, bins_whole) for k in a if k not in ("bin", "samples")):
            failures.append(f"resumed without loads.csv: {len(bins_kept)} bins, {len(bins_whole)} in one go, or "
                            "their numbers differ")
        for key in ("peak_N", "peak_at_m", "steady_mean_N", "phase1_slope_N_per_m", "first_failure_m"):
            a, b = sw["load"][key], sk["load"][key]
            if (a is None) != (b is None) or (a is not None and abs(a - b) > 1e-7 * max(1.0, abs(a))):
                failures.append(f"load.{key} {b} resumed without loads.csv, {a} in one go")
        whole_lines = open(os.path.join(whole, "loads.csv")).read().splitlines()
        if kept_rows != whole_lines[:1] + whole_lines[21:] or sk["loads_csv_from_s"] != 0.4:
            failures.append(f"resumed without loads.csv: {len(kept_rows)} lines from t = {sk['loads_csv_from_s']} s; "
                            f"expected the header and the one-go run's {len(whole_lines) - 21} rows after 0.4 s")
        # Its snapshot is numbered by the whole run's rows (0.8 s at 0.02 s a row: the 40th), not
        # by the rows of its own loads.csv.
        index = open(os.path.join(kept_only, "snapshots", "index.csv")).read().splitlines()
        if len(index) != 2 or not index[1].startswith("cells_000040.csv,0.8,"):
            failures.append(f"resumed without loads.csv: snapshots/index.csv {index}; expected cells_000040.csv at 0.8 s")
        sk9 = json.load(open(os.path.join(kept_only, "summary.json")))
        if sk9["status"] != "completed" or sk9["loads_csv_from_s"] != 0.4 or sk9["resumed_at_m"] != [0.08, 0.16]:
            failures.append(f"resumed again with the segment's loads.csv: status {sk9['status']}, loads_csv_from_s "
                            f"{sk9['loads_csv_from_s']}, resumed_at_m {sk9['resumed_at_m']}")

        # Rows 0.02 s apart: after a short row ending at 0.41 s the next ends at 0.42 s (its loads
        # averaged over 0.41-0.42 s only), and from the one after each row is the one-go run's.
        whole_rows = open(os.path.join(whole, "loads.csv")).read().splitlines()
        off_rows = open(os.path.join(off_grid, "loads.csv")).read().splitlines()
        if (off_rows[:21] != whole_rows[:21] or not off_rows[21].startswith("0.41,") or
                not off_rows[22].startswith("0.42,") or off_rows[23:] != whole_rows[22:]):
            failures.append(f"resumed after a short row at 0.41 s: {len(off_rows)} lines, rows 21-22 "
                            f"{off_rows[21][:12]!r} {off_rows[22][:12]!r}; expected the one-go rows with a split row at 0.41 s")
        switched_rows = open(os.path.join(switched, "loads.csv")).read().splitlines()
        if switched_rows[:21] != whole_rows[:21] or switched_rows[21:41] == whole_rows[21:41]:
            failures.append("with ice.friction_ice_ice=0.6 from 0.4 s: the rows up to 0.4 s should be the one-go "
                            "run's and the rows after it should differ")
        st = json.load(open(os.path.join(switched, "summary.json")))
        if (st["scenario"]["overrides"][-1] != "ice.friction_ice_ice=0.6" or st["resumed_at_m"] != [0.08, 0.16] or
                st["overrides_from_m"] != [{"set": "ice.friction_ice_ice=0.6", "from_m": 0.08}] or
                sw["overrides_from_m"] != []):
            failures.append(f"switched run's summary: overrides {st['scenario']['overrides']}, resumed_at_m "
                            f"{st['resumed_at_m']}, overrides_from_m {st['overrides_from_m']} (one go: {sw['overrides_from_m']})")
        if abs(ss["load"]["peak_at_m"] - sw["load"]["peak_at_m"]) > 1e-9:
            failures.append(f"peak at {ss['load']['peak_at_m']} m after resuming, {sw['load']['peak_at_m']} in one go")

        # A run records its whole parameter set, and a resumption keeps it whatever became of the
        # scenario file: a copy of quick.yaml, run to 0.4 s, then changed (ice-ice friction 0.3 ->
        # 0.5, E_v from its rule to a stated 1.3e6 Pa, a comment). Resumed as it is,
        # the run keeps its own values and writes the one-go run's rows; resumed with
        # --accept-changed-scenario, it takes the file's, and its rows after 0.4 s differ.
        quick_copy = os.path.join(tmp, "quick_kept.yaml")
        shutil.copy(os.path.join(source, "config/scenarios/quick.yaml"), quick_copy)
        copy_args = ["--scenario", quick_copy] + scenario[2:]
        kept, taken = os.path.join(tmp, "kept_params"), os.path.join(tmp, "taken_params")
        for d in (kept, taken):
            done = run(thin_ice, copy_args + ["--until-time", "0.4", "--out", d])
            if done.returncode != 0:
                sys.exit(f"FAIL: the run to resume after its file changed: exit status {done.returncode}: {done.stderr.strip()}")
        recorded = json.load(open(os.path.join(kept, "summary.json"))).get("parameters", {})
        if recorded.get("ice.friction_ice_ice") != "0.3" or "ice.vertical_modulus" not in recorded or \
                "sheet.seed" not in recorded or recorded.get("ice.vertical_modulus_floating_plate_multiple") != "4":
            failures.append(f"summary.json parameters: {recorded}; expected every key, friction 0.3, E_v's rule")
        with open(quick_copy) as f:
            text = f.read()
        text = re.sub(r"(?m)^  friction_ice_ice: \S+", "  friction_ice_ice: 0.5", text)
        text = re.sub(r"(?m)^  vertical_modulus_floating_plate_multiple: \S+", "  vertical_modulus: 1.3e6", text)
        with open(quick_copy, "w") as f:
            f.write(text + "# changed after the run\n")
        kept_done = run(thin_ice, ["resume", kept, "--until-time", "0.8"])
        taken_done = run(thin_ice, ["resume", taken, "--accept-changed-scenario", "--until-time", "0.8"])
        kept_rows = open(os.path.join(kept, "loads.csv")).read().splitlines()
        taken_rows = open(os.path.join(taken, "loads.csv")).read().splitlines()
        sk_params = json.load(open(os.path.join(kept, "summary.json"))).get("parameters", {})
        st_params = json.load(open(os.path.join(taken, "summary.json"))).get("parameters", {})
        if (kept_done.returncode != 0 or "the run keeps its own" not in kept_done.stderr or
                "recorded no value" in kept_done.stderr or
                "ice.friction_ice_ice 0.5 (the run's: 0.3)" not in kept_done.stderr or kept_rows != whole_rows or
                sk_params != recorded):
            failures.append(f"resumed after its file changed: exit status {kept_done.returncode}, stderr "
                            f"{kept_done.stderr.strip()[-300:]!r}, rows as in one go: {kept_rows == whole_rows}, "
                            f"parameters kept: {sk_params == recorded}")
        if (taken_done.returncode != 0 or "the file's values taken" not in taken_done.stderr or
                st_params.get("ice.friction_ice_ice") != "0.5" or
                st_params.get("ice.vertical_modulus") != "1300000" or
                "ice.vertical_modulus_floating_plate_multiple" in st_params or
                taken_rows[:21] != whole_rows[:21] or taken_rows[21:] == whole_rows[21:]):
            failures.append(f"resumed with --accept-changed-scenario after its file changed: exit status "
                            f"{taken_done.returncode}, stderr {taken_done.stderr.strip()[-300:]!r}, friction "
                            f"{st_params.get('ice.friction_ice_ice')}; expected the file's values from 0.4 s on")

        # Refusals: nothing in the directories changes.
        def contents(directory):
            return {f: open(os.path.join(directory, f), "rb").read() for f in sorted(os.listdir(directory))
                    if os.path.isfile(os.path.join(directory, f))}

        corrupt = os.path.join(tmp, "corrupt")
        shutil.copytree(split, corrupt)
        with open(os.path.join(corrupt, "checkpoint.bin"), "r+b") as f:
            f.truncate(100)
        no_checkpoint = os.path.join(tmp, "no_checkpoint")
        shutil.copytree(split, no_checkpoint)
        os.remove(os.path.join(no_checkpoint, "checkpoint.bin"))
        # A run started from another directory names its scenario relative to that directory.
        elsewhere = os.path.join(tmp, "elsewhere")
        shutil.copytree(split, elsewhere)
        with open(os.path.join(elsewhere, "summary.json")) as f:
            summary = json.load(f)
        summary["scenario"]["file"] = "config/scenarios/not_here.yaml"
        with open(os.path.join(elsewhere, "summary.json"), "w") as f:
            json.dump(summary, f, indent=2)
        # A damaged checkpoint (one flipped bit in the contents) and damaged records (a row deleted
        # at the start, one in the middle) are refused before anything is appended.
        flipped, no_first_row, no_middle_row = (os.path.join(tmp, d) for d in ("flipped", "no_first_row", "no_middle_row"))
        for d in (flipped, no_first_row, no_middle_row):
            shutil.copytree(split, d)
        with open(os.path.join(flipped, "checkpoint.bin"), "r+b") as f:
            f.seek(200)
            byte = f.read(1)[0]
            f.seek(200)
            f.write(bytes([byte ^ 0x01]))
        for d, row in ((no_first_row, 1), (no_middle_row, 10)):
            with open(os.path.join(d, "loads.csv")) as f:
                lines = f.readlines()
            del lines[row]  # lines[0] is the header
            with open(os.path.join(d, "loads.csv"), "w") as f:
                f.writelines(lines)
        # An older copy of loads.csv than the checkpoint (its last 5 rows gone), and a run carried on
        # from its kept record whose load_bins.csv is then lost (loads.csv holds only the new rows).
        stale, unkept = os.path.join(tmp, "stale"), os.path.join(tmp, "unkept")
        shutil.copytree(split, stale)
        shutil.copytree(kept_only, unkept)
        with open(os.path.join(stale, "loads.csv")) as f:
            lines = f.readlines()
        with open(os.path.join(stale, "loads.csv"), "w") as f:
            f.writelines(lines[:-5])
        os.remove(os.path.join(unkept, "load_bins.csv"))
        before = {d: contents(d) for d in (split, corrupt, no_checkpoint, elsewhere, floating, no_bottom, flipped,
                                           no_first_row, no_middle_row, stale, unkept)}
        cases = [(["--resume", split, "--until-time", "0.8"], "already at t = 0.8"),
                 (["--resume", split, "--until-time", "1", "--out", tmp], "give none of them"),
                 # what a run under way cannot change: the mesh (spaces around the key too), the time
                 # stepping, the pusher's speed (the checkpoint holds it), the calibration factor
                 (["--resume", split, "--until-time", "1", "--set", "sheet.seed=2"], "sheet.seed cannot change"),
                 (["--resume", split, "--until-time", "1", "--set", " sheet . jitter = 0.2"], "sheet.jitter cannot change"),
                 (["--resume", split, "--until-time", "1", "--set", "numerics.time_step=1e-5"], "numerics.time_step cannot"),
                 (["--resume", split, "--until-time", "1", "--set", "pusher.velocity=0.1"], "pusher.velocity cannot"),
                 (["--resume", split, "--until-time", "1", "--set", "structure.calibration_factor=0.5"],
                  "structure.calibration_factor cannot"),
                 (["--resume", split, "--until-time", "1", "--set", "ice.nonsense=1"], "unknown key 'nonsense'"),
                 # a law that may switch, but whose value the run's time step cannot hold (checked
                 # again below: the message must not offer a smaller time step)
                 (["--resume", split, "--until-time", "1", "--set", "ice.youngs_modulus=2e10"],
                  "a run under way keeps its numerics.time_step"),
                 # the false bottom may move down under the ice, not up through the floating cells
                 # over it (their slab bottoms float at about z = -0.04 m), and not where there is none
                 (["--resume", floating, "--until-time", "1", "--set", "bottom.depth=0.01"],
                  "a bottom may move down under a run, not up through the ice over it"),
                 (["--resume", no_bottom, "--until-time", "1", "--set", "bottom.depth=0.5"],
                  "the run has no false bottom (bottom.enabled: false)"),
                 (["--resume", corrupt, "--until-time", "1"], "truncated"),
                 (["--resume", flipped, "--until-time", "1"], "the checksum does not match the contents"),
                 (["--resume", no_first_row, "--until-time", "1"], "row 1 (t = 0.04 s) comes 0.04 s after t = 0"),
                 (["--resume", no_middle_row, "--until-time", "1"], "row 10 (t = 0.22 s) comes 0.04 s after the row"),
                 (["--resume", no_checkpoint, "--until-time", "1"], "has no checkpoint.bin"),
                 (["--resume", stale, "--until-time", "1"], "an older copy of the record (remove it to go on from"),
                 (["--resume", unkept, "--until-time", "1"], "the run's kept record is missing"),
                 # `thin_ice resume DIR` refuses as `thin_ice run --resume DIR` does, in its words
                 (["resume", no_checkpoint, "--until-time", "1"], "thin_ice run: " + no_checkpoint + " has no"),
                 (["--resume", elsewhere, "--until-time", "1"], "relative to the directory the run was started from"),
                 (scenario + ["--until-time", "1", "--out", tmp, "--accept-changed-scenario"], "with --resume DIR only"),
                 # a fresh run into a directory holding another would mix the two runs' files
                 (scenario + ["--until-time", "1", "--out", split], "already holds a run (summary.json)"),
                 # step counts beyond a long: refused, not overflowed into an empty "completed" run
                 (scenario + ["--until-time", "1e300", "--out", os.path.join(tmp, "huge")], "time steps of"),
                 (strip_scenario(source) + ["--output-interval", "1e300", "--until-time", "1",
                                            "--out", os.path.join(tmp, "huge")], "time steps of"),
                 # past the end of the pusher's travel (the toe at 1.1 m): refused, not crushed into the face
                 (scenario + ["--until-length", "1.2", "--out", os.path.join(tmp, "far")],
                  "--until-length 1.2 m is beyond the pusher's travel: its face reaches the structure's toe after 1.1 m")]
        for args, expected in cases:
            done = run(thin_ice, args)
            if done.returncode != 2 or expected not in done.stderr:
                failures.append(f"{' '.join(args[-4:])}: exit status {done.returncode}, stderr {done.stderr.strip()!r}; "
                                f"expected 2 and {expected!r}")
        # The time-step refusal: one line, and no smaller time step or more sub-steps offered.
        stiff = ["--resume", split, "--until-time", "1", "--set", "ice.youngs_modulus=2e10"]
        problem = refusal_problem(command(thin_ice, stiff), "ice.youngs_modulus=2e10")
        stderr = run(thin_ice, stiff).stderr
        if problem or "allowed: <=" in stderr or "structure_substeps >=" in stderr:
            failures.append(f"the unstable switch's refusal: {problem or stderr.strip()!r}")
        # The bottom's refusal counts the cells the bottom acts on (polygon past its start, x = 0.6 m)
        # whose slab bottom is under the new plane, counted here from the run's last snapshot.
        with open(os.path.join(floating, "snapshots", "index.csv")) as f:
            last = list(csv.DictReader(f))[-1]["file"]
        h = 0.051  # [m] quick.yaml's ice.thickness
        under = 0
        with open(os.path.join(floating, "snapshots", last)) as f:
            for cell in csv.DictReader(f):
                xs = [float(v) for v in cell["polygon_xy_m"].split()[0::2]]
                under += max(xs) > 0.6 and float(cell["z_m"]) - h / 2 < -0.01 - 1e-3 * h
        shallow = run(thin_ice, ["--resume", floating, "--until-time", "1", "--set", "bottom.depth=0.01"]).stderr
        if not (0 < under < 50) or f": {under} cells over the false bottom" not in shallow:
            failures.append(f"the bottom's refusal should count {under} of the strip's 50 cells: {shallow.strip()!r}")
        # ... and a deeper bottom is taken, and said so in summary.json.
        deeper = os.path.join(tmp, "deeper")
        shutil.copytree(floating, deeper)
        done = run(thin_ice, ["--resume", deeper, "--until-time", "0.3", "--set", "bottom.depth=0.5"])
        if done.returncode != 0:
            failures.append(f"--set bottom.depth=0.5 with --resume: exit status {done.returncode}: {done.stderr.strip()}")
        else:
            sd = json.load(open(os.path.join(deeper, "summary.json")))
            if sd["false_bottom"]["depth_m"] != 0.5 or sd["overrides_from_m"] != [{"set": "bottom.depth=0.5", "from_m": sd["resumed_at_m"][-1]}]:
                failures.append(f"the deeper bottom's summary: {sd['false_bottom']}, {sd['overrides_from_m']}")
        # --until-length end: the target is the end of the pusher's travel (the toe at 1.1 m), for a
        # fresh run and a resumption alike; each is stopped by SIGTERM once it has begun its record.
        to_end = os.path.join(tmp, "to_end")
        for args in (scenario + ["--until-length", "end", "--out", to_end], ["--resume", to_end, "--until-length", "end"]):
            code, summary = stopped_early(thin_ice, args, to_end)
            if code != 4 or summary.get("status") != "interrupted" or summary.get("target") != {"pushed_length_m": 1.1}:
                failures.append(f"{' '.join(args[-3:])}: exit status {code}, status {summary.get('status')}, target "
                                f"{summary.get('target')}; expected 4, interrupted, {{'pushed_length_m': 1.1}}")
        for refused in ("huge", "far"):
            if os.path.exists(os.path.join(tmp, refused)):
                failures.append(f"a refused run created its --out directory ({refused})")
        for d, files in before.items():
            if contents(d) != files:
                failures.append(f"a refused resumption changed {os.path.basename(d)}/ ({sorted(contents(d))})")
        # A resumed segment that blows up (the scenario file's dt raised past the critical step, taken
        # with --accept-changed-scenario) leaves the run as it was, snapshots included; its rows go
        # to unhealthy_segment.csv (exit status 3).
        scenario_copy = os.path.join(tmp, "quick_copy.yaml")
        shutil.copy(os.path.join(source, "config/scenarios/quick.yaml"), scenario_copy)
        blown = os.path.join(tmp, "blown")
        # (rows of 1 ms and a snapshot due at every row of the resumed segment: it blows up at
        # t = 0.206 s, after five of them were written)
        done = run(thin_ice, ["--scenario", scenario_copy] + strip_scenario(source)[2:] +
                   ["--until-time", "0.2", "--output-interval", "0.001", "--snapshots", "2", "--out", blown])
        if done.returncode != 0:
            failures.append(f"the run to blow up later: exit status {done.returncode}: {done.stderr.strip()}")
        else:
            with open(scenario_copy) as f:
                text = f.read()
            text = re.sub(r"(?m)^  time_step: \S+", "  time_step: 1.0e-3", text)
            text = re.sub(r"(?m)^  critical_step_safety: \S+", "  critical_step_safety: 1000", text)
            with open(scenario_copy, "w") as f:
                f.write(text)
            before = {d: contents(d) for d in (blown, os.path.join(blown, "snapshots"))}
            done = run(thin_ice, ["--resume", blown, "--accept-changed-scenario", "--until-time", "0.6", "--snapshots", "400"])
            after = {d: contents(d) for d in before}
            kept = {d: {f: v for f, v in after[d].items() if f != "unhealthy_segment.csv"} for d in after}
            if done.returncode != 3 or kept != before or "unhealthy_segment.csv" not in after[blown]:
                failures.append(f"a resumed segment that blew up: exit status {done.returncode} (expected 3), "
                                f"files changed: {[f for d in after for f in after[d] if before[d].get(f) != after[d][f]]}")
        # A scenario file stiffened under --accept-changed-scenario past what the run's time step
        # holds is refused as that, whatever --set is given beside it (harmless or unstable too),
        # and offers no smaller time step; a file changed harmlessly leaves the blame with the
        # unstable --set.
        for stiffen, extras, blamed in (
                (True, ([], ["--set", "ice.friction_ice_ice=0.4"], ["--set", "ice.vertical_modulus=2e10"]),
                 "thin_ice run: the run's scenario as it reads now ("),
                (False, (["--set", "ice.youngs_modulus=2e10"],), "thin_ice run: --set 'ice.youngs_modulus=2e10' with")):
            name = "stiffened" if stiffen else "retouched"
            scenario_file = os.path.join(tmp, f"quick_{name}.yaml")
            shutil.copy(os.path.join(source, "config/scenarios/quick.yaml"), scenario_file)
            changed = os.path.join(tmp, name)
            done = run(thin_ice, ["--scenario", scenario_file] + strip_scenario(source)[2:] +
                       ["--until-time", "0.05", "--out", changed])
            if done.returncode != 0:
                failures.append(f"the run to be {name}: exit status {done.returncode}: {done.stderr.strip()}")
                continue
            with open(scenario_file) as f:
                text = f.read()
            with open(scenario_file, "w") as f:
                f.write(re.sub(r"(?m)^  youngs_modulus: \S+", "  youngs_modulus: 2e10", text) if stiffen
                        else text + "# a comment added after the run\n")
            before = contents(changed)
            for extra in extras:
                done = run(thin_ice, ["--resume", changed, "--accept-changed-scenario", "--until-time", "0.1"] + extra)
                last = (done.stderr.strip().splitlines() or [""])[-1]
                innocent = stiffen and extra and "2e10" not in extra[-1]
                if (done.returncode != 2 or not last.startswith(blamed) or "allowed: <=" in last or
                        (innocent and extra[-1] in last) or contents(changed) != before):
                    failures.append(f"the {name} file, {' '.join(extra) or 'no --set'}: exit status "
                                    f"{done.returncode}, stderr {done.stderr.strip()!r}; expected 2 and {blamed!r}")
    if failures:
        sys.exit("FAIL: " + "; ".join(failures))
    print("OK: resumed runs identical to the run in one go (from the second row boundary after a short row); "
          "an override switched on at a resumption; twenty-two bad requests refused with exit status 2, and a scenario file "
          "stiffened past the run's time step refused as that; a deeper false bottom taken")


if __name__ == "__main__":
    main()
