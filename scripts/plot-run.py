#!/usr/bin/python3
"""Plot a finished (or running) StressContact run from its output directory.

    scripts/plot-run.py OUTPUT_DIR [--cycle N]

Reads only what the run wrote (docs/output.md): summary.json, contact_cycle<N>.csv and the
<Base name>.xdmf with its .h5 files. Writes PNG files into OUTPUT_DIR/plots/:

  eta.png              η (η_CF with contact) and each of its parts against the DOFs, log-log, with
                       the optimal slope DOFs^(-(k+1)/d) for the run's degree k and dimension d,
                       and the true error where the run has an exact solution.
  contact_traction.png (runs with contact) the normal pressure −σ_N and the tangential traction of
                       every contact point of the last cycle (or --cycle N) against the position
                       along the obstacle plane from the zone's middle (2D) or the distance from
                       the point of largest pressure (3D), both in the obstacle plane,
                       coloured by status (free, stick, slip); Hertz's profile when summary.json
                       has Hertz reference values (frictionless Half disc / Half ball runs) and the
                       Coulomb bound μ_F|σ_N| with Coulomb friction.
  mesh_eta.png         (2D, needs h5py) the mesh of that cycle coloured by the error indicator η_T.
  deformed.png         (2D, needs h5py) the body of that cycle deformed by the reconstructed
                       displacement u^R, magnified by the scale factor given in the title (largest
                       |u^R| = 5% of the body's size, or --scale), coloured by von Mises; with
                       contact a second panel shows the contact zone at true scale.
  load_history.png     (runs with load steps) from history.csv, the last cycle of each step: the
                       force on each support part and on the obstacle against the prescribed
                       displacement that changes from step to step (the part's reaction against
                       its own prescribed component, the contact force against the obstacle's
                       displacement), every force component against the step's time, and the
                       contact and stick zone's size against the time, in 2D with the stick
                       zone's ends (summary.json's contact.stick_zone_ends) as a band; where a
                       prescribed displacement reverses (a loading-unloading cycle), a panel of
                       the force minus its least-squares straight line in that displacement,
                       which shows a thin hysteresis loop. Steps are labelled all (up to 8 steps)
                       or at the first, the last and the turning points.

As a module (importlib, see docs/adaptivity/hertz2d_study.py) it offers the readers and the
Hertz reference from the run's own parameters (hertz_reference) to the docs' study scripts.

Material, geometry and friction data come from the run's own summary.json (its "parameters"),
nothing is assumed. Needs matplotlib (Debian: python3-matplotlib); h5py (python3-h5py) only for
mesh_eta.png.
"""

import argparse
import csv
import json
import math
import os
import re
import sys
import xml.etree.ElementTree as ET

# Parts of "eta" in summary.json that are not parts of η (docs/output.md "summary.json").
NOT_PARTS = {"total", "contact_normal_signed", "stress_energy_norm", "relative", "stress_energy_error",
             "efficiency_index", "marked_elements", "stop_reason"}
STATUS_COLOURS = {"free": "0.6", "stick": "tab:red", "slip": "tab:blue"}


def save(fig, plt, out, name):
    """Lay the figure out, write it as out/name at 120 dpi, close it; the path written."""
    fig.tight_layout()
    path = os.path.join(out, name)
    fig.savefig(path, dpi=120)
    plt.close(fig)
    return path


def load_summary(directory):
    path = os.path.join(directory, "summary.json")
    if not os.path.exists(path):
        sys.exit(f"plot-run: no summary.json in {directory}")
    with open(path, encoding="utf-8") as f:
        return json.load(f)


def param(summary, *keys, default=None):
    node = summary.get("parameters", {})
    for k in keys:
        if not isinstance(node, dict) or k not in node:
            return default
        node = node[k]
    return node


