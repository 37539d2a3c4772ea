"""Compare vtkHighOrderVolumeMapper's render modes with VTK's volume mappers on one dataset.

    hov-compare DATA.vtu ARRAY [--out DIR] [--size W H] [--azimuth A --elevation E --zoom Z]
                [--tf TF.json] [--resolutions 64,128,256] [--methods PATTERNS]
    /usr/bin/python3 -m highordervolume.compare ...   (the same)

Renders, under one camera and one vtkVolumeProperty, offscreen (an X server is needed:
xvfb-run -a -s "-screen 0 1280x1024x24 -noreset"):

  hov_cpu_<s>       ours, CPU_ACCURATE, exact integral, per-pixel sort: the REFERENCE of
                    opacity semantics <s> (vtk = VTK-unstructured a/u, gpu = GPU-compatible
                    -ln(1-a)/u); native cells. For data with cells only RAY_CAST renders
                    (Lagrange), hov_ray_<s> at its "pixel-exact" tolerance 1e-3 is the
                    reference instead.
  hov_proj_m<k>_<s> ours, OPENGL_PROJECTION with ProjectionColorMethod M<k> (k = 0..3)
  hov_ray_<s>       ours, RAY_CAST (only if the mapper has that render mode)
  vtk_pt            vtkProjectedTetrahedraMapper                        } tetrahedra of the
  vtk_ugrc          vtkUnstructuredGridVolumeRayCastMapper (Bunyk)      } input, VTK-
  vtk_zsweep        vtkUnstructuredGridVolumeZSweepMapper               } unstructured semantics
  vtk_gpu_<n>       vtkResampleToImage (n points on the longest side) +
                    vtkGPUVolumeRayCastMapper: GPU-compatible semantics

Every image is compared, per channel R/G/B over all pixels, with the reference of its
semantics: RGB over a black background in [0,1] (ours: the float image, premultiplied RGB;
VTK's: the 8-bit window capture / 255, so 0.002 is quantisation). Outputs in --out:

  compare_<key>.png   the window capture of each method
  compare_<key>.npy   the compared image, float32 RGB (h, w, 3), row 0 at the bottom
  compare_montage.png every image beside its false-colour difference map, labelled
  compare_table.md, compare_table.csv   the table (times in seconds, memory in MiB)

Exit status 0 if the reference image(s) rendered, 1 otherwise (other failures are reported
in the table's status column).
"""
import argparse
import fnmatch
import os
import sys
import time

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkCommand, vtkOutputWindow, vtkStringOutputWindow
from vtkmodules.vtkRenderingVolume import (vtkGPUVolumeRayCastMapper,
                                           vtkProjectedTetrahedraMapper,
                                           vtkUnstructuredGridLinearRayIntegrator,
                                           vtkUnstructuredGridVolumeRayCastMapper,
                                           vtkUnstructuredGridVolumeZSweepMapper)

from . import compare_report as report
from . import render_tools as rt
from .offscreen import OffscreenError
from .vtkRenderingHighOrderVolume import vtkHighOrderVolumeMapper

SEMANTICS = {"vtk": "VTK-unstructured", "gpu": "GPU-compatible"}
CHANNELS = "rgb"


class Progress:
    """One line per method: '[ 3/18  11%] key ... 100%  0.42 s' (live percentage on a tty)."""

    def __init__(self, total, stream=sys.stdout):
        self.total, self.done, self.stream = total, 0, stream
        self.tty = hasattr(stream, "isatty") and stream.isatty()
        self.key, self.t0 = "", 0.0

    def start(self, key):
        self.key, self.t0 = key, time.perf_counter()
        self.update(0.0)

    def head(self):
        return "[%2d/%d %3d%%] %-22s" % (self.done + 1, self.total,
                                        int(100.0 * self.done / max(self.total, 1)), self.key)

    def update(self, fraction):
        if self.tty:
            self.stream.write("\r%s %3d%%" % (self.head(), int(100 * fraction)))
            self.stream.flush()

    def observer(self, obj, event):
        self.update(obj.GetProgress())

    def finish(self, status):
        line = "%s 100%% %7.2f s  %s" % (self.head(), time.perf_counter() - self.t0, status)
        self.stream.write(("\r" if self.tty else "") + line + "\n")
        self.stream.flush()
        self.done += 1


