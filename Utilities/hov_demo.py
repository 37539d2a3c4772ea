#!/usr/bin/python3
"""Side-by-side demo: vtkHighOrderVolumeMapper next to VTK's unstructured volume mappers.

Renders the bundled bracket (linear tetrahedra, CalculiX von Mises stress) with

  * vtkHighOrderVolumeMapper, exact integral, VTK-unstructured opacity semantics,
    per-pixel segment sort (the REFERENCE image),
  * vtkHighOrderVolumeMapper, same, HIAC visibility-sort ordering by the exact
    vtkSteinVisibilitySort (the mapper's default) and by VTK's approximate
    vtkCellCenterDepthSort (its z-buffer witness counts the mis-ordered pixels),
  * vtkProjectedTetrahedraMapper with its default vtkCellCenterDepthSort and with our
    vtkSteinVisibilitySort,
  * vtkUnstructuredGridVolumeRayCastMapper (Bunyk + vtkUnstructuredGridLinearRayIntegrator),
  * vtkHighOrderVolumeMapper's fast OPENGL_PROJECTION mode (HIAC 7), colour methods M1 and M3,
  * vtkHighOrderVolumeMapper in GPU-compatible opacity semantics (extra, not comparable),

all under the same camera and the same vtkVolumeProperty, 512x512 offscreen; then (unless
--no-issue4) the two issue-4 datasets of Testing/Data, the dolfinx T-junction (10521
quadratic tetrahedra, 'speed') and the CalculiX zoo (tetrahedra, hexahedra, wedges,
pyramids, 'temperature'): ours on the native cells (the reference of those rows) beside ours,
vtkProjectedTetrahedraMapper and the unstructured ray caster on the tetrahedra of
vtkDataSetTriangleFilter (its time reported apart). It writes

  <out>/hov_demo_<key>.png     one screen capture per mapper (no labels)
  <out>/hov_demo_montage.png   all captures, labelled, plus the colour legend
  <out>/hov_demo_reference.vti our float image (premultiplied RGBA, row 0 at the bottom)
  <out>/hov_demo_gpu.vti       our float image in GPU-compatible semantics
  <out>/hov_demo_table.md      the table printed to stdout (one section per dataset)
  <out>/hov_demo_<tjunction|zoo>_<key>.png, <out>/hov_demo_<tjunction|zoo>_montage.png

Run (Debian's python has VTK; an X server is needed even offscreen):
  PYTHONPATH=<build>/lib/python3/dist-packages \
    xvfb-run -a -s "-screen 0 1280x1024x24 -noreset" /usr/bin/python3 Utilities/hov_demo.py --out /tmp/demo

Opacity semantics: vtkProjectedTetrahedraMapper and the unstructured ray caster turn the
opacity a(s) into extinction a(s)/u (u = scalar opacity unit distance); the comparison rows
use our mapper with the same VTK_UNSTRUCTURED semantics, so the differences measure
ordering, integration and quantisation only. The GPU-compatible row uses -ln(1-a)/u (what
vtkGPUVolumeRayCastMapper converges to) and is expected to differ.

Exit status: 0 on success; 1 if any render reports a VTK error, fails, or gives an
all-black image.
"""
import argparse
import os
import statistics
import sys
import time

import numpy as np
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (factory overrides)
import vtkmodules.vtkRenderingVolumeOpenGL2  # noqa: F401
import vtkmodules.vtkRenderingFreeType  # noqa: F401  (text rendering)
from vtkmodules.vtkCommonCore import vtkOutputWindow, vtkStringOutputWindow
from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader
from vtkmodules.vtkRenderingCore import (
    vtkCamera,
    vtkCellCenterDepthSort,
    vtkColorTransferFunction,
    vtkRenderer,
    vtkVolume,
    vtkVolumeProperty,
)
from vtkmodules.vtkCommonDataModel import vtkPiecewiseFunction
from vtkmodules.vtkRenderingAnnotation import vtkScalarBarActor
from vtkmodules.vtkRenderingVolume import (
    vtkProjectedTetrahedraMapper,
    vtkUnstructuredGridLinearRayIntegrator,
    vtkUnstructuredGridVolumeRayCastMapper,
)
from vtkmodules.util.numpy_support import vtk_to_numpy

