#!/usr/bin/python3
"""The adaptive Hertz 2D studies of docs/adaptivity.md.

    /usr/bin/python3 docs/adaptivity/hertz2d_study.py [--out DIR] [--plots-only] [--update-docs]

Runs build/apps/stresscontact/stresscontact on input/hertz2d*.xml (RUNS below) into
DIR/runs/<name> (DIR: --out, default /tmp/sc_hertz2d_study) and writes, from each run's own
outputs only:

- DIR/<name>.csv, one row per cycle: cycle, DOFs, eta and its parts, the signed normal part, load
  P, half-width a, peak pressure p0, Hertz's a and p0 for P (scripts/plot-run.py's
  hertz_reference: the run's own Material and Mesh/Radius, nothing assumed here), stick
  half-width, Newton steps, the cycle's seconds;
- DIR/plots/*.png, the plots of docs/adaptivity.md, drawn with scripts/plot-run.py's functions.

Each CSV is compared with the reference of the same name committed in docs/adaptivity/ (DOFs,
eta, P of the last cycle). Nothing in the repository changes unless --update-docs is given: it
copies the CSVs and PNGs into docs/adaptivity/. --plots-only redraws from the runs already in
DIR. Needs Debian's python3-matplotlib and python3-h5py. All runs take about 5 minutes on one
core.
"""
import argparse
import csv
import importlib.util
import math
import os
import shutil
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
APP = os.path.join(ROOT, "build", "apps", "stresscontact", "stresscontact")
HERE = os.path.join(ROOT, "docs", "adaptivity")
PARTS = ["volume", "asymmetry", "oscillation", "contact_complementarity", "contact_penetration",
         "contact_tension", "friction"]


def plot_run_module():
    """scripts/plot-run.py as a module (its name has a hyphen)."""
    spec = importlib.util.spec_from_file_location("plot_run", os.path.join(ROOT, "scripts", "plot-run.py"))
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


PR = plot_run_module()

# name: (deck, --set overrides). The runs use the decks' geometry, curved (quadratic) boundary
# elements with new vertices projected onto the circle, except the straight_* runs, whose point is
# the straight geometry: they keep the initial polygon (Project boundary = false), which needs
# straight-sided elements (Geometry order = 1), so they set both explicitly.
STRAIGHT = ["Mesh/Project boundary=false", "Mesh/Geometry order=1"]
RUNS = {
    "frictionless_nu028_adaptive": ("hertz2d_frictionless.xml", ["Adaptivity/Cycles=26"]),
    "frictionless_nu028_uniform": ("hertz2d_frictionless.xml", ["Adaptivity/Marking=Uniform", "Adaptivity/Cycles=3"]),
    "frictionless_nu04999_adaptive": ("hertz2d_frictionless.xml",
                                      ["Adaptivity/Cycles=26", "Material/Poisson ratio=0.4999"]),
    "frictionless_nu04999_uniform": ("hertz2d_frictionless.xml",
                                     ["Adaptivity/Marking=Uniform", "Adaptivity/Cycles=3",
                                      "Material/Poisson ratio=0.4999"]),
    "frictionless_nu05_adaptive": ("hertz2d_frictionless.xml",
                                   ["Adaptivity/Cycles=26", "Material/Poisson ratio=0.5"]),
    "coulomb_nu028_adaptive": ("hertz2d.xml", ["Adaptivity/Cycles=26"]),
    "coulomb_nu028_uniform": ("hertz2d.xml", ["Adaptivity/Marking=Uniform", "Adaptivity/Cycles=3"]),
    "coulomb_nu04999_adaptive": ("hertz2d_incompressible.xml", ["Adaptivity/Cycles=26"]),
    "coulomb_nu04999_uniform": ("hertz2d_incompressible.xml", ["Adaptivity/Marking=Uniform", "Adaptivity/Cycles=3"]),
    "straight_frictionless_adaptive": ("hertz2d_frictionless.xml", ["Adaptivity/Cycles=26"] + STRAIGHT),
    "straight_frictionless_uniform": ("hertz2d_frictionless.xml",
                                      ["Adaptivity/Marking=Uniform", "Adaptivity/Cycles=3"] + STRAIGHT),
}
HEADER = ["cycle", "dofs", "eta"] + PARTS + ["contact_normal_signed", "P", "a", "p0", "a_hertz", "p0_hertz",
                                             "stick_half_width", "newton_steps", "cycle_seconds"]


