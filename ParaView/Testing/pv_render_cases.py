"""pvbatch side of the ParaView tests: render cases with "Accurate Volume".

    pvbatch pv_render_cases.py spec.json

spec.json: {"plugin": path, "out": folder, "size": [w, h], "cases": [case, ...]}
case: {"name", "data", "array", "association" ("POINTS"/"CELLS"), "color": [[x, r, g, b]],
       "opacity": [[x, a]], "unit_distance", "camera": {"position", "focal_point",
       "view_up", "view_angle"}, "properties": {representation property: value},
       "frames": number of renders (timing; default 1), "keep_transfer_functions": colour by
       the array with its colour map and opacity function as they are (no ColorBy, which
       rescales the map), as a script switching back to an array does, "interactive_lod":
       after the still frames, one interactive frame with the view's LOD threshold at 0 (the
       surface ParaView draws while a large dataset is rotated), saved as <name>_lod.png,
       "blocks": [x, y, z]: render a composite dataset instead (GroupDatasets, OutputType
       "group_type", default vtkMultiBlockDataSet), blocks "BlockA" (the data) and "BlockB"
       (the data moved by [x, y, z]); select with properties.BlockSelectors; "group_type":
       "ghosts" makes one unstructured grid of both with BlockB's cells marked as ghosts,
       "calculator": {"function", "type"}: render the data with the point array "array"
       computed by ParaView's Calculator (ResultArrayType "type", e.g. "Unsigned Char")}

For each case it writes <out>/<name>.png (the screenshot, 8-bit RGB over black),
<out>/<name>.vti (the mapper's float image of the last frame) and one entry of
<out>/results.json: the camera as rendered (with the clipping range ParaView chose),
the diagnostics (information properties) and the frame times. Lines
"=== case <name>" on stderr separate the cases' messages. Runs on rank 0 of an
MPI run (pvbatch's usual mode); the other ranks render their pieces.
"""
import json
import os
import sys
import time

from paraview import servermanager
from paraview.simple import (AppendDatasets, Calculator, ColorBy, GetColorTransferFunction,
                             GetOpacityTransferFunction, GroupDatasets, Hide, LoadPlugin,
                             ProgrammableFilter, Render, SaveScreenshot, Show, Transform,
                             XMLUnstructuredGridReader, CreateView, Delete)

INFO = ["WitnessViolations", "RenderedCells", "SkippedCells", "TransparentCells", "PieceCells",
        "PieceCellTypes",
        "LastImageTime", "LastFrameTime", "RayCastErrorEstimate", "RenderCalls"]


def info_value(disp, name):
    prop = disp.GetProperty(name)
    return prop.GetData() if prop is not None else None


def setup_transfer_functions(case):
    lut = GetColorTransferFunction(case["array"])
    lut.AutomaticRescaleRangeMode = "Never"
    if case.get("paraview_colormap"):
        # ParaView's default map as a user gets it: Cool to Warm, Diverging, 256 steps.
        lut.ApplyPreset("Cool to Warm", True)
        lut.Discretize = 1  # ParaView's defaults (an earlier case may have changed them)
        lut.NumberOfTableValues = 256
        lut.RescaleTransferFunction(case["color"][0][0], case["color"][-1][0])
    else:
        lut.ColorSpace = "RGB"
        lut.Discretize = 0  # the mapper keeps every node: no 256-step table
        lut.RGBPoints = [v for node in case["color"] for v in node]
    lut.ScalarRangeInitialized = 1
    pwf = GetOpacityTransferFunction(case["array"])
    pwf.Points = [v for x, a in case["opacity"] for v in (x, a, 0.5, 0.0)]
    pwf.ScalarRangeInitialized = 1
    return lut, pwf


GHOST_SCRIPT = """
from vtkmodules.util.numpy_support import numpy_to_vtk
import numpy as np
source = self.GetInputDataObject(0, 0)
grid = self.GetOutputDataObject(0)
grid.ShallowCopy(source)
n = source.GetNumberOfCells()
ghosts = numpy_to_vtk((np.arange(n) >= n // 2).astype(np.uint8), deep=1)
ghosts.SetName("vtkGhostType")  # 1: a duplicate cell, drawn by its owner
grid.GetCellData().AddArray(ghosts)
"""


def composite_source(readers, reader, case):
    """The case's composite source made of @p reader (see "blocks"), made once."""
    group_type = case.get("group_type", "vtkMultiBlockDataSet")
    key = (case["data"], tuple(case["blocks"]), group_type)
    if key not in readers:
        # Block names are the inputs' registration names.
        first = Transform(registrationName="BlockA_" + group_type, Input=reader)
        second = Transform(registrationName="BlockB_" + group_type, Input=reader)
        second.Transform.Translate = case["blocks"]
        if group_type == "ghosts":
            both = AppendDatasets(Input=[first, second])
            readers[key] = ProgrammableFilter(Input=both, Script=GHOST_SCRIPT)
        else:
            readers[key] = GroupDatasets(Input=[first, second], OutputType=group_type,
                                         BlockNames=["BlockA", "BlockB"])
    return readers[key]


