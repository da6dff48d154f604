"""A picture of a StressContact run made with ParaView (docs/output.md "A picture with ParaView").

    pvpython --force-offscreen-rendering scripts/paraview-picture.py OUTPUT_DIR
             [--cycle N] [--colour von_mises|displacement] [--scale S] [--output PNG]
             [--size WIDTH HEIGHT]

Opens OUTPUT_DIR/<Base name>.xdmf with ParaView's default XDMF reader (Xdmf3ReaderS), goes to
the last cycle (or cycle N), and saves OUTPUT_DIR/plots/paraview.png (or --output): the body
deformed by the reconstructed displacement u^R (Warp By Vector) and coloured by von Mises (cell
field `von_mises`) or by |u^R| (`--colour displacement`), and the contact points of the
`contact` grid coloured by their status (grey free, red stick, blue slip). Two views side by
side: the whole body with u^R magnified by a scale factor (printed in the view; by default the
one that makes the largest displacement 5% of the body's size, or --scale S), and the contact
zone at true scale (scale factor 1: a magnified u^R would push the body through the obstacle).
A run without contact draws the left view only. The grids are taken by position (domain first,
boundary second, contact third; docs/output.md "Opening in ParaView"), not by name.

Needs ParaView's Python (Debian: apt-get install paraview python3-paraview, about 440 MB; not
needed to build or run StressContact). Debian's ParaView draws through GLX: on a machine without
a display run it as `xvfb-run -a pvpython --force-offscreen-rendering ...` (Debian: xvfb xauth).
Exit status 0 when the picture is written, 1 otherwise.
"""

import argparse
import glob
import json
import math
import os
import sys

from paraview import servermanager as sm
from paraview import simple as pv

# A programmable filter runs its script in this module's namespace and imports VTK's array
# algorithms there, which replace the built-in sum, min, max and abs (and fail on generators):
# the functions below have other names.
def total(values):
    return math.fsum(values)


def smallest(values):
    return sorted(values)[0]


def largest(values):
    return sorted(values)[-1]


def magnitude(v):
    return v if v >= 0 else -v

STATUS = [(0, "free", (0.6, 0.6, 0.6)), (1, "stick", (0.84, 0.15, 0.16)), (2, "slip", (0.12, 0.47, 0.71))]


def fail(message):
    print("paraview-picture:", message)
    sys.exit(1)


def xdmf_path(directory):
    base = "solution"
    summary = os.path.join(directory, "summary.json")
    if os.path.exists(summary):
        with open(summary, encoding="utf-8") as f:
            base = json.load(f).get("parameters", {}).get("Output", {}).get("Base name", base)
    path = os.path.join(directory, base + ".xdmf")
    if not os.path.exists(path):
        found = sorted(glob.glob(os.path.join(directory, "*.xdmf")))
        if len(found) != 1:
            fail(f"no {base}.xdmf in {directory}")
        path = found[0]
    # an absolute path: with a bare file name the XDMF library builds the .h5 paths wrongly
    return os.path.abspath(path)


def grid(reader, index):
    """The index-th grid of each step (0 domain, 1 boundary, 2 contact) as an unstructured grid."""
    return pv.ProgrammableFilter(Input=reader, OutputDataSetType="vtkUnstructuredGrid",
                                 CopyArrays=0, Script=f"""
leaves = []
def walk(o):
    if o is None:
        return
    if o.IsA("vtkMultiBlockDataSet"):
        for i in range(o.GetNumberOfBlocks()):
            walk(o.GetBlock(i))
    elif o.IsA("vtkMultiPieceDataSet"):
        for i in range(o.GetNumberOfPieces()):
            walk(o.GetPiece(i))
    else:
        leaves.append(o)
walk(self.GetInputDataObject(0, 0))
if len(leaves) > {index}:
    self.GetOutputDataObject(0).ShallowCopy(leaves[{index}])
""")


