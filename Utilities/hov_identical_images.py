#!/usr/bin/python3
"""Render the float image of every bundled dataset in every render mode of
vtkHighOrderVolumeMapper, with both opacity semantics and with and without the
features (isosurfaces, separate colour field, splatting, clipping; plus the
other orderings, integration methods and emission models), and write each as
raw float32 RGBA (premultiplied, row 0 at the bottom) for a bit-for-bit
comparison of two builds (Utilities/check_identical_images.sh).

    PYTHONPATH=<build>/lib/python3/dist-packages /usr/bin/python3 \
        Utilities/hov_identical_images.py --out DIR [--only REGEX] [--list]
    /usr/bin/python3 Utilities/hov_identical_images.py --compare DIR_A DIR_B

Only the mapper's public API (settings that exist in every build compared) is
used, so that the same cases run against the pre-change build. The window
cases (OPENGL_PROJECTION, and the CPU modes in a window, with an opaque box in
front of part of the volume) need a display or EGL (offscreen windows).

RAY_CAST cases set TerminationTransmittance to 1e-12, the value the ray caster
used before it honoured the setting, so that they compare bit for bit; the
case "*-raycast-default-termination" keeps the default 1e-9 (the one allowed
difference: --compare reports its differing pixels, not a failure).
"""
import argparse
import json
import math
import os
import re
import sys

DATA = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "Testing", "Data")

# name: (file, main array, colour array, isovalues as fractions of the range)
DATASETS = {
    "bracket": ("bracket_tet4_ccx.vtu", "von_mises", "displacement_magnitude"),
    "tjunction": ("tjunction_tet10_dolfinx.vtu", "speed", "velocity_potential"),
    "zoo": ("zoo_mixed_ccx.vtu", "temperature", "heat_flux_magnitude"),
    "plate": ("platehole_lagrange_hex_q4.vtu", "von_mises", "sigma_xx"),
    "lagrange_tjunction": ("tjunction_lagrange_tet_p4.vtu", "speed", "velocity_potential"),
}
# Cells each mode renders natively (other datasets give an empty image with a
# warning in that mode: still compared, cheap).
CPU_SIZE = (96, 80)
WINDOW_SIZE = (96, 80)
RAYCAST_SIZE = (40, 32)

# CPU_ACCURATE variants: (name, {setting: value}).
CPU_VARIANTS = [
    ("plain", {}),
    ("iso", {"iso": True}),
    ("fields", {"fields": True}),
    ("splat", {"splat": True}),
    ("clip", {"clip": True}),
    ("all", {"iso": True, "fields": True, "splat": True, "clip": True}),
    ("perpixel", {"perpixel": True}),
    ("perpixel-iso", {"perpixel": True, "iso": True}),
    ("approximate", {"approximate": True}),
    ("wvg", {"wvg": True}),
    ("parallel", {"parallel": True}),
    ("termination", {"termination": 1e-3}),
]
RAYCAST_VARIANTS = [
    ("plain", {}),
    ("clip", {"clip": True}),
    ("wvg", {"wvg": True}),
    ("parallel", {"parallel": True}),
]
PROJECTION_VARIANTS = [
    ("m3", {}),
    ("m0", {"method": 0}),
    ("m1", {"method": 1}),
    ("m2", {"method": 2}),
    ("m1-texture", {"method": 1, "texture": True}),
    ("approximate-order", {"approximate_order": True}),
    ("wvg", {"wvg": True}),
    ("parallel", {"parallel": True}),
]


def load(name):
    from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader
    path = os.path.join(DATA, DATASETS[name][0])
    reader = vtkXMLUnstructuredGridReader()
    reader.SetFileName(path)
    reader.Update()
    return reader.GetOutput()


