#!/usr/bin/env python3
"""Hertz 2D in both contact frames (docs/contact.md "Contact model").

Runs build/apps/stresscontact/stresscontact on input/hertz2d_frictionless.xml and
input/hertz2d.xml with local refinement towards the contact zone, with straight-sided (Mesh/
Geometry order = 1) and curved (2) boundary elements, into DIR/<case> (DIR: --out, default
/tmp/sc_contact_frames), and writes DIR/contact_frames.csv (with --update-docs also
docs/studies/contact_frames.csv, the reference the docs quote): geometry order, frame, degree, sweeps, nu, friction, DOFs, seconds, load P,
half-width a (outermost and from the area), peak pressure p0, Hertz a and p0 from P, the
staircase (max deviation of sigma_N from the line through its neighbours, inner 80%), the
profile error against Hertz (inner 80%) and the stick half-width (Coulomb). Hertz's values come
from each run's own parameters (scripts/plot-run.py's hertz_reference), nothing is assumed here.

Usage (from the repository root, after building):
    python3 docs/studies/contact_frames.py [--out DIR] [--update-docs]
"""
import argparse
import csv
import importlib.util
import json
import math
import os
import shutil
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
APP = os.path.join(ROOT, "build", "apps", "stresscontact", "stresscontact")
_spec = importlib.util.spec_from_file_location("plot_run", os.path.join(ROOT, "scripts", "plot-run.py"))
PR = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(PR)


def run(deck, sets, tag, out_dir):
    out = os.path.join(out_dir, tag)
    cmd = [APP, os.path.join(ROOT, "input", deck), "--output", out, "--quiet"]
    for s in sets:
        cmd += ["--set", s]
    t0 = time.time()
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)
    seconds = time.time() - t0
    with open(os.path.join(out, "summary.json")) as f:
        summary = json.load(f)
    rows = list(csv.DictReader(open(os.path.join(out, "contact_cycle0.csv"))))
    return summary, rows, seconds


def profile_measures(rows, a, p0):
    act = sorted((float(r["x"]), -float(r["sigma_n"])) for r in rows if r["status"] != "free")
    stair = prof = 0.0
    for i, (x, s) in enumerate(act):
        if abs(x) >= 0.8 * a:
            continue
        prof = max(prof, abs(s - p0 * math.sqrt(max(0.0, 1 - x * x / (a * a)))))
        if 0 < i < len(act) - 1:
            (xl, sl), (xr, sr) = act[i - 1], act[i + 1]
            stair = max(stair, abs(s - (sl + (sr - sl) * (x - xl) / (xr - xl))))
    return stair / p0, prof / p0


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--out", default="/tmp/sc_contact_frames")
    parser.add_argument("--update-docs", action="store_true",
                        help="copy the CSV into docs/studies/ (the committed reference)")
    args = parser.parse_args()
    if not os.path.exists(APP):
        sys.exit("build the application first (scripts/build-and-test.sh): " + APP)
    cases = []
    for geometry in (1, 2):
        # The body frame is not offered on curved faces (docs/contact.md "Curved contact faces").
        for frame in ("Obstacle normal", "Body normal") if geometry == 1 else ("Obstacle normal",):
            for k, sweeps in ((1, 6), (1, 8), (1, 10), (2, 6), (2, 8)):
                cases.append((geometry, frame, k, sweeps, 0.28, "None"))
            for nu in (0.28, 0.4999):
                cases.append((geometry, frame, 1, 8, nu, "Coulomb"))
    header = ["geometry_order", "frame", "degree", "sweeps", "nu", "friction", "dofs", "seconds", "P", "a",
              "a_area", "p0", "a_hertz", "p0_hertz", "staircase_rel_p0", "profile_err_rel_p0",
              "stick_half_width", "newton_steps"]
    results = []
    for geometry, frame, k, sweeps, nu, law in cases:
        deck = "hertz2d_frictionless.xml" if law == "None" else "hertz2d.xml"
        sets = ["Mesh/Geometry order=%d" % geometry,
                "Adaptivity/Cycles=0", "Contact/Frame=" + frame, "Discretization/Degree=%d" % k,
                "Material/Poisson ratio=%g" % nu, "Mesh/Local refinement/Levels=%d" % sweeps,
                "Mesh/Local refinement/Radius=0.12", "Mesh/Local refinement/Center={0, 0}"]
        tag = "g%d_%s_k%d_s%d_nu%g_%s" % (geometry, frame.split()[0], k, sweeps, nu, law)
        summary, rows, seconds = run(deck, sets, tag, args.out)
        cyc = summary["cycles"][-1]
        c = cyc["contact"]
        P = c["force"][1]
        aH, p0H = PR.hertz_reference(summary, P)
        stair, prof = profile_measures(rows, aH, p0H)
        r = [geometry, frame, k, sweeps, nu, law, cyc["dofs"]["total"], round(seconds, 1), P,
             c["half_width"], c["equivalent_half_width"], c["max_pressure"], aH, p0H, stair, prof,
             c["stick_half_width"], c["newton_iterations"]]
        results.append(r)
        print(" ".join(str(v) for v in r), flush=True)
    path = os.path.join(args.out, "contact_frames.csv")
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(header)
        w.writerows(results)
    print("wrote", path)
    if args.update_docs:
        shutil.copy(path, os.path.join(ROOT, "docs", "studies", "contact_frames.csv"))
        print("copied it into docs/studies/")


if __name__ == "__main__":
    main()
