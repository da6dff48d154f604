#!/usr/bin/python3
"""Speed against accuracy: run one scene over a grid of choices and draw its Pareto fronts.

    nice -n 10 /usr/bin/python3 scripts/trade-study.py SCENE [--grid default|tiny] [--out DIR]

Each grid point is one `stresscontact` run of the scene's deck with `--set` overrides (degree,
geometry order, uniform or Dörfler marking with θ, reconstruction degree, linear solver, Newton
and Krylov tolerances, ...). One run gives one point per adaptive cycle: the time of cycle i is
the process's fixed cost (its wall time less the sum of its cycles' phases) plus the phases of
cycles 0..i, without `output` and `checkpoint` (field output is switched off in every run; the
checkpoint is not the problem's work). The true error of each quantity is measured against the
scene's reference (docs/performance.md "The trade-study command"):

- `exact`: the manufactured solution; the run's own `errors` (summary.json) are the true errors;
- a number with a named source (the peer values of docs/peer);
- `run`: one reference run of the same scene on a finer discretisation, made first.

Writes DIR/<scene>/runs.csv (one row per run and cycle), DIR/<scene>/front_<quantity>.png and
prints each quantity's front and where the shipped deck lies against it. Runs one process at a
time. Scenes and grids: SCENES below; `--list` prints them. Source: docs/performance.md.
"""
import argparse
import csv
import itertools
import json
import math
import os
import re
import shutil
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

# Discretisation choices as lists of --set overrides, named for the CSV.
DEGREE = {"k1": ["Discretization/Degree=1"], "k2": ["Discretization/Degree=2"]}
GEOMETRY = {"curved": ["Mesh/Geometry order=2"], "straight": ["Mesh/Geometry order=1"]}


def marking(theta):
    if theta == "uniform":
        return ["Adaptivity/Marking=Uniform"]
    return ["Adaptivity/Marking=Dorfler", "Adaptivity/Bulk parameter=%g" % theta]


RECONSTRUCTION = {"rk+1": ["Estimator/Reconstruction degree=k+1"], "rk": ["Estimator/Reconstruction degree=k"]}
SOLVER = {
    "mumps": ["Linear Solver/Type=MUMPS"],
    "krylov": ["Linear Solver/Type=Iterative", "Linear Solver/Iterative/Tolerance=1e-8"],
    "krylov6": ["Linear Solver/Type=Iterative", "Linear Solver/Iterative/Tolerance=1e-6"],
    "multigrid": ["Linear Solver/Type=Iterative", "Linear Solver/Iterative/Stress block=Multigrid"],
}
# Contact/Newton/Stopping = Balanced (docs/theory.md "Solves balanced with the discretisation
# error"): a run labelled X_balanced is X with the balanced Krylov stop; the report sets the two
# side by side, cycle by cycle.
BALANCED = ["Contact/Newton/Stopping=Balanced"]

# Quantities read from a cycle record of summary.json. Contact: the load along the obstacle
# normal (|force| component of largest size), the zone's half-width / radius from its area
# (docs/contact.md "Outputs": robust to a ragged edge), the peak pressure, the stick zone's
# equivalent half-width / radius.
CONTACT_QUANTITIES = {
    "load": lambda c: max(abs(f) for f in c["contact"]["force"]),
    "half_width": lambda c: c["contact"].get("equivalent_half_width", c["contact"].get("equivalent_radius")),
    "max_pressure": lambda c: c["contact"]["max_pressure"],
    "stick_half_width": lambda c: c["contact"].get("equivalent_stick_half_width",
                                                   c["contact"].get("equivalent_stick_radius")),
}
# Manufactured scenes: the relative true errors the run computes itself against the exact solution.
EXACT_QUANTITIES = {
    "stress_energy": lambda c: c["eta"]["stress_energy_error"] / c["eta"]["stress_energy_norm"],
    "displacement_l2": lambda c: c["errors"]["displacement_l2_relative"],
}


def grid(**axes):
    """The Cartesian product of the named axes: [(label, [--set ...]), ...]."""
    names = list(axes)
    out = []
    for combo in itertools.product(*(axes[n] for n in names)):
        label = "_".join(str(v[0]) for v in combo)
        sets = [s for v in combo for s in v[1]]
        out.append((label, sets))
    return out


