"""Load-step runs of the application (docs/theory.md "Load steps", docs/contact.md "Load steps").

    python3 LoadSteps.py --app stresscontact --ranks N --case CASE --deck DECK --out DIR
                         [--expected FILE]
                         [--set KEY=VALUE ...] [--kill-cycle K] [--set-checkpoint-int TOOL]

Runs the deck on N ranks into DIR (emptied first) and checks its summary.json. The stored
numbers, the peer's tolerances and their sources are in the --expected file of the deck
(tests/expected/<deck>_<variant>.json, "values": name, value, relative tolerance):

cattaneo-mindlin  the Hertz half disc (nu = 0.4999, mu_F = 0.4) pressed (step 1), then moved
                  sideways (step 2). Analytic: Johnson, Contact Mechanics (1985) §7.1, for a
                  half-space (the normal and tangential problems decouple at nu -> 1/2): the load P
                  is unchanged by the tangential step (to 1e-3), Q/(mu_F P) is about 1/2 (the
                  deck's intent), the stick zone shrinks, and its half-width (c+ + c-)/2 =
                  a sqrt(1 - Q/(mu_F P)) within 0.03 of a (the half disc is not a half-space:
                  measured 0.719 against 0.707). Peer: P, Q (within 1.5e-3) and the stick zone's
                  two ends (within 0.04 a) against the primal GetFEM computation with incremental
                  friction, read from docs/peer/cattaneo_mindlin2d_primal.csv (docs/peer/README.md;
                  measured -7.1e-4, -5.9e-4, -0.007 a, +0.026 a). Stored: the final P, Q and stick
                  half-width of a 1-rank run of the shipped deck (2026-12-03), to 1e-8 at every
                  rank count (tests/expected/cattaneo_mindlin2d_default.json, with the peer's
                  tolerances).
mindlin-deresiewicz  input/mindlin_deresiewicz2d.xml: pressed (step 1), moved sideways to Q* about
                  mu_F P/2 (step 2), back half way (step 3: partial unloading) and on to -delta*
                  (step 4). Analytic: Johnson, Contact Mechanics (1985) §7.3 (Mindlin-Deresiewicz
                  unloading, half-space, decoupled at nu -> 1/2): on unloading to Q the traction is
                  the loading traction minus twice a Cattaneo correction, q - q* = -2 mu_F p0
                  (sqrt(1 - x^2/a^2) - (b/a) sqrt(1 - x^2/b^2)) on |x| < b, and -2 mu_F p in the
                  reversed-slip zones b < |x| < a, with b/a = sqrt(1 - (Q* - Q)/(2 mu_F P)); by
                  Masing's rule the reversal to -delta* gives Q = -Q*. Checked: every slip point of
                  steps 3 and 4 slips backwards (traction -mu_F p against step 2's +mu_F p), both
                  ends of the reversed-slip zones (step 3 within 0.03 a of +-b, the tolerance of the
                  cattaneo-mindlin case; measured 0.008 and 0.011), q - q* (the mean of the two
                  points at each x, step 2's traction interpolated onto step 3's refined mesh)
                  within 5% of mu_F p0 in the inner 70% of the stick zone (the unit test's bound
                  for Mindlin's profile; measured 1% in step 3, 2% in step 4), Q(-delta*) = -Q*
                  within 1% (measured 0.4%). Step 4's stick half-width b/a is checked within
                  0.05 of the half-space 0.706 (measured 0.667): the half disc keeps the odd
                  tractions locked in by pressing (docs/contact.md "Load steps"), which move the
                  loading step's zone by +0.034 on this mesh and the full reversal's by -0.039.
                  Peer: P, Q and the stick zone's ends of steps 2-4 against the primal GetFEM
                  computation of the same steps (md_peer_comparison; measured P -7.9e-4, Q within
                  6.9e-4 Q*, ends within 0.044 a; the peer's Q(-delta*)/Q* is -1.0040).
                  Stored: Q of steps 3 and 4 and their stick half-widths (1 rank, 2026-12-03), 1e-8
                  (tests/expected/mindlin_deresiewicz2d_default.json).
loop              input/mindlin_deresiewicz_loop2d.xml: pressed (step 1), moved sideways to delta*
                  (Q* about mu_F P/2) in n steps of h = delta*/n, back to -delta* and forth to
                  +delta* in steps of 2h (the run's steps must be so; n from the summary), so that
                  unloading point j (delta* - 2jh) and reloading point j (-delta* + 2jh) lie at
                  twice the distance jh of loading point j from their reversal. Masing's
                  construction (Masing 1926; Johnson, Contact Mechanics (1985) §7.3 for the
                  Mindlin-Deresiewicz unloading): Q_un(j) = Q* - 2 Q_load(j), Q_re(j) = -Q* +
                  2 Q_load(j), each within 0.015 Q* (measured at most 0.0082 Q* on both meshes:
                  the construction assumes a pressed state without tangential traction, and the
                  half disc's pressing locks in odd tractions, which the virgin branch carries
                  and the first reversal wipes out; docs/contact.md "Load steps"); the loop
                  closes: Q(+delta*) after reloading within 0.01 Q* of Q* (measured +0.40% and
                  +0.48%) and point-symmetric, |Q(+delta*) + Q(-delta*)| within 0.005 Q* (measured
                  1.7e-4 and 1.7e-3). Shape: in 2D the tangential displacement exists only
                  relative to a datum, which adds a term linear in Q; what does not depend on the
                  datum is the rest of Johnson's plane-strain Cattaneo compliance (§7.1's traction,
                  the half-plane's tangential surface displacement integrated to a datum:
                  docs/contact.md "Load steps"), delta(Q) = L Q + K mu_F P (1 - q) ln(1 - q), q =
                  Q/(mu_F P), K = (1 - nu^2)/(pi E), and for the reversed branches twice that at
                  half the force from their reversal point (Mindlin-Deresiewicz). L and the
                  coefficient B of the second term are fitted (least squares, L free) to all 3n
                  points and to the 2n reversed points alone: B/K within 0.15 of 1 for both
                  (measured 1.058 and 1.092 as shipped, 1.074 and 1.103 coarse; the loading
                  branch alone, reported only, 0.80 and 0.85: the locked-in tractions again. A
                  loop without the logarithmic term, B = 0, or with plane stress's 1/(pi E) =
                  1.33 K would fail).
                  P constant within 1e-3 (decoupled at nu -> 1/2). With --zone-ends (the
                  shipped deck, which refines in each step): on the reloading branch the stick
                  zone is centred again, its ends within 0.03 a of +-b, b/a = sqrt(1 - (Q -
                  Q(-delta*))/(2 mu_F P)) (Johnson §7.3 from the reversal point; at +delta* §7.1's
                  zone; the tolerance of cattaneo-mindlin; measured within 0.014 a). (On the
                  first unloading branch the zone is centred while the reversed slip stays in the
                  loading step's slip zone, +-0.940 a and +-0.879 a against 0.934 and 0.863, and
                  shifted after, like the loading step's: not checked.) Stored: Q*,
                  Q(-delta*) and Q(+delta*) after reloading (1 rank, 2026-12-03), 1e-8, per variant
                  (--variant; tests/expected/mindlin_deresiewicz_loop2d_<variant>.json). With --peer (the shipped deck): Q of every step within 1.5e-3 Q* of
                  the primal GetFEM computation of the 13 steps (loop_peer_comparison; measured
                  6.3e-4 Q* at most), whose own deviations from Masing are this run's to 2e-4 Q*.
incremental       input/hertz2d_incremental.xml (the Hertz half disc of input/hertz2d.xml, nu = 0.28,
                  mu_F = 0.4, on one fixed mesh) pressed by 0.01 t in N equal load steps, for each
                  N of --steps. One step is the static problem: its stick ratio c/a within 0.02 of
                  the converged static value 0.46 (docs/contact.md "Which 2D stick ratio to
                  trust"; 0.02 a is about the point spacing here). Several steps give the
                  incremental (path-dependent) answer. For a half-space its limit N -> infinity
                  is Spence's self-similar solution (Spence 1975): c/a = 0.877 in Goodman's
                  closed form, about 0.82 exactly (tests/SpenceHalfPlane.py); the half disc at
                  this load ends above both (0.90; docs/contact.md "Load steps" says why), so
                  they are not checked here. The checks are: c/a at least 0.3 above one step for
                  N >= 5 (measured 0.85-0.90 against 0.472), P within 0.5% of the one-step P, and
                  with three or more N >= 5 the area-based ratio growing with N by shrinking
                  differences (measured 0.849, 0.895, 0.905 for N = 5, 20, 40, and 0.905 at
                  N = 80). Stored: the final P and stick half-width of each N (1 rank,
                  2026-12-03, the deck's 11 refinement sweeps), 1e-8
                  (tests/expected/hertz2d_incremental_steps.json).
failed-step       the same deck with a Newton limit that step 1 meets and step 2 does not (its
                  first cycle needs 7 steps): exit status 2, summary.json names the failed step
                  (failed_load_step = 2), says converged = false, and keeps every cycle of step 1
                  (history.csv too).
restart           the shipped Cattaneo-Mindlin deck killed (SIGKILL, SC_KILL_IN_CYCLE = K) in
                  cycle K, then `--restart` (docs/adaptivity.md "Checkpoint and restart"). K = 13,
                  step 2's first cycle: the restart continues from the checkpoint of step 1's last
                  cycle (12) and commits the friction history itself. The final P, Q and stick
                  half-width must be the stored numbers of the uninterrupted run (to 1e-8, as
                  above), with every check of cattaneo-mindlin; the summary names the checkpoint's
                  cycle K - 1 and its load step, and has every cycle once, in its step.
restart-errors    a short run of the deck (it leaves a checkpoint in step 2), then restarts that
                  must be refused with exit status 1, a message naming the key, and the directory
                  left as it was: other 'Load steps/Times' than the checkpoint's, and a
                  checkpoint of the older format 3 (set by the tool --set-checkpoint-int; version
                  3 kept neither the load step nor the friction history).
"""

