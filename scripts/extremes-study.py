#!/usr/bin/python3
"""Stability at the extremes: the Hertz 2D scene at extreme ν, μ_F, load, E and mesh grading.

    nice -n 10 /usr/bin/python3 scripts/extremes-study.py [--out DIR] [--binary B]

One run per row (coarse: Gmsh mesh 0.2 and 2 Dörfler cycles; frictionless unless the row sets
friction), one process at a time. Prints a Markdown table: exit status, Newton steps per cycle,
η_CF/‖A^{1/2}σ_h‖ of the last cycle and the error where a reference is known:
- ν and the prescribed displacement: a and p₀ against Hertz's formulas from the run's own load
  (summary.json contact.hertz; docs/theory.md §"Hertz reference values"), the half-space formulas,
  valid while a ≪ R;
- E: the load divided by E against the E = 20600 run's (the problem is linear in 1/E at a given
  displacement: the load scales exactly with E);
- μ_F = 0 with Coulomb: the load against the frictionless run (the same problem);
- the graded mesh: the load against the ungraded run on the same deck.
Source: docs/performance.md "Stability at the extremes".
"""
import argparse
import importlib.util
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
spec = importlib.util.spec_from_file_location("trade_study", os.path.join(HERE, "trade-study.py"))
ts = importlib.util.module_from_spec(spec)
spec.loader.exec_module(ts)

BASE = ["Mesh/Initial mesh size=0.2", "Adaptivity/Cycles=2", "Contact/Friction law=None"] + ts.FAST_OUTPUT
COULOMB = ["Contact/Friction law=Coulomb"]
# A graded mesh: the half disc drawn in Gmsh with size 1e-5 at the lowest point and 0.1 elsewhere
# (element size ratio 1e4), written next to the runs.
GRADED_GEO = """R = 1;
Point(1) = {0, 1, 0};
Point(2) = {-R, 1, 0, 0.1};
Point(3) = {0, 1 - R, 0, 1e-5};
Point(4) = {R, 1, 0, 0.1};
Circle(1) = {2, 1, 3};
Circle(2) = {3, 1, 4};
Line(3) = {4, 2};
Curve Loop(1) = {1, 2, 3};
Plane Surface(1) = {1};
Physical Curve("Arc") = {1, 2};
Physical Curve("Top") = {3};
Physical Surface("Body") = {1};
"""


def rows(geo):
    out = []
    for nu in (0, 0.3, 0.49, 0.4999, 0.5):
        out.append(("ν = %g" % nu, ["Material/Poisson ratio=%g" % nu], "hertz"))
    for mu in (0, 0.01, 0.4, 1, 10):
        out.append(("μ_F = %g (Coulomb)" % mu, COULOMB + ["Contact/Friction coefficient=%g" % mu],
                    "frictionless" if mu == 0 else None))
    for frac in (1e-8, 1e-6, 1e-4, 1e-2, 1e-1):
        out.append(("u_D = %g R" % frac, ["Boundary Conditions/Top/Value={0, %g}" % -frac], "hertz"))
    for e in (1e-3, 1, 1e6, 1e12):
        out.append(("E = %g" % e, ["Material/Young modulus=%g" % e], "scaling"))
    out.append(("graded mesh, size ratio 1e4", ["Mesh/Source=Gmsh geometry", "Mesh/File=%s" % geo], "ungraded"))
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--out", default="extremes-study")
    ap.add_argument("--binary")
    ap.add_argument("--timeout", type=float, default=300.0)
    args = ap.parse_args()
    binary = args.binary or ts.find_binary()
    deck = os.path.join(ts.ROOT, "input/hertz2d_frictionless.xml")
    out = os.path.abspath(args.out)
    os.makedirs(out, exist_ok=True)
    geo = os.path.join(out, "graded_half_disc.geo")
    open(geo, "w").write(GRADED_GEO)

    def run(label, sets):
        name = "".join(ch if ch.isalnum() else "_" for ch in label)
        s, wall, status, _ = ts.run_one(binary, deck, BASE + sets, os.path.join(out, name), args.timeout)
        cyc = [c for c in (s or {}).get("cycles", []) if c.get("eta")]
        return s, wall, status, cyc

    _, _, st, base_cyc = run("baseline", [])
    if st != 0:
        sys.exit("extremes-study: the baseline run failed (exit %s)" % st)
    base_load = abs(base_cyc[-1]["contact"]["force"][1])
    print("| case | exit | Newton steps per cycle | DOFs | η_CF / ‖A^½σ_h‖ | load | error where known | seconds |")
    print("|---|---|---|---|---|---|---|---|")
    for label, sets, ref in rows(geo):
        s, wall, status, cyc = run(label, sets)
        if status != 0 or not cyc:
            msg = (s or {}).get("error") or ""
            print("| %s | %s | — | — | — | — | %s | %.1f |" % (label, status, msg.replace("|", "/")[:200], wall))
            continue
        c = cyc[-1]
        load = abs(c["contact"]["force"][1])
        err = ""
        if ref == "hertz" and "hertz" in c["contact"]:
            h = c["contact"]["hertz"]
            err = "a/a_H − 1 = %+.2e, p₀/p₀_H − 1 = %+.2e" % (c["contact"]["equivalent_half_width"] / h["half_width"] - 1,
                                                           h["max_pressure_ratio"] - 1)
        elif ref == "scaling":
            e = float(sets[0].split("=")[1])
            err = "(P/E)/(P/E)_{20600} − 1 = %+.1e" % ((load / e) / (base_load / 20600.0) - 1)
        elif ref in ("frictionless", "ungraded"):
            err = "P/P_%s − 1 = %+.1e" % (ref, load / base_load - 1)
        newton = ",".join(str(x["contact"]["newton_iterations"]) for x in cyc)
        print("| %s | %s | %s | %d | %.3g | %.6g | %s | %.1f |" % (label, status, newton, c["dofs"]["total"],
                                                                 c["eta"]["relative"], load, err, wall), flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
