"""Render an unstructured grid with the "Accurate Volume" representation beside ParaView's
own "Volume" (projected tetrahedra), in pvbatch; save both screenshots, the side-by-side
layout and our float image.

    xvfb-run -a -s "-screen 0 1280x1024x24 -noreset" \\
      env PYTHONPATH=/opt/highordervolume/python3-paraview/usr/lib/python3/dist-packages \\
      pvbatch ParaView/Examples/accurate_volume.py --out /tmp/av

Options: --data file.vtu, --array name, --mode "CPU accurate" | "OpenGL projection" |
"Ray cast", --size W H, --plugin-dir <folder of HighOrderVolume.so> (default: the build
tree's, build/paraview/lib/paraview-5.11/plugins/HighOrderVolume). An MPI run:
mpi_accurate_volume.py.
"""
import argparse
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.join(HERE, os.pardir, os.pardir)

parser = argparse.ArgumentParser()
parser.add_argument("--data", default=os.path.join(ROOT, "Testing", "Data", "bracket_tet4_ccx.vtu"))
parser.add_argument("--array", default="von_mises")
parser.add_argument("--mode", default="CPU accurate")
parser.add_argument("--size", type=int, nargs=2, default=[640, 480])
parser.add_argument("--out", default="accurate_volume_out")
parser.add_argument("--plugin-dir", default=os.environ.get("HOV_PARAVIEW_PLUGIN_DIR", os.path.join(
    ROOT, "build", "paraview", "lib", "paraview-5.11", "plugins", "HighOrderVolume")))
args = parser.parse_args()
os.makedirs(args.out, exist_ok=True)

# Load the plugin (hov_paraview_plugin.py beside it checks the ParaView version first).
sys.path.insert(0, os.path.abspath(args.plugin_dir))
import hov_paraview_plugin  # noqa: E402

from paraview.simple import (AssignViewToLayout, ColorBy, CreateLayout, CreateView,  # noqa: E402
                             GetColorTransferFunction, GetOpacityTransferFunction, Render,
                             SaveScreenshot, Show, XMLUnstructuredGridReader)

hov_paraview_plugin.load(globals())

reader = XMLUnstructuredGridReader(FileName=[os.path.abspath(args.data)])
reader.UpdatePipeline()
lo, hi = reader.PointData[args.array].GetRange()

# The colour map and opacity function both representations share.
lut = GetColorTransferFunction(args.array)
lut.ApplyPreset("Cool to Warm", True)
lut.RescaleTransferFunction(lo, hi)
lut.AutomaticRescaleRangeMode = "Never"
pwf = GetOpacityTransferFunction(args.array)
pwf.Points = [lo, 0.05, 0.5, 0.0, 0.5 * (lo + hi), 0.6, 0.5, 0.0, hi, 1.0, 0.5, 0.0]

b = reader.GetDataInformation().GetBounds()
diagonal = sum((b[2 * k + 1] - b[2 * k]) ** 2 for k in range(3)) ** 0.5
views = []
for representation in ("Accurate Volume", "Volume"):
    view = CreateView("RenderView")
    view.ViewSize = args.size
    view.OrientationAxesVisibility = 0
    view.UseColorPaletteForBackground = 0
    view.Background = [0.08, 0.08, 0.12]
    view.UseFXAA = 0  # FXAA would blur the volume's edges after compositing
    display = Show(reader, view)
    display.Representation = representation
    ColorBy(display, ("POINTS", args.array))
    display.ScalarOpacityUnitDistance = 0.03 * diagonal
    if representation == "Accurate Volume":
        display.RenderMode = args.mode
        display.OpacitySemantics = "VTK unstructured"  # what "Volume" (projected tetra) uses
        display.FloatImageFileName = os.path.abspath(os.path.join(args.out, "accurate_volume.vti"))
        ours = display
    views.append(view)
# One camera for both views: fitted to the data, then turned.
views[0].ResetCamera()
camera = views[0].GetActiveCamera()
camera.Azimuth(30.0)
camera.Elevation(25.0)
camera.OrthogonalizeViewUp()
views[1].CameraPosition = camera.GetPosition()
views[1].CameraFocalPoint = camera.GetFocalPoint()
views[1].CameraViewUp = camera.GetViewUp()
views[1].CameraViewAngle = camera.GetViewAngle()

for view, name in zip(views, ("accurate_volume", "paraview_volume")):
    Render(view)
    SaveScreenshot(os.path.join(args.out, name + ".png"), view, ImageResolution=args.size)
layout = CreateLayout("side by side")
AssignViewToLayout(views[0], layout, 0)
layout.SplitHorizontal(0, 0.5)
AssignViewToLayout(views[1], layout, 2)
SaveScreenshot(os.path.join(args.out, "side_by_side.png"), layout,
               ImageResolution=[2 * args.size[0], args.size[1]])

ours.UpdatePropertyInformation()
print("Accurate Volume (%s): %d cells of %d types, image %.3f s, frame %.3f s, witness %d" % (
    args.mode, ours.GetProperty("PieceCells").GetData(), ours.GetProperty("PieceCellTypes").GetData(),
    ours.GetProperty("LastImageTime").GetData(), ours.GetProperty("LastFrameTime").GetData(),
    ours.GetProperty("WitnessViolations").GetData()))
print("wrote", ", ".join(sorted(os.listdir(args.out))), "in", args.out)