import argparse
import csv
import hashlib
import json
import math
import os
import re
import shutil
import subprocess
import sys


def read_expected(path):
    """The --expected file: its "values" by name, and the whole file (for "peer"). Every file and
    every block of tolerances names the source of its numbers."""
    with open(path) as f:
        expected = json.load(f)
    if not expected.get("source"):
        sys.exit(f"{path}: no 'source' for its numbers")
    if "peer" in expected and not expected["peer"].get("source"):
        sys.exit(f"{path}: no 'source' for the peer's tolerances")
    return {v["name"]: v for v in expected.get("values", [])}, expected


def check_stored(checks, stored, name, value, label=None):
    """value against the stored value `name` of the --expected file, within its relative tolerance."""
    entry = stored.get(name)
    if entry is None:
        checks.check(False, f"{label or name} = {value!r}: no stored value '{name}' in the --expected file")
        return
    ref, tol = entry["value"], entry["tolerance"]
    checks.check(abs(value - ref) <= tol * abs(ref),
                 f"{label or name} = {value!r} against the stored {ref!r} ({tol:g})")


# The cheap variant of the loop (the default suite): fewer cycles in step 1, none in later steps.
COARSE_LOOP_SETS = ["Adaptivity/Cycles=6", "Load steps/Cycles per later step=0"]
# Tolerances of the loop case (see the top).
MASING_TOL, CLOSURE_TOL, SYMMETRY_TOL, SHAPE_TOL, ENDS_TOL = 0.015, 0.01, 0.005, 0.15, 0.03


