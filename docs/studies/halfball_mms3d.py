#!/usr/bin/python3
"""The manufactured 3D solution on the half ball, straight against curved faces, k = 1 and 2
(docs/verification.md "Curved boundaries"): runs tests/data/mms3d_half_ball.xml with uniform
cycles (k = 1: 2 cycles to 460k DOFs; k = 2: 1 cycle to 157k) at both geometry orders and prints
the Markdown table of DOFs, stress and displacement errors, the rates over the last level and the
domain's measure per cycle (summary.json `errors`, `mesh.measure`).

Usage (repository root, after building; SC_BUILD_DIR or --build, default build/):
  nice -n 10 /usr/bin/python3 docs/studies/halfball_mms3d.py [--ranks 2]     # about 5 minutes
"""
import argparse
import json
import math
import os
import subprocess

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def run(app, ranks, order, degree, cycles, outdir):
    out = os.path.join(outdir, "g%d_k%d" % (order, degree))
    cmd = [app, os.path.join(ROOT, "tests", "data", "mms3d_half_ball.xml"), "--quiet",
           "--output", out, "--set", "Mesh/Geometry order=%d" % order,
           "--set", "Discretization/Degree=%d" % degree, "--set", "Adaptivity/Cycles=%d" % cycles,
           "--set", "Output/Write XDMF=false"]
    if ranks > 1:
        flags = ["--oversubscribe"] + (["--allow-run-as-root"] if os.geteuid() == 0 else [])
        cmd = ["mpiexec"] + flags + ["-n", str(ranks)] + cmd
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)
    with open(os.path.join(out, "summary.json")) as f:
        return json.load(f)["cycles"]


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--build", default=os.environ.get("SC_BUILD_DIR", os.path.join(ROOT, "build")))
    ap.add_argument("--ranks", type=int, default=2)
    ap.add_argument("--output", default="/tmp/sc_halfball_mms3d")
    args = ap.parse_args()
    app = os.path.join(args.build, "apps", "stresscontact", "stresscontact")
    print("| geometry, k | DOFs | ‖σ−σ_h‖ | ‖u−u_h‖ | rates (σ, u) over the last level "
          "| measure (exact 2π/3 = %.6f) |" % (2 * math.pi / 3))
    print("|---|---|---|---|---|---|")
    for degree, cycles in ((1, 2), (2, 1)):
        for order, name in ((1, "straight"), (2, "curved")):
            cs = run(app, args.ranks, order, degree, cycles, args.output)
            dofs = [c["dofs"]["total"] for c in cs]
            s = [c["errors"]["stress_l2"] for c in cs]
            u = [c["errors"]["displacement_l2"] for c in cs]
            meas = [c["mesh"]["measure"] for c in cs]

            elements = [c["elements"] for c in cs]

            def rate(e):  # in h = (|Ω|/#elements)^(1/3)
                return -3.0 * math.log(e[-1] / e[-2]) / math.log(elements[-1] / elements[-2])

            digits = "%.4g" if order == 1 else "%.7g"
            print("| %s, %d | %s | %s | %s | %.2f, %.2f | %s |" % (
                name, degree, " → ".join(str(d) for d in dofs),
                " → ".join("%.4g" % x for x in s), " → ".join("%.4g" % x for x in u),
                rate(s), rate(u), " → ".join(digits % x for x in meas)), flush=True)


if __name__ == "__main__":
    main()
