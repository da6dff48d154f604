#!/usr/bin/python3
"""The talk's 3D example, adaptive (docs/adaptivity.md "Hertz 3D, adaptive").

Half ball of radius 1 on a rigid plane, u_D = (0, 0, -0.025) on the top, E = 2.5, nu = 0.25,
Coulomb mu_F = 0.4 (input/hertz3d.xml) and its frictionless twin (input/hertz3d_frictionless.xml),
both with the decks' Doerfler marking and 10 cycles. Writes one CSV per run under docs/adaptivity/ (per cycle:
DOFs, eta and its parts, load P, radius from the contact zone's area, peak pressure, the sphere
formulas' radius and p0 from P, stick radius, stick/slip points, Newton steps, seconds) and, with
Debian's python3-matplotlib, the plots hertz3d_eta.png and hertz3d_contact_stress.png (contact
pressure and shear stress on the contact surface after the last cycle, and their radial profiles
against Hertz).

Usage (repository root, after building):  /usr/bin/python3 docs/adaptivity/hertz3d_study.py
(--plots-only: redraw the plots from the CSVs and the outputs of an earlier run)
Both runs together take about 15 minutes on one core.
"""
import csv
import math
import os
import sys

# The runner, the CSV helpers and the rate fit of the 2D study (same directory).
from hertz2d_study import APP, HERE, PARTS, load_csv, rate, run_deck, write_csv

OUT = "/tmp/sc_adaptivity_study3d"
E, NU, MU = 2.5, 0.25, 0.4
RUNS = {
    "hertz3d_coulomb_adaptive": "hertz3d.xml",
    "hertz3d_frictionless_adaptive": "hertz3d_frictionless.xml",
}
# Two cycles more than the decks' 8: the zone then has about 900 active points.
SETS = ["Adaptivity/Cycles=10"]


def sphere(P):
    """Hertz (Johnson 1985) for a sphere of radius 1 pressed by P: contact radius and p0."""
    estar = E / (1 - NU * NU)
    a = (3 * P / (4 * estar)) ** (1.0 / 3.0)
    return a, 3 * P / (2 * math.pi * a * a)


def run(name):
    out = os.path.join(OUT, name)
    summary, seconds = run_deck(RUNS[name], SETS, out)
    rows = []
    for c in summary["cycles"]:
        eta = c.get("eta", {})
        ct = c["contact"]
        P = ct["force"][2]
        aH, p0H = sphere(P)
        rows.append([c["cycle"], c["dofs"]["total"], eta.get("total", float("nan"))] +
                    [eta.get(p, 0.0) for p in PARTS] +
                    [P, ct["equivalent_radius"], ct["max_pressure"], aH, p0H,
                     ct["equivalent_stick_radius"], ct["points"]["stick"], ct["points"]["slip"],
                     ct["newton_iterations"], sum(c.get("timings", {}).values())])
    header = ["cycle", "dofs", "eta"] + PARTS + ["P", "radius_from_area", "p0", "radius_hertz",
                                                 "p0_hertz", "stick_radius_from_area",
                                                 "stick_points", "slip_points", "newton_steps",
                                                 "cycle_seconds"]
    write_csv(name, header, rows)
    last = rows[-1]
    print("%-30s %2d cycles, %7d DOFs, eta %.3e, radius/Hertz %.3f, p0/Hertz %.3f, %.0f s"
          % (name, len(rows) - 1, last[1], last[2], last[11] / last[13], last[12] / last[14],
             seconds), flush=True)
    return out, len(rows) - 1


def contact_points(out, cycle):
    with open(os.path.join(out, "contact_cycle%d.csv" % cycle)) as f:
        return [{k: (v if k == "status" else float(v)) for k, v in r.items()}
                for r in csv.DictReader(f)]