def launch(args, extra, env=None, mpi=True):
    """The app on args.ranks ranks with the deck, args.sets and `extra`: (exit status, output).
    Without `mpi`, the app alone (one rank; an input error exits at once, where mpiexec takes
    about 1.5 s to end the job)."""
    cmd = []
    if mpi:
        cmd = ["mpiexec", "-n", str(args.ranks), "--oversubscribe"]
        if os.geteuid() == 0:
            cmd.append("--allow-run-as-root")
    cmd += [args.app, args.deck] + extra
    for s in args.sets:
        cmd += ["--set", s]
    print(" ".join(cmd), flush=True)
    result = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                            env=None if env is None else {**os.environ, **env})
    print(result.stdout[-3000:])
    return result.returncode, result.stdout


def summary_of(directory):
    with open(os.path.join(directory, "summary.json")) as f:
        return json.load(f)


def run(args, expected_exit=0, extra=None, env=None, fresh=True, mpi=True):
    if fresh and os.path.isdir(args.out):
        shutil.rmtree(args.out)
    rc, _ = launch(args, extra if extra is not None else ["--output", args.out], env, mpi)
    if rc != expected_exit:
        print(f"FAILED: the run exited with {rc}, expected {expected_exit}")
        sys.exit(1)
    return summary_of(args.out)


def restart(args, checks):
    """Killed in cycle args.kill_cycle, restarted; the checks of cattaneo_mindlin on the result."""
    if os.path.isdir(args.out):
        shutil.rmtree(args.out)
    # (On one rank without mpiexec, which takes about 2 s to end a job whose process was killed;
    # the restart too.)
    rc, _ = launch(args, ["--output", args.out, "--quiet"], {"SC_KILL_IN_CYCLE": str(args.kill_cycle)},
                   mpi=args.ranks > 1)
    checks.check(rc != 0 and os.path.exists(os.path.join(args.out, "checkpoint.h5")),
                 f"the run killed in cycle {args.kill_cycle} exited with {rc} and left a checkpoint")
    killed = summary_of(args.out)
    checks.check(len(killed["cycles"]) == args.kill_cycle,
                 f"the killed run's summary has the {args.kill_cycle} cycles before the kill "
                 f"({len(killed['cycles'])})")
    summary = run(args, 0, ["--restart", args.out], fresh=False, mpi=args.ranks > 1)
    record = summary.get("restart", {})
    steps = [c["load_step"]["step"] for c in summary["cycles"]]
    killed_step = [c["load_step"]["step"] for c in killed["cycles"]][-1]
    checks.check(record.get("checkpoint_cycle") == args.kill_cycle - 1 and
                 record.get("checkpoint_load_step") == killed_step,
                 f"restarted from the checkpoint of cycle {args.kill_cycle - 1} in load step {killed_step}: {record}")
    checks.check([c["cycle"] for c in summary["cycles"]] == list(range(len(steps))) and
                 steps == sorted(steps) and set(steps) == {1, 2},
                 f"every cycle once, in its load step: {steps}")
    return summary


def restart_errors(args, checks):
    """Restarts that must be refused, on the checkpoint of a short run (left in step 2)."""
    run(args, 0, ["--output", args.out, "--quiet"])

    def state():
        h = {}
        for name in sorted(os.listdir(args.out)):
            path = os.path.join(args.out, name)
            if os.path.isfile(path) and name != "stresscontact.lock":
                with open(path, "rb") as f:
                    h[name] = hashlib.sha256(f.read()).hexdigest()
        return h

    before = state()
    refusals = [
        ("Load steps other than the checkpoint's", ["--restart", args.out, "--set", "Load steps/Times={1, 3}"],
         r"the checkpoint '[^']*checkpoint\.h5' belongs to a run with other parameters: "
         r"'Load steps/Times' is \[1\.0,2\.0\] in the checkpoint and \[1\.0,3\.0\] in this run"),
    ]
    older = args.out + "_format3"
    if os.path.isdir(older):
        shutil.rmtree(older)
    shutil.copytree(args.out, older)
    tool = subprocess.run([args.set_checkpoint_int, os.path.join(older, "checkpoint.h5"),
                           "checkpoint_version", "3"])
    checks.check(tool.returncode == 0, "a copy of the checkpoint set to version 3")
    refusals.append(("a checkpoint of format 3", ["--restart", older],
                     r"the checkpoint '[^']*_format3/checkpoint\.h5' has 'checkpoint_version' = 3; this build "
                     r"reads version 5 \(from version 4 on the checkpoint keeps the load step and the contact "
                     r"points' friction history\)"))
    for what, extra, pattern in refusals:
        rc, out = launch(args, extra + ["--quiet"], mpi=False)
        checks.check(rc == 1 and re.search(pattern, out) is not None,
                     f"{what}: exit status {rc} (1), the message matches {pattern!r}")
    checks.check(state() == before, "the run's directory is left as it was")


class Checks:
    def __init__(self):
        self.failed = 0

    def check(self, ok, text):
        print(("ok      " if ok else "FAILED  ") + text)
        self.failed += 0 if ok else 1


def last_of_step(summary, step):
    cycles = [c for c in summary["cycles"] if c.get("load_step", {}).get("step") == step]
    return cycles[-1] if cycles else None


def stick_zone_from_csv(directory, cycle):
    """The stick zone's ends along x from contact_cycle<cycle>.csv as summary.json defines them:
    midway between the outermost stick point and the nearest other point beyond it."""
    with open(os.path.join(directory, f"contact_cycle{cycle}.csv")) as f:
        rows = list(csv.DictReader(f))
    stick = [float(r["x"]) for r in rows if r["status"] == "stick"]
    other = [float(r["x"]) for r in rows if r["status"] != "stick"]
    lo, hi = min(stick), max(stick)
    below, above = [x for x in other if x < lo], [x for x in other if x > hi]
    return [0.5 * (lo + max(below)) if below else lo, 0.5 * (hi + min(above)) if above else hi]