def hertz_reference(summary, load):
    """Hertz's (a, p0) for the run's load (Johnson 1985, docs/theory.md "Hertz reference values")
    from the run's own parameters: a Half disc (cylinder, 2D) or Half ball (sphere, 3D) of radius
    Mesh/Radius pressed on a plane; E* = E/(1 − ν²), in plane stress E* = E. None for other scenes
    or a load ≤ 0. With friction these are the frictionless values (p0 is then ~8% higher)."""
    source = param(summary, "Mesh", "Source", default="")
    dim = param(summary, "Problem", "Dimension", default=2)
    obstacle = param(summary, "Contact", "Obstacle", default="Plane")
    E = param(summary, "Material", "Young modulus")
    nu = param(summary, "Material", "Poisson ratio")
    R = param(summary, "Mesh", "Radius", default=1.0)
    if source not in ("Half disc", "Half ball") or obstacle != "Plane" or not E or nu is None or not load or load <= 0:
        return None
    plane_stress = dim == 2 and param(summary, "Material", "Plane", default="Strain") == "Stress"
    estar = E if plane_stress else E / (1.0 - nu * nu)
    if dim == 2:
        a = math.sqrt(4.0 * load * R / (math.pi * estar))
        return a, 2.0 * load / (math.pi * a)
    a = (3.0 * load * R / (4.0 * estar)) ** (1.0 / 3.0)
    return a, 3.0 * load / (2.0 * math.pi * a * a)


def plot_eta(summary, plt, out):
    # η = 0 (a run without load) has no place on the log scale
    cycles = [c for c in summary.get("cycles", [])
              if isinstance(c.get("eta"), dict) and isinstance(c["eta"].get("total"), (int, float))
              and c["eta"]["total"] > 0 and c.get("dofs", {}).get("total")]
    if not cycles:
        print("plot-run: no estimated cycle with η > 0 in summary.json: eta.png skipped")
        return None
    dofs = [c["dofs"]["total"] for c in cycles]
    fig, ax = plt.subplots(figsize=(7, 5))
    eta = [c["eta"]["total"] for c in cycles]
    ax.loglog(dofs, eta, "o-", color="black", lw=2, label="η (total)")
    parts = []
    for c in cycles:
        for k, v in c["eta"].items():
            if k not in NOT_PARTS and isinstance(v, (int, float)) and k not in parts:
                parts.append(k)
    for k in parts:
        pts = [(n, c["eta"].get(k)) for n, c in zip(dofs, cycles)]
        # a part that stays at round-off against η (e.g. the oscillation of zero data) is left out
        pts = [(n, v) for (n, v), e in zip(pts, eta) if isinstance(v, (int, float)) and v > 1e-10 * e]
        if len(pts) >= 1:
            ax.loglog([p[0] for p in pts], [p[1] for p in pts], ".--", lw=1, label=k.replace("_", " "))
    errors = [(n, c["eta"].get("stress_energy_error")) for n, c in zip(dofs, cycles)]
    errors = [(n, e) for n, e in errors if isinstance(e, (int, float)) and e > 0]
    if errors:
        ax.loglog([e[0] for e in errors], [e[1] for e in errors], "s-", color="tab:green",
                  label="‖A^{1/2}(σ − σ_h)‖ (exact solution)")
    k = param(summary, "Discretization", "Degree", default=None)
    d = param(summary, "Problem", "Dimension", default=None)
    if k and d and len(dofs) > 1 and dofs[-1] > dofs[0]:
        slope = (k + 1) / d
        ref = [eta[-1] * (n / dofs[-1]) ** (-slope) for n in (dofs[0], dofs[-1])]
        ax.loglog([dofs[0], dofs[-1]], ref, ":", color="0.4", label=f"DOFs^(−{slope:.3g}) (optimal, k = {k})")
    if len(dofs) > 2:
        tail = list(zip(dofs, eta))[-min(8, len(dofs)):]
        xs, ys = [math.log(n) for n, _ in tail], [math.log(e) for _, e in tail]
        mx, my = sum(xs) / len(xs), sum(ys) / len(ys)
        sxx = sum((x - mx) ** 2 for x in xs)
        if sxx > 0:
            rate = -sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sxx
            ax.set_title(f"η against DOFs: fitted rate {rate:.2f} over the last {len(tail)} cycles")
    ax.set_xlabel("DOFs")
    ax.set_ylabel("estimate")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    return save(fig, plt, out, "eta.png")