def plots(outs):
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        import matplotlib.tri as mtri
    except ImportError:
        print("python3-matplotlib is not installed: CSV only (apt-get install python3-matplotlib)")
        return

    # 1. eta_CF and its main parts against DOFs.
    fig, ax = plt.subplots(figsize=(6, 4.5))
    for name, label, style in (("hertz3d_coulomb_adaptive", "Coulomb μ_F = 0.4", "o-"),
                               ("hertz3d_frictionless_adaptive", "frictionless", "s--")):
        h, rows = load_csv(name)
        dofs = [r[1] for r in rows]
        ax.loglog(dofs, [r[2] for r in rows], style, ms=4, label="η_CF, " + label)
        if name == "hertz3d_coulomb_adaptive":
            for part, st in (("volume", ":"), ("contact_complementarity", "-."), ("friction", "--")):
                ax.loglog(dofs, [r[h.index(part)] for r in rows], st, lw=1, label=part)
            print("Coulomb: eta rate in DOFs over the last 5 cycles %.2f" % rate(rows, 5))
    x0, y0 = dofs[0], rows[0][2]
    ax.loglog([x0, dofs[-1]], [y0, y0 * (dofs[-1] / x0) ** (-2.0 / 3.0)], "k:", lw=0.8,
              label="DOFs^(-2/3) (optimal, k = 1)")
    ax.set_xlabel("DOFs")
    ax.set_ylabel("estimate")
    ax.set_title("Hertz 3D, adaptive (Dörfler θ = 0.5)")
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(HERE, "hertz3d_eta.png"), dpi=110)
    plt.close(fig)

    # 2. Contact pressure and shear stress on the contact surface (last cycle): the talk's 3D
    # example. Points of the contact CSV on the cap near the zone.
    out_c, last_c = outs["hertz3d_coulomb_adaptive"]
    out_f, last_f = outs["hertz3d_frictionless_adaptive"]
    pc = contact_points(out_c, last_c)
    pf = contact_points(out_f, last_f)
    hf, rows_f = load_csv("hertz3d_frictionless_adaptive")
    P = rows_f[-1][hf.index("P")]
    aH, p0H = sphere(P)
    near = [p for p in pc if math.hypot(p["x"], p["y"]) < 1.6 * aH]
    fig, axes = plt.subplots(2, 2, figsize=(10, 8.5))
    tri = mtri.Triangulation([p["x"] for p in near], [p["y"] for p in near])
    # Free points carry σ_N = 0 to round-off (±1e-15): clipped at 0, so that no triangle falls
    # below the lowest contour level and is left blank.
    pressure = [max(0.0, -p["sigma_n"]) for p in near]
    shear = [math.hypot(p["sigma_t"], p["sigma_t2"]) for p in near]
    for ax, values, title in ((axes[0][0], pressure, "contact pressure −σ_N (Coulomb)"),
                              (axes[0][1], shear, "shear stress |σ_T| (Coulomb)")):
        cs = ax.tricontourf(tri, values, levels=20, cmap="viridis")
        fig.colorbar(cs, ax=ax, shrink=0.85)
        ax.add_patch(plt.Circle((0, 0), aH, fill=False, ls="--", color="w", lw=1))
        ax.set_aspect("equal")
        ax.set_title(title, fontsize=10)
        ax.set_xlabel("x")
        ax.set_ylabel("y")
    stick = [p for p in near if p["status"] == "stick"]
    axes[0][1].plot([p["x"] for p in stick], [p["y"] for p in stick], "r.", ms=3, label="stick")
    axes[0][1].legend(fontsize=7, loc="upper right")
    # Radial profiles.
    ax = axes[1][0]
    for pts, style, label in ((pf, "s", "frictionless"), (pc, "o", "Coulomb μ_F = 0.4")):
        act = [p for p in pts if p["status"] != "free"]
        ax.plot([math.hypot(p["x"], p["y"]) for p in act], [-p["sigma_n"] for p in act], style,
                ms=2.5, alpha=0.6, label=label + " (active points)")
    r = [aH * i / 200 for i in range(201)]
    ax.plot(r, [p0H * math.sqrt(max(0.0, 1 - (x / aH) ** 2)) for x in r], "k-", lw=1.2,
            label="Hertz p0√(1 − r²/a²) from P")
    ax.set_xlabel("r")
    ax.set_ylabel("−σ_N")
    ax.set_title("pressure against the sphere formula", fontsize=10)
    ax.legend(fontsize=7)
    ax = axes[1][1]
    act = [p for p in pc if p["status"] != "free"]
    for status, style in (("stick", "r."), ("slip", "b.")):
        sel = [p for p in act if p["status"] == status]
        ax.plot([math.hypot(p["x"], p["y"]) for p in sel],
                [math.hypot(p["sigma_t"], p["sigma_t2"]) for p in sel], style, ms=3,
                label="|σ_T|, " + status)
    ax.plot([math.hypot(p["x"], p["y"]) for p in act], [-MU * p["sigma_n"] for p in act], "k.",
            ms=1, alpha=0.4, label="μ_F |σ_N|")
    ax.set_xlabel("r")
    ax.set_ylabel("shear")
    ax.set_title("shear stress and the Coulomb bound (Coulomb run)", fontsize=10)
    ax.legend(fontsize=7)
    fig.suptitle("Hertz 3D after %d adaptive cycles: u_D = (0, 0, −0.025), E = 2.5, ν = 0.25"
                 % last_c, fontsize=11)
    fig.tight_layout()
    fig.savefig(os.path.join(HERE, "hertz3d_contact_stress.png"), dpi=110)
    plt.close(fig)


def main():
    if "--plots-only" in sys.argv[1:]:
        # Redraw from the committed CSVs and the runs' outputs of an earlier call (under OUT).
        outs = {}
        for name in RUNS:
            with open(os.path.join(HERE, name + ".csv")) as f:
                outs[name] = (os.path.join(OUT, name), len(list(csv.reader(f))) - 2)
        plots(outs)
        return
    if not os.path.exists(APP):
        raise SystemExit("build first: %s is missing (scripts/build-and-test.sh)" % APP)
    os.makedirs(OUT, exist_ok=True)
    outs = {name: run(name) for name in RUNS}
    plots(outs)


if __name__ == "__main__":
    main()
