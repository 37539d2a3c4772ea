"""Shared helpers of the ParaView plugin tests (run with Debian's /usr/bin/python3 and the
VTK 9.1 build's package on PYTHONPATH; ParaView itself only ever runs in pvbatch
subprocesses, so the two VTKs never share a process).

Every test takes: --plugin <HighOrderVolume.so> --pvpython <extracted python3-paraview
dist-packages> --data <Testing/Data> --temp <output folder> [--pvbatch pvbatch].
"""
import argparse
import json
import math
import os
import shutil
import subprocess
import sys
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
PV_RENDER = os.path.join(HERE, "pv_render_cases.py")

# Datasets, arrays, views and transfer functions of the tests. Transfer-function nodes are
# (fraction of the array range, r, g, b) and (fraction, opacity); the unit distance is a
# fraction of the bounding-box diagonal.
DATASETS = {
    "bracket": {"file": "bracket_tet4_ccx.vtu", "array": "von_mises", "range": (0.0954205, 166.063),
                "direction": (0.55, -0.62, 0.56), "view_up": (0, 0, 1), "unit": 0.03,
                "cells": 56071, "types": 1},
    "zoo": {"file": "zoo_mixed_ccx.vtu", "array": "temperature", "range": (15.0, 120.0),
            "direction": (0.6, -0.7, 0.45), "view_up": (0, 0, 1), "unit": 0.06,
            "cells": 68714, "types": 4},
    "plate": {"file": "platehole_lagrange_hex_q4.vtu", "array": "von_mises",
              "range": (1.81153, 360.913), "direction": (0.35, -0.55, 0.76),
              "view_up": (0, 0, 1), "unit": 0.05, "cells": 192, "types": 1},
    "tjunction_p4": {"file": "tjunction_lagrange_tet_p4.vtu", "array": "speed",
                     "range": (0.0461095, 2.62627), "direction": (0.35, 0.45, 0.82),
                     "view_up": (0, 1, 0), "unit": 0.04, "cells": 3790, "types": 1},
}
BOUNDS = {"bracket": (0, 100, 0, 60, 0, 80), "zoo": (0, 4, 0, 2, 0, 1.8),
          "plate": (0, 1, 0, 1, 0, 0.1), "tjunction_p4": (-2, 2, -0.5, 1.8, -0.5, 0.5)}
COLOR_NODES = [(0.0, 0.05, 0.10, 0.90), (0.25, 0.10, 0.70, 0.90), (0.5, 0.20, 0.90, 0.30),
               (0.75, 1.00, 0.85, 0.10), (1.0, 0.95, 0.15, 0.10)]
OPACITY_NODES = [(0.0, 0.02), (0.25, 0.08), (0.5, 0.25), (0.62, 0.05), (0.75, 0.5), (1.0, 0.85)]
MODES = {"cpu": 0, "projection": 1, "raycast": 2}
MODE_NAMES = {0: "CPU accurate", 1: "OpenGL projection", 2: "Ray cast"}


def parse_args(extra=None):
    parser = argparse.ArgumentParser()
    parser.add_argument("--plugin", required=True)
    parser.add_argument("--pvpython", required=True, help="extracted python3-paraview dist-packages")
    parser.add_argument("--data", required=True)
    parser.add_argument("--temp", required=True)
    parser.add_argument("--pvbatch", default="pvbatch")
    parser.add_argument("--mpiexec", default="mpiexec")
    if extra:
        extra(parser)
    return parser.parse_args()


def camera_for(name, zoom=1.0):
    ds = DATASETS[name]
    b = BOUNDS[name]
    centre = [0.5 * (b[2 * k] + b[2 * k + 1]) for k in range(3)]
    diag = math.sqrt(sum((b[2 * k + 1] - b[2 * k]) ** 2 for k in range(3)))
    d = np.array(ds["direction"], dtype=float)
    d /= np.linalg.norm(d)
    distance = 0.5 * diag / math.sin(math.radians(15.0)) / zoom
    return {"position": [centre[k] + distance * d[k] for k in range(3)],
            "focal_point": centre, "view_up": list(ds["view_up"]), "view_angle": 30.0}


def make_case(args, name, mode, tag=None, **extra):
    ds = DATASETS[name]
    lo, hi = ds["range"]
    b = BOUNDS[name]
    diag = math.sqrt(sum((b[2 * k + 1] - b[2 * k]) ** 2 for k in range(3)))
    properties = {"RenderMode": MODE_NAMES[mode]}
    properties.update(extra.pop("properties", {}))
    case = {"name": tag or "%s_%s" % (name, [k for k, v in MODES.items() if v == mode][0]),
            "dataset": name, "data": os.path.join(args.data, ds["file"]), "array": ds["array"],
            "association": "POINTS",
            "color": [[lo + f * (hi - lo), r, g, bl] for f, r, g, bl in COLOR_NODES],
            "opacity": [[lo + f * (hi - lo), a] for f, a in OPACITY_NODES],
            "unit_distance": ds["unit"] * diag, "camera": camera_for(name),
            "properties": properties, "mode": mode}
    case.update(extra)
    return case


