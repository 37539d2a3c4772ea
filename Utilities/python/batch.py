"""Batch renderer: ``/usr/bin/python3 -m highordervolume.batch spec.json``.

Renders an image specification file (JSON; the format is documented in
README.md, section "Batch rendering") with vtkHighOrderVolumeMapper and
writes the float premultiplied RGBA image (.vti, array "RGBA") and/or a PNG.
It is the twin of the C++ executable ``hovBatchRender`` (Utilities/Batch):
same fields, same messages ("<field>: <problem>"), same calls on the mapper
in the same order, so both give bit-identical float images.

Errors (malformed spec, missing data or array): every message on stderr,
exit code 2, nothing rendered. Unknown fields are errors (keys starting with
"_" are comments). From Python::

    from highordervolume import batch
    spec = batch.load_spec("spec.json")      # raises SpecError listing every problem
    image = batch.render(spec)               # vtkImageData, array "RGBA"
    batch.write_outputs(spec, image)
"""
import json
import math
import os
import sys

from vtkmodules.util.misc import calldata_type
from vtkmodules.util.vtkConstants import VTK_STRING
from vtkmodules.vtkCommonCore import vtkCommand
from vtkmodules.vtkCommonDataModel import vtkImageData, vtkPiecewiseFunction, vtkPlane
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkIOLegacy import vtkUnstructuredGridReader
from vtkmodules.vtkIOXML import vtkXMLImageDataWriter, vtkXMLUnstructuredGridReader
from vtkmodules.vtkRenderingCore import vtkColorTransferFunction, vtkRenderer, vtkVolume

from . import vtkHighOrderVolumeMapper
from .offscreen import offscreen_window

RENDER_MODES = ("cpu_accurate", "opengl_projection", "ray_cast")
OPACITY_SEMANTICS = ("gpu_compatible", "vtk_unstructured", "raw_extinction")
EMISSION_MODELS = ("williams_max", "wilhelms_van_gelder")
INTEGRATIONS = ("exact", "approximate")
CELL_ORDERINGS = ("visibility_sort", "per_pixel_sort")
TOP_FIELDS = ("data", "array", "image", "background", "camera", "projection",
              "transfer_function", "isosurfaces", "clipping", "render_mode",
              "ray_cast_tolerance", "integration", "cell_ordering", "output")
_MISSING = object()


class SpecError(ValueError):
    """A malformed specification; ``errors`` lists one "<field>: <problem>" each."""

    def __init__(self, errors):
        super().__init__("\n".join(errors))
        self.errors = list(errors)


def _type_name(v):
    if v is _MISSING or v is None:
        return "nothing (missing or null)"
    if isinstance(v, bool):
        return "a boolean"
    if isinstance(v, (int, float)):
        return "a number"
    if isinstance(v, str):
        return "a string"
    if isinstance(v, list):
        return "an array"
    return "an object"


def _is_number(v):
    return isinstance(v, (int, float)) and not isinstance(v, bool)