def run_deck(deck, sets, out):
    """Run input/<deck> with the --set overrides into `out`: its summary.json and the seconds."""
    cmd = [APP, os.path.join(ROOT, "input", deck), "--quiet", "--output", out]
    for s in sets:
        cmd += ["--set", s]
    t0 = time.time()
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)
    return PR.load_summary(out), time.time() - t0


def write_csv(path, header, rows):
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(header)
        w.writerows(rows)


def load_csv(path):
    """The header and the rows (as numbers; an empty cell is 0) of a study CSV."""
    with open(path) as f:
        r = list(csv.reader(f))
    return r[0], [[float(x) if x != "" else 0.0 for x in row] for row in r[1:]]


def compare_with_reference(name, path, columns):
    """Print the last cycle's values next to the committed reference CSV's."""
    ref = os.path.join(HERE, name + ".csv")
    if not os.path.exists(ref):
        print(f"  {name}: no reference CSV in docs/adaptivity/ (new run)")
        return
    h, rows = load_csv(path)
    hr, ref_rows = load_csv(ref)
    if len(rows) != len(ref_rows):
        print(f"  {name}: {len(rows) - 1} cycles, the reference {len(ref_rows) - 1}")
    words = []
    for c in columns:
        new, old = rows[-1][h.index(c)], ref_rows[-1][hr.index(c)]
        rel = abs(new - old) / abs(old) if old else abs(new)
        words.append(f"{c} {new:.6g} (reference {old:.6g}, rel. diff. {rel:.1e})")
    print(f"  {name}, last cycle: " + ", ".join(words))


def run(name, out_dir):
    deck, sets = RUNS[name]
    out = os.path.join(out_dir, "runs", name)
    summary, seconds = run_deck(deck, sets, out)
    rows = []
    for c in summary["cycles"]:
        eta = c.get("eta", {})
        ct = c["contact"]
        P = ct["force"][1]
        a_h, p0_h = PR.hertz_reference(summary, P)
        rows.append([c["cycle"], c["dofs"]["total"], eta.get("total", float("nan"))] +
                    [eta.get(p, 0.0) for p in PARTS] +
                    [eta.get("contact_normal_signed", 0.0), P, ct["half_width"], ct["max_pressure"],
                     a_h, p0_h, ct["stick_half_width"], ct["newton_iterations"],
                     sum(c.get("timings", {}).values()) if isinstance(c.get("timings"), dict) else ""])
    path = os.path.join(out_dir, name + ".csv")
    write_csv(path, HEADER, rows)
    print("%-32s %3d cycles, %8d DOFs, eta %.3e, %.1f s" % (name, len(rows) - 1, rows[-1][1], rows[-1][2], seconds),
          flush=True)
    compare_with_reference(name, path, ["dofs", "eta", "P"])


def rate(rows, last):
    """Least-squares slope of −log η against log DOFs over the last `last` rows (columns 1, 2)."""
    xs = [math.log(r[1]) for r in rows[-last:]]
    ys = [math.log(r[2]) for r in rows[-last:]]
    mx, my = sum(xs) / len(xs), sum(ys) / len(ys)
    return -sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sum((x - mx) ** 2 for x in xs)


def contact_rows(run_dir, cycle):
    with open(os.path.join(run_dir, "contact_cycle%d.csv" % cycle), newline="") as f:
        return list(csv.DictReader(f))