def pv_env(args, threads=None):
    env = dict(os.environ)
    env["PYTHONPATH"] = args.pvpython
    if threads:
        env["VTK_SMP_MAX_THREADS"] = str(threads)
    return env


def run_pvbatch(args, cases, out, size, ranks=1, timeout=600, threads=None, oversubscribe=False):
    """Renders @p cases in one pvbatch run (@p ranks MPI ranks) into @p out, emptied first
    (so no earlier run's results or layers can pass for this one's); returns (results, stderr)."""
    shutil.rmtree(out, ignore_errors=True)
    os.makedirs(out)
    spec = {"plugin": args.plugin, "out": out, "size": list(size), "cases": cases}
    spec_path = os.path.join(out, "spec.json")
    with open(spec_path, "w") as f:
        json.dump(spec, f, indent=1)
    command = [args.pvbatch, PV_RENDER, spec_path]
    if ranks > 1:
        mpi = [args.mpiexec, "-np", str(ranks)]
        if os.geteuid() == 0:
            mpi.append("--allow-run-as-root")
        if oversubscribe:
            mpi.append("--oversubscribe")
        for var in ("PYTHONPATH", "DISPLAY", "VTK_SMP_MAX_THREADS", "XAUTHORITY"):
            mpi += ["-x", var]
        command = mpi + command
    start = time.perf_counter()
    proc = subprocess.run(command, env=pv_env(args, threads), capture_output=True, text=True,
                          timeout=timeout)
    seconds = time.perf_counter() - start
    stderr = proc.stderr + proc.stdout
    if proc.returncode != 0 or not os.path.exists(os.path.join(out, "results.json")):
        sys.stderr.write(stderr)
        raise RuntimeError("pvbatch failed (exit %d) after %.1f s: %s" % (
            proc.returncode, seconds, " ".join(command)))
    with open(os.path.join(out, "results.json")) as f:
        results = json.load(f)
    results["seconds"] = seconds
    return results, stderr


def has_errors(output):
    """Whether pvbatch's output reports an error: VTK's "ERROR:" text, ParaView's logger
    ("ERR|": with logging compiled in, vtkOutputWindow prints errors only that way) or a
    Python traceback."""
    return "ERROR" in output or "ERR|" in output or "Traceback" in output


def messages_by_case(stderr):
    """The pvbatch output split at the "=== case <name>" markers."""
    parts, current = {}, None
    for line in stderr.splitlines():
        if line.startswith("=== case "):
            current = line[len("=== case "):].strip()
            parts[current] = []
        elif current is not None:
            parts[current].append(line)
    return {k: "\n".join(v) for k, v in parts.items()}


def read_png_rgb(path):
    """8-bit RGB of a PNG as float in [0, 255], row 0 at the bottom (VTK's order)."""
    from vtkmodules.vtkIOImage import vtkPNGReader
    from vtkmodules.util.numpy_support import vtk_to_numpy
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    img = reader.GetOutput()
    w, h, _ = img.GetDimensions()
    a = vtk_to_numpy(img.GetPointData().GetScalars()).reshape(h, w, -1)
    return a[..., :3].astype(np.float64)


def read_vti_rgba(path):
    from vtkmodules.vtkIOXML import vtkXMLImageDataReader
    from vtkmodules.util.numpy_support import vtk_to_numpy
    reader = vtkXMLImageDataReader()
    reader.SetFileName(path)
    reader.Update()
    img = reader.GetOutput()
    w, h, _ = img.GetDimensions()
    return vtk_to_numpy(img.GetPointData().GetArray("RGBA")).reshape(h, w, 4).astype(np.float64)


class MessageCatcher:
    """Collects VTK 9.1's output window text (warnings and errors of the standalone mapper)."""

    def __init__(self):
        from vtkmodules.vtkCommonCore import vtkOutputWindow, vtkStringOutputWindow
        self.window = vtkStringOutputWindow()
        vtkOutputWindow.SetInstance(self.window)
        self.seen = 0

    def take(self):
        text = self.window.GetOutput() or ""
        new, self.seen = text[self.seen:], len(text)
        return new