def save_interactive_lod(view, out, case):
    """One interactive frame drawn with the LOD (threshold 0), saved as <name>_lod.png through
    ParaView's capture of interactive frames."""
    threshold = view.LODThreshold
    interactive = view.UseInteractiveRenderingForScreenshots
    path = os.path.join(out, case["name"] + "_lod.png")
    try:
        view.LODThreshold = 0.0
        view.UseInteractiveRenderingForScreenshots = 1
        SaveScreenshot(path, view, ImageResolution=list(view.ViewSize), TransparentBackground=0)
    finally:
        view.LODThreshold = threshold
        view.UseInteractiveRenderingForScreenshots = interactive
    return path


def render_case(case, view, readers, out, size):
    sys.stderr.write("=== case %s\n" % case["name"])
    sys.stderr.flush()
    data = case["data"]
    if data not in readers:
        readers[data] = XMLUnstructuredGridReader(FileName=[data])
    reader = readers[data]
    if case.get("blocks"):
        reader = composite_source(readers, reader, case)
    if case.get("calculator"):
        calc = case["calculator"]
        key = (data, case["array"], calc["function"], calc["type"])
        if key not in readers:
            readers[key] = Calculator(Input=reader, ResultArrayName=case["array"],
                                      Function=calc["function"], ResultArrayType=calc["type"])
        reader = readers[key]
    disp = Show(reader, view)
    disp.Representation = case.get("representation", "Accurate Volume")
    if case.get("association", "POINTS") == "NONE":
        disp.ColorArrayName = ["POINTS", ""]  # solid colour: no scalars for the volume
    else:
        association = case.get("association", "POINTS")
        if case.get("keep_transfer_functions"):
            # As a script switching back does: the array and its existing functions
            # (ColorBy would rescale the colour map to the data range, a change).
            disp.ColorArrayName = [association, case["array"]]
            disp.LookupTable = GetColorTransferFunction(case["array"])
            disp.ScalarOpacityFunction = GetOpacityTransferFunction(case["array"])
        else:
            ColorBy(disp, (association, case["array"]))
            setup_transfer_functions(case)
    disp.ScalarOpacityUnitDistance = case["unit_distance"]
    for name, value in case.get("properties", {}).items():
        setattr(disp, name, value)
    if disp.Representation == "Accurate Volume":
        disp.FloatImageFileName = os.path.join(out, case["name"] + ".vti")
    cam = case["camera"]
    view.CameraPosition = cam["position"]
    view.CameraFocalPoint = cam["focal_point"]
    view.CameraViewUp = cam["view_up"]
    view.CameraViewAngle = cam.get("view_angle", 30.0)
    view.CameraParallelProjection = 0
    times = []
    for _ in range(case.get("frames", 1)):
        start = time.perf_counter()
        Render(view)
        times.append(time.perf_counter() - start)
    png = os.path.join(out, case["name"] + ".png")
    SaveScreenshot(png, view, ImageResolution=size, TransparentBackground=0)
    lod_png = save_interactive_lod(view, out, case) if case.get("interactive_lod") else None
    camera = view.GetActiveCamera()
    result = {
        "name": case["name"],
        "png": png,
        "vti": os.path.join(out, case["name"] + ".vti"),
        "lod_png": lod_png,
        "frame_seconds": times,
        "camera": {
            "position": list(camera.GetPosition()),
            "focal_point": list(camera.GetFocalPoint()),
            "view_up": list(camera.GetViewUp()),
            "view_angle": camera.GetViewAngle(),
            "clipping_range": list(camera.GetClippingRange()),
        },
    }
    if case.get("paraview_colormap") or case.get("keep_transfer_functions"):
        lut = GetColorTransferFunction(case["array"])
        result["colormap"] = {"points": list(lut.RGBPoints), "space": str(lut.ColorSpace).strip("'\""),
                              "discretize": int(lut.Discretize),
                              "opacity": list(GetOpacityTransferFunction(case["array"]).Points),
                              "mtime": lut.GetClientSideObject().GetMTime()}
    if disp.Representation == "Accurate Volume":
        disp.UpdatePropertyInformation()
        result["info"] = {name: info_value(disp, name) for name in INFO}
        disp.FloatImageFileName = ""
    Hide(reader, view)
    return result


def main():
    with open(sys.argv[1]) as f:
        spec = json.load(f)
    out = spec["out"]
    os.makedirs(out, exist_ok=True)
    LoadPlugin(spec["plugin"], remote=False, ns=globals())
    size = spec.get("size", [256, 256])
    view = CreateView("RenderView")
    view.ViewSize = size
    view.OrientationAxesVisibility = 0
    view.UseFXAA = 0  # pvbatch enables FXAA; on several ranks it blurs edges after compositing
    view.UseColorPaletteForBackground = 0
    view.Background = [0.0, 0.0, 0.0]
    readers = {}
    results = [render_case(case, view, readers, out, size) for case in spec["cases"]]
    with open(os.path.join(out, "results.json"), "w") as f:
        json.dump({"ranks": servermanager.vtkProcessModule.GetProcessModule()
                   .GetNumberOfLocalPartitions(), "cases": results}, f, indent=1)
    Delete(view)


main()