try:
    from highordervolume import vtkHighOrderVolumeMapper, vtkSteinVisibilitySort
    from highordervolume.offscreen import OffscreenError, offscreen_window
    # Shared with the comparison tools (hov-compare): error catcher, capture, image I/O, montage.
    from highordervolume.render_tools import (DEFAULT_NODES, ErrorCatcher, capture,
                                              label_actor, montage, write_png, write_vti)
except ImportError as exc:  # pragma: no cover - environment problem
    sys.exit("cannot import highordervolume (set PYTHONPATH=<build>/lib/python3/dist-packages "
             "and use /usr/bin/python3): %s" % exc)

HERE = os.path.dirname(os.path.abspath(__file__))
DEFAULT_DATA = os.path.join(HERE, os.pardir, "Testing", "Data", "bracket_tet4_ccx.vtu")


def make_property(smin, smax, unit_distance=2.5):
    """A readable stress map: low stress faint blue, mid cyan/green, high yellow to red.

    The von Mises field is strongly skewed (median ~6 % of the maximum), so the nodes
    are spaced roughly geometrically over the range. Colour and opacity nodes sit at the
    same scalars (VTK's linear ray integrator only honours opacity nodes that are also
    colour nodes; see /work/shared/notes/vtk91.md)."""
    span = smax - smin
    nodes = DEFAULT_NODES  # (fraction of the range, r, g, b, opacity)
    ctf = vtkColorTransferFunction()
    otf = vtkPiecewiseFunction()
    for f, r, g, b, a in nodes:
        s = smin + f * span
        ctf.AddRGBPoint(s, r, g, b)
        otf.AddPoint(s, a)
    prop = vtkVolumeProperty()
    prop.SetColor(ctf)
    prop.SetScalarOpacity(otf)
    prop.SetScalarOpacityUnitDistance(unit_distance)  # dataset units
    prop.SetInterpolationTypeToLinear()
    prop.ShadeOff()
    return prop, ctf


def make_camera():
    """Fixed oblique view: the upright flange with its three holes and the base plate
    with its two bolt holes (bracket bounds 0..100 x 0..60 x 0..80)."""
    cam = vtkCamera()
    # Azimuth 35 deg, elevation 30 deg from the +z view of the bounding-box centre.
    cam.SetFocalPoint(50.0, 40.0, 40.0)
    cam.SetPosition(185.70964194187235, 176.60254037844388, 233.81345463497107)
    cam.SetViewUp(0.0, 1.0, 0.0)
    cam.OrthogonalizeViewUp()
    cam.SetViewAngle(30.0)
    cam.SetClippingRange(100.0, 500.0)
    return cam


def float_rgb(mapper):
    """Our float image composited over black: premultiplied RGB clamped to [0,1]."""
    img = mapper.GetFloatImage()
    w, h, _ = img.GetDimensions()
    rgba = vtk_to_numpy(img.GetPointData().GetArray("RGBA")).reshape(h, w, 4)
    return np.clip(rgba[..., :3].astype(np.float64), 0.0, 1.0)


def float_alpha(mapper):
    img = mapper.GetFloatImage()
    w, h, _ = img.GetDimensions()
    return vtk_to_numpy(img.GetPointData().GetArray("RGBA")).reshape(h, w, 4)[..., 3]


