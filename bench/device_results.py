#!/usr/bin/python3
"""The GPU section of bench/RESULTS.md, from what scripts/device_check brought back from a lent GPU
machine and was committed under bench/device/DATE/ (with a SOURCE.md saying where, when, from which
commit and with which command it was measured).

A GPU is lent to some sessions only, so scripts/bench (which regenerates RESULTS.md on the machine
at hand) cannot measure it: report.py appends this section from the committed files, and

    bench/device_results.py --results bench/RESULTS.md

rewrites it alone, between its markers, after a new bench/device/DATE/ is committed.
"""
import argparse
import glob
import json
import os
import re
import sys

BEGIN = "<!-- device results: written by bench/device_results.py from bench/device/ -->"
END = "<!-- end of device results -->"


def ncu_kernels(path):
    """Per kernel: launches, grid blocks, mean duration [us], mean DRAM [MB], mean % of peak."""
    kernels, current = {}, None
    with open(path, errors="replace") as f:
        for line in f:
            m = re.match(r"\s+\S*::(\w+)\(.*\) \((\d+), \d+, \d+\)x\((\d+), \d+, \d+\)", line)
            if m:
                current = kernels.setdefault(m.group(1), {"n": 0, "blocks": int(m.group(2)), "us": [], "mb": [], "pct": []})
                current["n"] += 1
                continue
            if current is None:
                continue
            parts = line.split()
            if len(parts) >= 3 and parts[0] == "gpu__time_duration.sum":
                scale = {"ns": 1e-3, "us": 1.0, "usecond": 1.0, "ms": 1e3, "msecond": 1e3}.get(parts[1], 1.0)
                current["us"].append(float(parts[2].replace(",", "")) * scale)
            elif len(parts) >= 3 and parts[0] == "dram__bytes.sum":
                scale = {"byte": 1e-6, "Kbyte": 1e-3, "Mbyte": 1.0, "Gbyte": 1e3}.get(parts[1], 1.0)
                current["mb"].append(float(parts[2].replace(",", "")) * scale)
            elif len(parts) >= 3 and parts[0] == "dram__throughput.avg.pct_of_peak_sustained_elapsed":
                current["pct"].append(float(parts[2].replace(",", "")))
    mean = lambda xs: sum(xs) / len(xs) if xs else float("nan")
    return {k: (v["n"], v["blocks"], mean(v["us"]), mean(v["mb"]), mean(v["pct"])) for k, v in kernels.items()}


def test_verdicts(path):
    """The GoogleTest verdict lines ([  PASSED  ], [  FAILED  ] ...) of a test log."""
    passed = failed = 0
    failures = []
    with open(path, errors="replace") as f:
        for line in f:
            if line.startswith("[       OK ]"):
                passed += 1
            elif line.startswith("[  FAILED  ]") and "(" in line and "ms)" in line:
                failed += 1
                failures.append(line.split("]", 1)[1].split("(")[0].strip())
    return passed, failed, failures


def device_lines(folder):
    lines = []
    source = os.path.join(folder, "SOURCE.md")
    if os.path.exists(source):
        with open(source) as f:
            lines += [l.rstrip("\n") for l in f]
        lines.append("")
    bench = os.path.join(folder, "bench.md")
    if os.path.exists(bench):
        lines += ["Throughput (`thin_ice_bench`, M-2 ice, as in the CPU table above):", ""]
        header_lines = 0  # the first table's header and rule are kept, the others' dropped
        with open(bench) as f:
            for line in f:
                if not line.startswith("|"):
                    continue
                if line.startswith("| cells") or line.startswith("|---"):
                    header_lines += 1
                    if header_lines > 2:
                        continue
                lines.append(line.rstrip("\n"))
        lines.append("")
    for ncu in sorted(glob.glob(os.path.join(folder, "ncu*.txt"))):
        kernels = ncu_kernels(ncu)
        if not kernels:
            continue
        lines += ["Nsight Compute, `%s` (mean per launch):" % os.path.basename(ncu), "",
                  "| kernel | launches | blocks of 128 | time [us] | DRAM [MB] | DRAM % of peak |",
                  "|---|---:|---:|---:|---:|---:|"]
        shown = lambda x, form: "-" if x != x else form % x  # not measured: "-"
        for name, (n, blocks, us, mb, pct) in kernels.items():
            lines.append("| %s | %d | %d | %s | %s | %s |" % (name, n, blocks, shown(us, "%.1f"), shown(mb, "%.2f"),
                                                             shown(pct, "%.1f")))
        lines.append("")
    tests = os.path.join(folder, "tests.txt")
    if os.path.exists(tests):
        passed, failed, failures = test_verdicts(tests)
        lines.append("GPU tests (`tests.txt`): %d passed, %d failed%s" %
                     (passed, failed, (": " + ", ".join(failures)) if failures else ""))
        lines.append("")
    for run in sorted(glob.glob(os.path.join(folder, "*.json"))):
        try:
            with open(run) as f:
                s = json.load(f)
            lines.append("`%s`: %s on %s, %d cells, to t = %.3g s: real-time factor %.3g" %
                         (os.path.basename(run), s["scenario"]["name"], s["backend"], s["cells"],
                          s["simulated_time_s"], s["real_time_factor"]))
        except (OSError, ValueError, KeyError):
            continue
    lines.append("")
    return lines


def device_section(bench_dir):
    """The section's lines, newest measurement first, between its markers."""
    lines = [BEGIN, "## GPU (measured on lent GPU machines)", ""]
    folders = sorted(glob.glob(os.path.join(bench_dir, "device", "*", "")), reverse=True)
    if not folders:
        lines += ["No GPU measurement is committed under bench/device/.", ""]
    for folder in folders:
        lines += ["### %s" % os.path.basename(os.path.normpath(folder)), ""]
        lines += device_lines(folder)
    lines.append(END)
    return lines


def rewrite(results_path, bench_dir):
    with open(results_path) as f:
        text = f.read()
    section = "\n".join(device_section(bench_dir))
    if BEGIN in text and END in text:
        head, rest = text.split(BEGIN, 1)
        tail = rest.split(END, 1)[1]
        text = head + section + tail
    else:
        text = text.rstrip("\n") + "\n\n" + section + "\n"
    with open(results_path + ".partial", "w") as f:
        f.write(text)
    os.replace(results_path + ".partial", results_path)


def main(argv):
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--results", required=True, help="the RESULTS.md to rewrite the GPU section of")
    a = p.parse_args(argv)
    if not os.path.isfile(a.results):
        print("bench/device_results.py: --results %s: no such file" % a.results, file=sys.stderr)
        return 2
    rewrite(a.results, os.path.dirname(os.path.abspath(a.results)))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
