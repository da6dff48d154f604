#!/usr/bin/python3
"""The talk's adaptive experiments on Hertz 2D (docs/adaptivity.md).

Runs build/apps/stresscontact/stresscontact on input/hertz2d*.xml, writes one CSV per run under
docs/adaptivity/ (cycle, DOFs, eta and its parts, the signed normal part, load P, half-width a,
peak pressure p0, Hertz a and p0 from P, Newton steps, seconds) and, with Debian's
python3-matplotlib (and python3-h5py for the deformed mesh), the PNG plots of docs/adaptivity.md.

Usage (repository root, after building):  /usr/bin/python3 docs/adaptivity/hertz2d_study.py
Runs take about 3 minutes on one core.
"""
import csv
import json
import math
import os
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
APP = os.path.join(ROOT, "build", "apps", "stresscontact", "stresscontact")
HERE = os.path.join(ROOT, "docs", "adaptivity")
OUT = "/tmp/sc_adaptivity_study"
PARTS = ["volume", "asymmetry", "oscillation", "contact_complementarity", "contact_penetration",
         "contact_tension", "friction"]

# name: (deck, --set overrides, nu). Every run pins Mesh/Geometry order = 1: the committed study
# was made with straight-sided elements (the default is curved; docs/contact.md "Curved contact
# faces" compares the two).
GEOMETRY = ["Mesh/Geometry order=1"]
RUNS = {
    "frictionless_nu028_adaptive": ("hertz2d_frictionless.xml", ["Adaptivity/Cycles=26"], 0.28),
    "frictionless_nu028_uniform": ("hertz2d_frictionless.xml",
                                   ["Adaptivity/Marking=Uniform", "Adaptivity/Cycles=3"], 0.28),
    "frictionless_nu04999_adaptive": ("hertz2d_frictionless.xml",
                                      ["Adaptivity/Cycles=26", "Material/Poisson ratio=0.4999"], 0.4999),
    "frictionless_nu04999_uniform": ("hertz2d_frictionless.xml",
                                     ["Adaptivity/Marking=Uniform", "Adaptivity/Cycles=3",
                                      "Material/Poisson ratio=0.4999"], 0.4999),
    "frictionless_nu05_adaptive": ("hertz2d_frictionless.xml",
                                   ["Adaptivity/Cycles=26", "Material/Poisson ratio=0.5"], 0.5),
    "coulomb_nu028_adaptive": ("hertz2d.xml", ["Adaptivity/Cycles=26"], 0.28),
    "coulomb_nu028_uniform": ("hertz2d.xml", ["Adaptivity/Marking=Uniform", "Adaptivity/Cycles=3"], 0.28),
    "coulomb_nu04999_adaptive": ("hertz2d_incompressible.xml", ["Adaptivity/Cycles=26"], 0.4999),
    "straight_frictionless_adaptive": ("hertz2d_frictionless.xml",
                                       ["Adaptivity/Cycles=26", "Mesh/Project boundary=false"], 0.28),
    "straight_frictionless_uniform": ("hertz2d_frictionless.xml",
                                      ["Adaptivity/Marking=Uniform", "Adaptivity/Cycles=3",
                                       "Mesh/Project boundary=false"], 0.28),
}


def run_deck(deck, sets, out):
    """Run input/<deck> with the --set overrides into `out`: its summary.json and the seconds."""
    cmd = [APP, os.path.join(ROOT, "input", deck), "--quiet", "--output", out]
    for s in sets:
        cmd += ["--set", s]
    t0 = time.time()
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)
    seconds = time.time() - t0
    with open(os.path.join(out, "summary.json")) as f:
        return json.load(f), seconds