def cattaneo_mindlin(summary, mu, checks, directory, expected):
    first, second = last_of_step(summary, 1), last_of_step(summary, 2)
    checks.check(summary.get("converged") is True, "the run converged")
    checks.check(first is not None and second is not None, "summary.json has cycles of steps 1 and 2")
    if first is None or second is None:
        return
    p1 = first["contact"]["force"][1]
    P, Q = second["contact"]["force"][1], abs(second["contact"]["force"][0])
    a, c = second["contact"]["half_width"], second["contact"]["stick_half_width"]
    johnson = math.sqrt(1.0 - Q / (mu * P))
    ends = second["contact"]["stick_zone_ends"]
    print(f"step 1: P = {p1:.6g}, stick half-width {first['contact']['stick_half_width']:.6g}; "
          f"step 2: P = {P:.10g}, Q = {Q:.10g} (Q/(mu P) = {Q / (mu * P):.4f}), a = {a:.6g}, "
          f"stick zone [{ends[0]:.6g}, {ends[1]:.6g}], c/a = {c / a:.4f} (Johnson {johnson:.4f}), "
          f"Newton steps of step 2's cycles {[x['contact']['newton_iterations'] for x in summary['cycles'] if x['load_step']['step'] == 2]}")
    checks.check(abs(P / p1 - 1.0) <= 1e-3, f"P unchanged by the tangential step: {P / p1 - 1.0:.2e} (<= 1e-3)")
    checks.check(abs(Q / (mu * P) - 0.5) <= 0.02, f"Q/(mu_F P) = {Q / (mu * P):.4f} (0.5 +- 0.02)")
    checks.check(c < first["contact"]["stick_half_width"], "the stick zone shrinks in step 2")
    checks.check(abs(c / a - johnson) <= 0.03, f"c/a = {c / a:.4f} against Johnson {johnson:.4f} (+- 0.03)")
    checks.check(abs((ends[1] - ends[0]) / 2 - c) <= 1e-12 * a, "stick_zone_ends span 2 stick_half_width")
    # Where the zone is (it once came out mirrored about its centre): the stick points of the
    # contact CSV (the obstacle normal is (0, 1), so the plane's coordinate is x).
    csv_ends = stick_zone_from_csv(directory, second["cycle"])
    checks.check(all(abs(e - r) <= 1e-12 * a for e, r in zip(ends, csv_ends)),
                 f"stick_zone_ends {ends} are those of the contact CSV's stick points {csv_ends} (1e-12 a)")
    stored, whole = expected
    peer_comparison(P, Q, a, ends, checks, whole["peer"])
    for key, value in (("P", P), ("Q", Q), ("stick", c)):
        check_stored(checks, stored, key, value)


def peer_comparison(P, Q, a, ends, checks, tolerances):
    """The end of step 2 against the independent primal computation with incremental Coulomb
    friction (GetFEM, Taylor-Hood P2/P1 isoparametric, level 3: docs/peer/README.md
    "Cattaneo-Mindlin", values read from docs/peer/cattaneo_mindlin2d_primal.csv). P and Q within
    force_tolerance (the peer's own spread: Taylor-Hood against pure P2, docs/peer/README.md), the
    stick zone's two ends within end_tolerance a: this run's contact points are 0.0031 = 0.037 a
    apart at the ends (its ends are midway between points), the peer's nodes 0.001 = 0.012 a.
    Measured: P -7.1e-4, Q -5.9e-4; ends -0.007 a and +0.026 a. The tolerances are the "peer"
    block of the --expected file."""
    PEER_FORCE_TOL, PEER_END_TOL = tolerances["force_tolerance"], tolerances["end_tolerance"]
    path = os.path.join(os.path.dirname(os.path.abspath(__file__)), os.pardir, "docs", "peer",
                        "cattaneo_mindlin2d_primal.csv")
    with open(path) as f:
        rows = [r for r in csv.DictReader(f)
                if (r["level"], r["elem"], r["method"], r["step"]) == ("3", "th", "mult", "2")]
    checks.check(len(rows) == 1, f"{path} has the level-3 Taylor-Hood row of step 2")
    if len(rows) != 1:
        return
    peer = rows[0]
    for name, value in (("P", P), ("Q", Q)):
        ref = float(peer[name])
        checks.check(abs(value / ref - 1.0) <= PEER_FORCE_TOL,
                     f"{name} = {value:.6g} against the peer's {ref:.6g}: {value / ref - 1.0:.2e} (<= {PEER_FORCE_TOL})")
    for side, value, key in (("lower", ends[0], "stick_minus"), ("upper", ends[1], "stick_plus")):
        ref = float(peer[key])
        checks.check(abs(value - ref) <= PEER_END_TOL * a,
                     f"the stick zone's {side} end {value / a:.4f} a against the peer's {ref / a:.4f} a "
                     f"({(value - ref) / a:+.4f} a, <= {PEER_END_TOL} a)")


def contact_points(out, cycle):
    """(x, pressure, sigma_t, status) of the points in contact in contact_cycle<N>.csv, by x."""
    with open(os.path.join(out, f"contact_cycle{cycle['cycle']}.csv")) as f:
        rows = [r for r in csv.DictReader(f) if r["status"] != "free"]
    return sorted((float(r["x"]), -float(r["sigma_n"]), float(r["sigma_t"]), r["status"]) for r in rows)


def mean_by_x(points, sign):
    """Point pairs at one x (the two faces meeting there): the mean traction sign * sigma_t per x."""
    by_x = {}
    for x, p, t, status in points:
        by_x.setdefault(round(x, 12), []).append((sign * t, status))
    return [(x, sum(v for v, _ in vals) / len(vals), [s for _, s in vals]) for x, vals in sorted(by_x.items())]