class _Checker:
    """Collects "<field>: <problem>" messages (the same as hovBatchSpec.cxx)."""

    def __init__(self):
        self.errors = []
        self.warnings = []

    def error(self, field, what):
        self.errors.append("%s: %s" % (field, what))

    def obj(self, v, field, allowed):
        if not isinstance(v, dict):
            self.error(field or "(top level)", "expected an object, got " + _type_name(v))
            return False
        for key in sorted(v):
            if not key.startswith("_") and key not in allowed:
                self.error(field + "." + key if field else key,
                           "unknown field (expected one of: %s)" % ", ".join(allowed))
        return True

    def number(self, v, field):
        if not _is_number(v):
            self.error(field, "expected a number, got " + _type_name(v))
            return None
        if not math.isfinite(v):  # NaN, Infinity, 1e999 (json reads them; C++ refuses them)
            self.error(field, "expected a finite number")
            return None
        return float(v)

    def positive(self, v, field):
        x = self.number(v, field)
        if x is not None and not x > 0.0:
            self.error(field, "expected a positive number")
            return None
        return x

    def integer(self, v, field, lo, hi):
        if not _is_number(v) or not math.isfinite(v) or float(v) != int(v):
            self.error(field, "expected an integer, got " + _type_name(v))
            return None
        if not lo <= int(v) <= hi:
            self.error(field, "expected an integer in [%d, %d], got %d" % (lo, hi, int(v)))
            return None
        return int(v)

    def string(self, v, field):
        if not isinstance(v, str):
            self.error(field, "expected a string, got " + _type_name(v))
            return None
        return v

    def numbers(self, v, field, n):
        if not isinstance(v, list):
            self.error(field, "expected %d numbers, got %s" % (n, _type_name(v)))
            return None
        if len(v) != n:
            self.error(field, "expected %d numbers, got %d" % (n, len(v)))
            return None
        out = []
        for i, x in enumerate(v):
            x = self.number(x, "%s[%d]" % (field, i))
            if x is None:
                return None
            out.append(x)
        return out

    def enum(self, v, field, names):
        s = self.string(v, field)
        if s is None:
            return None
        if s not in names:
            self.error(field, "unknown value '%s' (expected one of: %s)" % (s, ", ".join(names)))
            return None
        return names.index(s)

    def nodes(self, v, field, n):
        if not isinstance(v, list) or not v:
            self.error(field, "expected a non-empty array of [%s] nodes, got %s" % (
                "s, r, g, b" if n == 4 else "s, a",
                "an empty array" if isinstance(v, list) else _type_name(v)))
            return []
        out = []
        for i, node in enumerate(v):
            node = self.numbers(node, "%s[%d]" % (field, i), n)
            if node is not None:
                out.append(node)
        return out


def _resolve(base_dir, path):
    return path if not path or os.path.isabs(path) or not base_dir else os.path.join(base_dir, path)


def _parse_camera(c, cam, spec):
    if not c.obj(cam, "camera", ("position", "focal_point", "view_up", "view_angle", "azimuth",
                                 "elevation", "roll", "zoom")):
        return
    p, f = "position" in cam, "focal_point" in cam
    if p != f:
        c.error("camera.focal_point" if p else "camera.position",
                "required when camera.%s is given" % ("position" if p else "focal_point"))
    for key in ("position", "focal_point", "view_up"):
        if key in cam:
            spec["camera"][key] = c.numbers(cam[key], "camera." + key, 3)
    if not (p and f):
        spec["camera"].pop("position", None)
        spec["camera"].pop("focal_point", None)
    if "view_angle" in cam:
        a = c.positive(cam["view_angle"], "camera.view_angle")
        if a is not None and a >= 180.0:
            c.error("camera.view_angle", "expected degrees in (0, 180)")
        spec["camera"]["view_angle"] = a
    for key in ("azimuth", "elevation", "roll"):
        if key in cam:
            spec["camera"][key] = c.number(cam[key], "camera." + key)
    if "zoom" in cam:
        spec["camera"]["zoom"] = c.positive(cam["zoom"], "camera.zoom")


def _parse_transfer_function(c, tf, spec):
    if not c.obj(tf, "transfer_function", ("color", "opacity", "unit_distance", "opacity_semantics",
                                           "gpu_opacity_tolerance", "emission_model",
                                           "emission_scale")):
        return
    t = spec["transfer_function"]
    t["color"] = c.nodes(tf.get("color", _MISSING), "transfer_function.color", 4)
    t["opacity"] = c.nodes(tf.get("opacity", _MISSING), "transfer_function.opacity", 2)
    if "unit_distance" in tf:
        t["unit_distance"] = c.positive(tf["unit_distance"], "transfer_function.unit_distance")
    if "opacity_semantics" in tf:
        t["opacity_semantics"] = c.enum(tf["opacity_semantics"],
                                        "transfer_function.opacity_semantics", OPACITY_SEMANTICS)
    if "gpu_opacity_tolerance" in tf:
        t["gpu_opacity_tolerance"] = c.positive(tf["gpu_opacity_tolerance"],
                                                "transfer_function.gpu_opacity_tolerance")
    if "emission_model" in tf:
        t["emission_model"] = c.enum(tf["emission_model"], "transfer_function.emission_model",
                                     EMISSION_MODELS)
    if "emission_scale" in tf:
        t["emission_scale"] = c.number(tf["emission_scale"], "transfer_function.emission_scale")