def standalone_render(case, camera, size, catcher=None):
    """The VTK 9.1 module's float image of @p case through a render window (all three modes
    draw there), with ParaView's camera including its clipping range. Returns (rgba, mapper
    diagnostics, messages)."""
    import vtkmodules.vtkRenderingOpenGL2  # noqa: F401 (OpenGL render window)
    from vtkmodules.vtkCommonDataModel import vtkPiecewiseFunction
    from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader
    from vtkmodules.vtkRenderingCore import (vtkColorTransferFunction, vtkRenderWindow,
                                             vtkRenderer, vtkVolume, vtkVolumeProperty)
    from vtkmodules.util.numpy_support import vtk_to_numpy
    from highordervolume import vtkHighOrderVolumeMapper
    reader = vtkXMLUnstructuredGridReader()
    reader.SetFileName(case["data"])
    reader.Update()
    ctf = vtkColorTransferFunction()
    colormap = case.get("colormap")
    if colormap:
        # ParaView's map as the plugin reported it, continuous (its steps are not applied).
        getattr(ctf, "SetColorSpaceTo" + colormap["space"])()
        points = colormap["points"]
        for i in range(0, len(points), 4):
            ctf.AddRGBPoint(*points[i:i + 4])
    else:
        for x, r, g, b in case["color"]:
            ctf.AddRGBPoint(x, r, g, b)
    pwf = vtkPiecewiseFunction()
    for x, a in case["opacity"]:
        pwf.AddPoint(x, a)
    prop = vtkVolumeProperty()
    prop.SetColor(ctf)
    prop.SetScalarOpacity(pwf)
    prop.SetScalarOpacityUnitDistance(case["unit_distance"])
    prop.SetInterpolationTypeToLinear()
    prop.SetIndependentComponents(False)
    mapper = vtkHighOrderVolumeMapper()
    mapper.SetInputConnection(reader.GetOutputPort())
    if case.get("association", "POINTS") == "CELLS":
        mapper.SetScalarModeToUseCellFieldData()
    else:
        mapper.SetScalarModeToUsePointFieldData()
    mapper.SelectScalarArray(case["array"])
    mapper.SetRenderMode(case["mode"])
    if colormap:
        mapper.GetTransferFunction().SetSamplingTolerance(1e-4)  # the plugin's default
    setters = {"OpacitySemantics": lambda v: mapper.SetOpacitySemantics(
        ["GPU compatible", "VTK unstructured", "Raw extinction"].index(v)),
        "RayCastTolerance": mapper.SetRayCastTolerance,
        "AccurateBlendMode": lambda v: mapper.SetBlendMode(
            ["Composite", "Maximum intensity", "Minimum intensity", "Average intensity"].index(v)),
        "CellOrdering": lambda v: mapper.SetCellOrdering(
            ["Visibility sort", "Per-pixel sort"].index(v)),
        "SkipTransparentCells": lambda v: mapper.SetSkipTransparentCells(bool(v))}
    for name, value in case["properties"].items():
        if name in setters:
            setters[name](value)
    volume = vtkVolume()
    volume.SetMapper(mapper)
    volume.SetProperty(prop)
    ren = vtkRenderer()
    ren.SetBackground(0, 0, 0)
    ren.AddVolume(volume)
    cam = ren.GetActiveCamera()
    cam.SetPosition(*camera["position"])
    cam.SetFocalPoint(*camera["focal_point"])
    cam.SetViewUp(*camera["view_up"])
    cam.SetViewAngle(camera["view_angle"])
    cam.SetClippingRange(*camera["clipping_range"])
    win = vtkRenderWindow()
    win.SetOffScreenRendering(1)
    win.SetSize(*size)
    win.AddRenderer(ren)
    win.Render()
    img = mapper.GetFloatImage()
    w, h, _ = img.GetDimensions()
    rgba = vtk_to_numpy(img.GetPointData().GetArray("RGBA")).reshape(h, w, 4).astype(np.float64)
    info = {"RenderedCells": mapper.GetNumberOfRenderedCells(),
            "SkippedCells": mapper.GetNumberOfSkippedCells(),
            "TransparentCells": mapper.GetNumberOfTransparentCells(),
            "WitnessViolations": mapper.GetWitnessViolations(),
            "LastImageTime": mapper.GetLastImageTime()}
    messages = catcher.take() if catcher else ""
    win.Finalize()
    return rgba, info, messages


def to_8bit(rgba):
    """Premultiplied float RGBA over black, as an 8-bit screenshot stores it, in [0, 255]."""
    return np.floor(np.clip(rgba[..., :3], 0.0, 1.0) * 255.0 + 0.5)


def warning_lines(text):
    """The mapper's message texts (without VTK's file/line prefixes), for comparison."""
    lines = []
    for line in text.splitlines():
        for key in ("cells are of types", "Cannot render", "No numeric scalars", "Skipped cells",
                    "empty piece", "not yet supported", "ignores"):
            if key in line:
                lines.append(line[line.find(":", line.find(")")) + 1:].strip()
                             if ")" in line else line.strip())
                break
    return lines


def check(failures, ok, message):
    print(("ok   " if ok else "FAIL ") + message)
    if not ok:
        failures.append(message)


def finish(failures):
    if failures:
        print("\n%d failure(s):\n  %s" % (len(failures), "\n  ".join(failures)))
        sys.exit(1)
    print("all checks passed")
