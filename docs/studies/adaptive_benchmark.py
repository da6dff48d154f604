#!/usr/bin/python3
"""Cost per phase of the adaptive loop (docs/benchmarks.md): seconds per cycle for solve, reconstruct,
estimate, mark, refine, transfer, output, and the peak resident memory, read from the
`timings` and `memory` records of summary.json (docs/output.md).

Runs the application on the adaptive Hertz decks with --set overrides:
  2d: input/hertz2d.xml (Coulomb, the main job's deck), Dörfler cycles until a solved cycle has
      at least --max-dofs-2d DOFs (default 10^6);
  3d: input/hertz3d_frictionless.xml without its local pre-refinement, Dörfler cycles (the
      run_hertz3d_adaptive settings) until --max-dofs-3d DOFs (default 5*10^5).
and prints one Markdown table per run (docs/benchmarks.md "Adaptive loop"), with `uptime` before
and after each run: the machine is shared, compare ratios within a run.

Usage (repository root, after building; SC_BUILD_DIR or --build, default build/):
  /usr/bin/python3 docs/studies/adaptive_benchmark.py [--case 2d|3d|all] [--ranks N]
  /usr/bin/python3 docs/studies/adaptive_benchmark.py --case 2d|3d --scaling 1,2 [--repeat R]
      strong scaling (docs/benchmarks.md "Parallel efficiency"): the run at each rank count,
      alternating (1, 2, 1, 2, ...), R times each; per phase the seconds summed over the cycles
      (each cycle's phase the slowest rank's), the fastest of the R runs, and the whole-process
      wall time with the efficiency T_1 / (n T_n) against the first rank count.
  --lock FILE: take an exclusive flock on FILE for each run only (the timing and `uptime` start
      once it is held), so that a shared machine's other jobs wait between runs, not during them.
  --set KEY=VALUE (repeatable): one more --set for every run, e.g. the MUMPS ordering
      (docs/solvers.md "Ordering").
  /usr/bin/python3 docs/studies/adaptive_benchmark.py --smoke   # a few seconds (CTest)
The 2D run to 10^6 DOFs takes about 2 minutes on one core, the 3D run to 5*10^5 about 10.
"""
import argparse
import contextlib
import fcntl
import json
import os
import shutil
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
PHASES = ["solve", "reconstruct", "estimate", "mark", "refine", "transfer", "output"]
# The adaptive machinery, against the solve. The table also shows setup (spaces, numbering, the
# matrix graph) + assemble, and "other": mesh, partition, contact setup (constraint points),
# errors, checkpoint.
LOOP = ["reconstruct", "estimate", "mark", "refine", "transfer"]
SETUP = ["numbering", "setup", "assemble"]
# The strong-scaling table's rows: every phase of docs/output.md, the solve split into the
# direct solver's parts (linear_solver.seconds) and the rest of the Newton loop.
SCALING_ROWS = ["mesh", "partition", "numbering", "setup", "assemble", "contact setup", "transfer",
                "solve", "  equilibration", "  analysis", "  factorization", "  triangular solves",
                "  rest of the Newton loop", "reconstruct", "estimate", "errors", "mark", "refine",
                "output", "checkpoint"]


def cases(args):
    result = {}
    if args.smoke:
        result["2d-smoke"] = ("hertz2d.xml", ["Adaptivity/Cycles=2", "Mesh/Initial mesh size=0.2"])
        return result
    if args.case in ("2d", "all"):
        result["2d"] = ("hertz2d.xml", ["Adaptivity/Cycles=100",
                                        "Adaptivity/Max DOFs=%d" % args.max_dofs_2d])
    if args.case in ("3d", "all"):
        result["3d"] = ("hertz3d_frictionless.xml",
                        ["Mesh/Local refinement/Levels=0", "Adaptivity/Marking=Dorfler",
                         "Adaptivity/Cycles=100", "Adaptivity/Max DOFs=%d" % args.max_dofs_3d])
    for deck, sets in result.values():
        sets += args.extra_sets
    return result


def uptime():
    try:
        return subprocess.run(["uptime"], capture_output=True, text=True).stdout.strip()
    except OSError:
        return "(uptime not available)"


@contextlib.contextmanager
def held(path):
    """An exclusive flock on path for the block (nothing without a path)."""
    if not path:
        yield
        return
    with open(path, "a") as f:
        fcntl.flock(f, fcntl.LOCK_EX)
        try:
            yield
        finally:
            fcntl.flock(f, fcntl.LOCK_UN)