def hov_mapper(semantics, mode, method=None):
    m = vtkHighOrderVolumeMapper()
    if semantics == "vtk":
        m.SetOpacitySemanticsToVTKUnstructured()
    else:
        m.SetOpacitySemanticsToGPUCompatible()
    m.SetIntegrationMethodToExact()
    m.SetCellOrderingToPerPixelSort()
    if mode == "cpu":
        m.SetRenderModeToCPUAccurate()
    elif mode == "proj":
        m.SetRenderModeToOpenGLProjection()
        m.SetProjectionColorMethod(method)
    elif mode == "ray":
        m.SetRenderMode(m.RAY_CAST)
        if method is not None and hasattr(m, "SetRayCastTolerance"):
            m.SetRayCastTolerance(method)
    return m


def has_ray_cast():
    return hasattr(vtkHighOrderVolumeMapper, "RAY_CAST")


# Cell types CPU_ACCURATE renders (linear and quadratic, straight-sided); other volumetric
# cells (Lagrange, Bezier) need RAY_CAST, which then gives the reference image.
CPU_CELL_TYPES = {10, 11, 12, 13, 14, 24, 25, 26, 27, 29}


def needs_ray_reference(grid):
    """True if the grid has cells CPU_ACCURATE does not render and RAY_CAST is available."""
    types = set(np.unique(vtk_to_numpy(grid.GetCellTypesArray())).tolist()) \
        if grid.GetNumberOfCells() else set()
    return has_ray_cast() and bool(types - CPU_CELL_TYPES)


def reference_spec(semantics, ray_reference):
    """The reference method of one opacity semantics: CPU_ACCURATE, or RAY_CAST at its
    default "pixel-exact" tolerance for cells only the ray caster renders."""
    if ray_reference:
        return {"key": "hov_ray_" + semantics, "input": "native", "semantics": semantics,
                "reference": True, "name": "ours RAY_CAST (reference, pixel-exact)",
                "make": lambda s=semantics: hov_mapper(s, "ray")}
    return {"key": "hov_cpu_" + semantics, "input": "native", "semantics": semantics,
            "reference": True, "name": "ours CPU_ACCURATE (reference)",
            "make": lambda s=semantics: hov_mapper(s, "cpu")}


def ug_raycast(image_sample_distance=1.0):
    m = vtkUnstructuredGridVolumeRayCastMapper()
    m.SetRayIntegrator(vtkUnstructuredGridLinearRayIntegrator())
    m.SetAutoAdjustSampleDistances(0)
    m.SetImageSampleDistance(image_sample_distance)
    return m


def zsweep():
    m = vtkUnstructuredGridVolumeZSweepMapper()
    m.SetRayIntegrator(vtkUnstructuredGridLinearRayIntegrator())
    m.SetAutoAdjustSampleDistances(0)
    m.SetImageSampleDistance(1.0)
    return m


def gpu_mapper(sample_distance):
    m = vtkGPUVolumeRayCastMapper()
    m.SetBlendModeToComposite()
    m.SetAutoAdjustSampleDistances(0)
    m.LockSampleDistanceToInputSpacingOff()
    m.SetSampleDistance(sample_distance)
    return m


def method_specs(semantics, resolutions, ray_cast, ray_reference=False):
    """All methods as dicts: key, name, semantics ('vtk'|'gpu'), input ('native'|'tets'|
    'resample'), make (mapper factory; for 'resample' it takes the sample distance); the
    reference of each semantics first ("reference": True)."""
    specs = []
    for s in semantics:
        specs.append(reference_spec(s, ray_reference))
        for k in range(4):
            specs.append({"key": "hov_proj_m%d_%s" % (k, s), "input": "native", "semantics": s,
                          "name": "ours OPENGL_PROJECTION M%d" % k,
                          "make": lambda s=s, k=k: hov_mapper(s, "proj", k)})
        if ray_cast and not ray_reference:
            specs.append({"key": "hov_ray_" + s, "input": "native", "semantics": s,
                          "name": "ours RAY_CAST", "make": lambda s=s: hov_mapper(s, "ray")})
    if "vtk" in semantics:
        specs += [
            {"key": "vtk_pt", "input": "tets", "semantics": "vtk",
             "name": "vtkProjectedTetrahedraMapper", "make": vtkProjectedTetrahedraMapper},
            {"key": "vtk_ugrc", "input": "tets", "semantics": "vtk",
             "name": "vtkUnstructuredGridVolumeRayCastMapper", "make": ug_raycast},
            {"key": "vtk_zsweep", "input": "tets", "semantics": "vtk",
             "name": "vtkUnstructuredGridVolumeZSweepMapper", "make": zsweep}]
    if "gpu" in semantics:
        for n in resolutions:
            specs.append({"key": "vtk_gpu_%d" % n, "input": "resample", "resolution": n,
                          "semantics": "gpu",
                          "name": "vtkResampleToImage %d + vtkGPUVolumeRayCastMapper" % n,
                          "make": gpu_mapper})
    return specs


