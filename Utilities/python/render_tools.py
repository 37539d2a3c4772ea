"""Shared helpers of the comparison tools (highordervolume.compare, highordervolume.convergence)
and of the side-by-side demo (Utilities/hov_demo.py).

Reading a grid, the default transfer function fitted to the data range (or one from a JSON
file), a camera fitted to the data, preparing inputs for VTK's peers (tetrahedra for the
unstructured mappers, a resampled image for vtkGPUVolumeRayCastMapper), rendering a mapper
offscreen with timing, and image I/O. Images are numpy arrays (height, width, channels) with
row 0 at the bottom, as VTK stores them.
"""
import json
import os
import statistics
import time

import numpy as np
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (OpenGL factory overrides)
import vtkmodules.vtkRenderingVolumeOpenGL2  # noqa: F401
import vtkmodules.vtkRenderingFreeType  # noqa: F401  (text rendering for labels)
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.vtkCommonCore import VTK_STRING, vtkCommand
from vtkmodules.vtkCommonDataModel import vtkPiecewiseFunction
from vtkmodules.vtkFiltersCore import vtkImageAppend, vtkResampleToImage
from vtkmodules.vtkFiltersGeneral import vtkDataSetTriangleFilter, vtkTessellatorFilter
from vtkmodules.vtkImagingCore import vtkImageConstantPad
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkIOXML import vtkXMLImageDataWriter, vtkXMLUnstructuredGridReader
from vtkmodules.vtkRenderingCore import (vtkCamera, vtkColorTransferFunction, vtkRenderer,
                                         vtkTextActor, vtkVolume, vtkVolumeProperty,
                                         vtkWindowToImageFilter)

from .offscreen import offscreen_window

# Default transfer function (as Utilities/hov_demo.py): (fraction of the range, r, g, b, opacity).
# Low values faint blue, mid cyan/green, high yellow to red; colour and opacity nodes at the
# same scalars (VTK's linear ray integrator only honours opacity nodes that are colour nodes).
DEFAULT_NODES = [
    (0.00, 0.15, 0.25, 0.90, 0.02),
    (0.03, 0.20, 0.50, 1.00, 0.04),
    (0.09, 0.10, 0.90, 0.90, 0.10),
    (0.20, 0.30, 1.00, 0.30, 0.25),
    (0.35, 1.00, 1.00, 0.10, 0.50),
    (0.60, 1.00, 0.50, 0.00, 0.80),
    (1.00, 1.00, 0.05, 0.05, 1.00),
]
LINEAR_3D_TYPES = {10, 11, 12, 13, 14}  # tetra, voxel, hexahedron, wedge, pyramid


class ErrorCatcher:
    """Collects VTK ErrorEvents of the objects it observes."""

    def __init__(self):
        self.messages = []

    def watch(self, obj):
        # The call data (the message) is passed only if the callback declares its type.
        obj.AddObserver(vtkCommand.ErrorEvent, self.on_error)

    def on_error(self, obj, event, calldata=None):
        self.messages.append("%s: %s" % (obj.GetClassName(), calldata))

    on_error.CallDataType = VTK_STRING


def rss_mib():
    """Resident set size of this process in MiB (Linux /proc), 0 if unavailable."""
    try:
        with open("/proc/self/status") as f:
            for line in f:
                if line.startswith("VmRSS:"):
                    return float(line.split()[1]) / 1024.0
    except OSError:
        pass
    return 0.0


def read_grid(path, array_name):
    """The grid of a .vtu with `array_name` (a 1-component point array) as active scalars."""
    if not os.path.isfile(path):
        raise ValueError("no such file: %s" % path)
    reader = vtkXMLUnstructuredGridReader()
    reader.SetFileName(path)
    reader.Update()
    grid = reader.GetOutput()
    if grid.GetNumberOfCells() == 0:
        raise ValueError("no cells read from %s" % path)
    array = grid.GetPointData().GetArray(array_name)
    if array is None:
        names = [grid.GetPointData().GetArrayName(i)
                 for i in range(grid.GetPointData().GetNumberOfArrays())]
        raise ValueError("no point array '%s' in %s (point arrays: %s)"
                         % (array_name, path, ", ".join(names)))
    if array.GetNumberOfComponents() != 1:
        raise ValueError("point array '%s' has %d components; a scalar array is needed"
                         % (array_name, array.GetNumberOfComponents()))
    grid.GetPointData().SetActiveScalars(array_name)
    return grid