def interpolate(table, x):
    for (x0, y0, _), (x1, y1, _) in zip(table, table[1:]):
        if x0 <= x <= x1:
            w = (x - x0) / (x1 - x0)
            return (1.0 - w) * y0 + w * y1
    return None


def mindlin_deresiewicz(summary, out, mu, E, nu, checks, expected):
    checks.check(summary.get("converged") is True, "the run converged")
    steps = [last_of_step(summary, n) for n in (1, 2, 3, 4)]
    checks.check(all(c is not None for c in steps), "summary.json has cycles of steps 1 to 4")
    if any(c is None for c in steps):
        return
    loaded = steps[1]
    points2 = contact_points(out, loaded)
    # Units in which step 2's (forward) slip traction is +mu_F p.
    sign = 1.0 if sum(t for x, p, t, s in points2 if s == "slip") > 0 else -1.0
    qstar_x = loaded["contact"]["force"][0]
    qstar = abs(qstar_x)
    forward2 = [sign * t / (mu * p) for x, p, t, s in points2 if s == "slip"]
    checks.check(len(forward2) > 0 and min(forward2) > 1.0 - 1e-6,
                 f"step 2: {len(forward2)} slip points, all forward (q = +mu_F p)")
    P2 = loaded["contact"]["force"][1]
    checks.check(abs(qstar / (mu * P2) - 0.5) <= 0.02, f"step 2: Q*/(mu_F P) = {qstar / (mu * P2):.4f} (0.5 +- 0.02)")
    q2 = mean_by_x(points2, sign)
    Estar = E / (1.0 - nu * nu)
    values = {}
    for n, cycle in ((3, steps[2]), (4, steps[3])):
        P = cycle["contact"]["force"][1]
        # Q along step 2's direction (negative past the reversal).
        Q = cycle["contact"]["force"][0] * (1.0 if qstar_x > 0 else -1.0)
        a = math.sqrt(4.0 * P / (math.pi * Estar))  # Hertz, R = 1 (the unit test's a)
        p0 = 2.0 * P / (math.pi * a)
        b = a * math.sqrt(1.0 - (qstar - Q) / (2.0 * mu * P))
        ends = cycle["contact"]["stick_zone_ends"]
        c = cycle["contact"]["stick_half_width"]
        values[f"Q{n}"], values[f"stick{n}"] = Q, c
        points = contact_points(out, cycle)
        slip = [(x, sign * t / (mu * p)) for x, p, t, s in points if s == "slip"]
        print(f"step {n}: P = {P:.10g}, Q = {Q:.10g} (Q* = {qstar:.10g}), a = {a:.6g}, stick zone "
              f"[{ends[0] / a:.4f}, {ends[1] / a:.4f}] a, half-width {c / a:.4f} a, Mindlin-Deresiewicz "
              f"b/a = {b / a:.4f}; {len(slip)} slip points; Newton steps "
              f"{[x['contact']['newton_iterations'] for x in summary['cycles'] if x['load_step']['step'] == n]}")
        checks.check(len(slip) > 0 and max(v for _, v in slip) < -1.0 + 1e-6,
                     f"step {n}: every slip point slips backwards (q = -mu_F p; max q/(mu_F p) "
                     f"{max(v for _, v in slip) if slip else float('nan'):.6f})")
        stick_x = [x for x, p, t, s in points if s == "stick"]
        checks.check(any(x < ends[0] for x, _ in slip) and any(x > ends[1] for x, _ in slip)
                     and all(x <= min(stick_x) or x >= max(stick_x) for x, _ in slip),
                     f"step {n}: reversed slip at both edges, none between stick points")
        checks.check(abs(P / P2 - 1.0) <= 1e-3, f"step {n}: P unchanged: {P / P2 - 1.0:.2e} (<= 1e-3)")
        if n == 3:
            checks.check(ends[0] < loaded["contact"]["stick_zone_ends"][0] and ends[1] > loaded["contact"]["stick_zone_ends"][1],
                         "step 3: the stick zone holds step 2's (the reversal starts at the edges)")
            for end, ref in ((ends[0], -b), (ends[1], b)):
                checks.check(abs(end - ref) <= 0.03 * a,
                             f"step 3: stick zone end {end / a:.4f} a against {ref / a:.4f} a (+- 0.03 a)")
        else:
            checks.check(abs(Q / qstar + 1.0) <= 0.01, f"step 4: Q/Q* = {Q / qstar:.5f} (Masing: -1 +- 0.01)")
            checks.check(abs(c - b) <= 0.05 * a, f"step 4: stick half-width {c / a:.4f} a against {b / a:.4f} a (+- 0.05 a)")
        # q - q* at the stick points, per x (mean of the two points there), inner 70% of the zone.
        worst, count = 0.0, 0
        for x, q, statuses in mean_by_x(points, sign):
            if abs(x) >= 0.7 * b or any(s != "stick" for s in statuses):
                continue
            before = interpolate(q2, x)
            if before is None:
                continue
            md = -2.0 * mu * p0 * (math.sqrt(1.0 - x * x / (a * a)) - (b / a) * math.sqrt(1.0 - x * x / (b * b)))
            worst = max(worst, abs(q - before - md))
            count += 1
        checks.check(count >= 10 and worst <= 0.05 * mu * p0,
                     f"step {n}: q - q* against Mindlin-Deresiewicz at {count} points (>= 10): max deviation "
                     f"{worst / (mu * p0):.4f} mu_F p0 (<= 0.05)")
    md_peer_comparison(steps, out, checks, expected[1]["peer"])
    stored, _ = expected
    for key, value in values.items():
        check_stored(checks, stored, key, value)