def _parse_features(c, root, spec):
    if "isosurfaces" in root:
        iso = root["isosurfaces"]
        if not isinstance(iso, list):
            c.error("isosurfaces", "expected an array of objects, got " + _type_name(iso))
            iso = []
        for i, s in enumerate(iso):
            f = "isosurfaces[%d]" % i
            if c.obj(s, f, ("value", "color", "opacity")):
                value = c.number(s.get("value", _MISSING), f + ".value")
                color = c.numbers(s["color"], f + ".color", 3) if "color" in s else [1.0, 1.0, 1.0]
                opacity = c.number(s["opacity"], f + ".opacity") if "opacity" in s else 1.0
                spec["isosurfaces"].append((value, color, opacity))
    if "clipping" not in root or not c.obj(root["clipping"], "clipping",
                                           ("planes", "view_depth_range")):
        return
    clip = root["clipping"]
    planes = clip.get("planes", [])
    if not isinstance(planes, list):
        c.error("clipping.planes", "expected an array of objects, got " + _type_name(planes))
        planes = []
    for i, p in enumerate(planes):
        f = "clipping.planes[%d]" % i
        if c.obj(p, f, ("origin", "normal")):
            o = c.numbers(p.get("origin", _MISSING), f + ".origin", 3)
            n = c.numbers(p.get("normal", _MISSING), f + ".normal", 3) if o is not None else None
            if o is not None and n is not None:
                spec["clip_planes"].append((o, n))
    if "view_depth_range" in clip:
        r = c.numbers(clip["view_depth_range"], "clipping.view_depth_range", 2)
        if r is not None and not r[0] < r[1]:
            c.error("clipping.view_depth_range", "expected [near, far] with near < far")
        spec["view_depth_range"] = r


def _parse_io(c, root, base_dir, spec):
    data = c.string(root.get("data", _MISSING), "data")
    spec["data"] = _resolve(base_dir, data) if data is not None else None
    array = root.get("array", _MISSING)
    if isinstance(array, str):
        spec["array"]["name"] = array
    elif c.obj(array, "array", ("name", "component", "association")):
        spec["array"]["name"] = c.string(array.get("name", _MISSING), "array.name")
        if "component" in array:
            spec["array"]["component"] = c.integer(array["component"], "array.component", -1, 1 << 20)
        if "association" in array:
            spec["array"]["association"] = c.enum(array["association"], "array.association",
                                                  ("point", "cell"))
    out = root.get("output", _MISSING)
    if c.obj(out, "output", ("vti", "png")):
        for key in ("vti", "png"):
            if key in out:
                # relative to the current directory (data: to the spec's folder)
                spec["output"][key] = c.string(out[key], "output." + key)
        if "vti" not in out and "png" not in out:
            c.error("output", "expected at least one of vti, png")