def axis(table, *keys):
    return [(k, table[k]) for k in keys]


def thetas(*values):
    return [("uniform" if v == "uniform" else "th%g" % v, marking(v)) for v in values]


NO_FRICTION = ["Contact/Friction law=None"]
COULOMB = ["Contact/Friction law=Coulomb", "Contact/Friction coefficient=0.4"]
INCOMPRESSIBLE = ["Material/Poisson ratio=0.4999"]
FAST_OUTPUT = ["Output/Write XDMF=false", "Output/Write contact CSV=false"]

# Hertz 2D: peer value of the frictionless load at ν = 0.28 in the obstacle-normal frame
# (docs/peer/README.md, "Converged loads": P = 106.805 ± 0.003, GetFEM P2, four levels).
PEER_HERTZ2D_LOAD = {"load": (106.805, "peer GetFEM P2, docs/peer/README.md")}

HERTZ2D_GRID = dict(
    degree=axis(DEGREE, "k1", "k2"),
    marking=thetas("uniform", 0.3, 0.5, 0.7),
)


def hertz2d(deck, extra, reference_values=None, quantities=("load", "half_width", "max_pressure")):
    return {
        "deck": deck,
        "sets": extra,
        "quantities": list(quantities),
        # cycles per marking: uniform refinement multiplies the DOFs by 4 per cycle.
        "cycles": {"uniform": 2, "default": 12},
        "grid": grid(**HERTZ2D_GRID) + [("k1_th0.5_straight", DEGREE["k1"] + marking(0.5) + GEOMETRY["straight"]),
                                        ("k1_th0.5_rk", DEGREE["k1"] + marking(0.5) + RECONSTRUCTION["rk"]),
                                        ("k1_th0.5_krylov", DEGREE["k1"] + marking(0.5) + SOLVER["krylov"]),
                                        ("k1_th0.5_krylov_balanced", DEGREE["k1"] + marking(0.5) + SOLVER["krylov"] + BALANCED),
                                        ("k1_th0.5_multigrid", DEGREE["k1"] + marking(0.5) + SOLVER["multigrid"]),
                                        ("k1_th0.5_multigrid_balanced", DEGREE["k1"] + marking(0.5) + SOLVER["multigrid"] + BALANCED)],
        "tiny": [("k1_uniform", DEGREE["k1"] + marking("uniform"))],
        # The finest discretisation of the grid's family, run first: k = 2, Dörfler 0.5, more cycles.
        "reference": {"sets": DEGREE["k2"] + marking(0.5) + ["Adaptivity/Cycles=22"],
                      "values": reference_values or {}},
    }