def render_case(case, grid, prop, camera, size, frames, catcher):
    """Warm-up, one labelled render (for the montage), then `frames` timed renders (unlabelled)."""
    mapper = case["mapper"]
    catcher.watch(mapper)
    mapper.SetInputData(grid)
    volume = vtkVolume()
    volume.SetMapper(mapper)
    volume.SetProperty(prop)
    ren = vtkRenderer()
    ren.SetBackground(0.0, 0.0, 0.0)
    ren.AddVolume(volume)
    ren.SetActiveCamera(camera)
    label = label_actor(case["label"])
    ren.AddActor2D(label)
    win = offscreen_window(size, size)  # X if DISPLAY is set, Mesa EGL if not
    win.SetMultiSamples(0)
    win.AddRenderer(ren)
    catcher.watch(win)
    catcher.watch(ren)
    before = len(catcher.messages)

    # Warm-up: graphics resources, cell setup, sorting structures, integrator
    # tables. Not captured: VTK 9.1's vtkOpenGLProjectedTetrahedraMapper draws
    # the first chunk of its very first frame (the 1000 rearmost cells of the
    # order) without vertex attributes, i.e. not at all (it adds its VAO
    # attributes only once its index buffer is non-empty; README, "Known
    # issues of VTK's mappers"). Then the labelled frame for the montage.
    label.SetVisibility(0)
    win.Render()
    label.SetVisibility(1)
    win.Render()
    labelled, _ = capture(win)
    labelled_copy = type(labelled)()
    labelled_copy.DeepCopy(labelled)

    label.SetVisibility(0)
    times = []
    for _ in range(frames):
        t0 = time.perf_counter()
        win.Render()
        win.WaitForCompletion()  # glFinish: count asynchronous OpenGL work too
        times.append(time.perf_counter() - t0)
    image, rgb = capture(win)
    result = {
        "times": times,
        "median": statistics.median(times),
        "png": image,
        "labelled": labelled_copy,
        "screen_rgb": rgb,
        "errors": catcher.messages[before:],
    }
    if isinstance(mapper, vtkHighOrderVolumeMapper):
        result["float_rgb"] = float_rgb(mapper)
        result["float_alpha"] = float_alpha(mapper).astype(np.float64)
        fimg = type(mapper.GetFloatImage())()
        fimg.DeepCopy(mapper.GetFloatImage())
        result["float_image"] = fimg
        result["witness"] = mapper.GetWitnessViolations()
        result["cpu_time"] = mapper.GetLastImageTime()
    win.Finalize()
    return result


def legend_image(ctf, smin, smax, size, title, label_format="%.0f"):
    """A colour legend panel for the montage (the opacity ramp is in the table notes)."""
    bar = vtkScalarBarActor()
    bar.SetLookupTable(ctf)
    bar.SetTitle(title)
    bar.SetNumberOfLabels(6)
    bar.SetLabelFormat(label_format)
    bar.SetOrientationToVertical()
    bar.SetPosition(0.30, 0.08)
    bar.SetWidth(0.30)
    bar.SetHeight(0.84)
    ren = vtkRenderer()
    ren.SetBackground(0.0, 0.0, 0.0)
    ren.AddActor2D(bar)
    win = offscreen_window(size, size)
    win.AddRenderer(ren)
    win.Render()
    img, _ = capture(win)
    out = type(img)()
    out.DeepCopy(img)
    win.Finalize()
    return out


def fmt3(v):
    return "/".join("%.3g" % x for x in v)