def parse_spec(root, base_dir="."):
    """Check a decoded spec (dict); returns the normalised spec, raises SpecError."""
    c = _Checker()
    spec = {"array": {"name": None, "component": -1, "association": 0},
            "image": [512, 512], "background": [0.0, 0.0, 0.0], "camera": {},
            "projection": {"orthographic": False}, "transfer_function": {},
            "isosurfaces": [], "clip_planes": [], "view_depth_range": None,
            "render_mode": 0, "ray_cast_tolerance": 1e-3, "integration": 0, "cell_ordering": 0,
            "output": {}}
    if not c.obj(root, "", TOP_FIELDS):
        raise SpecError(c.errors)
    _parse_io(c, root, base_dir, spec)
    if "image" in root and c.obj(root["image"], "image", ("width", "height")):
        spec["image"] = [c.integer(root["image"].get("width", _MISSING), "image.width", 1, 16384),
                         c.integer(root["image"].get("height", _MISSING), "image.height", 1, 16384)]
    if "background" in root:
        spec["background"] = c.numbers(root["background"], "background", 3)
    if "camera" in root:
        _parse_camera(c, root["camera"], spec)
    proj = root.get("projection")
    if "projection" in root and c.obj(proj, "projection", ("type", "parallel_scale")):
        if "type" in proj:
            spec["projection"]["orthographic"] = c.enum(proj["type"], "projection.type",
                                                        ("perspective", "orthographic")) == 1
        if "parallel_scale" in proj:
            spec["projection"]["parallel_scale"] = c.positive(proj["parallel_scale"],
                                                              "projection.parallel_scale")
    _parse_transfer_function(c, root.get("transfer_function", _MISSING), spec)
    _parse_features(c, root, spec)
    for key, names in (("render_mode", RENDER_MODES), ("integration", INTEGRATIONS),
                       ("cell_ordering", CELL_ORDERINGS)):
        if key in root:
            spec[key] = c.enum(root[key], key, names)
    if "ray_cast_tolerance" in root:
        tol = c.positive(root["ray_cast_tolerance"], "ray_cast_tolerance")
        if tol is not None and not 1e-12 <= tol <= 0.1:
            c.error("ray_cast_tolerance", "expected a number in [1e-12, 0.1]")
        elif tol is not None:
            spec["ray_cast_tolerance"] = tol
    if spec["render_mode"] == 1 and (spec["isosurfaces"] or spec["clip_planes"]
                                     or spec["view_depth_range"]):
        c.error("render_mode",
                "opengl_projection does not support isosurfaces or clipping (use cpu_accurate)")
    if spec["render_mode"] == 2 and spec["isosurfaces"]:
        c.error("render_mode", "ray_cast does not support isosurfaces (use cpu_accurate)")
    if c.errors:
        raise SpecError(c.errors)
    return spec


def _reject_constant(token):
    # Python's json reads NaN and Infinity; they are not JSON (jsoncpp refuses them too).
    raise ValueError("%s is not a JSON number" % token)


def _finite_float(token):
    # A literal beyond the double range (1e999): refused as jsoncpp does, not read as infinity.
    value = float(token)
    if not math.isfinite(value):
        raise ValueError("'%s' is not a number" % token)
    return value


def load_spec(path):
    """Read and check a spec file; a relative data path is resolved against its folder."""
    try:
        with open(path, encoding="utf-8") as f:
            text = f.read()
    except OSError as e:
        raise SpecError(["(file): cannot read '%s' (%s)" % (path, e.strerror)])
    except UnicodeDecodeError as e:
        raise SpecError(["(file): not valid JSON: not UTF-8 text (%s)" % e])
    try:
        root = json.loads(text, parse_constant=_reject_constant, parse_float=_finite_float)
    except ValueError as e:
        raise SpecError(["(file): not valid JSON: %s" % e])
    except RecursionError:
        raise SpecError(["(file): not valid JSON: nested too deeply"])
    return parse_spec(root, os.path.dirname(path) or ".")


def read_data(spec):
    """The unstructured grid of spec["data"]; raises SpecError if unusable."""
    path = spec["data"]
    if not os.path.isfile(path):
        raise SpecError(["data: cannot read '%s'" % path])
    reader = vtkUnstructuredGridReader() if path.endswith(".vtk") else vtkXMLUnstructuredGridReader()
    reader.SetFileName(path)
    reader.Update()
    grid = reader.GetOutput()
    if grid is None or grid.GetNumberOfCells() == 0:
        raise SpecError(["data: no cells read from '%s'" % path])
    a = spec["array"]
    data = grid.GetCellData() if a["association"] == 1 else grid.GetPointData()
    array = data.GetArray(a["name"])
    if array is None:
        raise SpecError(["array.name: no %s array '%s' in '%s'" % (
            "cell" if a["association"] == 1 else "point", a["name"], path)])
    if a["component"] >= array.GetNumberOfComponents():
        raise SpecError(["array.component: %d but '%s' has %d components" % (
            a["component"], a["name"], array.GetNumberOfComponents())])
    return grid


