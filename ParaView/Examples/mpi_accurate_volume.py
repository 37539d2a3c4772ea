"""The Accurate Volume on several MPI ranks: ParaView redistributes the cells over the ranks
(kd-tree), each rank renders its piece exactly and IceT composites the layers in
visibility order.

    xvfb-run -a -s "-screen 0 1280x1024x24 -noreset" \\
      mpiexec -np 2 -x PYTHONPATH=/opt/highordervolume/python3-paraview/usr/lib/python3/dist-packages \\
        -x DISPLAY pvbatch ParaView/Examples/mpi_accurate_volume.py --out /tmp/av_mpi

(as root add --allow-run-as-root; more ranks than cores: --oversubscribe; one thread per
rank: -x VTK_SMP_MAX_THREADS=1). Writes the composited screenshot and, per rank, the float
layer of its piece (accurate_volume.vti, accurate_volume_rank<r>.vti). The script runs on
rank 0; the others follow its commands.
"""
import argparse
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.join(HERE, os.pardir, os.pardir)

parser = argparse.ArgumentParser()
parser.add_argument("--data", default=os.path.join(ROOT, "Testing", "Data", "zoo_mixed_ccx.vtu"))
parser.add_argument("--array", default="temperature")
parser.add_argument("--mode", default="CPU accurate")
parser.add_argument("--size", type=int, nargs=2, default=[640, 480])
parser.add_argument("--out", default="mpi_accurate_volume_out")
parser.add_argument("--plugin-dir", default=os.environ.get("HOV_PARAVIEW_PLUGIN_DIR", os.path.join(
    ROOT, "build", "paraview", "lib", "paraview-5.11", "plugins", "HighOrderVolume")))
args = parser.parse_args()
os.makedirs(args.out, exist_ok=True)

sys.path.insert(0, os.path.abspath(args.plugin_dir))
import hov_paraview_plugin  # noqa: E402

from paraview import servermanager  # noqa: E402
from paraview.simple import (ColorBy, CreateView, GetColorTransferFunction,  # noqa: E402
                             GetOpacityTransferFunction, Render, SaveScreenshot, Show,
                             XMLUnstructuredGridReader)

hov_paraview_plugin.load(globals())
ranks = servermanager.vtkProcessModule.GetProcessModule().GetNumberOfLocalPartitions()

reader = XMLUnstructuredGridReader(FileName=[os.path.abspath(args.data)])
reader.UpdatePipeline()
lo, hi = reader.PointData[args.array].GetRange()
b = reader.GetDataInformation().GetBounds()
diagonal = sum((b[2 * k + 1] - b[2 * k]) ** 2 for k in range(3)) ** 0.5

view = CreateView("RenderView")
view.ViewSize = args.size
view.OrientationAxesVisibility = 0
view.UseColorPaletteForBackground = 0
view.Background = [0.08, 0.08, 0.12]
view.UseFXAA = 0  # FXAA would blur the composited volume's edges
display = Show(reader, view)
display.Representation = "Accurate Volume"
ColorBy(display, ("POINTS", args.array))
lut = GetColorTransferFunction(args.array)
lut.ApplyPreset("Cool to Warm", True)
lut.RescaleTransferFunction(lo, hi)
pwf = GetOpacityTransferFunction(args.array)
pwf.Points = [lo, 0.05, 0.5, 0.0, 0.5 * (lo + hi), 0.6, 0.5, 0.0, hi, 1.0, 0.5, 0.0]
display.ScalarOpacityUnitDistance = 0.03 * diagonal
display.RenderMode = args.mode
display.FloatImageFileName = os.path.abspath(os.path.join(args.out, "accurate_volume.vti"))
view.ResetCamera()
camera = view.GetActiveCamera()
camera.Azimuth(30.0)
camera.Elevation(25.0)
camera.OrthogonalizeViewUp()
Render(view)
SaveScreenshot(os.path.join(args.out, "accurate_volume_%d_ranks.png" % ranks), view,
               ImageResolution=args.size)
display.UpdatePropertyInformation()
print("%d ranks; rank 0 rendered %d of %d cells (%d types) in %.3f s" % (
    ranks, display.GetProperty("PieceCells").GetData(),
    reader.GetDataInformation().GetNumberOfCells(),
    display.GetProperty("PieceCellTypes").GetData(), display.GetProperty("LastImageTime").GetData()))
print("wrote", ", ".join(sorted(os.listdir(args.out))), "in", args.out)