class Scene:
    """Dataset, property, camera and cached inputs of one comparison."""

    def __init__(self, args):
        self.grid = rt.read_grid(args.data, args.array)
        self.array = args.array
        self.smin, self.smax = self.grid.GetPointData().GetArray(args.array).GetRange(0)
        self.prop = rt.make_property(self.smin, self.smax, args.tf, args.unit_distance,
                                     self.grid.GetBounds())
        self.gpu_prop = rt.gpu_property(self.prop, self.smin, self.smax)
        self.width, self.height = args.size
        self.camera = rt.fit_camera(self.grid.GetBounds(), self.width, self.height,
                                    args.azimuth, args.elevation, args.zoom)
        self.subdivisions = args.subdivisions
        self.gpu_sample_factor = args.gpu_sample_factor
        self.ray_reference = needs_ray_reference(self.grid)
        self.cache = {}

    def prepare(self, spec):
        """(data, preparation name, seconds, RSS delta MiB) of the spec's input, cached."""
        if spec["input"] == "native":
            return self.grid, "native cells", 0.0, 0.0
        key = spec["input"] + str(spec.get("resolution", ""))
        if key not in self.cache:
            rss0 = rt.rss_mib()
            if spec["input"] == "tets":
                data, name, secs = rt.tetrahedralize(self.grid, self.subdivisions)
                name = "%s: %d tetrahedra" % (name, data.GetNumberOfCells())
            else:
                data, secs = rt.resample(self.grid, self.array, spec["resolution"],
                                         self.smin, self.smax)
                name = "vtkResampleToImage %s" % "x".join(map(str, data.GetDimensions()))
            self.cache[key] = (data, name, secs, rt.rss_mib() - rss0)
        return self.cache[key]

    def mapper(self, spec, data):
        if spec["input"] == "resample":
            factor = spec.get("sample_factor", self.gpu_sample_factor)
            return spec["make"](factor * min(data.GetSpacing()))
        return spec["make"]()

    def property(self, spec):
        return self.gpu_prop if spec["input"] == "resample" else self.prop


def compared_image(result):
    """float32 RGB over black in [0,1]: ours' float image, else the 8-bit capture / 255."""
    if "float_rgba" in result:
        return np.clip(result["float_rgba"][..., :3], 0.0, 1.0).astype(np.float32)
    return result["screen_rgb"].astype(np.float32)


def warning_summary(printed):
    """'' or '; N VTK warning(s), first: <message>' from what VTK printed."""
    count = printed.count("Warning: In ")
    if not count:
        return ""
    first = ""
    lines = printed.splitlines()
    for i, line in enumerate(lines):
        if line.startswith("Warning: In ") and i + 1 < len(lines):
            first = lines[i + 1].split("): ", 1)[-1].strip()
            break
    return "; %d VTK warning%s, first: %s" % (count, "s" if count > 1 else "", first[:160])