def write_csv(name, header, rows):
    with open(os.path.join(HERE, name + ".csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(header)
        w.writerows(rows)


def load_csv(name):
    """The header and the rows (as numbers; an empty cell is 0) of docs/adaptivity/<name>.csv."""
    with open(os.path.join(HERE, name + ".csv")) as f:
        r = list(csv.reader(f))
    return r[0], [[float(x) if x != "" else 0.0 for x in row] for row in r[1:]]


def run(name):
    deck, sets, nu = RUNS[name]
    out = os.path.join(OUT, name)
    summary, seconds = run_deck(deck, GEOMETRY + sets, out)
    rows = []
    for c in summary["cycles"]:
        eta = c.get("eta", {})
        ct = c["contact"]
        P = ct["force"][1]
        estar = 20600.0 / (1 - nu * nu)
        aH = math.sqrt(4 * P / (math.pi * estar))
        rows.append([c["cycle"], c["dofs"]["total"], eta.get("total", float("nan"))] +
                    [eta.get(p, 0.0) for p in PARTS] +
                    [eta.get("contact_normal_signed", 0.0), P, ct["half_width"], ct["max_pressure"],
                     aH, 2 * P / (math.pi * aH), ct["stick_half_width"], ct["newton_iterations"],
                     sum(c.get("timings", {}).values()) if isinstance(c.get("timings"), dict) else ""])
    header = ["cycle", "dofs", "eta"] + PARTS + ["contact_normal_signed", "P", "a", "p0", "a_hertz",
                                                 "p0_hertz", "stick_half_width", "newton_steps",
                                                 "cycle_seconds"]
    write_csv(name, header, rows)
    print("%-32s %3d cycles, %8d DOFs, eta %.3e, %.1f s" % (name, len(rows) - 1, rows[-1][1],
                                                            rows[-1][2], seconds), flush=True)
    return out


def rate(rows, last):
    """Least-squares slope of −log η against log DOFs over the last `last` rows (columns 1, 2)."""
    xs = [math.log(r[1]) for r in rows[-last:]]
    ys = [math.log(r[2]) for r in rows[-last:]]
    mx, my = sum(xs) / len(xs), sum(ys) / len(ys)
    return -sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sum((x - mx) ** 2 for x in xs)


def plots(outs):
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("python3-matplotlib is not installed: CSV only (apt-get install python3-matplotlib)")
        return

    # 1. eta_CF against DOFs, uniform vs adaptive, per nu (the talk's "Convergence comparison").
    for tag, title in (("frictionless_nu028", "ν = 0.28, frictionless"),
                       ("frictionless_nu04999", "ν = 0.4999, frictionless"),
                       ("straight_frictionless", "straight boundaries, ν = 0.28, frictionless"),
                       ("coulomb_nu028", "ν = 0.28, Coulomb μ_F = 0.4")):
        fig, ax = plt.subplots(figsize=(6, 4.5))
        for kind, style in (("adaptive", "o-"), ("uniform", "s--")):
            name = tag + "_" + kind
            if not os.path.exists(os.path.join(HERE, name + ".csv")):
                continue
            h, rows = load_csv(name)
            ax.loglog([r[1] for r in rows], [r[2] for r in rows], style, label="η_CF, " + kind, ms=4)
            if kind == "adaptive":
                for p, st in (("volume", ":"), ("contact_complementarity", "-."), ("friction", "--")):
                    i = h.index(p)
                    if any(r[i] > 0 for r in rows):
                        ax.loglog([r[1] for r in rows], [r[i] for r in rows], st, label=p + " (adaptive)", lw=1)
        h, rows = load_csv(tag + "_adaptive")
        n0 = rows[-1][1]
        ax.loglog([n0 / 30, n0], [rows[-1][2] * 30, rows[-1][2]], "k-", lw=0.8, label="DOFs⁻¹")
        ax.set_xlabel("DOFs")
        ax.set_ylabel("η")
        ax.set_title(title)
        ax.grid(True, which="both", lw=0.3)
        ax.legend(fontsize=7)
        fig.tight_layout()
        fig.savefig(os.path.join(HERE, "eta_" + tag + ".png"), dpi=110)
        plt.close(fig)

    # 2. Grid points on half of Γ_C after 10 adaptive cycles, and the pressure against Hertz at the
    #    last cycle (the talk's "Refinement of contact zone" and "Contact stress and displacement").
    out = outs["frictionless_nu028_adaptive"]
    fig, axs = plt.subplots(2, 1, figsize=(6.5, 6))
    for cyc, y in ((10, 1.0), (0, 0.0)):
        path = os.path.join(out, "contact_cycle%d.csv" % cyc)
        if os.path.exists(path):
            xs = sorted(float(r["x"]) for r in csv.DictReader(open(path)) if float(r["x"]) >= 0)
            axs[0].plot(xs, [y] * len(xs), "|", ms=12, label="cycle %d (%d points)" % (cyc, len(xs)))
    axs[0].set_xlim(0, 0.4)
    axs[0].set_yticks([])
    axs[0].set_xlabel("x on Γ_C (half)")
    axs[0].legend(fontsize=8)
    axs[0].set_title("contact points on half of Γ_C (DOF points of the arc faces)")
    h, rows = load_csv("frictionless_nu028_adaptive")
    last = int(rows[-1][0])
    pts = [r for r in csv.DictReader(open(os.path.join(out, "contact_cycle%d.csv" % last)))]
    P = rows[-1][h.index("P")]
    a, p0 = rows[-1][h.index("a_hertz")], rows[-1][h.index("p0_hertz")]
    xs = sorted((float(r["x"]), -float(r["sigma_n"]), float(r["sigma_t"])) for r in pts if abs(float(r["x"])) < 2 * a)
    axs[1].plot([x for x, _, _ in xs], [s for _, s, _ in xs], ".", ms=3, label="−σ_N at the contact points")
    hx = [-1.5 * a + 3 * a * i / 400 for i in range(401)]
    axs[1].plot(hx, [p0 * math.sqrt(max(0.0, 1 - x * x / (a * a))) for x in hx], "k-", lw=0.8,
                label="Hertz from P = %.3f" % P)
    axs[1].set_xlabel("x")
    axs[1].set_ylabel("pressure")
    axs[1].legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(HERE, "contact_zone.png"), dpi=110)
    plt.close(fig)

    # 3. Coulomb: normal and tangential traction along Γ_C at the last cycle.
    out = outs["coulomb_nu028_adaptive"]
    h, rows = load_csv("coulomb_nu028_adaptive")
    last = int(rows[-1][0])
    pts = [r for r in csv.DictReader(open(os.path.join(out, "contact_cycle%d.csv" % last)))]
    a = rows[-1][h.index("a")]
    xs = sorted((float(r["x"]), -float(r["sigma_n"]), float(r["sigma_t"]), r["status"]) for r in pts
                if abs(float(r["x"])) < 1.5 * a)
    fig, ax = plt.subplots(figsize=(6.5, 4))
    ax.plot([x[0] for x in xs], [x[1] for x in xs], ".", ms=3, label="−σ_N")
    ax.plot([x[0] for x in xs], [x[2] for x in xs], ".", ms=3, label="σ_T")
    ax.plot([x[0] for x in xs], [0.4 * x[1] for x in xs], "-", lw=0.6, label="μ_F |σ_N|")
    ax.plot([x[0] for x in xs], [-0.4 * x[1] for x in xs], "-", lw=0.6)
    ax.set_xlabel("x")
    ax.set_title("Coulomb μ_F = 0.4, ν = 0.28: tractions on Γ_C, cycle %d" % last)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(HERE, "coulomb_tractions.png"), dpi=110)
    plt.close(fig)


