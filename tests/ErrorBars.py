#!/usr/bin/python3
"""CTest error_bars_hertz2d: accuracy targets and error bars on the frictionless Hertz 2D deck.

One run of input/hertz2d_frictionless.xml asking for "P within 0.1%, p0 within 1%" by
Adaptivity/Target force error and Target pressure error (Cycles raised to 100 as a cap, not a
count). Checks (docs/adaptivity.md "Accuracy targets and a time budget", docs/output.md "Error
bars"):
- the run stops because the targets are met: stop_reason, summary.json `stop`, the last progress
  line, and `accuracy_targets` of the last cycle all say so, with relative estimates within the
  targets;
- the load is then within 0.1% of the peer's converged load P = 106.805 ± 0.003 (docs/peer/README.md
  "Converged loads", GetFEM P2): the promise the target makes to the user;
- from the fourth cycle on, the estimated error of the load is not below its true error against the
  peer value wherever that true error is resolved (above twice the peer's uncertainty);
- cycle 0 has no error bars (null), every later cycle has them;
- the half-width's error bar is 1.5 × its resolution (`contact.half_width_resolution`, docs/output.md
  "Error bars"), and from the fourth cycle on it contains the half-width's true error against the
  peer's converged a = 0.07782 (docs/peer/README.md "Converged loads", the same digits on levels 1-3;
  ± 1e-5 for its rounding and the levels);
- from the fourth cycle on the fitted half-width (`contact.fitted_half_width`, docs/contact.md
  "Outputs") exists, has an error bar, and the bar contains its true error against the same a.
"""
import argparse
import json
import math
import os
import subprocess
import sys

PEER_P, PEER_U = 106.805, 0.003
PEER_A, PEER_A_U = 0.07782, 1e-5


def fail(msg):
    print("FAIL: " + msg)
    sys.exit(1)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--app", required=True)
    ap.add_argument("--deck", required=True)
    ap.add_argument("--out", required=True)
    args = ap.parse_args()
    cmd = [args.app, args.deck, "--output", args.out, "--set", "Output/Write XDMF=false",
           "--set", "Output/Write contact CSV=false", "--set", "Adaptivity/Cycles=100",
           "--set", "Adaptivity/Target force error=1e-3", "--set", "Adaptivity/Target pressure error=1e-2"]
    p = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    print(p.stdout[-3000:])
    if p.returncode != 0:
        fail("exit %d" % p.returncode)
    lines = [l for l in p.stdout.splitlines() if l.strip()]
    if not lines[-1].startswith("done (accuracy targets met): "):
        fail("last progress line: " + lines[-1])
    s = json.load(open(os.path.join(args.out, "summary.json")))
    cycles = s["cycles"]
    last = cycles[-1]
    if not s["stop"]["accuracy_targets_met"] or s["stop"]["time_budget_reached"]:
        fail("summary stop: %s" % s["stop"])
    if not last["stop_reason"].startswith("accuracy targets met (estimated relative errors): force "):
        fail("stop_reason: " + last["stop_reason"])
    if s["stop"]["reason"] != last["stop_reason"]:
        fail("stop.reason differs from the last stop_reason")
    targets = {t["quantity"]: t for t in last["accuracy_targets"]}
    if sorted(targets) != ["force", "pressure"]:
        fail("targets %s" % sorted(targets))
    for t in targets.values():
        if not (t["met"] and 0 <= t["estimated_relative_error"] <= t["target"]):
            fail("target not met: %s" % t)
    force = math.hypot(*last["contact"]["force"])
    rel = abs(force - PEER_P) / PEER_P
    print("stopped after cycle %d (%d DOFs): P = %.5f, true relative error %.2e (peer), estimate %.2e"
          % (last["cycle"], last["dofs"]["total"], force, rel, targets["force"]["estimated_relative_error"]))
    if rel > 1e-3:
        fail("load %.5f is %.2e from the peer's %.3f (> 1e-3)" % (force, rel, PEER_P))
    if any(v is not None for v in cycles[0]["contact"]["estimated_error"].values()):
        fail("cycle 0 has error bars")
    for c in cycles[1:]:
        ee = c["contact"]["estimated_error"]
        if ee["force"] is None or ee["max_pressure"] is None or ee["half_width"] is None:
            fail("cycle %d lacks error bars: %s" % (c["cycle"], ee))
        if c["reactions"]["Top"]["estimated_error"]["force"] is None:
            fail("cycle %d lacks the reaction's error bar" % c["cycle"])
        r = c["contact"]["half_width_resolution"]
        if not (r > 0 and abs(ee["half_width"] - 1.5 * r) <= 1e-12 * r):
            fail("cycle %d: half-width error bar %.6g, resolution %.6g (want 1.5 x)" % (c["cycle"], ee["half_width"], r))
        if c["cycle"] < 3:
            continue
        t = abs(math.hypot(*c["contact"]["force"]) - PEER_P)
        if t > 2 * PEER_U and ee["force"] < t:
            fail("cycle %d: estimated load error %.3g below the true error %.3g" % (c["cycle"], ee["force"], t))
        t = abs(c["contact"]["half_width"] - PEER_A)
        if ee["half_width"] + PEER_A_U < t:
            fail("cycle %d: half-width error bar %.3g below the true error %.3g" % (c["cycle"], ee["half_width"], t))
        fitted, fe = c["contact"]["fitted_half_width"], ee.get("fitted_half_width")
        if fitted is None or fe is None:
            fail("cycle %d: no fitted half-width (%s) or no error bar (%s)" % (c["cycle"], fitted, fe))
        t = abs(fitted - PEER_A)
        if fe + PEER_A_U < t:
            fail("cycle %d: fitted half-width %.6g, error bar %.3g below the true error %.3g" % (c["cycle"], fitted, fe, t))
        print("cycle %d: fitted half-width %.6f, true error %.2e (peer a), error bar %.2e"
              % (c["cycle"], fitted, t, fe))
    print("PASS")
    return 0


if __name__ == "__main__":
    sys.exit(main())
