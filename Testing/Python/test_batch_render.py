"""Batch renderer: a spec reproduces the float image of the API, bit for bit.

For two specs of the bundled bracket (56071 linear tetrahedra) covering every
field (default fit with azimuth/elevation/roll/zoom/view angle, perspective;
explicit position/focal point/view up, orthographic with a parallel scale,
per-pixel ordering, VTK-unstructured opacity, Wilhelms-Van Gelder emission,
a component of a 3-component array, an isosurface, a clipping plane and a
view-depth slab), and a third of the curved order-4 Lagrange plate in the
RAY_CAST mode (tolerance 1e-4, a clipping plane), the float image is rendered
three ways:
  1. directly with the wrapped C++ API (vtkHighOrderVolumeMapper, code written
     here, independent of highordervolume.batch),
  2. ``/usr/bin/python3 -m highordervolume.batch spec.json`` (.vti output),
  3. the C++ executable ``hovBatchRender spec.json`` (.vti output),
and the RGBA arrays must be exactly equal (and not empty). The PNG outputs
must exist and match the float image composited over the background to
within one 8-bit step. In opengl_projection mode, transfer_function.
gpu_opacity_tolerance reaches the projection in both entry points.
"""
import json
import os
import subprocess
import sys

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonDataModel import vtkPiecewiseFunction, vtkPlane
from vtkmodules.vtkIOImage import vtkPNGReader
from vtkmodules.vtkIOXML import vtkXMLImageDataReader, vtkXMLUnstructuredGridReader
from vtkmodules.vtkRenderingCore import vtkColorTransferFunction, vtkRenderer, vtkVolume

import highordervolume
from highordervolume import vtkHighOrderVolumeMapper

from hov_pytest import arguments, check, finish


def batch_exe(temp):
    exe = os.environ.get("HOV_BATCH_RENDER")
    if exe:
        return exe
    return os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(temp))), "bin",
                        "hovBatchRender")


SPECS = {
    "fit": {
        "_comment": "default fit, then relative camera moves",
        "array": "von_mises",
        "image": {"width": 96, "height": 72},
        "camera": {"azimuth": 30, "elevation": 20, "roll": 5, "zoom": 1.3, "view_angle": 28,
                   "view_up": [0, 0, 1]},
        "transfer_function": {"color": [[0, 0.1, 0.2, 0.9], [60, 0.2, 0.9, 0.3], [170, 1, 0.2, 0.1]],
                              "opacity": [[0, 0.02], [40, 0.3], [170, 0.9]], "unit_distance": 4},
        "render_mode": "cpu_accurate",
    },
    "explicit": {
        "array": {"name": "displacement", "component": 2, "association": "point"},
        "image": {"width": 80, "height": 96},
        "background": [0.2, 0.3, 0.4],
        "camera": {"position": [210, 150, 240], "focal_point": [50, 30, 40], "view_up": [0, 0, 1]},
        "projection": {"type": "orthographic", "parallel_scale": 70},
        "transfer_function": {"color": [[-0.05, 0, 0, 1], [0, 1, 1, 1], [0.23, 1, 0, 0]],
                              "opacity": [[-0.05, 0.5], [0.23, 0.05]], "unit_distance": 3,
                              "opacity_semantics": "vtk_unstructured",
                              "emission_model": "wilhelms_van_gelder", "emission_scale": 0.7},
        "isosurfaces": [{"value": 0.1, "color": [1, 1, 0], "opacity": 0.4}],
        "clipping": {"planes": [{"origin": [50, 30, 40], "normal": [1, 0.2, 0]}],
                     "view_depth_range": [150, 320]},
        "cell_ordering": "per_pixel_sort",
        "integration": "exact",
    },
    "ray_cast": {
        "_comment": "curved order-4 Lagrange hexahedra in the RAY_CAST mode",
        "_data": "platehole_lagrange_hex_q4.vtu",
        "array": "von_mises",
        "image": {"width": 64, "height": 48},
        "camera": {"azimuth": 25, "elevation": 35, "zoom": 1.2, "view_up": [0, 0, 1]},
        "transfer_function": {"color": [[0, 0.1, 0.2, 0.9], [120, 0.2, 0.9, 0.3], [361, 1, 0.2, 0.1]],
                              "opacity": [[0, 0.05], [150, 0.4], [361, 0.9]], "unit_distance": 0.05},
        "clipping": {"planes": [{"origin": [0.5, 0.5, 0.05], "normal": [1, -0.3, 0]}]},
        "render_mode": "ray_cast",
        "ray_cast_tolerance": 1e-4,
    },
}