def count_grids(reader, time):
    data = sm.Fetch(reader)
    it = data.NewIterator()
    it.InitTraversal()
    n = 0
    while not it.IsDoneWithTraversal():
        n += 1
        it.GoToNextItem()
    return n


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("output_dir", metavar="OUTPUT_DIR")
    parser.add_argument("--cycle", type=int, default=None, help="cycle (default: the last one written)")
    parser.add_argument("--colour", choices=["von_mises", "displacement"], default="von_mises")
    parser.add_argument("--scale", type=float, default=None,
                        help="scale factor of u^R in the whole-body view (default: largest |u^R| = 5%% of the body)")
    parser.add_argument("--output", default=None, help="PNG file (default OUTPUT_DIR/plots/paraview.png)")
    parser.add_argument("--size", type=int, nargs=2, default=[1600, 700], metavar=("WIDTH", "HEIGHT"))
    args = parser.parse_args()

    reader = pv.Xdmf3ReaderS(FileName=[xdmf_path(args.output_dir)])
    times = list(reader.TimestepValues) if reader.TimestepValues else [0.0]
    time = times[-1] if args.cycle is None else float(args.cycle)
    if time not in times:
        fail(f"cycle {args.cycle} is not in the file (cycles {', '.join(f'{t:g}' for t in times)})")
    reader.UpdatePipeline(time)
    grids = count_grids(reader, time)

    domain = grid(reader, 0)
    domain.UpdatePipeline(time)
    info = domain.GetDataInformation()
    if info.GetNumberOfCells() == 0:
        fail("the domain grid of that cycle is empty")
    point_arrays = [domain.PointData.GetArray(i).GetName() for i in range(domain.PointData.GetNumberOfArrays())]
    if "reconstructed_displacement" not in point_arrays:
        fail("the cycle has no reconstructed_displacement (an unestimated cycle): nothing to warp by")
    if args.colour == "von_mises" and domain.CellData.GetArray("von_mises") is None:
        fail("the domain grid has no von_mises field")
    bounds = info.GetBounds()
    extent = [bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4]]
    dim = 3 if extent[2] > 1e-12 * largest(extent) else 2
    size = math.sqrt(total([e * e for e in extent]))
    umax = domain.PointData["reconstructed_displacement"].GetRange(-1)[1]  # largest |u^R|
    scale = args.scale if args.scale is not None else (0.05 * size / umax if umax > 0 else 1.0)

    contact = None
    if grids >= 3:
        contact = grid(reader, 2)
        contact.UpdatePipeline(time)
        if contact.GetDataInformation().GetNumberOfPoints() == 0:
            contact = None

    layout = pv.CreateLayout("picture")
    views = [pv.CreateView("RenderView")]
    pv.AssignViewToLayout(view=views[0], layout=layout, hint=0)
    if contact is not None:
        views.append(pv.CreateView("RenderView"))
        pv.AssignViewToLayout(view=views[1], layout=layout, hint=0)

    if args.colour == "von_mises":
        field, association, title = "von_mises", "CELLS", "von Mises stress"
    else:
        field, association, title = "reconstructed_displacement", "POINTS", "|u^R|"
    lut = pv.GetColorTransferFunction(field)
    lut.ApplyPreset("Viridis (matplotlib)", True)

    status_lut = pv.GetColorTransferFunction("status")
    status_lut.InterpretValuesAsCategories = 1
    status_lut.Annotations = [text for v, name, _ in STATUS for text in (str(v), name)]
    status_lut.IndexedColors = [x for _, _, c in STATUS for x in c]

    for i, view in enumerate(views):
        factor = scale if i == 0 else 1.0
        warped = pv.WarpByVector(Input=domain, Vectors=["POINTS", "reconstructed_displacement"],
                                 ScaleFactor=factor)
        body = pv.Show(warped, view)
        body.Representation = "Surface With Edges" if i == 1 or dim == 2 else "Surface"
        body.EdgeColor = [0.3, 0.3, 0.3]
        pv.ColorBy(body, (association, field, "Magnitude") if field != "von_mises" else (association, field))
        body.RescaleTransferFunctionToDataRange(True, False)
        if i == 0:
            body.SetScalarBarVisibility(view, True)
            bar = pv.GetScalarBar(lut, view)
            bar.Title = title
            bar.ComponentTitle = ""
            bar.TitleColor = bar.LabelColor = [0, 0, 0]
        if contact is not None:
            # u^R at the contact points (sampled from the body), warped by the same factor
            at_points = pv.ResampleWithDataset(SourceDataArrays=domain, DestinationMesh=contact)
            at_points.PassPointArrays = 1
            at_points.CellLocator = "Static Cell Locator"
            moved = pv.WarpByVector(Input=at_points, Vectors=["POINTS", "reconstructed_displacement"],
                                    ScaleFactor=factor)
            points = pv.Show(moved, view)
            points.SetRepresentationType("Points")
            points.PointSize = 6 if i == 0 else 9
            points.RenderPointsAsSpheres = 1
            pv.ColorBy(points, ("POINTS", "status"))
            points.LookupTable = status_lut
            if i == 0:
                points.SetScalarBarVisibility(view, True)
                sbar = pv.GetScalarBar(status_lut, view)
                sbar.Title = "contact status"
                sbar.TitleColor = sbar.LabelColor = [0, 0, 0]
                sbar.WindowLocation = "Upper Right Corner"
        label = (f"cycle {time:g}, u^R magnified {factor:.3g} times" if i == 0 else
                 "contact zone, true scale (u^R x 1)" + ("" if dim == 2 else ", seen from below"))
        text = pv.Text(Text=label)
        shown = pv.Show(text, view)
        shown.WindowLocation = "Upper Center"
        shown.FontSize = 14
        view.OrientationAxesVisibility = 0
        view.Background = [1, 1, 1]
        if hasattr(view, "UseColorPaletteForBackground"):
            view.UseColorPaletteForBackground = 0
        for source in (text,):
            pv.GetDisplayProperties(source, view).Color = [0, 0, 0]

    # cameras: 2D looks along -z; 3D from below the contact plane, obliquely
    for i, view in enumerate(views):
        view.ViewTime = time
        view.ViewSize = [args.size[0] // len(views), args.size[1]]
        if dim == 2:
            view.InteractionMode = "2D"
            view.CameraPosition = [0, 0, 10]
            view.CameraFocalPoint = [0, 0, 0]
            view.CameraViewUp = [0, 1, 0]
        else:
            view.CameraPosition = [1.5, -2.0, -1.6]
            view.CameraFocalPoint = [0, 0, 0]
            view.CameraViewUp = [0, 0, 1]
        view.ResetCamera(False)
    if contact is not None:
        # zoom on the active points (all points when none is active)
        data = sm.Fetch(contact)
        status = data.GetPointData().GetArray("status")
        pts = [data.GetPoint(j) for j in range(data.GetNumberOfPoints())
               if status is None or status.GetValue(j) > 0]
        if not pts:
            pts = [data.GetPoint(j) for j in range(data.GetNumberOfPoints())]
        lo = [smallest([p[k] for p in pts]) for k in range(3)]
        hi = [largest([p[k] for p in pts]) for k in range(3)]
        half = largest([h - l for l, h in zip(lo, hi)] + [0.03 * size])
        centre = [(l + h) / 2 for l, h in zip(lo, hi)]
        zoom = views[1]
        zoom.CameraFocalPoint = centre
        if dim == 2:
            zoom.CameraPosition = [centre[0], centre[1], centre[2] + 10]
            zoom.CameraParallelProjection = 1
            zoom.CameraParallelScale = 0.9 * half
        else:  # from below the contact plane, looking up at the zone
            zoom.CameraPosition = [centre[0], centre[1], centre[2] - 10 * size]
            zoom.CameraViewUp = [0, 1, 0]
            zoom.CameraParallelProjection = 1
            zoom.CameraParallelScale = 0.9 * half

    output = args.output or os.path.join(args.output_dir, "plots", "paraview.png")
    os.makedirs(os.path.dirname(os.path.abspath(output)), exist_ok=True)
    pv.SaveScreenshot(output, layout, ImageResolution=args.size, TransparentBackground=0)
    if not os.path.exists(output):
        fail(f"ParaView wrote no {output}")
    print("wrote", output)
    sys.stdout.flush()
    # Tearing down the render windows under Xvfb (software GLX) ends in "X Error ... GLXBadContext"
    # and exit status 1 after the picture is written: leave without the teardown.
    os._exit(0)


if __name__ == "__main__":
    sys.exit(main())