def setup_property(spec, prop):
    t = spec["transfer_function"]
    color = vtkColorTransferFunction()
    for s, r, g, b in t["color"]:
        color.AddRGBPoint(s, r, g, b)
    opacity = vtkPiecewiseFunction()
    for s, a in t["opacity"]:
        opacity.AddPoint(s, a)
    prop.SetColor(color)
    prop.SetScalarOpacity(opacity)
    prop.SetScalarOpacityUnitDistance(t.get("unit_distance", 1.0))
    prop.SetInterpolationTypeToLinear()
    prop.IndependentComponentsOff()
    prop.ShadeOff()


def setup_mapper(spec, mapper):
    a, t = spec["array"], spec["transfer_function"]
    if a["association"] == 1:
        mapper.SetScalarModeToUseCellFieldData()
    else:
        mapper.SetScalarModeToUsePointFieldData()
    mapper.SelectScalarArray(a["name"])
    if a["component"] >= 0:
        mapper.SetVectorMode(vtkHighOrderVolumeMapper.COMPONENT)
        mapper.SetVectorComponent(a["component"])
    mapper.SetOpacitySemantics(t.get("opacity_semantics", 0))
    mapper.SetGPUOpacityTolerance(t.get("gpu_opacity_tolerance", 1e-4))
    mapper.SetEmissionModel(t.get("emission_model", 0))
    mapper.SetEmissionScale(t.get("emission_scale", 1.0))
    mapper.SetIntegrationMethod(spec["integration"])
    mapper.SetCellOrdering(spec["cell_ordering"])
    mapper.SetRenderMode(spec["render_mode"])
    mapper.SetRayCastTolerance(spec["ray_cast_tolerance"])
    for value, (r, g, b), opacity in spec["isosurfaces"]:
        mapper.AddIsosurface(value, r, g, b, opacity)
    for origin, normal in spec["clip_planes"]:
        plane = vtkPlane()
        plane.SetOrigin(origin)
        plane.SetNormal(normal)
        mapper.AddClippingPlane(plane)
    if spec["view_depth_range"]:
        mapper.SetViewDepthClipping(True)
        mapper.SetViewDepthRange(spec["view_depth_range"])


def setup_camera(spec, bounds, renderer):
    cam, camera = spec["camera"], renderer.GetActiveCamera()
    width, height = spec["image"]
    camera.SetParallelProjection(spec["projection"]["orthographic"])
    view_up = cam.get("view_up", [0.0, 1.0, 0.0])
    camera.SetViewUp(view_up)
    if "position" in cam:
        camera.SetFocalPoint(cam["focal_point"])
        camera.SetPosition(cam["position"])
        camera.SetViewUp(view_up)
    else:
        # Looking down -z; along +y if the view up is (nearly) the z axis.
        norm = math.sqrt(view_up[0] * view_up[0] + view_up[1] * view_up[1] +
                         view_up[2] * view_up[2])
        z_up = norm > 0.0 and abs(view_up[2]) > 0.999 * norm
        camera.SetFocalPoint(0.0, 0.0, 0.0)
        camera.SetPosition(0.0, -1.0 if z_up else 0.0, 0.0 if z_up else 1.0)
        renderer.SetAspect(float(width) / height, 1.0)
        renderer.ResetCamera(bounds)
    if "view_angle" in cam:
        camera.SetViewAngle(cam["view_angle"])
    if "azimuth" in cam:
        camera.Azimuth(cam["azimuth"])
    if "elevation" in cam:
        camera.Elevation(cam["elevation"])
        camera.OrthogonalizeViewUp()
    if "roll" in cam:
        camera.Roll(cam["roll"])
    if "zoom" in cam:
        camera.Zoom(cam["zoom"])
    if "parallel_scale" in spec["projection"]:
        camera.SetParallelScale(spec["projection"]["parallel_scale"])
    renderer.ResetCameraClippingRange(bounds)