def camera_for(grid, parallel, aspect):
    """A fixed, deterministic view of the grid's bounds (no window needed)."""
    from vtkmodules.vtkRenderingCore import vtkCamera
    b = grid.GetBounds()
    c = [0.5 * (b[0] + b[1]), 0.5 * (b[2] + b[3]), 0.5 * (b[4] + b[5])]
    r = 0.5 * math.sqrt((b[1] - b[0]) ** 2 + (b[3] - b[2]) ** 2 + (b[5] - b[4]) ** 2)
    direction = [0.55, -0.45, 0.70]
    n = math.sqrt(sum(d * d for d in direction))
    direction = [d / n for d in direction]
    camera = vtkCamera()
    camera.SetFocalPoint(*c)
    dist = r / math.sin(math.radians(15.0)) * 0.9
    camera.SetPosition(*[c[k] + dist * direction[k] for k in range(3)])
    camera.SetViewUp(0.0, 0.0, 1.0)
    camera.SetViewAngle(30.0)
    camera.SetClippingRange(max(dist - 2 * r, 1e-3 * dist), dist + 2 * r)
    if parallel:
        camera.ParallelProjectionOn()
        camera.SetParallelScale(0.8 * r)
    return camera, c, r


def volume_property(lo, hi, r, opts):
    from vtkmodules.vtkRenderingCore import vtkColorTransferFunction, vtkVolumeProperty
    from vtkmodules.vtkCommonDataModel import vtkPiecewiseFunction
    span = hi - lo
    color = vtkColorTransferFunction()
    color.AddRGBPoint(lo, 0.23, 0.30, 0.75)
    color.AddRGBPoint(lo + 0.45 * span, 0.87, 0.87, 0.87)
    color.AddRGBPoint(hi, 0.71, 0.02, 0.15)
    opacity = vtkPiecewiseFunction()
    opacity.AddPoint(lo, 0.02)
    opacity.AddPoint(lo + 0.3 * span, 0.35)
    opacity.AddPoint(lo + 0.6 * span, 0.1)
    opacity.AddPoint(hi, 0.8)
    prop = vtkVolumeProperty()
    prop.SetColor(color)
    prop.SetScalarOpacity(opacity)
    prop.SetScalarOpacityUnitDistance(r / 6.0)
    prop.SetInterpolationTypeToLinear()
    if opts.get("iso"):
        prop.ShadeOn()
        prop.SetAmbient(0.2)
        prop.SetDiffuse(0.7)
        prop.SetSpecular(0.3)
    return prop


def configure(mapper, grid, name, mode, semantics, opts, centre, r, camera):
    from vtkmodules.vtkCommonDataModel import vtkPlane
    _, array, color_array = DATASETS[name]
    mapper.SetInputData(grid)
    mapper.SetScalarModeToUsePointFieldData()
    mapper.SelectScalarArray(array)
    mapper.SetRenderMode(mode)
    mapper.SetOpacitySemantics(semantics)
    lo, hi = grid.GetPointData().GetArray(array).GetRange()
    if opts.get("iso"):
        mapper.AddIsosurface(lo + 0.35 * (hi - lo), 1.0, 0.85, 0.1, 0.5)
        mapper.AddIsosurface(lo + 0.7 * (hi - lo), 0.2, 0.9, 0.3, 0.7)
    if opts.get("fields"):
        mapper.SetColorArrayName(color_array)
    if opts.get("splat"):
        mapper.SplattingOn()
        mapper.SetSplatPixelThreshold(2.0)
    if opts.get("clip"):
        plane = vtkPlane()
        plane.SetOrigin(*centre)
        plane.SetNormal(0.3, 0.8, -0.2)
        mapper.AddClippingPlane(plane)
        mapper.SetViewDepthClipping(True)
        near, far = camera.GetClippingRange()
        d = camera.GetDistance()
        mapper.SetViewDepthRange(d - 0.8 * r, d + 0.5 * r)
    if opts.get("perpixel"):
        mapper.SetCellOrderingToPerPixelSort()
    if opts.get("approximate"):
        mapper.SetIntegrationMethodToApproximate()
    if opts.get("wvg"):
        mapper.SetEmissionModelToWilhelmsVanGelder()
        mapper.SetEmissionScale(0.7)
    if "termination" in opts:
        mapper.SetTerminationTransmittance(opts["termination"])
    if "method" in opts:
        mapper.SetProjectionColorMethod(opts["method"])
    if opts.get("texture"):
        mapper.SetProjectionOpacityLookupToTexture()
    if opts.get("approximate_order"):
        mapper.SetProjectionOrder(1)
    return lo, hi