def api_image(spec, data):
    """The float image with the same settings, written directly against the API."""
    reader = vtkXMLUnstructuredGridReader()
    reader.SetFileName(data)
    reader.Update()
    grid = reader.GetOutput()
    mapper = vtkHighOrderVolumeMapper()
    mapper.SetInputData(grid)
    mapper.SetScalarModeToUsePointFieldData()
    array = spec["array"] if isinstance(spec["array"], dict) else {"name": spec["array"]}
    mapper.SelectScalarArray(array["name"])
    if array.get("component", -1) >= 0:
        mapper.SetVectorMode(vtkHighOrderVolumeMapper.COMPONENT)
        mapper.SetVectorComponent(array["component"])
    tf = spec["transfer_function"]
    semantics = ["gpu_compatible", "vtk_unstructured", "raw_extinction"]
    mapper.SetOpacitySemantics(semantics.index(tf.get("opacity_semantics", "gpu_compatible")))
    mapper.SetEmissionModel(["williams_max", "wilhelms_van_gelder"].index(
        tf.get("emission_model", "williams_max")))
    mapper.SetEmissionScale(tf.get("emission_scale", 1.0))
    if spec.get("cell_ordering") == "per_pixel_sort":
        mapper.SetCellOrderingToPerPixelSort()
    if spec.get("render_mode") == "ray_cast":
        mapper.SetRenderModeToRayCast()
        mapper.SetRayCastTolerance(spec.get("ray_cast_tolerance", 1e-3))
    for iso in spec.get("isosurfaces", []):
        mapper.AddIsosurface(iso["value"], *iso["color"], iso["opacity"])
    clip = spec.get("clipping", {})
    for p in clip.get("planes", []):
        plane = vtkPlane()
        plane.SetOrigin(p["origin"])
        plane.SetNormal(p["normal"])
        mapper.AddClippingPlane(plane)
    if "view_depth_range" in clip:
        mapper.ViewDepthClippingOn()
        mapper.SetViewDepthRange(clip["view_depth_range"])
    color, opacity = vtkColorTransferFunction(), vtkPiecewiseFunction()
    for s, r, g, b in tf["color"]:
        color.AddRGBPoint(s, r, g, b)
    for s, a in tf["opacity"]:
        opacity.AddPoint(s, a)
    volume = vtkVolume()
    volume.SetMapper(mapper)
    prop = volume.GetProperty()
    prop.SetColor(color)
    prop.SetScalarOpacity(opacity)
    prop.SetScalarOpacityUnitDistance(tf["unit_distance"])
    prop.SetInterpolationTypeToLinear()
    prop.IndependentComponentsOff()
    width, height = spec["image"]["width"], spec["image"]["height"]
    renderer = vtkRenderer()
    camera = renderer.GetActiveCamera()
    cam = spec["camera"]
    bounds = grid.GetBounds()
    if spec.get("projection", {}).get("type") == "orthographic":
        camera.ParallelProjectionOn()
    camera.SetViewUp(cam.get("view_up", [0, 1, 0]))
    if "position" in cam:
        camera.SetFocalPoint(cam["focal_point"])
        camera.SetPosition(cam["position"])
        camera.SetViewUp(cam.get("view_up", [0, 1, 0]))
    else:
        up = cam.get("view_up", [0, 1, 0])
        if abs(up[2]) > 0.999 * (up[0] ** 2 + up[1] ** 2 + up[2] ** 2) ** 0.5:
            camera.SetPosition(0, -1, 0)  # z up: the fit looks along +y
        renderer.SetAspect(width / height, 1.0)
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
    if "parallel_scale" in spec.get("projection", {}):
        camera.SetParallelScale(spec["projection"]["parallel_scale"])
    renderer.ResetCameraClippingRange(bounds)
    ok = mapper.RenderImage(camera, volume, width, height)
    check(ok == 1, "API RenderImage succeeded")
    return vtk_to_numpy(mapper.GetFloatImage().GetPointData().GetArray("RGBA")).copy()


