#!/usr/bin/python3
"""CTest trade_study: scripts/trade-study.py on its tiny grid of two coarse scenes.

Checks the CSV columns, and recomputes every error from the runs' own summary.json files and the
scene's reference independently of the script:
- mms2d (manufactured, exact solution): the stress error is the run's ‖A^{1/2}(σ − σ_h)‖ over
  ‖A^{1/2}σ_h‖ (summary.json eta.stress_energy_error / eta.stress_energy_norm) and the displacement
  error errors.displacement_l2_relative; k = 2 is more accurate than k = 1 on the same mesh
  (a priori: O(h^{k+1}), docs/verification.md).
- hertz2d_frictionless on the 0.25 mesh: the load error is against the peer value 106.805
  (docs/peer/README.md "Converged loads"), the half-width and peak pressure errors against the
  reference run's last cycle (its own summary.json).
Exit 77 (skipped) where /usr/bin/python3 cannot import matplotlib.
"""
import argparse
import csv
import json
import os
import subprocess
import sys


def fail(msg):
    print("FAIL: " + msg)
    sys.exit(1)


def close(a, b, tol=1e-12):
    return abs(a - b) <= tol * max(1.0, abs(b))


def read_rows(path):
    with open(path) as f:
        reader = csv.DictReader(f)
        return reader.fieldnames, list(reader)


def last_cycles(summary_path):
    s = json.load(open(summary_path))
    return {c["cycle"]: c for c in s["cycles"] if c.get("eta")}


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--app", required=True)
    ap.add_argument("--script", required=True)
    ap.add_argument("--out", required=True)
    args = ap.parse_args()
    try:
        import matplotlib  # noqa: F401
    except ImportError:
        print("skipped: no matplotlib for %s" % sys.executable)
        return 77

    base_columns = ["scene", "run", "sets", "cycle", "dofs", "seconds", "process_seconds", "peak_rss_mb",
                    "eta", "eta_relative", "newton_iterations", "phase_setup", "phase_assemble",
                    "phase_solve", "phase_estimate"]

    # Manufactured: errors against the exact solution.
    cmd = [sys.executable, args.script, "mms2d", "--grid", "tiny", "--cycles", "1", "--binary", args.app,
           "--out", args.out]
    subprocess.run(cmd, check=True)
    out = os.path.join(args.out, "mms2d")
    cols, rows = read_rows(os.path.join(out, "runs.csv"))
    for c in base_columns + ["stress_energy", "stress_energy_error", "displacement_l2", "displacement_l2_error"]:
        if c not in cols:
            fail("mms2d runs.csv lacks column %s (has %s)" % (c, cols))
    runs = {r["run"] for r in rows}
    if runs != {"k1_uniform", "k2_uniform", "shipped"} or len(rows) != 6:
        fail("mms2d: expected 3 runs of 2 cycles, got %s (%d rows)" % (sorted(runs), len(rows)))
    for r in rows:
        c = last_cycles(os.path.join(out, r["run"], "summary.json"))[int(r["cycle"])]
        want = c["eta"]["stress_energy_error"] / c["eta"]["stress_energy_norm"]
        if not close(float(r["stress_energy_error"]), want):
            fail("mms2d %s c%s: stress error %s, summary.json gives %r" % (r["run"], r["cycle"], r["stress_energy_error"], want))
        if not close(float(r["displacement_l2_error"]), c["errors"]["displacement_l2_relative"]):
            fail("mms2d %s: displacement error mismatch" % r["run"])
        if int(r["dofs"]) != c["dofs"]["total"]:
            fail("mms2d %s: DOFs mismatch" % r["run"])
        if not (0 < float(r["seconds"]) <= float(r["process_seconds"]) + 1e-9):
            fail("mms2d %s c%s: seconds %s not in (0, process %s]" % (r["run"], r["cycle"], r["seconds"], r["process_seconds"]))
    by = {(r["run"], r["cycle"]): float(r["stress_energy_error"]) for r in rows}
    for cyc in ("0", "1"):
        if not by[("k2_uniform", cyc)] < 0.5 * by[("k1_uniform", cyc)]:
            fail("mms2d cycle %s: k = 2 error %g not below half the k = 1 error %g" % (cyc, by[("k2_uniform", cyc)], by[("k1_uniform", cyc)]))
    if not os.path.getsize(os.path.join(out, "front_stress_energy.png")) > 1000:
        fail("mms2d: no front plot")

    # Hertz 2D frictionless: peer load, reference run for the other quantities.
    cmd = [sys.executable, args.script, "hertz2d_frictionless", "--grid", "tiny", "--cycles", "0",
           "--set", "Mesh/Initial mesh size=0.25", "--binary", args.app, "--out", args.out, "--no-plot"]
    subprocess.run(cmd, check=True)
    out = os.path.join(args.out, "hertz2d_frictionless")
    cols, rows = read_rows(os.path.join(out, "runs.csv"))
    for q in ("load", "half_width", "max_pressure"):
        if q not in cols or q + "_error" not in cols:
            fail("hertz2d runs.csv lacks %s / %s_error" % (q, q))
    ref = last_cycles(os.path.join(out, "reference", "summary.json"))
    ref = ref[max(ref)]["contact"]
    peer_load = 106.805  # docs/peer/README.md, obstacle normal, frictionless, ν = 0.28
    refjson = json.load(open(os.path.join(out, "reference.json")))["reference"]
    if refjson["load"]["value"] != peer_load or "docs/peer" not in refjson["load"]["source"]:
        fail("hertz2d: the load reference is not the peer value: %s" % refjson["load"])
    if len(rows) != 2:
        fail("hertz2d: expected 2 rows (k1_uniform, shipped), got %d" % len(rows))
    for r in rows:
        c = last_cycles(os.path.join(out, r["run"], "summary.json"))[int(r["cycle"])]["contact"]
        load = abs(c["force"][1])
        checks = [("load", load, peer_load),
                  ("half_width", c["equivalent_half_width"], ref["equivalent_half_width"]),
                  ("max_pressure", c["max_pressure"], ref["max_pressure"])]
        for q, value, reference in checks:
            if not close(float(r[q]), value):
                fail("hertz2d %s: %s %s, summary.json %r" % (r["run"], q, r[q], value))
            want = abs(value - reference) / abs(reference)
            if not close(float(r[q + "_error"]), want):
                fail("hertz2d %s: %s_error %s, expected %r" % (r["run"], q, r[q + "_error"], want))
        # A coarse mesh (0.25, 1 cycle) is not converged: its load is off the peer by 0.1–10%.
        if not 1e-3 < float(r["load_error"]) < 0.1:
            fail("hertz2d %s: load error %s outside (1e-3, 0.1) on the 0.25 mesh" % (r["run"], r["load_error"]))
    print("trade_study: columns and errors agree with the runs' summary.json and the references")
    return 0


if __name__ == "__main__":
    sys.exit(main())