def render(spec, grid=None, progress=None):
    """Render a checked spec; returns the float image (vtkImageData, array "RGBA").

    ``progress(mapper, fraction)`` is called on every progress event (it may
    call mapper.SetAbortExecute(1) to stop a CPU render early)."""
    grid = grid if grid is not None else read_data(spec)
    mapper = vtkHighOrderVolumeMapper()
    mapper.SetInputData(grid)
    errors = []

    @calldata_type(VTK_STRING)  # VTK passes the message text
    def on_error(obj, event, message):
        errors.append(message)
        sys.stderr.write("error: %s\n" % message)
    mapper.AddObserver(vtkCommand.ErrorEvent, on_error)
    setup_mapper(spec, mapper)
    if progress is not None:
        mapper.AddObserver(vtkCommand.ProgressEvent,
                           lambda obj, event: progress(obj, obj.GetProgress()))
    volume = vtkVolume()
    volume.SetMapper(mapper)
    setup_property(spec, volume.GetProperty())
    renderer = vtkRenderer()
    renderer.SetBackground(spec["background"])
    setup_camera(spec, grid.GetBounds(), renderer)
    width, height = spec["image"]
    if spec["render_mode"] != 1:  # the CPU modes
        if not mapper.RenderImage(renderer.GetActiveCamera(), volume, width, height):
            raise RuntimeError("render failed (see the messages above)")
    else:
        # X if DISPLAY is set, Mesa EGL if not; OffscreenError (a RuntimeError) if neither.
        window = offscreen_window(width, height)
        window.AddRenderer(renderer)
        renderer.AddVolume(volume)
        window.Render()
    if errors:
        raise RuntimeError("render failed (see the messages above)")
    image = vtkImageData()
    image.DeepCopy(mapper.GetFloatImage())
    return image


def write_png(path, image, background=(0.0, 0.0, 0.0)):
    """The float image over ``background`` as 8-bit RGB PNG (as hovBatchRender does)."""
    import numpy as np
    from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
    rgba = vtk_to_numpy(image.GetPointData().GetArray("RGBA")).astype(np.float64)
    bg = np.asarray(background, dtype=np.float64)
    rgb = rgba[:, :3] + (1.0 - rgba[:, 3:4]) * bg
    rgb = np.floor(255.0 * np.clip(rgb, 0.0, 1.0) + 0.5).astype(np.uint8)
    png = vtkImageData()
    png.SetDimensions(image.GetDimensions())
    png.GetPointData().SetScalars(numpy_to_vtk(rgb, deep=True))
    writer = vtkPNGWriter()
    writer.SetFileName(path)
    writer.SetInputData(png)
    _remove_old(path)
    writer.Write()
    if writer.GetErrorCode() or not _written(path):
        raise OSError("output.png: cannot write '%s'" % path)


def write_vti(path, image):
    writer = vtkXMLImageDataWriter()
    writer.SetFileName(path)
    writer.SetInputData(image)
    _remove_old(path)
    if not writer.Write() or writer.GetErrorCode() or not _written(path):
        raise OSError("output.vti: cannot write '%s'" % path)


def _remove_old(path):
    """An old output file must not pass for the new one."""
    try:
        os.remove(path)
    except OSError:
        pass


def _written(path):
    """True if ``path`` exists and is not empty (vtkXMLWriter.Write() returns 1
    for a missing folder; the failure is only in its messages)."""
    try:
        return os.path.getsize(path) > 0
    except OSError:
        return False


def write_outputs(spec, image):
    if spec["output"].get("vti"):
        write_vti(spec["output"]["vti"], image)
    if spec["output"].get("png"):
        write_png(spec["output"]["png"], image, spec["background"])


def main(argv=None):
    argv = sys.argv[1:] if argv is None else argv
    if len(argv) != 1:
        sys.stderr.write("usage: python3 -m highordervolume.batch spec.json\n")
        return 2
    try:
        spec = load_spec(argv[0])
        grid = read_data(spec)
    except SpecError as e:
        for msg in e.errors:
            sys.stderr.write("%s: error: %s\n" % (argv[0], msg))
        return 2

    def report(mapper, fraction):
        sys.stderr.write("\rprogress %d%%%s" % (int(100.0 * fraction + 0.5),
                                                "\n" if fraction >= 1.0 else ""))
        sys.stderr.flush()
    try:
        image = render(spec, grid, report)
        write_outputs(spec, image)
    except (RuntimeError, OSError) as e:
        sys.stderr.write("%s\n" % e)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
