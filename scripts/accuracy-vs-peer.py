#!/usr/bin/python3
"""Whole-process time to "a, p0 within 1%, P within 0.1%" on Hertz 2D: StressContact asked for
that accuracy (Adaptivity/Target ... error, docs/adaptivity.md) against the peer GetFEM script
(docs/peer/hertz2d_primal.py) on its coarsest mesh that meets it (level 0: P, a, p0 within 0.01%,
0.01%, 0.1% of the peer's converged values, docs/peer/README.md). One run, the codes alternating,
`uptime` before and after; each process timed from outside (fork to exit).

    nice -n 10 /usr/bin/python3 scripts/accuracy-vs-peer.py [--rounds 3] [--out DIR]

Prints one line per process and the median per code; the true errors of StressContact's last
cycle against the peer values (load: the peer's converged P; a and p0: the peer's frictionless
values do not exist for Coulomb, so only the load of the frictionless scene and the estimated
errors are printed for Coulomb).
"""
import argparse
import json
import math
import os
import statistics
import subprocess
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
APP = os.path.join(ROOT, "build", "apps", "stresscontact", "stresscontact")
TARGETS = ["Adaptivity/Cycles=100", "Adaptivity/Target force error=1e-3",
           "Adaptivity/Target width error=1e-2", "Adaptivity/Target pressure error=1e-2"]


def timed(cmd, **kw):
    t0 = time.time()
    p = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, **kw)
    dt = time.time() - t0
    if p.returncode != 0:
        raise SystemExit("failed: %s\n%s" % (" ".join(cmd), p.stdout[-2000:]))
    return dt, p.stdout


def stresscontact(deck, out, xdmf):
    cmd = [APP, os.path.join(ROOT, deck), "--quiet", "--output", out]
    if not xdmf:
        cmd += ["--set", "Output/Write XDMF=false", "--set", "Output/Write contact CSV=false"]
    for s in TARGETS:
        cmd += ["--set", s]
    dt, _ = timed(cmd)
    s = json.load(open(os.path.join(out, "summary.json")))
    c = s["cycles"][-1]
    ct = c["contact"]
    fitted = ct.get("fitted_half_width")
    return dt, "cycle %d, %d DOFs, P %.4f, a %.5f (fitted %s), p0 %.2f; %s" % (
        c["cycle"], c["dofs"]["total"], math.hypot(*ct["force"]), ct["half_width"],
        "%.5f" % fitted if fitted is not None else "none", ct["max_pressure"],
        "targets met" if s["stop"]["accuracy_targets_met"] else "NOT met: " + s["stop"]["reason"])


def peer(out):
    csv = os.path.join(out, "peer.csv")
    dt, text = timed(["/usr/bin/python3", os.path.join(ROOT, "docs/peer/hertz2d_primal.py"), "--levels", "0",
                      "--models", "obstacle", "--methods", "mult", "--csv", csv])
    row = [l for l in text.splitlines() if l.startswith("obstacle mult 0 ")][0].split()
    mesh = [l for l in text.splitlines() if l.startswith("# level 0")][0].split("mesh_s=")[1]
    return dt, "level 0, %s DOFs, P %s, a %s, p0 %s; mesh %s s, solve %s s" % (row[5], row[7], row[10], row[12],
                                                                               mesh, row[19])


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--rounds", type=int, default=3)
    ap.add_argument("--out", default="/tmp/accuracy-vs-peer")
    args = ap.parse_args()
    os.makedirs(args.out, exist_ok=True)
    print(subprocess.run(["uptime"], stdout=subprocess.PIPE, text=True).stdout.strip(), flush=True)
    jobs = [("StressContact frictionless (hertz2d_frictionless.xml, targets)",
             lambda: stresscontact("input/hertz2d_frictionless.xml", os.path.join(args.out, "f"), False)),
            ("StressContact frictionless, XDMF fields written",
             lambda: stresscontact("input/hertz2d_frictionless.xml", os.path.join(args.out, "fx"), True)),
            ("GetFEM frictionless (hertz2d_primal.py level 0, whole process)", lambda: peer(args.out)),
            ("StressContact Coulomb (hertz2d.xml, targets)",
             lambda: stresscontact("input/hertz2d.xml", os.path.join(args.out, "c"), False))]
    times = {name: [] for name, _ in jobs}
    for r in range(args.rounds):
        for name, job in jobs:
            dt, what = job()
            times[name].append(dt)
            print("round %d | %s | %.2f s | %s" % (r + 1, name, dt, what), flush=True)
    print(subprocess.run(["uptime"], stdout=subprocess.PIPE, text=True).stdout.strip())
    for name, t in times.items():
        print("median %.2f s (min %.2f) | %s" % (statistics.median(t), min(t), name))


if __name__ == "__main__":
    main()