def peer_finest_steps(name):
    """The rows of docs/peer/NAME (a cattaneo_mindlin2d_primal.py --deck-steps output) of its
    finest level, Taylor-Hood with the multiplier method, by step: (path, level, {step: row})."""
    path = os.path.join(os.path.dirname(os.path.abspath(__file__)), os.pardir, "docs", "peer", name)
    with open(path) as f:
        rows = [r for r in csv.DictReader(f) if (r["elem"], r["method"]) == ("th", "mult")]
    level = max(int(r["level"]) for r in rows)
    return path, level, {int(r["step"]): r for r in rows if int(r["level"]) == level}


def md_peer_comparison(steps, out, checks, tolerances):
    """Steps 2-4 of input/mindlin_deresiewicz2d.xml against the primal GetFEM computation with
    incremental friction of the same steps (docs/peer/README.md "Mindlin-Deresiewicz", values
    read from docs/peer/mindlin_deresiewicz2d_primal.csv, its finest level): P, and Q (the top's
    reaction along x) within force_tolerance of P and of Q* (the "peer" block of the --expected
    file, the tolerance of peer_comparison).
    Each end of the stick zone within this run's point spacing at that end (from the contact CSV;
    0.0061 = 0.074 a at most ends of this coarser deck) plus the peer's node spacing h_min: both
    codes put an end midway between two points, so each is within half its spacing of its
    discrete zone's end."""
    PEER_FORCE_TOL = tolerances["force_tolerance"]
    path, level, peer = peer_finest_steps("mindlin_deresiewicz2d_primal.csv")
    checks.check(sorted(peer) == [1, 2, 3, 4], f"{path} has steps 1-4 of level {level}")
    if 2 not in peer:
        return
    qstar = float(peer[2]["Q"])
    for n in (2, 3, 4):
        if n not in peer:
            continue
        cycle, ref = steps[n - 1], peer[n]
        P, Q = cycle["contact"]["force"][1], cycle["reactions"]["Top"]["force"][0]
        a, ends = cycle["contact"]["half_width"], cycle["contact"]["stick_zone_ends"]
        checks.check(abs(P / float(ref["P"]) - 1.0) <= PEER_FORCE_TOL,
                     f"step {n}: P = {P:.6g} against the peer's {float(ref['P']):.6g}: {P / float(ref['P']) - 1.0:+.2e} "
                     f"(<= {PEER_FORCE_TOL})")
        checks.check(abs(Q - float(ref["Q"])) <= PEER_FORCE_TOL * abs(qstar),
                     f"step {n}: Q = {Q:.6g} against the peer's {float(ref['Q']):.6g}: "
                     f"{(Q - float(ref['Q'])) / qstar:+.2e} Q* (<= {PEER_FORCE_TOL} Q*)")
        xs = sorted({x for x, _, _, _ in contact_points(out, cycle)})
        for side, value, key in (("lower", ends[0], "stick_minus"), ("upper", ends[1], "stick_plus")):
            r = float(ref[key])
            below, above = [x for x in xs if x < value], [x for x in xs if x > value]
            spacing = (min(above) - max(below)) if below and above else float("nan")
            tol = spacing + float(ref["h_min"])
            checks.check(abs(value - r) <= tol,
                         f"step {n}: the stick zone's {side} end {value / a:+.4f} a against the peer's {r / a:+.4f} a "
                         f"({(value - r) / a:+.4f} a, <= {tol / a:.4f} a: spacing {spacing / a:.4f} a + the peer's "
                         f"{float(ref['h_min']) / a:.4f} a)")

def loop_peer_comparison(pts, n, checks, tolerances):
    """Every step of the loop against the primal GetFEM computation of the same 13 steps
    (docs/peer/README.md "Mindlin-Deresiewicz loop", docs/peer/mindlin_deresiewicz_loop2d_primal.csv,
    its finest level): Q within force_tolerance Q* (the "peer" block of the --expected file, the
    tolerance of peer_comparison), and the peer's own deviations from Masing's construction
    printed beside this run's."""
    PEER_FORCE_TOL = tolerances["force_tolerance"]
    path, level, rows = peer_finest_steps("mindlin_deresiewicz_loop2d_primal.csv")
    peer = {step: float(r["Q"]) for step, r in rows.items()}
    checks.check(sorted(peer) == list(range(1, len(pts) + 1)), f"{path} has steps 1-{len(pts)} of level {level}")
    if len(peer) != len(pts):
        return
    qstar = peer[n + 1]
    for k, (d, Q, _, _) in enumerate(pts[1:], start=2):
        checks.check(abs(Q - peer[k]) <= PEER_FORCE_TOL * qstar,
                     f"step {k}: Q = {Q:.6f} against the peer's {peer[k]:.6f} ({(Q - peer[k]) / qstar:+.2e} Q*, "
                     f"<= {PEER_FORCE_TOL} Q*)")
    dev = []
    for j in range(1, n + 1):
        dev.append(((peer[n + 1 + j] - (qstar - 2.0 * peer[1 + j])) / qstar,
                    (peer[2 * n + 1 + j] - (-qstar + 2.0 * peer[1 + j])) / qstar))
    print("the peer's deviations from Masing (unloading, reloading) / Q*: " +
          ", ".join(f"({u:+.4f}, {r:+.4f})" for u, r in dev))


def fit_compliance(rows):
    """Least squares for (L, B) in d = L x + B g over rows (x, g, d): the 2x2 normal equations."""
    sxx = sum(x * x for x, g, d in rows)
    sxg = sum(x * g for x, g, d in rows)
    sgg = sum(g * g for x, g, d in rows)
    sxd = sum(x * d for x, g, d in rows)
    sgd = sum(g * d for x, g, d in rows)
    det = sxx * sgg - sxg * sxg
    L, B = (sgg * sxd - sxg * sgd) / det, (sxx * sgd - sxg * sxd) / det
    return L, B, max(abs(L * x + B * g - d) for x, g, d in rows)