def comparison_rows(ok_cases, reference, ref_alpha, failures, input_column=False):
    """Markdown rows: each case's image against the reference float image (RGB over black)."""
    lines = []
    extra = " input |" if input_column else ""
    lines.append("| mapper |" + extra + " opacity semantics | frame time [s] | CPU image [s] "
                 "| compared image | max abs diff R/G/B | mean abs diff R/G/B "
                 "| mean abs diff R/G/B, covered px | witness |")
    lines.append("|---|---|---|---|---|---|---|---|---|" + ("---|" if input_column else ""))
    for c in ok_cases:
        res = c["result"]
        ours = "float_rgb" in res
        img = res["float_rgb"] if ours else res["screen_rgb"]
        if img.shape != reference.shape:
            failures.append("%s: image shape %s != reference %s"
                            % (c["key"], img.shape, reference.shape))
            continue
        diff = np.abs(img - reference)
        dmax = diff.reshape(-1, 3).max(axis=0)
        dmean = diff.reshape(-1, 3).mean(axis=0)
        covered = (ref_alpha > 1.0 / 255.0) | (img.max(axis=2) > 0.0)
        dcov = diff[covered].mean(axis=0) if covered.any() else np.zeros(3)
        note = " (other semantics: not comparable)" if c["semantics"] != "VTK-unstructured" else ""
        lines.append("| %s |%s %s | %.3f | %s | %s | %s%s | %s | %s | %s |" % (
            c["name"], (" %s |" % c["input"]) if input_column else "", c["semantics"],
            res["median"], "%.3f" % res["cpu_time"] if ours else "-",
            "float" if ours else "8-bit capture",
            fmt3(dmax), note, fmt3(dmean), fmt3(dcov),
            str(res["witness"]) if ours else "-"))
        if ours:
            # Sanity: our own 8-bit capture against our float image (display path).
            c["display_diff"] = np.abs(res["screen_rgb"] - img).max()
    lines.append("")
    for c in ok_cases:
        if "display_diff" in c:
            lines.append("- %s: on-screen capture vs its own float image, max |diff| %.4f "
                         "(8-bit display path)." % (c["key"], c["display_diff"]))
    return lines


def parse_arguments():
    """The demo's command line."""
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--data", default=DEFAULT_DATA, help="a .vtu of linear tetrahedra")
    parser.add_argument("--array", default="von_mises", help="point array to render")
    parser.add_argument("--out", default="hov_demo_out", help="output directory")
    parser.add_argument("--size", type=int, default=512, help="window width and height")
    parser.add_argument("--unit-distance", type=float, default=2.5,
                        help="scalar opacity unit distance (dataset units; bracket is 100x60x80)")
    parser.add_argument("--frames", type=int, default=3, help="timed renders per mapper (>= 3)")
    parser.add_argument("--no-issue4", action="store_true",
                        help="skip the quadratic-tet and mixed-cell datasets (issue 4)")
    args = parser.parse_args()
    return args