def run_one(scene, spec, frames, catcher, log, progress):
    """Render one method; returns the row dict (without errors) and the compared image."""
    row = {"key": spec["key"], "method": spec["name"], "semantics": SEMANTICS[spec["semantics"]]}
    rss0 = rt.rss_mib()
    data, prep_name, prep_s, prep_rss = scene.prepare(spec)
    # Size before rendering: mappers add structures to their input (links, ...).
    data_mib = data.GetActualMemorySize() / 1024.0
    mapper = scene.mapper(spec, data)
    mapper.AddObserver(vtkCommand.ProgressEvent, progress.observer)
    before = len(catcher.messages)
    res = rt.render_mapper(mapper, data, scene.property(spec), scene.camera, scene.width,
                           scene.height, frames, catcher)
    printed_all = log.GetOutput() or ""
    printed, log.seen = printed_all[log.seen:], len(printed_all)
    errors = catcher.messages[before:] + (["VTK printed an error"] if "ERROR" in printed else [])
    row.update({"input": prep_name, "prep_s": prep_s, "first_render_s": res["first_s"],
                "frame_s": res["frame_s"],
                "rss_delta_mib": max(0.0, rt.rss_mib() - rss0) + (prep_rss if prep_s else 0.0),
                "data_mib": data_mib})
    if errors:
        row["status"] = "error: " + errors[0].strip().replace("\n", " ")[:120]
    else:
        row["status"] = "ok" + warning_summary(printed)
    if printed.strip():
        sys.stderr.write("[%s] VTK output:\n%s\n" % (spec["key"], printed.strip()[:2000]))
    del mapper
    return row, res, (None if errors else compared_image(res))


def add_scene_arguments(parser):
    """Dataset, camera, transfer function and rendering options shared with hov-convergence."""
    parser.add_argument("data", help="a .vtu file (any cell type the module reads)")
    parser.add_argument("array", help="point array (scalar) to render")
    parser.add_argument("--size", type=int, nargs=2, default=[256, 256], metavar=("W", "H"))
    parser.add_argument("--azimuth", type=float, default=30.0, help="degrees (default fit)")
    parser.add_argument("--elevation", type=float, default=20.0, help="degrees")
    parser.add_argument("--zoom", type=float, default=1.3)
    parser.add_argument("--tf", help="transfer function JSON (default: fitted to the range)")
    parser.add_argument("--unit-distance", type=float,
                        help="scalar opacity unit distance (default: JSON, else diagonal/50)")
    parser.add_argument("--frames", type=int, default=3, help="timed renders per method")
    parser.add_argument("--subdivisions", type=int, default=1,
                        help="vtkTessellatorFilter levels for non-linear cells")
    parser.add_argument("--gpu-sample-factor", type=float, default=0.5,
                        help="GPU sample distance as a fraction of the smallest voxel spacing")


def parse_args(argv=None):
    parser = argparse.ArgumentParser(
        prog="hov-compare", description="Compare vtkHighOrderVolumeMapper's render modes with "
        "VTK's volume mappers (images, montage, error/time/memory table).")
    add_scene_arguments(parser)
    parser.add_argument("--out", default="hov_compare_out", help="output directory")
    parser.add_argument("--resolutions", default="64,128,256",
                        help="vtkResampleToImage points on the longest side, comma separated")
    parser.add_argument("--semantics", default="vtk,gpu", help="vtk, gpu or vtk,gpu")
    parser.add_argument("--methods", default="*",
                        help="comma-separated key patterns to run (references always run)")
    parser.add_argument("--diff-scale", type=float, default=0.1,
                        help="difference maps saturate at this error")
    parser.add_argument("--montage-colors", type=int, default=0,
                        help="quantise the montage PNG to this many colours (0: full colour)")
    parser.add_argument("--list", action="store_true", help="list the method keys and exit")
    args = parser.parse_args(argv)
    args.resolutions = [int(r) for r in args.resolutions.split(",") if r.strip()]
    args.semantics = [s.strip() for s in args.semantics.split(",") if s.strip()]
    bad = [s for s in args.semantics if s not in SEMANTICS]
    if bad or not args.semantics:
        parser.error("--semantics: use vtk, gpu or vtk,gpu")
    if args.frames < 1 or min(args.size) < 8:
        parser.error("--frames >= 1 and --size >= 8 needed")
    return args


def selected_specs(args, ray_reference=False):
    specs = method_specs(args.semantics, args.resolutions, has_ray_cast(), ray_reference)
    patterns = [p.strip() for p in args.methods.split(",") if p.strip()]
    return [s for s in specs if s.get("reference")
            or any(fnmatch.fnmatch(s["key"], p) for p in patterns)]


