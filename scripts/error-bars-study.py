#!/usr/bin/python3
"""Validate the error bars of summary.json (contact.estimated_error, docs/output.md "Error bars").

    nice -n 10 /usr/bin/python3 scripts/error-bars-study.py [--out DIR] [--scenes ...] [--cycles N]

For each scene, one run of its deck with `Adaptivity/Cycles` = N (default 24; field output off).
Its last cycle is the reference of the quantities (the peer's converged load of docs/peer where
there is one), with an uncertainty u_ref = the largest change of the quantity over the run's last
two cycles (for the peer load, the peer's stated uncertainty). At every cycle c from the fourth
(c = 3) to `--last` (default 16, the shipped decks' count; 8 cycles before the reference) the table
gives the ratio estimated error / true error, true error =
|q_c − q_ref|; a cycle where the true error is not larger than 2·u_ref is not resolved ("u").
The rule of the table (docs/verification.md "Error bars"): 1 ≤ ratio ≤ 10; it does not hold in
every cycle (the table marks each exception). `--check` (the long test `error_bars_study`) exits 1
if, in a scene, more than 5% of the resolved ratios are below 1 (the estimate under the true
error: the unsafe side; measured at most 2.6%).
"""
import argparse
import json
import math
import os
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
APP = os.path.join(ROOT, "build", "apps", "stresscontact", "stresscontact")

# The peer's converged loads (docs/peer/README.md "Converged loads"): value, uncertainty.
PEER_HERTZ2D_LOAD = (106.805, 0.003)

SCENES = {
    "hertz2d_frictionless": ("input/hertz2d_frictionless.xml", [], PEER_HERTZ2D_LOAD),
    "hertz2d_coulomb": ("input/hertz2d.xml", [], None),
    "hertz2d_incompressible_frictionless": ("input/hertz2d_frictionless.xml", ["Material/Poisson ratio=0.4999"], None),
    "hertz2d_incompressible_coulomb": ("input/hertz2d.xml", ["Material/Poisson ratio=0.4999"], None),
    "hertz3d_frictionless": ("input/hertz3d_frictionless.xml", [], None),
    "hertz3d_coulomb": ("input/hertz3d.xml", [], None),
}


def quantities(c, dim):
    ct = c["contact"]
    w = "half_width" if dim == 2 else "radius"
    q = {"force": math.sqrt(sum(f * f for f in ct["force"])), w: ct[w], "equivalent_" + w: ct["equivalent_" + w],
         "max_pressure": ct["max_pressure"]}
    s = "stick_" + w
    if s in ct.get("estimated_error", {}):
        q[s] = ct[s]
        q["equivalent_" + s] = ct["equivalent_" + s]
    return q


def run(scene, out, cycles, app):
    deck, sets, _ = SCENES[scene]
    d = os.path.join(out, scene)
    cmd = [app, os.path.join(ROOT, deck), "--quiet", "--output", d, "--set", "Output/Write XDMF=false",
           "--set", "Output/Write contact CSV=false", "--set", "Adaptivity/Cycles=%d" % cycles]
    for s in sets:
        cmd += ["--set", s]
    subprocess.run(cmd, check=True)
    return os.path.join(d, "summary.json")


def table(scene, summary_path, last_cycle):
    s = json.load(open(summary_path))
    cyc = [c for c in s["cycles"] if c.get("contact")]
    dim = len(cyc[0]["contact"]["force"])
    last = quantities(cyc[-1], dim)
    prev = [quantities(c, dim) for c in cyc[-3:-1]]
    peer = SCENES[scene][2]
    rows, resolved, passed, below = [], 0, 0, 0
    for name, ref in last.items():
        u = max(abs(p[name] - ref) for p in prev)
        source = "run c%d" % cyc[-1]["cycle"]
        if name == "force" and peer:
            ref, u, source = peer[0], peer[1], "peer"
        cells = []
        for c in cyc:
            if c["cycle"] < 3 or c["cycle"] > last_cycle:
                continue
            e = c["contact"]["estimated_error"].get(name)
            t = abs(quantities(c, dim)[name] - ref)
            if e is None:
                cells.append("–")
            elif t <= 2 * u:
                cells.append("u")
            else:
                r = e / t
                resolved += 1
                ok = 1.0 <= r <= 10.0
                passed += ok
                below += r < 1.0
                cells.append(("%.2g" % r) + ("" if ok else "*"))
        rows.append((name, "%.6g ± %.2g (%s)" % (ref, u, source), cells))
    first = [c["cycle"] for c in cyc if 3 <= c["cycle"] <= last_cycle]
    return rows, first, resolved, passed, below


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--out", default="/tmp/error-bars-study")
    ap.add_argument("--scenes", nargs="+", default=[s for s in SCENES if not s.startswith("hertz3d")])
    ap.add_argument("--cycles", type=int, default=24)
    ap.add_argument("--last", type=int, default=16, help="last cycle tabulated")
    ap.add_argument("--app", default=APP)
    ap.add_argument("--table-only", action="store_true", help="re-read OUT/<scene>/summary.json")
    ap.add_argument("--check", action="store_true")
    args = ap.parse_args()
    bad = []
    for scene in args.scenes:
        path = os.path.join(args.out, scene, "summary.json")
        if not args.table_only:
            path = run(scene, args.out, args.cycles, args.app)
        rows, cycles, resolved, passed, below = table(scene, path, args.last)
        print("\n%s: estimated / true error per cycle (u: true error within twice the reference's "
              "uncertainty; *: outside [1, 10]); %d of %d resolved ratios in [1, 10], %d below 1 (the "
              "estimate under the true error), %d above 10\n"
              % (scene, passed, resolved, below, resolved - passed - below))
        print("| quantity | reference | " + " | ".join("c%d" % c for c in cycles) + " |")
        print("|---|---|" + "---|" * len(cycles))
        for name, ref, cells in rows:
            print("| %s | %s | %s |" % (name, ref, " | ".join(cells)))
        if resolved and below > 0.05 * resolved:
            bad.append("%s: %d of %d ratios below 1" % (scene, below, resolved))
    if args.check and bad:
        print("FAIL: " + "; ".join(bad))
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
