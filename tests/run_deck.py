"""The run step shared by the Python tests that check what a run's output feeds (PlotRun.py,
ParaviewPicture.py): the deck run quietly into an emptied directory, so that nothing of an
earlier run can pass the check."""

import shutil
import subprocess


def run_deck(app, deck, out, sets):
    """Run `app deck --quiet --output out --set s ...` into an emptied `out`; False (and the
    command printed) when the run fails."""
    shutil.rmtree(out, ignore_errors=True)
    run = [app, deck, "--quiet", "--output", out]
    for s in sets:
        run += ["--set", s]
    if subprocess.run(run).returncode != 0:
        print("FAILED: the run failed:", " ".join(run))
        return False
    return True
