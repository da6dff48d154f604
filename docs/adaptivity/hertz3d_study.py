#!/usr/bin/python3
"""The talk's 3D example, adaptive (docs/adaptivity.md "Hertz 3D, adaptive").

    /usr/bin/python3 docs/adaptivity/hertz3d_study.py [--out DIR] [--plots-only] [--update-docs]
                                                      [--uniform]

Half ball of radius 1 on a rigid plane, u_D = (0, 0, -0.025) on the top, Coulomb mu_F = 0.4
(input/hertz3d.xml) and its frictionless twin (input/hertz3d_frictionless.xml), both with the
decks' Doerfler marking and 10 cycles; with --uniform also the Coulomb deck with one uniform
cycle (the uniform twin: 277,800 DOFs, about 8 minutes and 5 GB on one core). Runs go to
DIR/runs/<name> (DIR: --out, default /tmp/sc_hertz3d_study); from each run's own outputs only
(the material, the radius and the friction coefficient come from its summary.json) it writes
DIR/<name>.csv (per cycle: DOFs, eta and its parts, load P, radius from the contact zone's area,
peak pressure, the sphere formulas' radius and p0 from P, stick radius, stick/slip points, Newton
steps, seconds) and the plots DIR/plots/hertz3d_eta.png and hertz3d_contact_stress.png (contact
pressure and shear stress on the contact surface after the last cycle, and their radial profiles
against Hertz). Each CSV is compared with the reference of the same name in docs/adaptivity/;
--update-docs copies the CSVs and PNGs there. --plots-only redraws from the runs in DIR.
The two adaptive runs together take about 15 minutes on one core.
"""
import argparse
import csv
import math
import os
import shutil
import sys

# The runner, the CSV helpers, the rate fit and scripts/plot-run.py of the 2D study (same directory).
from hertz2d_study import APP, HERE, PARTS, PR, compare_with_reference, load_csv, rate, run_deck, write_csv

RUNS = {
    "hertz3d_coulomb_adaptive": ("hertz3d.xml", ["Adaptivity/Cycles=10"]),
    "hertz3d_frictionless_adaptive": ("hertz3d_frictionless.xml", ["Adaptivity/Cycles=10"]),
}
# Two cycles more than the decks' 8: the zone then has about 900 active points.
UNIFORM = {"hertz3d_coulomb_uniform": ("hertz3d.xml", ["Adaptivity/Marking=Uniform", "Adaptivity/Cycles=1"])}
HEADER = ["cycle", "dofs", "eta"] + PARTS + ["P", "radius_from_area", "p0", "radius_hertz", "p0_hertz",
                                             "stick_radius_from_area", "stick_points", "slip_points",
                                             "newton_steps", "cycle_seconds"]


def run(name, deck, sets, out_dir):
    out = os.path.join(out_dir, "runs", name)
    summary, seconds = run_deck(deck, sets, out)
    rows = csv_rows(summary)
    path = os.path.join(out_dir, name + ".csv")
    write_csv(path, HEADER, rows)
    last = rows[-1]
    print("%-30s %2d cycles, %7d DOFs, eta %.3e, radius/Hertz %.3f, p0/Hertz %.3f, %.0f s"
          % (name, len(rows) - 1, last[1], last[2], last[11] / last[13], last[12] / last[14],
             seconds), flush=True)
    compare_with_reference(name, path, ["dofs", "eta", "P"])


def csv_rows(summary):
    """The CSV rows (HEADER) of a run's cycles, from its summary.json."""
    rows = []
    for c in summary["cycles"]:
        eta = c.get("eta", {})
        ct = c["contact"]
        P = ct["force"][2]
        aH, p0H = PR.hertz_reference(summary, P)
        rows.append([c["cycle"], c["dofs"]["total"], eta.get("total", float("nan"))] +
                    [eta.get(p, 0.0) for p in PARTS] +
                    [P, ct["equivalent_radius"], ct["max_pressure"], aH, p0H,
                     ct["equivalent_stick_radius"], ct["points"]["stick"], ct["points"]["slip"],
                     ct["newton_iterations"], sum(c.get("timings", {}).values())])
    return rows