SCENES = {
    "hertz2d_frictionless": hertz2d("input/hertz2d_frictionless.xml", NO_FRICTION, PEER_HERTZ2D_LOAD),
    "hertz2d_coulomb": hertz2d("input/hertz2d.xml", COULOMB,
                               quantities=("load", "half_width", "max_pressure", "stick_half_width")),
    "hertz2d_incompressible_frictionless": hertz2d("input/hertz2d_frictionless.xml", NO_FRICTION + INCOMPRESSIBLE),
    "hertz2d_incompressible_coulomb": hertz2d("input/hertz2d.xml", COULOMB + INCOMPRESSIBLE,
                                              quantities=("load", "half_width", "max_pressure",
                                                          "stick_half_width")),
    # 3D: small grids (k = 1, three markings), the reference a run of 9 Dörfler cycles.
    "hertz3d_frictionless": {
        "deck": "input/hertz3d_frictionless.xml", "sets": NO_FRICTION,
        "quantities": ["load", "half_width", "max_pressure"],
        "cycles": {"uniform": 1, "default": 6},
        "grid": grid(degree=axis(DEGREE, "k1"), marking=thetas("uniform", 0.3, 0.5)),
        "tiny": [("k1_uniform", DEGREE["k1"] + marking("uniform"))],
        "reference": {"sets": DEGREE["k1"] + marking(0.5) + ["Adaptivity/Cycles=9"], "values": {}},
    },
    "hertz3d_coulomb": {
        "deck": "input/hertz3d.xml", "sets": COULOMB,
        "quantities": ["load", "half_width", "max_pressure", "stick_half_width"],
        "cycles": {"uniform": 1, "default": 6},
        "grid": grid(degree=axis(DEGREE, "k1"), marking=thetas("uniform", 0.3, 0.5)),
        "tiny": [("k1_uniform", DEGREE["k1"] + marking("uniform"))],
        "reference": {"sets": DEGREE["k1"] + marking(0.5) + ["Adaptivity/Cycles=9"], "values": {}},
    },
    "mms2d": {
        "deck": "input/mms2d.xml", "sets": [], "quantities": list(EXACT_QUANTITIES),
        "cycles": {"uniform": 3, "default": 10},
        "grid": grid(degree=axis(DEGREE, "k1", "k2"), marking=thetas("uniform", 0.3, 0.5, 0.7))
        + [("k1_uniform_rk", DEGREE["k1"] + marking("uniform") + RECONSTRUCTION["rk"]),
           ("k1_uniform_krylov", DEGREE["k1"] + marking("uniform") + SOLVER["krylov"]),
           ("k1_uniform_krylov6", DEGREE["k1"] + marking("uniform") + SOLVER["krylov6"])],
        "tiny": [("k1_uniform", DEGREE["k1"] + marking("uniform")), ("k2_uniform", DEGREE["k2"] + marking("uniform"))],
        "reference": "exact",
    },
    "mms3d": {
        "deck": "input/mms3d.xml", "sets": [], "quantities": list(EXACT_QUANTITIES),
        "cycles": {"uniform": 1, "default": 4},
        "grid": grid(degree=axis(DEGREE, "k1", "k2"), marking=thetas("uniform", 0.5)),
        "tiny": [("k1_uniform", DEGREE["k1"] + marking("uniform"))],
        "reference": "exact",
    },
    # Not Hertz: a rigid cylinder indenting a block; the peer's converged frictionless load
    # (docs/peer/README.md, indentation2d: P = 4.27827 ± 0.00009, GetFEM P2, four levels).
    "indentation2d": {
        "deck": "input/indentation2d.xml", "sets": NO_FRICTION,
        "quantities": ["load", "half_width", "max_pressure"],
        "cycles": {"uniform": 2, "default": 14},
        "grid": grid(degree=axis(DEGREE, "k1", "k2"), marking=thetas("uniform", 0.3, 0.5, 0.7)),
        "tiny": [("k1_uniform", DEGREE["k1"] + marking("uniform"))],
        "reference": {"sets": DEGREE["k2"] + marking(0.5) + ["Adaptivity/Cycles=20"],
                      "values": {"load": (4.27827, "peer GetFEM P2, docs/peer/README.md")}},
    },
}

COLUMNS = ["scene", "run", "sets", "cycle", "dofs", "elements", "seconds", "process_seconds",
           "peak_rss_mb", "eta", "eta_relative", "newton_iterations", "krylov_iterations",
           "phase_setup", "phase_assemble", "phase_solve", "phase_estimate", "phase_other"]


def find_binary():
    for path in ("build/apps/stresscontact/stresscontact",):
        full = os.path.join(ROOT, path)
        if os.access(full, os.X_OK):
            return full
    sys.exit("trade-study: no stresscontact binary under %s/build; give --binary" % ROOT)


def run_one(binary, deck, sets, outdir, timeout):
    """One whole process; returns (summary dict or None, wall seconds, exit status)."""
    if os.path.isdir(outdir):
        shutil.rmtree(outdir)
    cmd = [binary, deck, "--quiet", "--output", outdir]
    for s in sets:
        cmd += ["--set", s]
    start = time.monotonic()
    try:
        proc = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, timeout=timeout)
        status = proc.returncode
    except subprocess.TimeoutExpired:
        status = "timeout"
    wall = time.monotonic() - start
    path = os.path.join(outdir, "summary.json")
    summary = json.load(open(path)) if os.path.exists(path) else None
    return summary, wall, status, cmd


def cycle_phase_seconds(c):
    return {k: v for k, v in (c.get("timings") or {}).items() if k not in ("output", "checkpoint")}