def run(app, name, deck, sets, ranks, outdir, lock=None):
    out = os.path.join(outdir, name + "_np%d" % ranks)
    cmd = [app, os.path.join(ROOT, "input", deck), "--quiet", "--output", out]
    for s in sets:
        cmd += ["--set", s]
    if ranks > 1:
        flags = ["--oversubscribe"] + (["--allow-run-as-root"] if os.geteuid() == 0 else [])
        cmd = ["mpiexec"] + flags + ["-n", str(ranks)] + cmd
    with held(lock):
        before = uptime()
        t0 = time.time()
        subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)
        seconds = time.time() - t0
        after = uptime()
    with open(os.path.join(out, "summary.json")) as f:
        summary = json.load(f)
    return summary, seconds, before, after, cmd


def fmt(seconds):
    """Seconds with 3 significant digits (a phase ranges from microseconds to minutes)."""
    return "%.3g" % seconds


def table(summary):
    head = (["cycle", "DOFs", "Newton steps"] + PHASES +
            ["setup + assemble", "other", "cycle total",
             "(reconstruct + estimate + mark + refine + transfer) / solve", "peak MB max / sum"])
    lines = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    keys = PHASES + ["setup + assemble", "other"]
    totals = {k: 0.0 for k in keys}
    for c in summary["cycles"]:
        t = dict(c.get("timings") or {})
        mem = c.get("memory") or {}
        t["setup + assemble"] = sum(t.get(k, 0.0) for k in SETUP)
        t["other"] = sum(v for k, v in (c.get("timings") or {}).items()
                         if k not in PHASES and k not in SETUP)
        for k in keys:
            totals[k] += t.get(k, 0.0)
        loop = sum(t.get(p, 0.0) for p in LOOP)
        solve = t.get("solve", 0.0)
        newton = c.get("nonlinear_iterations")
        cells = [str(c["cycle"]), "{:,}".format(c["dofs"]["total"]), "" if newton is None else str(newton)]
        cells += [fmt(t[k]) if k in t else "–" for k in keys]
        cells += [fmt(sum(t[k] for k in keys if k in t)),
                  ("%.1f %%" % (100.0 * loop / solve)) if solve > 0 else "–",
                  "%.0f / %.0f" % (mem.get("peak_rss_max_mb", float("nan")),
                                   mem.get("peak_rss_sum_mb", float("nan")))]
        lines.append("| " + " | ".join(cells) + " |")
    loop = sum(totals[p] for p in LOOP)
    cells = (["all", "", ""] + [fmt(totals[k]) for k in keys] +
             [fmt(sum(totals.values())),
              ("%.1f %%" % (100.0 * loop / totals["solve"])) if totals["solve"] > 0 else "–", ""])
    lines.append("| " + " | ".join(cells) + " |")
    return "\n".join(lines)


def phase_totals(summary):
    """Seconds per phase summed over the cycles (SCALING_ROWS), with the solver's parts."""
    totals = {k: 0.0 for k in SCALING_ROWS}
    for c in summary["cycles"]:
        for k, v in (c.get("timings") or {}).items():
            totals[k] = totals.get(k, 0.0) + v
        parts = ((c.get("linear_solver") or {}).get("seconds")) or {}
        keys = ("equilibration", "analysis", "factorization", "triangular_solves")
        for key in keys:
            totals["  " + key.replace("_", " ")] += parts.get(key, 0.0)
        if "solve" in (c.get("timings") or {}):
            totals["  rest of the Newton loop"] += c["timings"]["solve"] - sum(
                parts.get(k, 0.0) for k in keys)
    return totals