def make_property(smin, smax, tf_path=None, unit_distance=None, bounds=None):
    """vtkVolumeProperty from a JSON file or the default nodes fitted to [smin, smax].

    JSON: {"nodes": [[s, r, g, b, a], ...]} or {"color": [[s, r, g, b], ...], "opacity":
    [[s, a], ...]}, optional "relative": true (s are fractions of the data range) and
    "unit_distance" (scalar opacity unit distance, dataset units). Default unit distance:
    1/50 of the bounding-box diagonal."""
    spec = {"nodes": DEFAULT_NODES, "relative": True}
    if tf_path:
        with open(tf_path) as f:
            spec = json.load(f)
    rel = bool(spec.get("relative", False))

    def scalar(s):
        return smin + s * (smax - smin) if rel else s

    ctf = vtkColorTransferFunction()
    otf = vtkPiecewiseFunction()
    if "nodes" in spec:
        for s, r, g, b, a in spec["nodes"]:
            ctf.AddRGBPoint(scalar(s), r, g, b)
            otf.AddPoint(scalar(s), a)
    else:
        for s, r, g, b in spec["color"]:
            ctf.AddRGBPoint(scalar(s), r, g, b)
        for s, a in spec["opacity"]:
            otf.AddPoint(scalar(s), a)
    if ctf.GetSize() == 0 or otf.GetSize() == 0:
        raise ValueError("transfer function without colour or opacity nodes")
    if unit_distance is None:
        unit_distance = spec.get("unit_distance")
    if unit_distance is None:
        b = bounds or (0, 1, 0, 1, 0, 1)
        unit_distance = 0.02 * float(np.linalg.norm([b[1] - b[0], b[3] - b[2], b[5] - b[4]]))
    prop = vtkVolumeProperty()
    prop.SetColor(ctf)
    prop.SetScalarOpacity(otf)
    prop.SetScalarOpacityUnitDistance(unit_distance)
    prop.SetInterpolationTypeToLinear()
    prop.ShadeOff()
    return prop


def fit_camera(bounds, width, height, azimuth=30.0, elevation=20.0, zoom=1.0):
    """Perspective camera looking at the bounds (VTK's ResetCamera), then azimuth/elevation
    [degrees] about the focal point and zoom; fixed clipping range around the bounds. No window
    needed: the renderer's aspect is the image's (the camera is the same as in a window of that
    size, bit for bit)."""
    ren = vtkRenderer()
    ren.SetAspect(float(width) / height, 1.0)
    cam = ren.GetActiveCamera()
    cam.SetFocalPoint(0, 0, 0)
    cam.SetPosition(0, -1, 0)  # look along +y with z up: a natural start for FE models
    cam.SetViewUp(0, 0, 1)
    ren.ResetCamera(bounds)
    cam.Azimuth(azimuth)
    cam.Elevation(elevation)
    cam.OrthogonalizeViewUp()
    cam.Zoom(zoom)
    ren.ResetCameraClippingRange(bounds)
    out = vtkCamera()
    out.DeepCopy(cam)
    return out


def cell_types(grid):
    return sorted(int(t) for t in np.unique(vtk_to_numpy(grid.GetCellTypesArray())))