def eta_plots(out_dir, plt, plots):
    """η_CF against DOFs, uniform against adaptive, per scene (the talk's "Convergence comparison")."""
    written = []
    for tag, title in (("frictionless_nu028", "ν = 0.28, frictionless"),
                       ("frictionless_nu04999", "ν = 0.4999, frictionless"),
                       ("straight_frictionless", "straight boundaries, ν = 0.28, frictionless"),
                       ("coulomb_nu028", "ν = 0.28, Coulomb μ_F = 0.4"),
                       ("coulomb_nu04999", "ν = 0.4999, Coulomb μ_F = 0.4")):
        fig, ax = plt.subplots(figsize=(6, 4.5))
        for kind, style in (("adaptive", "o-"), ("uniform", "s--")):
            path = os.path.join(out_dir, tag + "_" + kind + ".csv")
            if not os.path.exists(path):
                continue
            h, rows = load_csv(path)
            ax.loglog([r[1] for r in rows], [r[2] for r in rows], style, label="η_CF, " + kind, ms=4)
            if kind == "adaptive":
                for p, st in (("volume", ":"), ("contact_complementarity", "-."), ("friction", "--")):
                    i = h.index(p)
                    if any(r[i] > 0 for r in rows):
                        ax.loglog([r[1] for r in rows], [r[i] for r in rows], st, label=p + " (adaptive)", lw=1)
        h, rows = load_csv(os.path.join(out_dir, tag + "_adaptive.csv"))
        n0 = rows[-1][1]
        ax.loglog([n0 / 30, n0], [rows[-1][2] * 30, rows[-1][2]], "k-", lw=0.8, label="DOFs⁻¹ (optimal, k = 1)")
        ax.set_xlabel("DOFs")
        ax.set_ylabel("η (energy norm of the stress error)")
        ax.set_title(title + f": adaptive rate {rate(rows, 10):.2f} over the last 10 cycles", fontsize=10)
        ax.grid(True, which="both", lw=0.3)
        ax.legend(fontsize=7)
        fig.tight_layout()
        written.append(os.path.join(plots, "eta_" + tag + ".png"))
        fig.savefig(written[-1], dpi=110)
        plt.close(fig)
    return written