def rows_of_run(scene, label, sets, summary, wall, quantities):
    cycles = [c for c in summary["cycles"] if c.get("eta")]
    all_phases = sum(sum((c.get("timings") or {}).values()) for c in summary["cycles"])
    fixed = max(0.0, wall - all_phases)  # process start, mesh generation outside cycles, exit
    rows, elapsed = [], fixed
    for c in cycles:
        phases = cycle_phase_seconds(c)
        elapsed += sum(phases.values())
        r = {"scene": scene, "run": label, "sets": " ; ".join(sets), "cycle": c["cycle"],
             "dofs": c["dofs"]["total"], "elements": c["elements"], "seconds": elapsed,
             "process_seconds": wall, "peak_rss_mb": c["memory"]["peak_rss_max_mb"],
             "eta": c["eta"]["total"], "eta_relative": c["eta"]["relative"],
             "newton_iterations": (c.get("contact") or {}).get("newton_iterations", ""),
             "krylov_iterations": (c.get("linear_iterations") or {}).get("total", "")}
        for p in ("setup", "assemble", "solve", "estimate"):
            r["phase_" + p] = phases.get(p, 0.0)
        r["phase_setup"] += phases.get("numbering", 0.0)  # the DOF numbering is set-up too
        r["phase_other"] = sum(phases.values()) - sum(r["phase_" + p] for p in ("setup", "assemble", "solve", "estimate"))
        for q in quantities:
            r[q] = (CONTACT_QUANTITIES.get(q) or EXACT_QUANTITIES[q])(c)
        rows.append(r)
    return rows


def pareto(points):
    """Non-dominated (seconds, error) points, by increasing time."""
    front, best = [], math.inf
    for p in sorted(points, key=lambda p: (p[0], p[1])):
        if p[1] < best:
            front.append(p)
            best = p[1]
    return front


