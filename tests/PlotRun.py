"""scripts/plot-run.py on a short run of a deck (docs/output.md "Plotting a run").

    /usr/bin/python3 PlotRun.py --app stresscontact --script scripts/plot-run.py --deck DECK
                                --out DIR [--set KEY=VALUE ...]

Runs the deck with the --set overrides into DIR (emptied first, so no earlier PNG can pass), then
plot-run.py with this interpreter, and checks the PNGs the run must give: eta.png always,
contact_traction.png with contact (a cycle with contact quantities in summary.json),
mesh_eta.png and deformed.png in 2D, load_history.png with load steps (a cycle with load_step). Each must be a PNG image that is not one flat colour, and plot-run.py must
exit 0 without a warning (matplotlib warns about degenerate axes and log scales without data).
Exit status 77 (skipped) when this interpreter cannot import matplotlib and h5py (Debian:
python3-matplotlib, python3-h5py, for /usr/bin/python3), 1 on a failed check.
"""

import argparse
import json
import os
import subprocess
import sys

from run_deck import run_deck


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--app", required=True)
    parser.add_argument("--script", required=True)
    parser.add_argument("--deck", required=True)
    parser.add_argument("--out", required=True)
    parser.add_argument("--set", action="append", default=[], dest="sets")
    args = parser.parse_args()
    try:
        import h5py  # noqa: F401  (plot-run.py needs it for mesh_eta.png)
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.image
    except ImportError as e:
        print(f"skipped: {sys.executable} cannot import matplotlib and h5py ({e}); "
              "Debian: apt-get install python3-matplotlib python3-h5py")
        return 77

    if not run_deck(args.app, args.deck, args.out, args.sets):
        return 1
    plot = subprocess.run([sys.executable, args.script, args.out], capture_output=True, text=True)
    print(plot.stdout + plot.stderr, end="")
    failures = []
    if plot.returncode != 0:
        failures.append(f"plot-run.py exited with {plot.returncode}")
    if "Warning" in plot.stdout + plot.stderr:
        failures.append("plot-run.py printed a warning")

    with open(os.path.join(args.out, "summary.json"), encoding="utf-8") as f:
        summary = json.load(f)
    dim = summary["parameters"]["Problem"]["Dimension"]
    contact = any(c.get("contact") for c in summary["cycles"])
    steps = any(c.get("load_step") for c in summary["cycles"])
    expected = (["eta.png"] + (["contact_traction.png"] if contact else []) +
                (["mesh_eta.png", "deformed.png"] if dim == 2 else []) + (["load_history.png"] if steps else []))
    for name in expected:
        path = os.path.join(args.out, "plots", name)
        if not os.path.isfile(path) or os.path.getsize(path) == 0:
            failures.append(f"{name} is missing or empty")
            continue
        with open(path, "rb") as f:
            if f.read(8) != b"\x89PNG\r\n\x1a\n":
                failures.append(f"{name} is not a PNG file")
                continue
        pixels = matplotlib.image.imread(path)
        if pixels.size == 0 or float(pixels.std()) == 0.0:
            failures.append(f"{name} is one flat colour")
            continue
        if name == "load_history.png":
            # Data drawn, not only axes and text (grey): coloured pixels (a channel spread above
            # 0.3), at least 0.3% of the picture. Axes without any curve have none.
            rgb = pixels[..., :3]
            coloured = float(((rgb.max(axis=-1) - rgb.min(axis=-1)) > 0.3).mean())
            print(f"{name}: {100 * coloured:.2f}% coloured pixels")
            if coloured < 0.003:
                failures.append(f"{name} has no curves ({100 * coloured:.2f}% coloured pixels, below 0.3%)")
        print(f"{name}: {pixels.shape[1]} x {pixels.shape[0]} pixels, {os.path.getsize(path)} bytes")
    for failure in failures:
        print("FAILED:", failure)
    print(f"{os.path.basename(args.deck)}: {len(expected)} plot(s) expected "
          f"({dim}D, {'contact' if contact else 'no contact'}{', load steps' if steps else ''}): "
          f"{'FAILED' if failures else 'ok'}")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