def contact_zone_plot(out_dir, plt, plots):
    """Contact points on half of Γ_C at cycles 0 and 10 (the talk's "Refinement of contact zone"),
    the pressure against Hertz at the last cycle, and its error against Hertz."""
    run_dir = os.path.join(out_dir, "runs", "frictionless_nu028_adaptive")
    summary = PR.load_summary(run_dir)
    last = summary["cycles"][-1]
    P = last["contact"]["force"][1]
    a, p0 = PR.hertz_reference(summary, P)
    half_width = last["contact"]["half_width"]
    fig, axs = plt.subplots(3, 1, figsize=(6.5, 8.5), gridspec_kw={"height_ratios": [1, 2, 1.3]})
    xmax = 0.4
    # The vertex on the axis has x = ±1e-15 or so: count it on this half.
    xmin = -1e-9
    for cyc, y in ((10, 1.0), (0, 0.0)):
        xs = sorted(float(r["x"]) for r in contact_rows(run_dir, cyc) if xmin <= float(r["x"]) <= xmax)
        active = sum(1 for r in contact_rows(run_dir, cyc)
                     if xmin <= float(r["x"]) <= xmax and r["status"] in ("stick", "slip"))
        axs[0].plot(xs, [y] * len(xs), "|", ms=12,
                    label="cycle %d: %d points in 0 ≤ x ≤ %g (%d in contact)" % (cyc, len(xs), xmax, active))
    axs[0].axvline(a, color="black", ls="--", lw=0.8, label="Hertz a = %.4f" % a)
    axs[0].set_xlim(0, xmax)
    axs[0].set_ylim(-0.7, 2.9)  # room for the legend above the ticks
    axs[0].set_yticks([])
    axs[0].set_xlabel("x on Γ_C (length unit of the mesh)")
    axs[0].legend(fontsize=7, loc="upper right")
    axs[0].set_title("contact points on half of Γ_C (each face's own points: two at every vertex)", fontsize=10)

    pts = sorted((float(r["x"]), -float(r["sigma_n"]), r["status"]) for r in contact_rows(run_dir, last["cycle"])
                 if abs(float(r["x"])) < 1.5 * a)
    hx = [-1.5 * a + 3 * a * i / 600 for i in range(601)]

    def hertz(x):
        return p0 * math.sqrt(max(0.0, 1 - x * x / (a * a)))

    axs[1].plot([x for x, _, _ in pts], [s for _, s, _ in pts], ".", ms=3,
                label="−σ_N at the contact points, cycle %d" % last["cycle"])
    axs[1].plot(hx, [hertz(x) for x in hx], "k-", lw=0.8, label="Hertz for the run's load P = %.3f" % P)
    for sign in (-1, 1):
        axs[1].axvline(sign * a, color="black", ls="--", lw=0.8, label="±a (Hertz) = ±%.4f" % a if sign > 0 else None)
        axs[1].axvline(sign * half_width, color="tab:red", ls=":", lw=1,
                       label="± computed half-width %.4f" % half_width if sign > 0 else None)
    axs[1].set_ylabel("pressure −σ_N (unit of E)")
    axs[1].legend(fontsize=7, loc="lower center")
    axs[1].set_title("pressure against Hertz (a = %.4f, p₀ = %.1f)" % (a, p0), fontsize=10)
    active = [(x, s) for x, s, st in pts if st in ("stick", "slip")]
    axs[2].plot([x for x, _ in active], [(s - hertz(x)) / p0 for x, s in active], ".", ms=3)
    axs[2].axhline(0.0, color="black", lw=0.6)
    for sign in (-1, 1):
        axs[2].axvline(sign * a, color="black", ls="--", lw=0.8)
    axs[2].set_ylabel("(−σ_N − p_Hertz)/p₀")
    axs[2].set_xlabel("x (length unit of the mesh)")
    axs[2].set_title("error against Hertz at the active points", fontsize=10)
    for ax in axs[1:]:
        ax.set_xlim(-1.5 * a, 1.5 * a)
        ax.grid(True, lw=0.3)
    fig.tight_layout()
    path = os.path.join(plots, "contact_zone.png")
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return [path]


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--out", default="/tmp/sc_hertz2d_study", help="runs, CSVs and plots (default %(default)s)")
    parser.add_argument("--plots-only", action="store_true", help="redraw from the runs already in --out")
    parser.add_argument("--update-docs", action="store_true",
                        help="copy the CSVs and PNGs into docs/adaptivity/ (the committed references)")
    args = parser.parse_args()
    out_dir = os.path.abspath(args.out)
    plots = os.path.join(out_dir, "plots")
    os.makedirs(plots, exist_ok=True)
    if not args.plots_only:
        if not os.path.exists(APP):
            sys.exit("build the application first: " + APP)
        for name in RUNS:
            run(name, out_dir)
    for name in RUNS:
        rows = load_csv(os.path.join(out_dir, name + ".csv"))[1]
        last = min(10, len(rows) - 1)
        print("%-32s rate of eta over the last %d cycles: %.2f" % (name, last, rate(rows, last)))
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        sys.exit("python3-matplotlib is not installed: CSVs only (apt-get install python3-matplotlib)")
    written = eta_plots(out_dir, plt, plots) + contact_zone_plot(out_dir, plt, plots)
    # Coulomb: normal and tangential tractions at the last cycle, stick/slip coloured, with the
    # Coulomb bound and the frictionless Hertz profile (scripts/plot-run.py's contact plot).
    for tag in ("nu028", "nu04999"):
        run_dir = os.path.join(out_dir, "runs", "coulomb_%s_adaptive" % tag)
        summary = PR.load_summary(run_dir)
        name = "coulomb_tractions.png" if tag == "nu028" else "coulomb_tractions_nu04999.png"
        written.append(PR.plot_contact(summary, run_dir, None, plt, plots, name=name))
    # The mesh after 5 adaptive cycles, deformed by u^R (the talk's deformed mesh).
    run_dir = os.path.join(out_dir, "runs", "frictionless_nu028_adaptive")
    written.append(PR.plot_deformed(PR.load_summary(run_dir), run_dir, 5, plt, plots,
                                    name="deformed_mesh_cycle5.png",
                                    title="Hertz 2D, frictionless, ν = 0.28: cycle 5 of the adaptive run"))
    written = [p for p in written if p]
    for p in written:
        print("wrote", p)
    if args.update_docs:
        for name in RUNS:
            shutil.copy(os.path.join(out_dir, name + ".csv"), HERE)
        for p in written:
            shutil.copy(p, HERE)
        print(f"copied {len(RUNS)} CSVs and {len(written)} PNGs into {HERE}")


if __name__ == "__main__":
    main()