def watch_messages(mapper):
    """The mapper's warnings and errors, as texts without file, line and address."""
    from vtkmodules.util.misc import calldata_type
    from vtkmodules.util.vtkConstants import VTK_STRING
    from vtkmodules.vtkCommonCore import vtkCommand
    messages = []

    def keep(kind):
        @calldata_type(VTK_STRING)
        def observer(obj, event, text):
            body = text.split("): ", 1)[-1].strip()
            messages.append(kind + ": " + body)
        return observer

    mapper.AddObserver(vtkCommand.WarningEvent, keep("warning"))
    mapper.AddObserver(vtkCommand.ErrorEvent, keep("error"))
    return messages


def cases():
    """(case name, dataset, mode, semantics, variant options, in a window)."""
    out = []
    for name in DATASETS:
        for sem_name, sem in (("gpu", 0), ("vtk", 1)):
            for var, opts in CPU_VARIANTS:
                out.append(("%s-%s-cpu-%s" % (name, sem_name, var), name, 0, sem, opts, False))
            out.append(("%s-%s-cpu-window" % (name, sem_name), name, 0, sem, {}, True))
            out.append(("%s-%s-cpu-window-iso" % (name, sem_name), name, 0, sem, {"iso": True}, True))
            for var, opts in PROJECTION_VARIANTS:
                out.append(("%s-%s-projection-%s" % (name, sem_name, var), name, 1, sem, opts, True))
            for var, opts in RAYCAST_VARIANTS:
                o = dict(opts)
                o["termination"] = 1e-12
                out.append(("%s-%s-raycast-%s" % (name, sem_name, var), name, 2, sem, o, False))
            out.append(("%s-%s-raycast-window" % (name, sem_name), name, 2, sem,
                        {"termination": 1e-12}, True))
        out.append(("%s-gpu-raycast-default-termination" % name, name, 2, 0, {}, False))
    return out


_GRIDS = {}