def contact_points(out, cycle):
    with open(os.path.join(out, "contact_cycle%d.csv" % cycle)) as f:
        return [{k: (v if k == "status" else float(v)) for k, v in r.items()}
                for r in csv.DictReader(f)]


def csv_path(out_dir, name):
    """DIR/<name>.csv of this call's runs, else the committed reference (docs/adaptivity/)."""
    for path in (os.path.join(out_dir, name + ".csv"), os.path.join(HERE, name + ".csv")):
        if os.path.exists(path):
            if not path.startswith(out_dir):
                print("%s: no run in %s, the committed %s is drawn" % (name, out_dir, os.path.relpath(path)))
            return path
    return None


def plots(out_dir, plt, plot_dir):
    from matplotlib.ticker import FuncFormatter, LogLocator, NullFormatter
    import matplotlib.tri as mtri
    written = []

    # 1. eta_CF and its main parts against DOFs (and the uniform twin where it was run).
    fig, ax = plt.subplots(figsize=(6.5, 4.8))
    for name, label, style in (("hertz3d_coulomb_adaptive", "Coulomb μ_F = 0.4, adaptive", "o-"),
                               ("hertz3d_frictionless_adaptive", "frictionless, adaptive", "s--"),
                               ("hertz3d_coulomb_uniform", "Coulomb μ_F = 0.4, uniform", "^-.")):
        path = csv_path(out_dir, name)
        if path is None:
            continue
        h, rows = load_csv(path)
        dofs = [r[1] for r in rows]
        ax.loglog(dofs, [r[2] for r in rows], style, ms=4, label="η_CF, " + label)
        if name == "hertz3d_coulomb_adaptive":
            for part, st in (("volume", ":"), ("contact_complementarity", "-."), ("friction", "--")):
                ax.loglog(dofs, [r[h.index(part)] for r in rows], st, lw=1, label=part + " (Coulomb, adaptive)")
            print("Coulomb: eta rate in DOFs over the last 5 cycles %.2f" % rate(rows, 5))
            x0, y0, x1 = dofs[0], rows[0][2], dofs[-1]
    ax.loglog([x0, x1], [y0, y0 * (x1 / x0) ** (-2.0 / 3.0)], "k:", lw=0.8, label="DOFs^(-2/3) (optimal, k = 1)")
    # the DOFs span less than a decade: ticks at 1, 2 and 5 times the powers of ten, in thousands
    ax.xaxis.set_major_locator(LogLocator(base=10, subs=(1.0, 2.0, 3.0, 5.0)))
    ax.xaxis.set_major_formatter(FuncFormatter(lambda v, _: "%gk" % (v / 1000)))
    ax.xaxis.set_minor_formatter(NullFormatter())
    ax.set_xlabel("DOFs")
    ax.set_ylabel("η (energy norm of the stress error)")
    ax.set_title("Hertz 3D: adaptive (Dörfler θ = 0.5) and uniform refinement")
    ax.grid(True, which="both", lw=0.3)
    ax.legend(fontsize=7, loc="lower left")
    fig.tight_layout()
    written.append(os.path.join(plot_dir, "hertz3d_eta.png"))
    fig.savefig(written[-1], dpi=110)
    plt.close(fig)

    # 2. Contact pressure and shear stress on the contact surface (last cycle): the talk's 3D
    # example. Points of the contact CSV on the cap near the zone.
    out_c = os.path.join(out_dir, "runs", "hertz3d_coulomb_adaptive")
    out_f = os.path.join(out_dir, "runs", "hertz3d_frictionless_adaptive")
    if not (os.path.exists(os.path.join(out_c, "summary.json")) and os.path.exists(os.path.join(out_f, "summary.json"))):
        print("no runs in %s: hertz3d_contact_stress.png skipped" % out_dir)
        return written
    sc, sf = PR.load_summary(out_c), PR.load_summary(out_f)
    last_c, last_f = sc["cycles"][-1]["cycle"], sf["cycles"][-1]["cycle"]
    pc = contact_points(out_c, last_c)
    pf = contact_points(out_f, last_f)
    P = sf["cycles"][-1]["contact"]["force"][2]
    aH, p0H = PR.hertz_reference(sf, P)
    MU = PR.param(sc, "Contact", "Friction coefficient")
    E, NU = PR.param(sc, "Material", "Young modulus"), PR.param(sc, "Material", "Poisson ratio")
    top = PR.param(sc, "Boundary Conditions", "Top", "Value")
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
        fig.colorbar(cs, ax=ax, shrink=0.85, label="unit of E")
        ax.add_patch(plt.Circle((0, 0), aH, fill=False, ls="--", color="w", lw=1))
        ax.set_aspect("equal")
        ax.set_title(title, fontsize=10)
        ax.set_xlabel("x (length unit of the mesh)")
        ax.set_ylabel("y")
    stick = [p for p in near if p["status"] == "stick"]
    axes[0][1].plot([p["x"] for p in stick], [p["y"] for p in stick], "r.", ms=3, label="stick")
    axes[0][1].legend(fontsize=7, loc="upper right")
    # Radial profiles.
    ax = axes[1][0]
    for pts, style, label in ((pf, "s", "frictionless"), (pc, "o", "Coulomb μ_F = %g" % MU)):
        act = [p for p in pts if p["status"] != "free"]
        ax.plot([math.hypot(p["x"], p["y"]) for p in act], [-p["sigma_n"] for p in act], style,
                ms=2.5, alpha=0.6, label=label + " (active points)")
    r = [aH * i / 200 for i in range(201)]
    ax.plot(r, [p0H * math.sqrt(max(0.0, 1 - (x / aH) ** 2)) for x in r], "k-", lw=1.2,
            label="Hertz p0√(1 − r²/a²) from P")
    ax.set_xlabel("r, distance from the axis (length unit of the mesh)")
    ax.set_ylabel("pressure −σ_N (unit of E)")
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
    ax.set_xlabel("r, distance from the axis (length unit of the mesh)")
    ax.set_ylabel("shear |σ_T| (unit of E)")
    ax.set_title("shear stress and the Coulomb bound (Coulomb run)", fontsize=10)
    ax.legend(fontsize=7)
    fig.suptitle("Hertz 3D after %d adaptive cycles: u_D = %s, E = %g, ν = %g (from the runs)"
                 % (last_c, tuple(top) if top else "?", E, NU), fontsize=11)
    fig.tight_layout()
    written.append(os.path.join(plot_dir, "hertz3d_contact_stress.png"))
    fig.savefig(written[-1], dpi=110)
    plt.close(fig)
    return written


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--out", default="/tmp/sc_hertz3d_study", help="runs, CSVs and plots (default %(default)s)")
    parser.add_argument("--plots-only", action="store_true", help="redraw from the runs already in --out")
    parser.add_argument("--uniform", action="store_true", help="also the uniform twin (about 8 minutes, 5 GB)")
    parser.add_argument("--update-docs", action="store_true",
                        help="copy the CSVs and PNGs into docs/adaptivity/ (the committed references)")
    args = parser.parse_args()
    out_dir = os.path.abspath(args.out)
    plot_dir = os.path.join(out_dir, "plots")
    os.makedirs(plot_dir, exist_ok=True)
    runs = dict(RUNS, **(UNIFORM if args.uniform else {}))
    if not args.plots_only:
        if not os.path.exists(APP):
            raise SystemExit("build first: %s is missing (scripts/build-and-test.sh)" % APP)
        for name, (deck, sets) in runs.items():
            run(name, deck, sets, out_dir)
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        sys.exit("python3-matplotlib is not installed: CSVs only (apt-get install python3-matplotlib)")
    written = plots(out_dir, plt, plot_dir)
    for p in written:
        print("wrote", p)
    if args.update_docs:
        csvs = [os.path.join(out_dir, n + ".csv") for n in dict(RUNS, **UNIFORM)
                if os.path.exists(os.path.join(out_dir, n + ".csv"))]
        for p in csvs + written:
            shutil.copy(p, HERE)
        print(f"copied {len(csvs)} CSVs and {len(written)} PNGs into {HERE}")


if __name__ == "__main__":
    main()