def deformed_mesh_plot(outs):
    """The mesh after 5 adaptive cycles, warped by u^R (the talk's deformed mesh), from the
    cycle's HDF5 file (Debian's python3-h5py)."""
    try:
        import h5py
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        import matplotlib.tri as mtri
    except ImportError:
        print("python3-h5py or python3-matplotlib missing: no deformed-mesh plot")
        return
    path = os.path.join(outs["frictionless_nu028_adaptive"], "solution_c0005.h5")
    with h5py.File(path, "r") as f:
        xyz = f["domain/geometry"][()]
        tri = f["domain/topology"][()]
        u = f["domain/point/reconstructed_displacement"][()]
    # True scale (u^R is about 1% of the radius): the right panel stretches y to show the flat
    # contact zone on the plane y = 0; a magnified u^R would cross the plane.
    t = mtri.Triangulation(xyz[:, 0] + u[:, 0], xyz[:, 1] + u[:, 1], tri)
    fig, axs = plt.subplots(1, 2, figsize=(10, 4.2))
    for ax, xlim, ylim, title in ((axs[0], (-1.05, 1.05), (-0.05, 1.05), "whole body"),
                                  (axs[1], (-0.15, 0.15), (-0.003, 0.012), "contact zone, y stretched")):
        ax.triplot(t, lw=0.3, color="C0")
        ax.axhline(0.0, color="k", lw=0.8)
        ax.set_xlim(*xlim)
        ax.set_ylim(*ylim)
        if ylim[1] > 1:
            ax.set_aspect("equal")
        ax.set_title("cycle 5, deformed by u^R: %s (%d elements)" % (title, len(tri)), fontsize=9)
    fig.tight_layout()
    fig.savefig(os.path.join(HERE, "deformed_mesh_cycle5.png"), dpi=110)
    plt.close(fig)


def main():
    if not os.path.exists(APP):
        sys.exit("build the application first: " + APP)
    outs = {name: run(name) for name in RUNS}
    for name in RUNS:
        rows = load_csv(name)[1]
        print("%-32s rate of eta over the last %d cycles: %.2f" % (name, min(10, len(rows) - 1),
                                                                   rate(rows, min(10, len(rows) - 1))))
    plots(outs)
    deformed_mesh_plot(outs)


if __name__ == "__main__":
    main()