def render_case(case, out_dir):
    from vtkmodules.vtkRenderingCore import vtkVolume, vtkRenderer, vtkActor, vtkPolyDataMapper
    from vtkmodules.vtkFiltersSources import vtkCubeSource
    import highordervolume
    from highordervolume.offscreen import offscreen_window
    import vtkmodules.vtkRenderingOpenGL2  # noqa: F401 (the OpenGL factory overrides)
    import vtkmodules.vtkInteractionStyle  # noqa: F401
    from vtkmodules.util.numpy_support import vtk_to_numpy
    cname, name, mode, semantics, opts, window = case
    if name not in _GRIDS:
        _GRIDS[name] = load(name)
    grid = _GRIDS[name]
    size = RAYCAST_SIZE if mode == 2 else (WINDOW_SIZE if window else CPU_SIZE)
    camera, centre, r = camera_for(grid, opts.get("parallel", False), size[0] / size[1])
    mapper = highordervolume.vtkHighOrderVolumeMapper()
    messages = watch_messages(mapper)
    lo, hi = configure(mapper, grid, name, mode, semantics, opts, centre, r, camera)
    volume = vtkVolume()
    volume.SetMapper(mapper)
    volume.SetProperty(volume_property(lo, hi, r, opts))
    if window:
        ren = vtkRenderer()
        ren.SetBackground(0.1, 0.1, 0.15)
        ren.SetActiveCamera(camera)
        # An opaque box in front of part of the volume: the depth buffer clips rays.
        cube = vtkCubeSource()
        cube.SetCenter(centre[0], centre[1], centre[2] + 0.1 * r)
        cube.SetXLength(0.5 * r)
        cube.SetYLength(0.3 * r)
        cube.SetZLength(0.4 * r)
        cube_mapper = vtkPolyDataMapper()
        cube_mapper.SetInputConnection(cube.GetOutputPort())
        actor = vtkActor()
        actor.SetMapper(cube_mapper)
        ren.AddActor(actor)
        ren.AddVolume(volume)
        win = offscreen_window(size[0], size[1])
        win.SetMultiSamples(0)
        win.AddRenderer(ren)
        win.Render()
        status = 1
    else:
        status = mapper.RenderImage(camera, volume, size[0], size[1])
    image = mapper.GetFloatImage()
    rgba = vtk_to_numpy(image.GetPointData().GetScalars()).astype("<f4")
    rgba.tofile(os.path.join(out_dir, cname + ".raw"))
    meta = {"status": status, "size": list(size), "rendered": mapper.GetNumberOfRenderedCells(),
            "segments": mapper.GetNumberOfSegments(), "pieces": mapper.GetNumberOfPieces(),
            "rays": mapper.GetNumberOfRays(), "witness": mapper.GetWitnessViolations(),
            "splatted": mapper.GetNumberOfSplattedCells(),
            "triangles": mapper.GetNumberOfProjectedTriangles(),
            "messages": messages}
    if mode == 2:
        err = mapper.GetRayCastErrorImage().GetPointData().GetScalars()
        if err is not None and err.GetNumberOfTuples() > 0:
            vtk_to_numpy(err).astype("<f4").tofile(os.path.join(out_dir, cname + ".error.raw"))
    with open(os.path.join(out_dir, cname + ".json"), "w") as f:
        json.dump(meta, f, sort_keys=True)
    if window:
        win.Finalize()


def compare(a, b):
    import numpy
    allowed = re.compile(r"-raycast-default-termination\.")
    names = sorted(set(os.listdir(a)) | set(os.listdir(b)))
    bad = 0
    same = 0
    for n in names:
        pa, pb = os.path.join(a, n), os.path.join(b, n)
        if not (os.path.exists(pa) and os.path.exists(pb)):
            print("MISSING %s (only in %s)" % (n, a if os.path.exists(pa) else b))
            bad += 1
            continue
        with open(pa, "rb") as fa, open(pb, "rb") as fb:
            da, db = fa.read(), fb.read()
        if da == db:
            same += 1
            continue
        note = "allowed difference" if allowed.search(n) else "DIFFERS"
        if n.endswith(".raw") and len(da) == len(db):
            xa = numpy.frombuffer(da, "<f4")
            xb = numpy.frombuffer(db, "<f4")
            comps = 1 if n.endswith(".error.raw") else 4
            diff = numpy.abs(xa.astype(float) - xb.astype(float)).reshape(-1, comps)
            pixels = int(numpy.count_nonzero(diff.max(axis=1)))
            print("%s %s: %d of %d pixels differ, max %.3g" % (note, n, pixels, diff.shape[0],
                                                             diff.max()))
        else:
            print("%s %s" % (note, n))
        if not allowed.search(n):
            bad += 1
    print("%d files identical, %d differ (not allowed)" % (same, bad))
    return 0 if bad == 0 else 1


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--out")
    parser.add_argument("--only", default="")
    parser.add_argument("--list", action="store_true")
    parser.add_argument("--compare", nargs=2)
    args = parser.parse_args()
    if args.compare:
        return compare(*args.compare)
    selected = [c for c in cases() if re.search(args.only, c[0])]
    if args.list:
        for c in selected:
            print(c[0])
        return 0
    os.makedirs(args.out, exist_ok=True)
    for i, case in enumerate(selected):
        sys.stderr.write("[%d/%d] %s\n" % (i + 1, len(selected), case[0]))
        render_case(case, args.out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