def front_time_at(front, error):
    """Least time on the front that reaches an error ≤ error (None: the front never does)."""
    times = [t for t, e, _ in front if e <= error]
    return min(times) if times else None


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("scene", nargs="?", help="one of SCENES (--list)")
    ap.add_argument("--list", action="store_true", help="print the scenes, their grids and references")
    ap.add_argument("--grid", choices=("default", "tiny"), default="default",
                    help="tiny: one or two coarse runs (the CTest)")
    ap.add_argument("--out", default="trade-study", help="output directory (default ./trade-study)")
    ap.add_argument("--binary", help="stresscontact executable (default build/apps/stresscontact/stresscontact)")
    ap.add_argument("--cycles", type=int, help="override the adaptive cycles of every grid run")
    ap.add_argument("--set", action="append", default=[], dest="extra",
                    help="an extra --set for every run (e.g. a coarser initial mesh)")
    ap.add_argument("--runs", help="only the grid runs whose label matches this regular expression "
                    "(the shipped deck's run is labelled 'shipped'); the reference run is made as always")
    ap.add_argument("--timeout", type=float, default=600.0, help="seconds per run")
    ap.add_argument("--no-plot", action="store_true")
    ap.add_argument("--summarize", action="store_true",
                    help="only re-read DIR/SCENE/runs.csv: fronts, targets and plots, no runs")
    args = ap.parse_args()

    if args.list or not args.scene:
        for name, s in SCENES.items():
            ref = s["reference"] if s["reference"] == "exact" else "run: " + " ".join(s["reference"]["sets"])
            print("%s: %s, %d runs, quantities %s, reference %s" % (name, s["deck"], len(s["grid"]),
                                                                    ",".join(s["quantities"]), ref))
        return 0
    if args.scene not in SCENES:
        sys.exit("trade-study: unknown scene '%s'; known: %s" % (args.scene, ", ".join(SCENES)))
    scene = SCENES[args.scene]
    binary = args.binary or find_binary()
    deck = os.path.join(ROOT, scene["deck"])
    outdir = os.path.join(os.path.abspath(args.out), args.scene)
    os.makedirs(outdir, exist_ok=True)
    base = scene["sets"] + FAST_OUTPUT + args.extra
    quantities = scene["quantities"]
    tiny = args.grid == "tiny"
    if args.summarize:
        report(args.scene, quantities, read_csv(os.path.join(outdir, "runs.csv")), outdir, not args.no_plot)
        return 0

    def cycles_for(sets):
        if args.cycles is not None:
            return args.cycles
        uniform = "Adaptivity/Marking=Uniform" in sets
        return scene["cycles"]["uniform" if uniform else "default"]

    # The reference values of each quantity: (value, source).
    reference = {}
    if scene["reference"] != "exact":
        reference.update(scene["reference"]["values"])
        missing = [q for q in quantities if q not in reference]
        if missing:
            ref_sets = base + scene["reference"]["sets"]
            if tiny:  # the tiny grid's reference: one more cycle than its runs
                ref_sets = base + DEGREE["k2"] + marking("uniform") + ["Adaptivity/Cycles=%d" % ((args.cycles or 0) + 1)]
            summary, wall, status, cmd = run_one(binary, deck, ref_sets, os.path.join(outdir, "reference"), args.timeout)
            if status != 0 or summary is None:
                sys.exit("trade-study: the reference run failed (exit %s): %s" % (status, " ".join(cmd)))
            last = [c for c in summary["cycles"] if c.get("eta")][-1]
            for q in missing:
                reference[q] = ((CONTACT_QUANTITIES[q])(last),
                                "reference run (%d DOFs, %.1f s): %s" % (last["dofs"]["total"], wall,
                                                                        " ".join(scene["reference"]["sets"] if not tiny else ref_sets)))
            print("reference run: %d DOFs, %.1f s" % (last["dofs"]["total"], wall), flush=True)

    runs = list(scene["tiny"] if tiny else scene["grid"])
    runs.append(("shipped", []))  # the deck as shipped (its own cycles and marking)
    if args.runs:
        runs = [r for r in runs if re.search(args.runs, r[0])]
    rows = []
    for label, sets in runs:
        full = base + sets
        if label != "shipped":
            full = full + ["Adaptivity/Cycles=%d" % cycles_for(sets)]
        elif args.cycles is not None:
            full = full + ["Adaptivity/Cycles=%d" % args.cycles]
        summary, wall, status, cmd = run_one(binary, deck, full, os.path.join(outdir, label), args.timeout)
        if status != 0 or summary is None:
            print("%-22s FAILED (exit %s): %s" % (label, status, (summary or {}).get("error")), flush=True)
            continue
        got = rows_of_run(args.scene, label, full, summary, wall, quantities)
        for r in got:
            for q in quantities:
                if scene["reference"] == "exact":
                    r[q + "_error"] = r[q]  # the run's own error against the exact solution
                else:
                    ref = reference[q][0]
                    r[q + "_error"] = abs(r[q] - ref) / abs(ref) if ref != 0 else abs(r[q])
        rows += got
        last = got[-1]
        print("%-22s %2d cycles %8d DOFs %7.2f s  " % (label, len(got), last["dofs"], last["seconds"])
              + "  ".join("%s %.2e" % (q, last[q + "_error"]) for q in quantities), flush=True)

    columns = COLUMNS + [c for q in quantities for c in (q, q + "_error")]
    with open(os.path.join(outdir, "runs.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=columns)
        w.writeheader()
        for r in rows:
            w.writerow(r)
    with open(os.path.join(outdir, "reference.json"), "w") as f:
        json.dump({"reference": "exact" if scene["reference"] == "exact" else
                   {q: {"value": v, "source": s} for q, (v, s) in reference.items()}}, f, indent=1)

    report(args.scene, quantities, rows, outdir, not args.no_plot)
    return 0


TARGETS = (1e-2, 1e-3)


def first_time_within(rows, q, target):
    """Seconds at the first cycle of the rows whose error is ≤ target (None: never)."""
    for r in rows:
        if r[q + "_error"] <= target:
            return r["seconds"], "%s/c%d" % (r["run"], r["cycle"])
    return None


def balanced_tables(quantities, rows):
    """Each run X that has a run X_balanced: per cycle, the error of each quantity, Newton steps,
    Krylov iterations and seconds of both, and the totals."""
    labels = list(dict.fromkeys(r["run"] for r in rows))
    for label in labels:
        if not label.endswith("_balanced") or label[:-len("_balanced")] not in labels:
            continue
        fixed = {r["cycle"]: r for r in rows if r["run"] == label[:-len("_balanced")]}
        bal = {r["cycle"]: r for r in rows if r["run"] == label}
        print("balanced against fixed: %s (fixed | balanced)" % label)
        print("  cycle   DOFs fixed|bal  " + "  ".join("%-19s" % (q + " error") for q in quantities)
              + "  Newton  Krylov     seconds")
        total = {"fixed": [0, 0, 0.0], "bal": [0, 0, 0.0]}
        for c in sorted(set(fixed) & set(bal)):
            f, b = fixed[c], bal[c]
            for key, r in (("fixed", f), ("bal", b)):
                total[key][0] += int(r["newton_iterations"] or 0)
                total[key][1] += int(r["krylov_iterations"] or 0)
                total[key][2] += float(r["phase_solve"] or 0.0)
            print("  %5d %6d|%-6d  " % (c, f["dofs"], b["dofs"])
                  + "  ".join("%.2e|%.2e" % (f[q + "_error"], b[q + "_error"]) for q in quantities)
                  + "  %3s|%-3s %4s|%-5s %5.2f|%.2f" % (f["newton_iterations"], b["newton_iterations"],
                                                        f["krylov_iterations"], b["krylov_iterations"],
                                                        f["seconds"], b["seconds"]))
        last = max(set(fixed) & set(bal))
        print("  totals to cycle %d: Newton %d|%d, Krylov %d|%d, solve phase %.2f|%.2f s, seconds %.2f|%.2f"
              % (last, total["fixed"][0], total["bal"][0], total["fixed"][1], total["bal"][1],
                 total["fixed"][2], total["bal"][2], fixed[last]["seconds"], bal[last]["seconds"]))


def report(scene, quantities, rows, outdir, plots):
    """Each quantity's front; the time to reach 1% and 0.1%: the front's, and the shipped deck's
    (its first cycle within the target) with its excess over the front."""
    balanced_tables(quantities, rows)
    for q in quantities:
        pts = [(r["seconds"], r[q + "_error"], "%s/c%d" % (r["run"], r["cycle"])) for r in rows if r[q + "_error"] > 0]
        front = pareto(pts)
        print("front %s: " % q + ", ".join("%.2fs %.1e (%s)" % p for p in front))
        shipped = [r for r in rows if r["run"] == "shipped"]
        for target in TARGETS:
            t = front_time_at(front, target)
            who = [p[2] for p in front if p[0] == t][0] if t is not None else "-"
            line = "  %s within %g: front %s (%s)" % (q, target, "%.2f s" % t if t is not None else "never", who)
            if shipped:
                s = first_time_within(shipped, q, target)
                if s is None:
                    line += "; shipped deck: never"
                elif t is not None:
                    line += "; shipped deck %.2f s (%s), %+.0f%%" % (s[0], s[1], 100.0 * (s[0] / t - 1.0))
            print(line)
        if shipped:
            s = shipped[-1]
            print("  shipped deck's last cycle: %.2f s, error %.2e" % (s["seconds"], s[q + "_error"]))
        if plots:
            plot(outdir, scene, q, rows, front)


def read_csv(path):
    rows = []
    with open(path) as f:
        for r in csv.DictReader(f):
            for k, v in r.items():
                if k not in ("scene", "run", "sets") and v != "":
                    r[k] = float(v)
            r["cycle"] = int(r["cycle"])
            rows.append(r)
    return rows


def plot(outdir, scene, q, rows, front):
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("trade-study: no matplotlib, no plots (use /usr/bin/python3)")
        return
    fig, ax = plt.subplots(figsize=(6.4, 4.6))
    for label in dict.fromkeys(r["run"] for r in rows):
        rs = [r for r in rows if r["run"] == label and r[q + "_error"] > 0]
        if rs:
            ax.loglog([r["seconds"] for r in rs], [r[q + "_error"] for r in rs], "o-" if label != "shipped" else "k*-",
                      ms=3 if label != "shipped" else 8, lw=0.8, label=label)
    if front:
        ax.loglog([p[0] for p in front], [p[1] for p in front], "k--", lw=1.5, label="front")
    ax.set_xlabel("seconds (process start + cycles, without output)")
    ax.set_ylabel("relative error of %s" % q)
    ax.set_title("%s: %s" % (scene, q))
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=6, ncol=2)
    fig.tight_layout()
    fig.savefig(os.path.join(outdir, "front_%s.png" % q), dpi=110)
    plt.close(fig)


if __name__ == "__main__":
    sys.exit(main())