def tetrahedralize(grid, subdivisions=1):
    """Linear tetrahedra for VTK's unstructured peers: (tets, method, seconds).

    All tetrahedra: the grid itself. Linear cells: vtkDataSetTriangleFilter. Any non-linear
    cell: vtkTessellatorFilter (edge subdivision, `subdivisions` levels, merged points), which
    interpolates the point data with the cells' own shape functions."""
    types = set(cell_types(grid))
    t0 = time.perf_counter()
    if types == {10}:
        return grid, "input tetrahedra", 0.0
    if types <= LINEAR_3D_TYPES:
        flt = vtkDataSetTriangleFilter()
        flt.TetrahedraOnlyOn()
        name = "vtkDataSetTriangleFilter"
    else:
        flt = vtkTessellatorFilter()
        flt.SetOutputDimension(3)
        flt.SetMaximumNumberOfSubdivisions(subdivisions)
        flt.MergePointsOn()
        name = "vtkTessellatorFilter (%d subdivision%s)" % (subdivisions,
                                                            "" if subdivisions == 1 else "s")
    flt.SetInputData(grid)
    flt.Update()
    out = flt.GetOutput()
    out.GetPointData().SetActiveScalars(grid.GetPointData().GetScalars().GetName())
    return out, name, time.perf_counter() - t0


def resample_dims(bounds, resolution):
    """Sampling dimensions with `resolution` points along the longest side, cubic voxels."""
    ext = np.array([bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4]])
    longest = max(ext.max(), 1e-300)
    return [max(2, int(round(resolution * e / longest))) for e in ext]


def resample(grid, array_name, resolution, smin, smax):
    """vtkResampleToImage of the grid: (image, seconds). Points outside every cell get the
    scalar smin - 1e-3 (smax - smin), to which gpu_property() gives opacity 0."""
    t0 = time.perf_counter()
    flt = vtkResampleToImage()
    flt.SetInputDataObject(grid)
    flt.UseInputBoundsOn()
    flt.SetSamplingDimensions(*resample_dims(grid.GetBounds(), resolution))
    flt.Update()
    image = flt.GetOutput()
    pd = image.GetPointData()
    values = vtk_to_numpy(pd.GetArray(array_name)).astype(np.float32)
    valid = vtk_to_numpy(pd.GetArray(flt.GetMaskArrayName())) != 0
    values[~valid] = outside_value(smin, smax)
    out = type(image)()
    out.CopyStructure(image)
    arr = numpy_to_vtk(values, deep=True)
    arr.SetName(array_name)
    out.GetPointData().SetScalars(arr)
    return out, time.perf_counter() - t0


def outside_value(smin, smax):
    return smin - 1e-3 * max(smax - smin, 1e-30)


def gpu_property(prop, smin, smax):
    """A copy of prop whose opacity is 0 at the outside value of resample()."""
    out = vtkVolumeProperty()
    out.DeepCopy(prop)
    otf = vtkPiecewiseFunction()
    otf.DeepCopy(prop.GetScalarOpacity())
    otf.AddPoint(outside_value(smin, smax), 0.0)
    out.SetScalarOpacity(otf)
    return out


def warm_up_gl():
    """Render an empty offscreen window once, so that loading the OpenGL libraries and the
    first context does not count in the first method's time and memory. Raises OffscreenError if no window can be made."""
    win = offscreen_window(16, 16)
    win.AddRenderer(vtkRenderer())
    win.Render()
    win.Finalize()


def capture(window):
    """The window's colour buffer as (vtkImageData, float RGB in [0,1] of shape (h, w, 3))."""
    w2i = vtkWindowToImageFilter()
    w2i.SetInput(window)
    w2i.SetInputBufferTypeToRGB()
    w2i.ReadFrontBufferOff()
    w2i.ShouldRerenderOff()
    w2i.Update()
    img = w2i.GetOutput()
    w, h, _ = img.GetDimensions()
    rgb = vtk_to_numpy(img.GetPointData().GetScalars()).reshape(h, w, 3)
    return img, rgb.astype(np.float64) / 255.0


def float_rgba(mapper):
    """vtkHighOrderVolumeMapper's float image: premultiplied RGBA, shape (h, w, 4)."""
    img = mapper.GetFloatImage()
    w, h, _ = img.GetDimensions()
    return vtk_to_numpy(img.GetPointData().GetArray("RGBA")).reshape(h, w, 4)


