#!/usr/bin/python3
"""CTest run_hertz2d_balanced: the contact Newton's Krylov solves balanced with η_CF.

    python3 BalancedSolves.py --app stresscontact --deck DECK --out DIR --expected FILE

Runs DECK (Hertz 2D frictionless) on the 0.2 mesh, 4 Dörfler cycles, Linear Solver/Type =
Iterative (GMRES, exact stress block), with Contact/Newton/Stopping = Balanced and its default
fraction γ, and compares its summary.json with stored numbers of the same run with
Stopping = Fixed (Tolerance 1e-8; 1 rank, 2026-12-03; "fixed_run" of the --expected file,
tests/expected/hertz2d_frictionless_balanced.json) (docs/theory.md "Solves balanced with the
discretisation error"):

- the same meshes (DOFs of every cycle) and Newton steps per cycle: the rule changes no mesh and
  no active-set decision here, and the Newton loop still ends on a settled active set (it
  returns only after a step that changed no point: converged = true);
- the load of every cycle within γ η/‖A^{1/2}σ_h‖ (relative) of the stored fixed one: the load is
  a linear functional of σ and the rule bounds the estimated algebraic error of σ by γ η in the
  energy norm (η of the previous cycle: the bound the run records, contact.balanced.bound);
- in every balanced cycle the recorded estimate contact.balanced.algebraic_error ≤ bound;
- fewer Krylov iterations in total than the stored fixed count, and no more Newton steps.
"""
import argparse
import json
import os
import shutil
import subprocess
import sys

SETS = ["Mesh/Initial mesh size=0.2", "Adaptivity/Cycles=4", "Adaptivity/Marking=Dorfler",
        "Linear Solver/Type=Iterative", "Output/Write XDMF=false",
        "Output/Write contact CSV=false"]


def fail(msg):
    print("FAIL: " + msg)
    sys.exit(1)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--app", required=True)
    ap.add_argument("--deck", required=True)
    ap.add_argument("--out", required=True)
    ap.add_argument("--stopping", default="Balanced", help="Fixed: print the numbers to store")
    ap.add_argument("--expected", help="the stored fixed run (tests/expected/<deck>_balanced.json)")
    args = ap.parse_args()
    if args.stopping != "Fixed":
        if not args.expected:
            ap.error("--expected is needed to compare with the stored fixed run")
        with open(args.expected) as f:
            expected = json.load(f)
        if not expected.get("source"):
            fail("%s: no 'source' for its numbers" % args.expected)
        stored_fixed = expected["fixed_run"]
    if os.path.isdir(args.out):
        shutil.rmtree(args.out)
    cmd = [args.app, args.deck, "--quiet", "--output", args.out]
    for s in SETS + ["Contact/Newton/Stopping=" + args.stopping]:
        cmd += ["--set", s]
    print(" ".join(cmd), flush=True)
    result = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    print(result.stdout[-2000:])
    if result.returncode != 0:
        fail("the run exited with %d" % result.returncode)
    summary = json.load(open(os.path.join(args.out, "summary.json")))
    gamma = summary["parameters"]["Contact"]["Newton"]["Balance fraction"]
    cycles = summary["cycles"]
    dofs = [c["dofs"]["total"] for c in cycles]
    load = [c["contact"]["force"][1] for c in cycles]
    newton = [c["contact"]["newton_iterations"] for c in cycles]
    krylov = sum(c["linear_iterations"]["total"] for c in cycles)
    if args.stopping == "Fixed":
        print(json.dumps({"dofs": dofs, "load": load, "newton": newton, "krylov_total": krylov}))
        return 0

    ok = True

    def check(cond, what):
        nonlocal ok
        print(("ok   " if cond else "FAIL ") + what)
        ok = ok and cond

    # The Newton loop returns only after a step that changed no point (else a ConvergenceError,
    # converged = false and a non-zero exit).
    check(summary["converged"] is True, "converged")

    check(dofs == stored_fixed["dofs"], "DOFs per cycle %s == stored fixed %s" % (dofs, stored_fixed["dofs"]))
    check(newton == stored_fixed["newton"],
          "Newton steps per cycle %s == stored fixed %s" % (newton, stored_fixed["newton"]))
    for i, c in enumerate(cycles):
        bal = c["contact"].get("balanced")
        if i == 0:
            check(bal is None, "cycle 0 (no η yet) solved with the fixed tolerance")
            continue
        if bal is None:
            check(False, "cycle %d has no contact.balanced record" % i)
            continue
        norm = cycles[i - 1]["eta"]["stress_energy_norm"]
        tol = bal["bound"] / norm
        eta_prev = cycles[i - 1]["eta"]["total"]
        check(abs(bal["bound"] - gamma * eta_prev) <= 1e-12 * bal["bound"],
              "cycle %d: bound %.6g == γ η of cycle %d (%.6g)" % (i, bal["bound"], i - 1, gamma * eta_prev))
        check(bal["algebraic_error"] <= bal["bound"],
              "cycle %d: estimated algebraic error %.3g <= bound %.3g" % (i, bal["algebraic_error"], bal["bound"]))
        rel = abs(load[i] - stored_fixed["load"][i]) / abs(stored_fixed["load"][i])
        check(rel <= tol, "cycle %d: load %.12g against fixed %.12g: relative %.2e <= γ η/|A^1/2 σ_h| = %.2e"
              % (i, load[i], stored_fixed["load"][i], rel, tol))
    check(krylov < stored_fixed["krylov_total"],
          "Krylov iterations %d < stored fixed %d" % (krylov, stored_fixed["krylov_total"]))
    check(sum(newton) <= sum(stored_fixed["newton"]),
          "Newton steps %d <= stored fixed %d" % (sum(newton), sum(stored_fixed["newton"])))
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