def last_contact_csv(directory, cycle):
    files = {}
    for name in os.listdir(directory):
        m = re.fullmatch(r"contact_cycle(\d+)\.csv", name)
        if m:
            files[int(m.group(1))] = os.path.join(directory, name)
    if not files:
        return None, None
    if cycle is None:
        cycle = max(files)
    return cycle, files.get(cycle)


def plot_contact(summary, directory, cycle, plt, out, name="contact_traction.png"):
    cycle, path = last_contact_csv(directory, cycle)
    if path is None:
        print("plot-run: no contact_cycle<N>.csv for that cycle: contact_traction.png skipped")
        return None
    with open(path, newline="", encoding="utf-8") as f:
        rows = list(csv.DictReader(f))
    if not rows:
        print(f"plot-run: {path} has no contact points: contact_traction.png skipped")
        return None
    dim = 3 if "z" in rows[0] else 2
    coords = ["x", "y", "z"][:dim]
    x = [[float(r[c]) for c in coords] for r in rows]
    sn = [float(r["sigma_n"]) for r in rows]
    st = [float(r["sigma_t"]) for r in rows]
    if dim == 3:
        st = [math.hypot(a, float(r["sigma_t2"])) for a, r in zip(st, rows)]
    status = [r.get("status", "") for r in rows]
    pressure = [-v for v in sn]

    normal = param(summary, "Contact", "Obstacle normal", default=None)
    if not normal or len(normal) != dim or not any(normal):
        normal = [0.0] * (dim - 1) + [1.0]
    nn = math.sqrt(sum(v * v for v in normal))
    normal = [v / nn for v in normal]

    def in_plane(p):
        h = sum(a * b for a, b in zip(p, normal))
        return [a - h * b for a, b in zip(p, normal)]

    # centre of the zone, in the plane. 2D: the middle between the outermost active points (all
    # points when none is active); a mean would be biased by the uneven point density. 3D: the
    # point of largest pressure (a ragged zone edge and coinciding control points make the box
    # or the mean of the active points a poor centre on coarse meshes).
    if dim == 2:
        active_x = [in_plane(p) for p, s in zip(x, status) if s in ("stick", "slip")] or [in_plane(p) for p in x]
        centre = in_plane([0.5 * (min(p[j] for p in active_x) + max(p[j] for p in active_x))
                           for j in range(dim)])
    else:
        centre = in_plane(x[max(range(len(x)), key=lambda i: pressure[i])])
    if dim == 2:
        tangent = [-normal[1], normal[0]]
        pos = [sum((a - c) * t for a, c, t in zip(in_plane(p), centre, tangent)) for p in x]
        xlabel = "position along the obstacle plane (from the middle of the contact zone)"
    else:
        pos = [math.sqrt(sum((a - c) ** 2 for a, c in zip(in_plane(p), centre))) for p in x]
        xlabel = "distance from the point of largest pressure, in the obstacle plane"

    fig, (ax1, ax2) = plt.subplots(2, 1, figsize=(7, 7), sharex=True)
    for s in sorted(set(status)):
        idx = [i for i, v in enumerate(status) if v == s]
        colour = STATUS_COLOURS.get(s, "tab:orange")
        ax1.plot([pos[i] for i in idx], [pressure[i] for i in idx], ".", color=colour, ms=4,
                 label=s or "points")
        ax2.plot([pos[i] for i in idx], [st[i] for i in idx], ".", color=colour, ms=4, label=s or "points")

    entry = next((c for c in summary.get("cycles", []) if c.get("cycle") == cycle), None)
    contact = (entry or {}).get("contact") or {}
    hertz = contact.get("hertz") or {}
    a = hertz.get("half_width", hertz.get("radius"))
    p0 = hertz.get("max_pressure")
    style, label = "-", "Hertz from the run's load"
    force = contact.get("force")
    if not (a and p0) and force:
        # a Hertz scene with friction: the frictionless profile for the same load, as a reference
        ref = hertz_reference(summary, force[-1])
        if ref:
            (a, p0), style = ref, "--"
            label = "frictionless Hertz for the run's load"
    if a and p0:
        n = 200
        lo = -a if dim == 2 else 0.0
        xs = [lo + (a - lo) * i / n for i in range(n + 1)]
        ax1.plot(xs, [p0 * math.sqrt(max(0.0, 1 - (v / a) ** 2)) for v in xs], style, color="black",
                 lw=1, label=f"{label} (a = {a:.4g}, p₀ = {p0:.4g})")
    law = param(summary, "Contact", "Friction law", default="None")
    mu = param(summary, "Contact", "Friction coefficient", default=0.0) or 0.0
    if law == "Coulomb" and mu > 0:
        label = f"μ_F|σ_N| (μ_F = {mu:g})"
        if dim == 2:  # a line through the points, both signs
            order = sorted(range(len(pos)), key=lambda i: pos[i])
            ax2.plot([pos[i] for i in order], [mu * pressure[i] for i in order], "-", color="0.3",
                     lw=0.8, label=label)
            ax2.plot([pos[i] for i in order], [-mu * pressure[i] for i in order], "-", color="0.3", lw=0.8)
        else:  # in 3D several points share a distance: the bound of each point
            ax2.plot(pos, [mu * p for p in pressure], "_", color="0.3", ms=5, label=label)
    title = f"contact tractions, cycle {cycle}"
    if force:
        title += f" (force {', '.join(f'{v:.6g}' for v in force)})"
    ax1.set_title(title)
    ax1.set_ylabel("normal pressure −σ_N (unit of E)")
    ax2.set_ylabel("tangential traction σ_T (unit of E)" if dim == 2 else "|σ_T| (unit of E)")
    ax2.set_xlabel(xlabel)
    for ax in (ax1, ax2):
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize=8)
    active = [p for p, s in zip(pos, status) if s in ("stick", "slip")]
    span = max((abs(v) for v in active), default=0.0)
    if span > 0:  # zoom on the zone (the free points extend over the whole contact boundary)
        ax2.set_xlim((-1.5 * span if dim == 2 else 0.0), 1.5 * span)
    return save(fig, plt, out, name)


