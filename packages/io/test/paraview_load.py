# Opens the XDMF files written by io_unit_tests_np4 in ParaView (pvpython, Xdmf3ReaderS, the
# reader ParaView picks by default) and checks what ParaView sees: time steps, and per step the
# blocks' cell and point counts, array names and component counts, and the partition range.
# Usage: pvpython paraview_load.py EXPECTED.json   (file -> expectations, see CMakeLists.txt)
import json
import sys

from paraview import servermanager as sm
from paraview.simple import Delete, OpenDataFile

failures = []


def check(cond, what):
    if not cond:
        failures.append(what)


expected = json.load(open(sys.argv[1]))
for path, exp in expected.items():
    reader = OpenDataFile(path)
    check(reader is not None, f"{path}: ParaView cannot open it")
    if reader is None:
        continue
    times = list(reader.TimestepValues)
    check(times == exp["times"], f"{path}: times {times} != {exp['times']}")
    for t, steps in zip(exp["times"], exp["steps"]):
        reader.UpdatePipeline(t)
        data = sm.Fetch(reader)
        it = data.NewIterator()
        it.InitTraversal()
        blocks = []
        while not it.IsDoneWithTraversal():
            blocks.append(it.GetCurrentDataObject())
            it.GoToNextItem()
        check(len(blocks) == len(steps), f"{path} t={t}: {len(blocks)} blocks, want {len(steps)}")
        for b, want in zip(blocks, steps):
            cd, pd = b.GetCellData(), b.GetPointData()
            cells = {cd.GetArrayName(i): cd.GetArray(i).GetNumberOfComponents()
                     for i in range(cd.GetNumberOfArrays())}
            points = {pd.GetArrayName(i): pd.GetArray(i).GetNumberOfComponents()
                      for i in range(pd.GetNumberOfArrays())}
            got = {"cells": b.GetNumberOfCells(), "points": b.GetNumberOfPoints(),
                   "cell_arrays": cells, "point_arrays": points,
                   "partition": list(cd.GetArray("partition").GetRange()) if "partition" in cells else None}
            for key, value in want.items():
                check(got[key] == value, f"{path} t={t}: {key} = {got[key]}, want {value}")
    Delete(reader)

for f in failures:
    print("FAILED:", f)
print(f"{len(expected)} files checked in ParaView, {len(failures)} failures")
sys.exit(1 if failures else 0)