def loop(summary, mu, E, nu, checks, zone_ends, expected, peer=False):
    """The Mindlin-Deresiewicz hysteresis loop (see the top): Masing's construction from the
    computed loading branch, the loop's closure and symmetry, and its shape against Johnson's
    plane-strain compliance without the datum's linear term."""
    checks.check(summary.get("converged") is True, "the run converged")
    last = {}
    for c in summary["cycles"]:
        last[c["load_step"]["step"]] = c
    steps = [last[k] for k in sorted(last)]
    # (prescribed x of Top, Top's reaction along x, P, the cycle)
    pts = [(c["load_step"]["prescribed"]["Top"][0], c["reactions"]["Top"]["force"][0],
            -c["reactions"]["Top"]["force"][1], c) for c in steps]
    n = (len(pts) - 1) // 3
    ok = n >= 2 and len(pts) == 3 * n + 1 and pts[0][0] == 0.0
    if ok:
        dstar = pts[n][0]
        h = dstar / n
        want = ([k * h for k in range(n + 1)] + [dstar - 2 * j * h for j in range(1, n + 1)] +
                [-dstar + 2 * j * h for j in range(1, n + 1)])
        ok = dstar > 0 and all(abs(p[0] - w) <= 1e-9 * dstar for p, w in zip(pts, want))
    checks.check(ok, f"the steps trace the loop: pressed, n loading steps of delta*/n, n steps of 2 delta*/n "
                     f"to -delta* and n back to +delta* (n = {n}; prescribed x {[p[0] for p in pts]})")
    if not ok:
        return
    load, un, re_ = pts[1:n + 1], pts[n + 1:2 * n + 1], pts[2 * n + 1:]
    qstar, qrev, qend = load[-1][1], un[-1][1], re_[-1][1]
    P = sum(p[2] for p in pts[1:]) / (len(pts) - 1)
    muP = mu * P
    drift = max(abs(p[2] / pts[0][2] - 1.0) for p in pts)
    checks.check(drift <= 1e-3, f"P constant over the steps: largest change {drift:.2e} (<= 1e-3)")
    checks.check(abs(qstar / muP - 0.5) <= 0.02, f"Q*/(mu_F P) = {qstar / muP:.4f} (0.5 +- 0.02)")
    print(f"P = {P:.8g}, Q* = {qstar:.10g}, delta* = {load[-1][0]:.8g}; Newton steps of the steps' "
          f"last cycles {[p[3]['contact']['newton_iterations'] for p in pts]}")
    for j in range(n):
        for name, branch, masing in (("unloading", un, qstar - 2.0 * load[j][1]),
                                     ("reloading", re_, -qstar + 2.0 * load[j][1])):
            d, Q = branch[j][0], branch[j][1]
            checks.check(abs(Q - masing) <= MASING_TOL * qstar,
                         f"{name} at x = {d / load[-1][0]:+.2f} delta*: Q = {Q:.6f} against Masing's "
                         f"{masing:.6f} ({(Q - masing) / qstar:+.4f} Q*, <= {MASING_TOL})")
    checks.check(abs(qend / qstar - 1.0) <= CLOSURE_TOL,
                 f"the loop closes: Q(+delta*) after reloading / Q* = {qend / qstar:.5f} (1 +- {CLOSURE_TOL})")
    checks.check(abs(qend + qrev) <= SYMMETRY_TOL * qstar,
                 f"the loop is point-symmetric: Q(+delta*) + Q(-delta*) = {(qend + qrev) / qstar:+.2e} Q* "
                 f"(<= {SYMMETRY_TOL})")
    # Johnson's plane-strain shape without the datum's linear term (see the top).
    K = (1.0 - nu * nu) / (math.pi * E)

    def g(x):
        q = x / muP
        return muP * (1.0 - q) * math.log(1.0 - q)

    dstar = load[-1][0]
    virgin = [(Q, g(Q), d) for d, Q, _, _ in load]
    reversed_ = ([(qstar - Q, 2.0 * g((qstar - Q) / 2.0), dstar - d) for d, Q, _, _ in un] +
                 [(Q - qrev, 2.0 * g((Q - qrev) / 2.0), d + dstar) for d, Q, _, _ in re_])
    for what, rows, tol in (("the whole loop", virgin + reversed_, SHAPE_TOL),
                            ("the reversed branches", reversed_, SHAPE_TOL),
                            ("the loading branch", virgin, None)):
        L, B, worst = fit_compliance(rows)
        text = (f"shape of {what} ({len(rows)} points): B/K = {B / K:.4f} (L = {L:.6e}, largest residual "
                f"{worst / dstar:.1e} delta*)")
        if tol is None:
            print(text + " (reported, not checked)")
        else:
            checks.check(abs(B / K - 1.0) <= tol, text + f", Johnson: 1 +- {tol}")
    if zone_ends:
        # Johnson §7.3 for the reloading branch from (-delta*, Q(-delta*)): reversed slip at
        # b < |x| < a, b/a = sqrt(1 - (Q - Q(-delta*))/(2 mu_F P)); at +delta* the zone of §7.1's
        # loading to Q (the same b in a symmetric loop).
        for d, Q, Pj, cyc in re_:
            c = cyc["contact"]
            a, ends = c["half_width"], c["stick_zone_ends"]
            b = a * math.sqrt(1.0 - (Q - qrev) / (2.0 * mu * Pj))
            for side, end, ref in (("lower", ends[0], -b), ("upper", ends[1], b)):
                checks.check(abs(end - ref) <= ENDS_TOL * a,
                             f"reloading at x = {d / dstar:+.2f} delta*: the stick zone's {side} end {end / a:+.4f} a "
                             f"against Johnson's {ref / a:+.4f} a (+- {ENDS_TOL} a)")
    if peer:
        loop_peer_comparison(pts, n, checks, expected[1]["peer"])
    stored, _ = expected
    for key, value in {"Qstar": qstar, "Qrev": qrev, "Qend": qend}.items():
        check_stored(checks, stored, key, value)