def read_history(directory):
    """history.csv as a list of rows (column -> float, None for an empty cell), or None."""
    path = os.path.join(directory, "history.csv")
    if not os.path.exists(path):
        return None
    with open(path, newline="", encoding="utf-8") as f:
        return [{k: (float(v) if v not in ("", None) else None) for k, v in row.items()}
                for row in csv.DictReader(f)]


def plot_load_history(summary, directory, plt, out, name="load_history.png"):
    """load_history.png for a run with load steps (history.csv's step column), else None."""
    rows = read_history(directory)
    if not rows or "step" not in rows[0]:
        return None
    # The last cycle of each step: the step's result on its final mesh.
    last = {}
    for r in rows:
        if r["step"] is not None:
            last[int(r["step"])] = r
    steps = [last[k] for k in sorted(last)]
    if not steps:
        return None
    dim = param(summary, "Problem", "Dimension", default=2)
    axes_names = "xyz"[:dim]
    times = [r["time"] for r in steps]
    columns = list(rows[0].keys())
    reactions = [c for c in columns if c.startswith("reaction_")]
    contact = "force_x" in columns

    # Force against prescribed displacement: each tabulated component that changes over the
    # steps, with the force of the same part and direction (a Displacement part's reaction, the
    # contact force for the obstacle's displacement).
    pairs = []
    for c in columns:
        m = re.fullmatch(r"prescribed_(.+)_(\d+)", c)
        if not m:
            continue
        values = [r[c] for r in steps]
        if None in values or max(values) == min(values):
            continue
        part, i = m.group(1), int(m.group(2))
        if i >= dim:
            continue
        force = "force_" + axes_names[i] if part == "obstacle" else f"reaction_{part}_{axes_names[i]}"
        if force in columns and param(summary, "Boundary Conditions", part, "Type",
                                      default="Displacement" if part == "obstacle" else None) == "Displacement":
            pairs.append((c, force, part, axes_names[i]))

    # A displacement that reverses (a loading-unloading cycle): the force minus its least-squares
    # straight line in the displacement, where a thin hysteresis loop shows.
    def reverses(xs):
        d = [b - a for a, b in zip(xs, xs[1:]) if b != a]
        return any(d0 * d1 < 0 for d0, d1 in zip(d, d[1:]))

    loops = [pair for pair in pairs if reverses([r[pair[0]] for r in steps])]
    panels = (1 if pairs else 0) + len(loops) + 1 + (1 if contact else 0)
    fig, axs = plt.subplots(1, panels, figsize=(5.2 * panels, 4.4), squeeze=False)
    axs = list(axs[0])
    markers = dict(marker="o", ms=5)

    def step_ticks(ax, xs):
        # One distinct time: a range around it (matplotlib warns about an empty one).
        if max(xs) == min(xs):
            ax.set_xlim(xs[0] - 0.5, xs[0] + 0.5)

    def annotate_steps(ax, xs, ys):
        # Every step of a short history; of a longer one the first, the last and the turning points.
        turning = [k for k in range(1, len(xs) - 1) if (xs[k] - xs[k - 1]) * (xs[k + 1] - xs[k]) < 0]
        shown = range(len(xs)) if len(xs) <= 8 else [0] + turning + [len(xs) - 1]
        for k in shown:
            ax.annotate(f"step {int(steps[k]['step'])}", (xs[k], ys[k]), textcoords="offset points",
                        xytext=(4, -12), fontsize=7)

    if pairs:
        ax = axs.pop(0)
        for c, force, part, axis in pairs:
            xs = [r[c] for r in steps]
            ys = [r[force] for r in steps]
            label = (f"contact force {axis} against the obstacle's displacement {axis}" if part == "obstacle"
                     else f"reaction of {part}, {axis}, against its prescribed {axis}")
            ax.plot(xs, ys, "-", label=label, **markers)
            annotate_steps(ax, xs, ys)
        ax.set_xlabel("prescribed displacement")
        ax.set_ylabel("force on the body")
        ax.set_title("force against prescribed displacement")
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize=7)

    for c, force, part, axis in loops:
        ax = axs.pop(0)
        xs = [r[c] for r in steps]
        ys = [r[force] for r in steps]
        mx, my = sum(xs) / len(xs), sum(ys) / len(ys)
        slope = sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sum((x - mx) ** 2 for x in xs)
        rest = [y - my - slope * (x - mx) for x, y in zip(xs, ys)]
        ax.plot(xs, rest, "-", color="tab:purple", **markers)
        annotate_steps(ax, xs, rest)
        ax.axhline(0.0, color="0.6", lw=0.8)
        ax.set_xlabel(f"prescribed {axis} of {part}" if part != "obstacle" else f"obstacle's displacement {axis}")
        ax.set_ylabel(f"force minus {slope:.4g} × displacement (least squares)")
        ax.set_title("hysteresis: force minus its best straight line")
        ax.grid(True, alpha=0.3)

    ax = axs.pop(0)
    if contact:
        for a in axes_names:
            ax.plot(times, [r["force_" + a] for r in steps], "-", label=f"contact force {a}", **markers)
    for c in reactions:
        part_axis = c[len("reaction_"):]
        ax.plot(times, [r[c] for r in steps], "--", label=f"reaction {part_axis[:-2]} {part_axis[-1]}", **markers)
    step_ticks(ax, times)
    ax.set_xlabel("time t (Load steps/Times)")
    ax.set_ylabel("force on the body")
    ax.set_title("forces against time (last cycle of each step)")
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=7)

    if contact:
        ax = axs.pop(0)
        zone = "half_width" if dim == 2 else "radius"
        ax.plot(times, [r[zone] for r in steps], "-", color="0.3", label=f"contact zone ({zone.replace('_', '-')})", **markers)
        ax.plot(times, [r["stick_" + zone] for r in steps], "-", color="tab:red",
                label=f"stick zone ({zone.replace('_', '-')})", **markers)
        if dim == 2:
            ends = {}
            for c in summary.get("cycles", []):
                e = c.get("contact", {}).get("stick_zone_ends") if isinstance(c.get("contact"), dict) else None
                step = c.get("load_step", {}).get("step")
                if e and step is not None:
                    ends[int(step)] = e
            band = [ends.get(int(r["step"])) for r in steps]
            if all(band) and any(b[1] > b[0] for b in band):  # (no band without stick points)
                ax.fill_between(times, [b[0] for b in band], [b[1] for b in band], color="tab:red", alpha=0.15,
                                label="stick zone: its ends along the plane")
                ax.axhline(0.0, color="0.6", lw=0.8)
        step_ticks(ax, times)
        ax.set_xlabel("time t (Load steps/Times)")
        ax.set_ylabel("length")
        ax.set_title("contact and stick zone against time")
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize=7)

    name_of_run = param(summary, "Problem", "Name", default="")
    if name_of_run:
        fig.suptitle(name_of_run, fontsize=9)
    return save(fig, plt, out, name)