def add_errors(row, image, reference, ref_key):
    row["reference"] = ref_key
    if image is None or reference is None:
        return
    stats = rt.error_stats(image, reference)
    for stat in ("max", "mean", "p99"):
        for c, v in zip(CHANNELS, stats[stat]):
            row["%s_%s" % (stat, c)] = v


def run(args):
    """Render every selected method; returns (rows, montage entries, scene)."""
    scene = Scene(args)
    specs = selected_specs(args, scene.ray_reference)
    os.makedirs(args.out, exist_ok=True)
    log = vtkStringOutputWindow()
    vtkOutputWindow.SetInstance(log)
    log.seen = 0
    catcher = rt.ErrorCatcher()
    progress = Progress(len(specs))
    rt.warm_up_gl()
    rows, entries, refs = [], [], {}
    for spec in specs:
        progress.start(spec["key"])
        try:
            row, res, image = run_one(scene, spec, args.frames, catcher, log, progress)
        except Exception as exc:  # report and go on with the other methods
            row = {"key": spec["key"], "method": spec["name"],
                   "semantics": SEMANTICS[spec["semantics"]], "status": "failed: %r" % exc}
            res, image = None, None
        if res is not None:
            rt.write_png(res["png"], os.path.join(args.out, "compare_%s.png" % spec["key"]))
        if image is not None:
            row["image"] = "compare_%s.npy" % spec["key"]
            np.save(os.path.join(args.out, row["image"]), image)
        if spec.get("reference"):
            refs[spec["semantics"]] = (spec["key"], image)
        ref_key, reference = refs.get(spec["semantics"], ("", None))
        add_errors(row, image, reference, ref_key)
        progress.finish(row["status"])
        rows.append(row)
        max_err = max(row["max_" + c] for c in CHANNELS) if "max_r" in row else float("nan")
        entries.append((row["key"], image, reference, max_err))
    return rows, entries, scene, refs


def notes(args, scene):
    b = scene.grid.GetBounds()
    return [
        "Dataset %s, array '%s' (range %.6g..%.6g), %d cells, %dx%d pixels, camera azimuth "
        "%g, elevation %g, zoom %g (fitted to the bounds %s), scalar opacity unit distance %.4g."
        % (os.path.basename(args.data), args.array, scene.smin, scene.smax,
           scene.grid.GetNumberOfCells(), scene.width, scene.height, args.azimuth,
           args.elevation, args.zoom, "/".join("%.3g" % v for v in b),
           scene.prop.GetScalarOpacityUnitDistance()),
        "Errors: |image - reference| per channel R/G/B over all pixels, RGB over black in "
        "[0,1]; reference: our %s float image in the row's opacity semantics "
        "(VTK-unstructured a/u for VTK's unstructured mappers, GPU-compatible -ln(1-a)/u for "
        "the GPU ray caster). VTK's images are 8-bit captures (0.002 is quantisation). "
        "Times: seconds, first render (includes setup and sorting structures) and the median "
        "of %d further renders; prep: tessellation / resampling (shared by the rows using that "
        "input). Memory: resident-set growth over the row, and the rendered dataset's size."
        % ("RAY_CAST (tolerance 1e-3; the cells need the ray caster)" if scene.ray_reference
           else "CPU_ACCURATE", args.frames)]


def main(argv=None):
    args = parse_args(argv)
    if args.list:
        for spec in selected_specs(args, needs_ray_reference(rt.read_grid(args.data, args.array))):
            print(spec["key"], "-", spec["name"])
        return 0
    try:
        rows, entries, scene, refs = run(args)
    except (ValueError, OSError, OffscreenError) as exc:  # bad file, array, TF, no window ...
        print("hov-compare: %s" % exc, file=sys.stderr)
        return 1
    report.write_csv(rows, os.path.join(args.out, "compare_table.csv"))
    text = report.write_markdown(rows, os.path.join(args.out, "compare_table.md"),
                                 "hov-compare: %s" % os.path.basename(args.data),
                                 notes(args, scene))
    report.write_montage(entries, os.path.join(args.out, "compare_montage.png"),
                         args.diff_scale, colors=args.montage_colors or None,
                         panel_inches=max(1.2, scene.width / 100.0))
    print(text)
    missing = [s for s in args.semantics if refs.get(s, (None, None))[1] is None]
    if missing:
        print("hov-compare: the reference image failed for %s" % ", ".join(missing),
              file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