def read_vti(path):
    if not os.path.isfile(path):
        return None
    reader = vtkXMLImageDataReader()
    reader.SetFileName(path)
    reader.Update()
    array = reader.GetOutput().GetPointData().GetArray("RGBA")
    return None if array is None else vtk_to_numpy(array).copy()


def read_png(path):
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    return vtk_to_numpy(reader.GetOutput().GetPointData().GetScalars()).astype(np.float64)


def run_case(name, spec, args, exe, env):
    data = os.path.join(os.path.abspath(args.data), spec.get("_data", "bracket_tet4_ccx.vtu"))
    folder = os.path.join(os.path.abspath(args.temp), "batch_" + name)
    os.makedirs(folder, exist_ok=True)
    results = {}
    for tool, command in (("python", [sys.executable, "-m", "highordervolume.batch"]),
                          ("cxx", [exe])):
        full = dict(spec, data=data, output={"vti": tool + ".vti", "png": tool + ".png"})
        path = os.path.join(folder, "spec_%s.json" % tool)
        with open(path, "w") as f:
            json.dump(full, f, indent=1)
        for out in ("vti", "png"):
            if os.path.exists(os.path.join(folder, tool + "." + out)):
                os.remove(os.path.join(folder, tool + "." + out))
        proc = subprocess.run(command + [path], capture_output=True, text=True, env=env,
                          cwd=os.path.dirname(path))
        check(proc.returncode == 0, "%s %s: exit code %d %s" % (
            name, tool, proc.returncode, proc.stderr.strip()[-300:] if proc.returncode else ""))
        check("progress 100%" in proc.stderr, "%s %s: progress reported to 100%%" % (name, tool))
        results[tool] = read_vti(os.path.join(folder, tool + ".vti"))
        png = os.path.join(folder, tool + ".png")
        if check_exists(png, "%s %s: PNG written" % (name, tool)) and results[tool] is not None:
            rgba = results[tool].astype(np.float64)
            bg = np.array(spec.get("background", [0, 0, 0]), dtype=np.float64)
            expected = 255.0 * np.clip(rgba[:, :3] + (1.0 - rgba[:, 3:4]) * bg, 0, 1)
            diff = np.abs(read_png(png) - expected).max()
            check(diff <= 0.5 + 1e-9, "%s %s: PNG = float image over the background (max %.3f)"
                  % (name, tool, diff))
    reference = api_image(spec, data)
    alpha = reference[:, 3]
    check(alpha.max() > 0.3 and (alpha > 0.01).sum() > 300,
          "%s: API image not trivial (max alpha %.3f, %d covered pixels)"
          % (name, alpha.max(), (alpha > 0.01).sum()))
    for tool in ("python", "cxx"):
        image = results[tool]
        same = image is not None and image.shape == reference.shape and \
            np.array_equal(image.view(np.uint32), reference.view(np.uint32))
        detail = "missing" if image is None else "max |diff| %.3g" % (
            np.abs(image - reference).max() if image.shape == reference.shape else -1)
        check(same, "%s: %s batch image bit-identical to the API image (%s)" % (name, tool, detail))