def demo_cases():
    """The mappers the demo compares on the bracket (the reference first, GPU-compatible last)."""
    def hov(semantics, ordering):
        m = vtkHighOrderVolumeMapper()
        if ordering == "cellcentre":
            m.SetVisibilitySort(vtkCellCenterDepthSort())
        m.SetIntegrationMethodToExact()
        if semantics == "vtk":
            m.SetOpacitySemanticsToVTKUnstructured()
        else:
            m.SetOpacitySemanticsToGPUCompatible()
        if ordering == "pixel":
            m.SetCellOrderingToPerPixelSort()
        else:
            m.SetCellOrderingToVisibilitySort()
        return m

    def hov_projection(method):
        # The fast OpenGL path (HIAC 7), default exact (Stein) order.
        m = vtkHighOrderVolumeMapper()
        m.SetRenderModeToOpenGLProjection()
        m.SetOpacitySemanticsToVTKUnstructured()
        m.SetProjectionColorMethod(method)
        return m

    pt = vtkProjectedTetrahedraMapper()
    pt_stein = vtkProjectedTetrahedraMapper()
    pt_stein.SetVisibilitySort(vtkSteinVisibilitySort())
    rc = vtkUnstructuredGridVolumeRayCastMapper()
    rc.SetRayIntegrator(vtkUnstructuredGridLinearRayIntegrator())
    rc.SetAutoAdjustSampleDistances(0)
    rc.SetImageSampleDistance(1.0)

    cases = [
        {"key": "hov_pixelsort", "mapper": hov("vtk", "pixel"), "semantics": "VTK-unstructured",
         "name": "vtkHighOrderVolumeMapper, per-pixel sort (reference)",
         "label": "HighOrderVolume exact, per-pixel sort (reference)"},
        {"key": "hov_visibility", "mapper": hov("vtk", "visibility"),
         "semantics": "VTK-unstructured",
         "name": "vtkHighOrderVolumeMapper, exact Stein visibility sort (default)",
         "label": "HighOrderVolume exact, Stein sort (default)"},
        {"key": "hov_cellcentre", "mapper": hov("vtk", "cellcentre"),
         "semantics": "VTK-unstructured",
         "name": "vtkHighOrderVolumeMapper, VTK's cell-centre sort",
         "label": "HighOrderVolume exact, cell-centre sort"},
        {"key": "projected_tetrahedra", "mapper": pt, "semantics": "VTK-unstructured",
         "name": "vtkProjectedTetrahedraMapper (cell-centre sort)",
         "label": "vtkProjectedTetrahedraMapper"},
        {"key": "projected_tetrahedra_stein", "mapper": pt_stein, "semantics": "VTK-unstructured",
         "name": "vtkProjectedTetrahedraMapper + vtkSteinVisibilitySort",
         "label": "vtkProjectedTetrahedraMapper + Stein sort"},
        {"key": "ug_raycast", "mapper": rc, "semantics": "VTK-unstructured",
         "name": "vtkUnstructuredGridVolumeRayCastMapper (Bunyk, linear integrator)",
         "label": "vtkUnstructuredGridVolumeRayCastMapper"},
        {"key": "hov_projection_m1", "mapper": hov_projection(1),
         "semantics": "VTK-unstructured",
         "name": "vtkHighOrderVolumeMapper, OPENGL_PROJECTION M1 (fast path)",
         "label": "HighOrderVolume OpenGL projection M1"},
        {"key": "hov_projection_m3", "mapper": hov_projection(3),
         "semantics": "VTK-unstructured",
         "name": "vtkHighOrderVolumeMapper, OPENGL_PROJECTION M3 (fast path, default colour)",
         "label": "HighOrderVolume OpenGL projection M3"},
        {"key": "hov_gpu", "mapper": hov("gpu", "pixel"), "semantics": "GPU-compatible",
         "name": "vtkHighOrderVolumeMapper, per-pixel sort, GPU-compatible (extra)",
         "label": "HighOrderVolume, GPU-compatible semantics"},
    ]
    return cases


def render_cases(cases, grid, prop, camera, args, frames, catcher, log, failures):
    """Render every case (its result in case["result"]); failures appended."""
    for case in cases:
        try:
            case["result"] = render_case(case, grid, prop, camera, args.size, frames, catcher)
        except Exception as exc:  # a failed render must fail the demo
            failures.append("%s: exception %r" % (case["key"], exc))
            continue
        res = case["result"]
        printed_all = log.GetOutput() or ""
        printed, log.seen = printed_all[log.seen:], len(printed_all)
        if printed:
            sys.stderr.write("[%s] VTK output:\n%s\n" % (case["key"], printed.strip()))
            if "ERROR" in printed:
                failures.append("%s: VTK printed an error" % case["key"])
        for msg in res["errors"]:
            failures.append("%s: VTK error: %s" % (case["key"], msg.strip()))
        if res["screen_rgb"].max() <= 0.0:
            failures.append("%s: the screen capture is all black" % case["key"])
        if "float_rgb" in res and res["float_rgb"].max() <= 0.0:
            failures.append("%s: our float image is all black" % case["key"])
        write_png(res["png"], os.path.join(args.out, "hov_demo_%s.png" % case["key"]))