def incremental(args, checks, expected):
    """input/hertz2d_incremental.xml in N equal steps for each N of args.steps (see the top)."""
    results = {}
    base = args.out
    for n in args.steps:
        times = ", ".join(f"{k / n:.12g}" for k in range(1, n + 1))
        args.out = os.path.join(base, f"steps{n}")
        summary = run(args, extra=["--output", args.out, "--set", f"Load steps/Times={{{times}}}"])
        last = summary["cycles"][-1]
        checks.check(summary.get("converged") is True and last["load_step"]["step"] == n,
                     f"N = {n}: converged, {n} steps")
        k = last["contact"]
        results[n] = (k["force"][1], k["stick_half_width"] / k["half_width"],
                      k["equivalent_stick_half_width"] / k["equivalent_half_width"])
        steps_newton = [c["contact"]["newton_iterations"] for c in summary["cycles"]]
        print(f"N = {n}: P = {k['force'][1]!r}, c/a = {results[n][1]:.4f} (outermost points), "
              f"{results[n][2]:.4f} (areas); Newton steps {steps_newton}")
        stored, _ = expected
        for key, name, value in ((f"P{n}", "P", k["force"][1]), (f"stick{n}", "stick half-width", k["stick_half_width"])):
            check_stored(checks, stored, key, value, f"N = {n}: {name}")
    args.out = base
    if 1 in results:
        checks.check(abs(results[1][1] - 0.46) <= 0.02, f"N = 1: c/a = {results[1][1]:.4f} against the static 0.46 (+- 0.02)")
        for n, (P, ratio, _) in results.items():
            if n >= 5:
                checks.check(ratio >= results[1][1] + 0.3, f"N = {n}: c/a = {ratio:.4f} at least 0.3 above one step's {results[1][1]:.4f}")
                checks.check(abs(P / results[1][0] - 1.0) <= 0.005, f"N = {n}: P/P(N = 1) - 1 = {P / results[1][0] - 1.0:.2e} (<= 5e-3)")
    many = sorted(n for n in results if n >= 5)
    for n0, n1, n2 in zip(many, many[1:], many[2:]):
        d1, d2 = results[n1][2] - results[n0][2], results[n2][2] - results[n1][2]
        checks.check(0.0 < d2 < d1, f"area-based c/a grows with N by shrinking differences: N = {n0} -> {n1}: {d1:+.4f}, "
                     f"{n1} -> {n2}: {d2:+.4f}")


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--app", required=True)
    parser.add_argument("--ranks", type=int, default=1)
    parser.add_argument("--case", required=True,
                        choices=["cattaneo-mindlin", "mindlin-deresiewicz", "loop", "incremental", "failed-step",
                                 "restart", "restart-errors"])
    parser.add_argument("--steps", type=int, action="append", default=[], help="incremental: a number of steps N")
    parser.add_argument("--deck", required=True)
    parser.add_argument("--out", required=True)
    parser.add_argument("--set", action="append", default=[], dest="sets")
    parser.add_argument("--kill-cycle", type=int, default=13)
    parser.add_argument("--variant", choices=["shipped", "coarse"], default="shipped",
                        help="loop: the deck as shipped, or with COARSE_LOOP_SETS (each has its --expected file)")
    parser.add_argument("--peer", action="store_true",
                        help="loop: compare Q of every step with docs/peer/mindlin_deresiewicz_loop2d_primal.csv")
    parser.add_argument("--zone-ends", action="store_true",
                        help="loop: check the stick zone's ends on the reloading branch (a deck refined in each step)")
    parser.add_argument("--set-checkpoint-int", help="tests/tools/set_checkpoint_int (restart-errors)")
    parser.add_argument("--expected", help="the stored numbers (tests/expected/<deck>_<variant>.json)")
    args = parser.parse_args()
    checks = Checks()
    expected = None
    if args.case in ("cattaneo-mindlin", "restart", "mindlin-deresiewicz", "incremental", "loop"):
        if not args.expected:
            parser.error(f"--case {args.case} needs --expected")
        expected = read_expected(args.expected)
    if args.case == "restart":
        cattaneo_mindlin(restart(args, checks), 0.4, checks, args.out, expected)
    elif args.case == "restart-errors":
        restart_errors(args, checks)
    elif args.case == "cattaneo-mindlin":
        cattaneo_mindlin(run(args), 0.4, checks, args.out, expected)
    elif args.case == "incremental":
        if os.path.isdir(args.out):
            shutil.rmtree(args.out)
        incremental(args, checks, expected)
    elif args.case == "loop":
        if args.variant == "coarse":
            args.sets = COARSE_LOOP_SETS + args.sets
        loop(run(args, mpi=args.ranks > 1), 0.4, 20600.0, 0.4999, checks, args.zone_ends, expected, args.peer)
    elif args.case == "mindlin-deresiewicz":
        mindlin_deresiewicz(run(args), args.out, 0.4, 20600.0, 0.4999, checks, expected)
    else:
        summary = run(args, 2)
        steps = [c.get("load_step", {}).get("step") for c in summary["cycles"]]
        checks.check(summary.get("failed_load_step") == 2, f"failed_load_step = {summary.get('failed_load_step')} (2)")
        checks.check(summary.get("converged") is False, "converged = false")
        checks.check("Maximum iterations" in str(summary.get("error", "")), "the error names the Newton limit")
        checks.check(len(steps) > 1 and all(s == 1 for s in steps), f"the cycles of step 1 are kept: {steps}")
        with open(os.path.join(args.out, "history.csv")) as f:
            rows = len(f.read().strip().splitlines()) - 1
        checks.check(rows == len(steps), f"history.csv has the {len(steps)} cycles of step 1 ({rows})")
    print(f"{checks.failed} check(s) failed")
    return 1 if checks.failed else 0


if __name__ == "__main__":
    sys.exit(main())