def render_mapper(mapper, data, prop, camera, width, height, frames, catcher, label=None):
    """One warm-up render (timed as 'first_s': includes setup and sorting structures), then
    `frames` timed renders (median 'frame_s'); returns a dict with the 8-bit capture as float
    RGB ('screen_rgb'), the PNG-ready vtkImageData ('png') and, for mappers with a float
    image, 'float_rgba'. Window sizes are width x height, black background."""
    catcher.watch(mapper)
    mapper.SetInputData(data)
    volume = vtkVolume()
    volume.SetMapper(mapper)
    volume.SetProperty(prop)
    ren = vtkRenderer()
    ren.SetBackground(0.0, 0.0, 0.0)
    ren.AddVolume(volume)
    ren.SetActiveCamera(camera)
    if label:
        ren.AddActor2D(label_actor(label))
    win = offscreen_window(width, height)  # X if DISPLAY is set, Mesa EGL if not
    win.SetMultiSamples(0)
    win.AddRenderer(ren)
    catcher.watch(win)
    catcher.watch(ren)
    t0 = time.perf_counter()
    win.Render()
    win.WaitForCompletion()
    first = time.perf_counter() - t0
    times = []
    for _ in range(frames):
        t0 = time.perf_counter()
        win.Render()
        win.WaitForCompletion()  # glFinish: count asynchronous OpenGL work too
        times.append(time.perf_counter() - t0)
    png, rgb = capture(win)
    keep = type(png)()
    keep.DeepCopy(png)
    result = {"first_s": first, "times": times,
              "frame_s": statistics.median(times) if times else first,
              "png": keep, "screen_rgb": rgb}
    if hasattr(mapper, "GetFloatImage"):
        result["float_rgba"] = np.array(float_rgba(mapper), dtype=np.float32)
    win.Finalize()
    return result


def write_png(image, path):
    writer = vtkPNGWriter()
    writer.SetFileName(path)
    writer.SetInputData(image)
    writer.Write()


def write_vti(image, path):
    writer = vtkXMLImageDataWriter()
    writer.SetFileName(path)
    writer.SetInputData(image)
    writer.Write()


def label_actor(text):
    actor = vtkTextActor()
    actor.SetInput(text)
    tp = actor.GetTextProperty()
    tp.SetFontSize(16)
    tp.SetColor(1.0, 1.0, 1.0)
    tp.SetFontFamilyToArial()
    actor.SetDisplayPosition(8, 8)
    return actor


def montage(images, columns, size):
    """Grid of equally sized RGB vtkImageData, first image at the top left."""
    rows = []
    for r in range(0, len(images), columns):
        row = vtkImageAppend()
        row.SetAppendAxis(0)
        for img in images[r:r + columns]:
            row.AddInputData(img)
        row.Update()
        out = row.GetOutput()
        if out.GetDimensions()[0] < columns * size:  # pad a short last row
            pad = vtkImageConstantPad()
            pad.SetInputData(out)
            pad.SetOutputWholeExtent(0, columns * size - 1, 0, size - 1, 0, 0)
            pad.SetConstant(0)
            pad.Update()
            out = pad.GetOutput()
        rows.append(out)
    grid = vtkImageAppend()
    grid.SetAppendAxis(1)
    for out in reversed(rows):  # row 0 of an image is its bottom
        grid.AddInputData(out)
    grid.Update()
    return grid.GetOutput()


def error_stats(image, reference):
    """Per-channel |image - reference| over all pixels (float64 of the given arrays):
    dict max/mean/p99 -> list over channels."""
    diff = np.abs(np.asarray(image, dtype=np.float64) - np.asarray(reference, dtype=np.float64))
    flat = diff.reshape(-1, diff.shape[-1])
    return {"max": flat.max(axis=0).tolist(), "mean": flat.mean(axis=0).tolist(),
            "p99": np.percentile(flat, 99.0, axis=0).tolist()}