def main():
    import hov_demo_datasets  # the quadratic / mixed-cell datasets (imports this module)

    args = parse_arguments()
    frames = max(3, args.frames)
    os.makedirs(args.out, exist_ok=True)

    reader = vtkXMLUnstructuredGridReader()
    reader.SetFileName(args.data)
    reader.Update()
    grid = reader.GetOutput()
    if grid.GetNumberOfCells() == 0:
        sys.exit("no cells read from %s" % args.data)
    array = grid.GetPointData().GetArray(args.array)
    if array is None:
        sys.exit("no point array '%s' in %s" % (args.array, args.data))
    grid.GetPointData().SetActiveScalars(args.array)
    smin, smax = array.GetRange(0)
    prop, ctf = make_property(smin, smax, args.unit_distance)
    camera = make_camera()
    catcher = ErrorCatcher()
    # Everything VTK prints (errors of objects we do not observe too) goes through here.
    log = vtkStringOutputWindow()
    vtkOutputWindow.SetInstance(log)
    log.seen = 0  # characters of the log already shown

    cases = demo_cases()

    failures = []
    render_cases(cases, grid, prop, camera, args, frames, catcher, log, failures)

    ok_cases = [c for c in cases if "result" in c]
    ref_case = cases[0]
    if "result" not in ref_case:
        for f in failures:
            print("FAILED:", f, file=sys.stderr)
        return 1
    reference = ref_case["result"]["float_rgb"]
    ref_alpha = ref_case["result"]["float_alpha"]
    write_vti(ref_case["result"]["float_image"], os.path.join(args.out, "hov_demo_reference.vti"))
    if "result" in cases[-1]:
        write_vti(cases[-1]["result"]["float_image"], os.path.join(args.out, "hov_demo_gpu.vti"))

    # Montage: labelled captures plus the colour legend.
    panels = [c["result"]["labelled"] for c in ok_cases]
    panels.append(legend_image(ctf, smin, smax, args.size, args.array))
    write_png(montage(panels, 3, args.size), os.path.join(args.out, "hov_demo_montage.png"))

    # Table.
    lines = []
    lines.append("# vtkHighOrderVolumeMapper demo: %s, array '%s' (range %.4g..%.4g), "
                 "%d cells, %dx%d" % (os.path.basename(args.data), args.array, smin, smax,
                                      grid.GetNumberOfCells(), args.size, args.size))
    lines.append("")
    lines.append("Same camera, same vtkVolumeProperty (7 colour/opacity nodes at the same "
                 "scalars, scalar opacity unit distance %.3g). Reference: our float image, "
                 "per-pixel sort, VTK-unstructured semantics (extinction a(s)/u, what VTK's "
                 "unstructured mappers use, so those rows compare like with like). "
                 "Differences are |image - reference| on RGB over black in [0,1], per channel "
                 "R/G/B, over all pixels and over the covered pixels (reference alpha > 1/255 "
                 "or image not black); VTK images are 8-bit screen captures (so up to 0.002 is "
                 "quantisation), ours are float images. "
                 "Frame time: median of %d wall-clock renderWindow.Render() + WaitForCompletion() "
                 "after a warm-up render, same view; "
                 "'CPU image' is GetLastImageTime() of the last frame."
                 % (prop.GetScalarOpacityUnitDistance(), frames))
    lines.append("")
    lines.extend(comparison_rows(ok_cases, reference, ref_alpha, failures))
    lines.append("- Frame times per render [s]: " + "; ".join(
        "%s %s" % (c["key"], ", ".join("%.3f" % t for t in c["result"]["times"]))
        for c in ok_cases))
    if not args.no_issue4:
        for ds in hov_demo_datasets.ISSUE4_DATASETS:
            lines.extend(hov_demo_datasets.issue4_dataset(ds, args, frames, catcher, log, failures))
        for ds in hov_demo_datasets.RAYCAST_DATASETS:  # issue 6: curved Lagrange, RAY_CAST
            lines.extend(hov_demo_datasets.raycast_dataset(ds, args, catcher, log, failures))
    table = "\n".join(lines)
    print(table)
    with open(os.path.join(args.out, "hov_demo_table.md"), "w") as f:
        f.write(table + "\n")

    if failures:
        for f in failures:
            print("FAILED:", f, file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    try:
        sys.exit(main())
    except OffscreenError as exc:  # no X server that answers and no EGL, or a bad size
        sys.exit("hov_demo: %s" % exc)