def scaling(args, app):
    """Strong scaling: alternate the rank counts, keep the fastest run of each, tabulate."""
    counts = [int(n) for n in args.scaling.split(",")]
    for name, (deck, sets) in cases(args).items():
        best = {}
        print("## %s: strong scaling over %s rank(s), %d run(s) each, alternating" %
              (name, args.scaling, args.repeat))
        for r in range(args.repeat):
            for n in counts:
                summary, seconds, before, after, cmd = run(app, name, deck, sets, n, args.output,
                                                          args.lock)
                print("run %d, %d rank(s): %.1f s wall, %s DOFs in %d cycles; uptime before: %s; "
                      "after: %s" % (r + 1, n, seconds,
                                     "{:,}".format(summary["cycles"][-1]["dofs"]["total"]),
                                     len(summary["cycles"]), before, after), flush=True)
                if n not in best or seconds < best[n][1]:
                    best[n] = (summary, seconds, cmd)
                if not args.keep:
                    shutil.rmtree(os.path.join(args.output, name + "_np%d" % n), ignore_errors=True)
        for n in counts:
            print("command (%d): %s" % (n, " ".join(("'%s'" % c) if " " in c else c
                                                    for c in best[n][2])))
        dofs = {n: [c["dofs"]["total"] for c in best[n][0]["cycles"]] for n in counts}
        if any(dofs[n] != dofs[counts[0]] for n in counts):
            print("WARNING: the meshes differ between rank counts")
        totals = {n: phase_totals(best[n][0]) for n in counts}
        base = counts[0]
        head = ["phase"] + ["%d rank(s) s" % n for n in counts] + [
            "speed-up %d→%d" % (base, n) for n in counts[1:]]
        print()
        print("| " + " | ".join(head) + " |")
        print("|" + "---|" * len(head))
        for row in SCALING_ROWS + ["sum of phases", "whole process (wall)"]:
            if row == "sum of phases":
                vals = {n: sum(v for k, v in totals[n].items() if not k.startswith("  "))
                        for n in counts}
            elif row == "whole process (wall)":
                vals = {n: best[n][1] for n in counts}
            else:
                vals = {n: totals[n].get(row, 0.0) for n in counts}
            if all(v == 0.0 for v in vals.values()):
                continue
            cells = [row.strip() if not row.startswith("  ") else "… " + row.strip()]
            cells += ["%.3g" % vals[n] for n in counts]
            cells += [("%.2f" % (vals[base] / vals[n])) if vals[n] > 0 else "–" for n in counts[1:]]
            print("| " + " | ".join(cells) + " |")
        print()
        for n in counts[1:]:
            print("whole-process efficiency %d→%d ranks: %.0f %%" %
                  (base, n, 100.0 * base * best[base][1] / (n * best[n][1])))
        print(flush=True)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--build", default=os.environ.get("SC_BUILD_DIR", os.path.join(ROOT, "build")))
    ap.add_argument("--case", choices=["2d", "3d", "all"], default="all")
    ap.add_argument("--ranks", type=int, default=1)
    ap.add_argument("--max-dofs-2d", type=int, default=1000000)
    ap.add_argument("--max-dofs-3d", type=int, default=500000)
    ap.add_argument("--output", default="/tmp/sc_adaptive_benchmark")
    ap.add_argument("--smoke", action="store_true", help="2 cycles on a coarse 2D mesh (seconds)")
    ap.add_argument("--keep", action="store_true", help="keep the runs' output directories")
    ap.add_argument("--scaling", help="strong scaling over these rank counts, e.g. 1,2")
    ap.add_argument("--repeat", type=int, default=1, help="--scaling: runs per rank count")
    ap.add_argument("--lock", help="flock this file for each run only (shared machines)")
    ap.add_argument("--set", action="append", default=[], dest="extra_sets", metavar="KEY=VALUE",
                    help="one more --set for every run (e.g. 'Linear Solver/MUMPS/Ordering=METIS')")
    args = ap.parse_args()

    app = os.path.join(args.build, "apps", "stresscontact", "stresscontact")
    if not os.access(app, os.X_OK):
        sys.exit("adaptive_benchmark: no application at %s (build first, or --build DIR)" % app)
    if args.scaling:
        scaling(args, app)
        return
    for name, (deck, sets) in cases(args).items():
        summary, seconds, before, after, cmd = run(app, name, deck, sets, args.ranks, args.output,
                                                  args.lock)
        print("## %s, %d rank(s): %d cycles to %s DOFs, %.1f s wall" %
              (name, args.ranks, len(summary["cycles"]) - 1,
               "{:,}".format(summary["cycles"][-1]["dofs"]["total"]), seconds))
        print("command: " + " ".join(("'%s'" % c) if " " in c else c for c in cmd))
        print("uptime before: " + before)
        print("uptime after:  " + after)
        print()
        print(table(summary))
        print(flush=True)
        # Every phase must be timed: the last cycle has all but mark (it stops instead), the
        # one before it has mark.
        cycles = summary["cycles"]
        missing = [p for p in PHASES if p != "mark" and p not in (cycles[-1].get("timings") or {})]
        if len(cycles) > 1 and "mark" not in (cycles[-2].get("timings") or {}):
            missing.append("mark")
        if missing or not cycles[-1].get("memory"):
            sys.exit("adaptive_benchmark: no timing for %s, or no memory record" % ", ".join(missing))
        if not args.keep:
            shutil.rmtree(os.path.join(args.output, name + "_np%d" % args.ranks), ignore_errors=True)


if __name__ == "__main__":
    main()