def xdmf_step(directory, summary, cycle):
    """(h5 path, topology path, geometry path, eta path or None) of the domain grid of a cycle
    (the last step when cycle is None), read from the .xdmf."""
    base = param(summary, "Output", "Base name", default="solution")
    xdmf = os.path.join(directory, base + ".xdmf")
    if not os.path.exists(xdmf):
        return None
    steps = [g for g in ET.parse(xdmf).getroot().iter("Grid")
             if g.get("CollectionType") == "Spatial"]
    if not steps:
        return None
    step = steps[-1]
    if cycle is not None:
        step = next((g for g in steps if g.get("Name") == f"cycle {cycle}"), None)
        if step is None:
            return None
    domain = next((g for g in step.findall("Grid") if g.get("Name") == "domain"), None)
    if domain is None:
        return None

    def item(node):
        text = node.find("DataItem").text.strip() if node is not None and node.find("DataItem") is not None else None
        return text.split(":", 1) if text and ":" in text else None

    topo = item(domain.find("Topology"))
    geom = item(domain.find("Geometry"))
    eta = next((a for a in domain.findall("Attribute") if a.get("Name") == "eta"), None)
    return topo, geom, item(eta), step.get("Name")


def plot_mesh(summary, directory, cycle, plt, out):
    if param(summary, "Problem", "Dimension", default=2) != 2:
        return None
    try:
        import h5py
    except ImportError:
        print("plot-run: h5py is not installed (python3-h5py): mesh_eta.png skipped")
        return None
    found = xdmf_step(directory, summary, cycle)
    if not found or not found[0] or not found[1]:
        print("plot-run: no .xdmf step with a domain grid: mesh_eta.png skipped")
        return None
    (tfile, tpath), (gfile, gpath), eta_item, name = found
    with h5py.File(os.path.join(directory, tfile), "r") as f:
        cells = f[tpath][()]
    with h5py.File(os.path.join(directory, gfile), "r") as f:
        xyz = f[gpath][()]
    eta = None
    if eta_item:
        with h5py.File(os.path.join(directory, eta_item[0]), "r") as f:
            eta = f[eta_item[1]][()]
    import matplotlib.tri as mtri
    tri = mtri.Triangulation(xyz[:, 0], xyz[:, 1], cells)
    dx = float(xyz[:, 0].max() - xyz[:, 0].min()) or 1.0
    dy = float(xyz[:, 1].max() - xyz[:, 1].min()) or 1.0
    fig, ax = plt.subplots(figsize=(8, min(8.0, max(3.0, 6.5 * dy / dx + 1.0))))
    if eta is not None and len(eta) == len(cells):
        positive = eta[eta > 0]
        from matplotlib.colors import LogNorm
        lo = sorted(positive)[len(positive) // 100] if len(positive) else 0.0  # 1st percentile
        norm = LogNorm(vmin=max(lo, positive.max() * 1e-6), vmax=positive.max()) if len(positive) else None
        pc = ax.tripcolor(tri, facecolors=eta.clip(min=positive.min() if len(positive) else 0), norm=norm,
                          cmap="viridis", edgecolors="none")
        fig.colorbar(pc, ax=ax, label="η_T")
    ax.triplot(tri, color="black", lw=0.1, alpha=0.4)
    ax.set_aspect("equal")
    ax.set_title(f"mesh and error indicator, {name} ({len(cells)} elements)")
    return save(fig, plt, out, "mesh_eta.png")


def domain_fields(directory, summary, cycle, names):
    """(step name, xyz, cells, {name: array}) of the domain grid of a cycle (the last one when
    cycle is None) with the fields asked for that the step has; None when h5py or the step is
    missing."""
    try:
        import h5py
    except ImportError:
        return None
    base = param(summary, "Output", "Base name", default="solution")
    xdmf = os.path.join(directory, base + ".xdmf")
    if not os.path.exists(xdmf):
        return None
    steps = [g for g in ET.parse(xdmf).getroot().iter("Grid") if g.get("CollectionType") == "Spatial"]
    step = steps[-1] if steps and cycle is None else next((g for g in steps if g.get("Name") == f"cycle {cycle}"), None)
    domain = None if step is None else next((g for g in step.findall("Grid") if g.get("Name") == "domain"), None)
    if domain is None:
        return None

    def read(node):
        item = node.find("DataItem") if node is not None else None
        if item is None or ":" not in (item.text or ""):
            return None
        fname, path = item.text.strip().split(":", 1)
        with h5py.File(os.path.join(directory, fname), "r") as f:
            return f[path][()]

    fields = {}
    for a in domain.findall("Attribute"):
        if a.get("Name") in names:
            fields[a.get("Name")] = read(a)
    return step.get("Name"), read(domain.find("Geometry")), read(domain.find("Topology")), fields


def plot_deformed(summary, directory, cycle, plt, out, scale=None, name="deformed.png", title=None):
    """The 2D body deformed by u^R × scale (default: largest |u^R| = 5% of the body's diagonal),
    coloured by von Mises; with contact points in the cycle a second panel at true scale around
    the contact zone (u^R × 1, the obstacle plane drawn)."""
    if param(summary, "Problem", "Dimension", default=2) != 2:
        return None
    found = domain_fields(directory, summary, cycle, {"reconstructed_displacement", "von_mises"})
    if not found or found[1] is None or found[2] is None:
        print("plot-run: no .xdmf step with a domain grid (or no h5py): " + name + " skipped")
        return None
    step, xyz, cells, fields = found
    u, vm = fields.get("reconstructed_displacement"), fields.get("von_mises")
    if u is None or vm is None:
        print(f"plot-run: {step} has no reconstructed_displacement or von_mises: {name} skipped")
        return None
    import matplotlib.tri as mtri
    umax = float(max(math.hypot(p[0], p[1]) for p in u))
    diag = math.hypot(float(xyz[:, 0].max() - xyz[:, 0].min()), float(xyz[:, 1].max() - xyz[:, 1].min()))
    if scale is None:
        scale = 0.05 * diag / umax if umax > 0 else 1.0
    number = int(step.split()[-1]) if step.split()[-1].isdigit() else cycle
    points = []
    if number is not None:
        _, path = last_contact_csv(directory, number)
        if path:
            with open(path, newline="", encoding="utf-8") as f:
                points = [r for r in csv.DictReader(f) if r.get("status") in ("stick", "slip")]
    panels = 2 if points else 1
    fig, axes = plt.subplots(1, panels, figsize=(6.5 * panels, 5.2), squeeze=False)
    vmax = float(vm.max()) or 1.0
    for k, ax in enumerate(axes[0]):
        factor = scale if k == 0 else 1.0
        tri = mtri.Triangulation(xyz[:, 0] + factor * u[:, 0], xyz[:, 1] + factor * u[:, 1], cells)
        pc = ax.tripcolor(tri, facecolors=vm, cmap="viridis", vmin=0.0, vmax=vmax, edgecolors="none")
        ax.triplot(tri, color="black", lw=0.15, alpha=0.5)
        if k == 0:
            ax.set_aspect("equal")
            ax.set_title(f"{step}: deformed by u^R × {scale:.3g} (magnified)", fontsize=10)
            fig.colorbar(pc, ax=ax, label="von Mises stress (unit of E)", shrink=0.8)
        else:
            xs = [float(r["x"]) for r in points]
            half = max(max(xs) - min(xs), 1e-3 * diag)
            mid = 0.5 * (max(xs) + min(xs))
            normal = param(summary, "Contact", "Obstacle normal", default=[0.0, 1.0]) or [0.0, 1.0]
            opoint = param(summary, "Contact", "Obstacle point", default=[0.0, 0.0]) or [0.0, 0.0]
            if abs(normal[0]) < 1e-12:  # a horizontal plane: draw it
                ax.axhline(opoint[1], color="black", lw=1.2, label="obstacle plane")
                ax.legend(fontsize=8, loc="upper right")
            ax.set_xlim(mid - 1.2 * half, mid + 1.2 * half)
            ys = [float(r["y"]) for r in points]
            ax.set_ylim(min(ys) - 0.1 * half, min(ys) + 0.5 * half)
            ax.set_title(f"contact zone at true scale (u^R × 1), {len(points)} active points", fontsize=10)
        ax.set_xlabel("x (length unit of the mesh)")
        ax.set_ylabel("y")
    if title:
        fig.suptitle(title, fontsize=11)
    return save(fig, plt, out, name)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                     epilog="Writes OUTPUT_DIR/plots/*.png (docs/output.md \"Plotting a run\").")
    parser.add_argument("output_dir", metavar="OUTPUT_DIR", help="a run's output directory")
    parser.add_argument("--cycle", type=int, default=None,
                        help="cycle of the contact and mesh plots (default: the last one written)")
    parser.add_argument("--scale", type=float, default=None,
                        help="magnification of u^R in deformed.png (default: largest |u^R| = 5%% of the body)")
    args = parser.parse_args()
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        sys.exit("plot-run: matplotlib is not installed for " + sys.executable + " (Debian: apt-get install python3-matplotlib, then run with /usr/bin/python3)")
    summary = load_summary(args.output_dir)
    out = os.path.join(args.output_dir, "plots")
    os.makedirs(out, exist_ok=True)
    written = [p for p in (plot_eta(summary, plt, out),
                           plot_contact(summary, args.output_dir, args.cycle, plt, out),
                           plot_mesh(summary, args.output_dir, args.cycle, plt, out),
                           plot_deformed(summary, args.output_dir, args.cycle, plt, out, args.scale),
                           plot_load_history(summary, args.output_dir, plt, out)) if p]
    for p in written:
        print("wrote", p)
    return 0 if written else 1


if __name__ == "__main__":
    sys.exit(main())
