"""pvbatch side of the ParaView benchmarks: frame times of "Accurate Volume" and of
ParaView's own "Volume" (projected tetrahedra) in the same run, frames interleaved.

    [mpiexec -np N] pvbatch pv_bench_frames.py spec.json

spec.json: {"plugin", "out" (a .json file), "size": [w, h], "frames", "warmup",
  "source": {"kind": "wavelet", "extent": e} (a Wavelet [-e, e]^3 tetrahedralised by
  ParaView's Tetrahedralize filter) or {"kind": "file", "path", "array"},
  "representations": ["Accurate Volume", "Volume"], "mode": "CPU accurate",
  "semantics": "VTK unstructured", "color": [[x, r, g, b]], "opacity": [[x, a]],
  "unit_distance", "camera": {"position", "focal_point", "view_up", "view_angle"} (optional),
  "azimuth_step": degrees the camera turns per frame}
The camera turns azimuth_step degrees between frames (the same angles for every
representation). Each frame is one Render() of the view on rank 0 (all ranks render and
composite inside it). Writes per representation the frame times (s), the cells of the
dataset and, for ours, the mapper's image time of the last frame on rank 0.
"""
import json
import sys
import time

from paraview import servermanager
from paraview.simple import (ColorBy, CreateView, GetColorTransferFunction,
                             GetOpacityTransferFunction, Hide, LoadPlugin, Render, Show,
                             Tetrahedralize, Wavelet, XMLUnstructuredGridReader)

with open(sys.argv[1]) as f:
    spec = json.load(f)
LoadPlugin(spec["plugin"], remote=False, ns=globals())
source = spec["source"]
if source["kind"] == "wavelet":
    e = source["extent"]
    data = Tetrahedralize(Input=Wavelet(WholeExtent=[-e, e, -e, e, -e, e]))
    array = "RTData"
else:
    data = XMLUnstructuredGridReader(FileName=[source["path"]])
    array = source["array"]
data.UpdatePipeline()
cells = data.GetDataInformation().GetNumberOfCells()

lut = GetColorTransferFunction(array)
lut.AutomaticRescaleRangeMode = "Never"
lut.ColorSpace = "RGB"
lut.Discretize = 0
lut.RGBPoints = [v for node in spec["color"] for v in node]
pwf = GetOpacityTransferFunction(array)
pwf.Points = [v for x, a in spec["opacity"] for v in (x, a, 0.5, 0.0)]

views, displays = {}, {}
for rep in spec["representations"]:
    view = CreateView("RenderView")
    view.ViewSize = spec["size"]
    view.OrientationAxesVisibility = 0
    view.UseFXAA = 0
    disp = Show(data, view)
    disp.Representation = rep
    ColorBy(disp, ("POINTS", array))
    disp.ScalarOpacityUnitDistance = spec["unit_distance"]
    if rep == "Accurate Volume":
        disp.RenderMode = spec.get("mode", "CPU accurate")
        disp.OpacitySemantics = spec.get("semantics", "VTK unstructured")
    cam = spec.get("camera")
    if cam:
        view.CameraPosition = cam["position"]
        view.CameraFocalPoint = cam["focal_point"]
        view.CameraViewUp = cam["view_up"]
        view.CameraViewAngle = cam.get("view_angle", 30.0)
    else:
        view.ResetCamera()
    views[rep], displays[rep] = view, disp

# Warm-up (first render: pipelines, redistribution, sort set-up); then interleaved frames.
for rep, view in views.items():
    for _ in range(spec.get("warmup", 1)):
        view.StillRender()
times = {rep: [] for rep in views}
for frame in range(spec["frames"]):
    for rep, view in views.items():
        view.GetActiveCamera().Azimuth(spec.get("azimuth_step", 3.0))
        start = time.perf_counter()
        view.StillRender()
        times[rep].append(time.perf_counter() - start)
result = {"cells": cells, "ranks": servermanager.vtkProcessModule.GetProcessModule()
          .GetNumberOfLocalPartitions(), "times": times}
if "Accurate Volume" in displays:
    disp = displays["Accurate Volume"]
    disp.UpdatePropertyInformation()
    result["image_time_rank0"] = disp.GetProperty("LastImageTime").GetData()
    result["piece_cells_rank0"] = disp.GetProperty("PieceCells").GetData()
    result["cell_types_rank0"] = disp.GetProperty("PieceCellTypes").GetData()
with open(spec["out"], "w") as f:
    json.dump(result, f, indent=1)