def check_projection_tolerance(args, exe, env):
    """opengl_projection: transfer_function.gpu_opacity_tolerance reaches the
    projection (its M3 vertex colours integrate the refined extinction table of
    that tolerance): a coarse 0.05 changes the image (by 1.5e-4 here), the same
    way in both entry points."""
    folder = os.path.join(os.path.abspath(args.temp), "batch_projection_tolerance")
    os.makedirs(folder, exist_ok=True)
    base = {"data": os.path.join(os.path.abspath(args.data), "bracket_tet4_ccx.vtu"),
            "array": "von_mises", "image": {"width": 64, "height": 48},
            "camera": {"azimuth": 30, "elevation": 20}, "render_mode": "opengl_projection",
            "transfer_function": {"color": [[0, 0.1, 0.2, 0.9], [170, 1, 0.2, 0.1]],
                                  "opacity": [[0, 0.02], [170, 0.95]], "unit_distance": 4}}
    images = {}
    for variant, tolerance in (("default", None), ("coarse", 0.05)):
        spec = json.loads(json.dumps(base))
        if tolerance is not None:
            spec["transfer_function"]["gpu_opacity_tolerance"] = tolerance
        for tool, command in (("python", [sys.executable, "-m", "highordervolume.batch"]),
                              ("cxx", [exe])):
            spec["output"] = {"vti": "%s_%s.vti" % (variant, tool)}
            path = os.path.join(folder, "spec_%s_%s.json" % (variant, tool))
            with open(path, "w") as f:
                json.dump(spec, f)
            proc = subprocess.run(command + [path], capture_output=True, text=True, env=env,
                                  cwd=folder)
            check(proc.returncode == 0, "projection %s %s: exit %d %s" % (
                variant, tool, proc.returncode,
                proc.stderr.strip()[-300:] if proc.returncode else ""))
            images[variant, tool] = read_vti(os.path.join(folder, spec["output"]["vti"]))
    if any(v is None for v in images.values()):
        check(False, "projection tolerance: every image written")
        return
    for variant in ("default", "coarse"):
        d = np.abs(images[variant, "python"] - images[variant, "cxx"]).max()
        check(d <= 1e-6, "projection %s: python and C++ images agree (max %.3g)" % (variant, d))
    d = np.abs(images["default", "cxx"] - images["coarse", "cxx"]).max()
    alpha = images["default", "cxx"][:, 3].max()
    check(alpha > 0.3 and d > 3e-5,
          "projection: gpu_opacity_tolerance 0.05 reaches the projection (max |diff| %.3g, "
          "max alpha %.2f)" % (d, alpha))


def check_progress(args):
    """batch.render's progress callback: monotone to 1; aborting leaves zeros, no NaN."""
    from highordervolume import batch
    spec = dict(SPECS["fit"], data=os.path.join(os.path.abspath(args.data), "bracket_tet4_ccx.vtu"),
                output={"vti": "unused.vti"})
    spec = batch.parse_spec(spec)
    seen = []
    full = vtk_to_numpy(batch.render(spec, progress=lambda m, f: seen.append(f))
                        .GetPointData().GetArray("RGBA")).copy()
    check(len(seen) > 10 and seen[0] == 0.0 and seen[-1] == 1.0 and
          all(b >= a for a, b in zip(seen, seen[1:])),
          "python progress: %d events from 0 to 1, non-decreasing" % len(seen))
    aborted_flags = []

    def abort(mapper, fraction):
        if fraction >= 0.25:
            mapper.SetAbortExecute(1)
        aborted_flags.append(mapper.GetLastRenderAborted())
    part = vtk_to_numpy(batch.render(spec, progress=abort).GetPointData().GetArray("RGBA"))
    zero = (part == 0).all(axis=1)
    same = (part == full).all(axis=1)
    check(not np.isnan(part).any() and (zero | same).all() and zero.sum() > (full[:, 3] == 0).sum(),
          "python abort: no NaN, pixels either complete or zero (%d of %d zero vs %d in the full "
          "image)" % (zero.sum(), len(zero), (full[:, 3] == 0).sum()))


def check_exists(path, what):
    ok = os.path.isfile(path)
    check(ok, what)
    return ok


def main():
    args = arguments()
    exe = batch_exe(args.temp)
    check(os.access(exe, os.X_OK), "hovBatchRender found at " + exe)
    env = dict(os.environ)
    env["PYTHONPATH"] = os.path.dirname(os.path.dirname(highordervolume.__file__)) + \
        os.pathsep + env.get("PYTHONPATH", "")
    for name, spec in SPECS.items():
        run_case(name, spec, args, exe, env)
    check_projection_tolerance(args, exe, env)
    check_progress(args)
    return finish()


if __name__ == "__main__":
    sys.exit(main())
