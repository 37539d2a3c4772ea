"""The quadratic and mixed-cell datasets of the demo (Utilities/hov_demo.py, README command 1).

Ours renders the native cells; VTK's mappers get linear tetrahedra (quadratic tetrahedra split
8-way at their nodes, linear cells by vtkDataSetTriangleFilter), the tessellation timed
separately. Imported by hov_demo.main(); uses its rendering and table helpers.
"""
import os
import sys
import time

import numpy as np
from vtkmodules.vtkCommonDataModel import vtkPiecewiseFunction
from vtkmodules.vtkFiltersGeneral import vtkDataSetTriangleFilter
from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader
from vtkmodules.vtkRenderingCore import vtkCamera, vtkColorTransferFunction, vtkVolumeProperty
from vtkmodules.vtkRenderingVolume import (vtkProjectedTetrahedraMapper,
                                           vtkUnstructuredGridLinearRayIntegrator,
                                           vtkUnstructuredGridVolumeRayCastMapper)
from vtkmodules.util.numpy_support import vtk_to_numpy

import hov_demo as demo
from highordervolume import vtkHighOrderVolumeMapper


# The issue-4 datasets (Testing/Data): quadratic tetrahedra and a mixed-cell zoo. Ours
# renders the native cells; VTK's mappers need linear tetrahedra: quadratic tetrahedra split
# 8-way at their nodes (split_quadratic_tets), linear cells by vtkDataSetTriangleFilter
# (hexahedron -> 5 or 6, wedge -> 3, pyramid -> 2); tessellation timed separately. Cameras as in Testing/Cxx
# (hovTestReferenceDatasets.cxx); transfer function: 5 nodes, opacity nodes = colour nodes
# (denser here than in the tests: smaller unit distance).
ISSUE4_DATASETS = [
    {"tag": "tjunction", "file": "tjunction_tet10_dolfinx.vtu", "array": "speed", "unit": 0.12,
     "label_format": "%.1f",
     "focal": (0.0, 0.55, 0.0), "position": (2.2, 2.6, 5.2), "up": (0, 1, 0), "angle": 40.0,
     "clip": (2.0, 12.0)},
    {"tag": "zoo", "file": "zoo_mixed_ccx.vtu", "array": "temperature", "unit": 0.3,
     "label_format": "%.0f",
     "focal": (2.0, 1.0, 0.9), "position": (5.2, -3.6, 4.4), "up": (0, 0, 1), "angle": 38.0,
     "clip": (2.0, 14.0)},
]
ISSUE4_NODES = [  # (fraction of the range, r, g, b, opacity), as hovTestRef::DatasetTF
    (0.00, 0.05, 0.10, 0.90, 0.02),
    (0.25, 0.10, 0.70, 0.90, 0.08),
    (0.50, 0.20, 0.90, 0.30, 0.25),
    (0.75, 1.00, 0.85, 0.10, 0.50),
    (1.00, 0.95, 0.15, 0.10, 0.85),
]


# The regular 1 -> 8 split of a VTK_QUADRATIC_TETRA at its nodes (corners 0-3, mid-edge
# nodes 4-9 on (0,1), (1,2), (2,0), (0,3), (1,3), (2,3)), octahedron cut along 6-8.
# Conforming across shared faces (a face is always cut into the same 4 triangles), the
# field is exactly the nodal values; vtkDataSetTriangleFilter instead runs its ordered
# (Delaunay) triangulator on the 10 nodes of these non-primary cells, which on the curved
# boundary cells of the T-junction gives 83031 instead of 84168 tetrahedra and a
# non-conforming, overlapping tessellation (our per-pixel witness flags ~18000 pixels).
RED_SPLIT = np.array([[0, 4, 6, 7], [4, 1, 5, 8], [6, 5, 2, 9], [7, 8, 9, 3],
                      [4, 6, 7, 8], [4, 6, 5, 8], [6, 7, 8, 9], [6, 5, 8, 9]])


def split_quadratic_tets(grid):
    """Linear tetrahedra of a grid of quadratic tetrahedra (same points and point data)."""
    from vtkmodules.util.numpy_support import numpy_to_vtkIdTypeArray
    from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkUnstructuredGrid
    conn = vtk_to_numpy(grid.GetCells().GetConnectivityArray()).reshape(-1, 10)
    tets = conn[:, RED_SPLIT].reshape(-1, 4)
    xyz = vtk_to_numpy(grid.GetPoints().GetData()).astype(np.float64)
    a, b, c, d = (xyz[tets[:, k]] for k in range(4))
    flip = np.einsum("ij,ij->i", np.cross(b - a, c - a), d - a) < 0
    tets[flip, 1], tets[flip, 2] = tets[flip, 2], tets[flip, 1].copy()
    cells = vtkCellArray()
    offsets = np.arange(0, 4 * len(tets) + 1, 4, dtype=np.int64)
    cells.SetData(numpy_to_vtkIdTypeArray(offsets, deep=True),
                  numpy_to_vtkIdTypeArray(tets.ravel().astype(np.int64), deep=True))
    out = vtkUnstructuredGrid()
    out.SetPoints(grid.GetPoints())
    out.GetPointData().ShallowCopy(grid.GetPointData())
    out.SetCells(10, cells)  # VTK_TETRA
    return out


def issue4_property(smin, smax, unit):
    ctf = vtkColorTransferFunction()
    otf = vtkPiecewiseFunction()
    for f, r, g, b, a in ISSUE4_NODES:
        ctf.AddRGBPoint(smin + f * (smax - smin), r, g, b)
        otf.AddPoint(smin + f * (smax - smin), a)
    prop = vtkVolumeProperty()
    prop.SetColor(ctf)
    prop.SetScalarOpacity(otf)
    prop.SetScalarOpacityUnitDistance(unit)
    prop.SetInterpolationTypeToLinear()
    prop.ShadeOff()
    return prop, ctf


def issue4_dataset(ds, args, frames, catcher, log, failures):
    """Ours on the native cells beside ours, PT and RC on the tetrahedra: PNGs, montage,
    table lines (the reference is our float image of the native cells)."""
    path = os.path.join(demo.HERE, os.pardir, "Testing", "Data", ds["file"])
    reader = vtkXMLUnstructuredGridReader()
    reader.SetFileName(path)
    reader.Update()
    grid = reader.GetOutput()
    grid.GetPointData().SetActiveScalars(ds["array"])
    smin, smax = grid.GetPointData().GetArray(ds["array"]).GetRange(0)
    t0 = time.perf_counter()
    quadratic = grid.GetNumberOfCells() > 0 and all(
        grid.GetCellType(i) == 24 for i in range(grid.GetNumberOfCells()))
    if quadratic:
        tets = split_quadratic_tets(grid)
        tess_name = "the regular 8-way split of every quadratic tetrahedron at its nodes"
    else:
        tri = vtkDataSetTriangleFilter()
        tri.SetInputData(grid)
        tri.TetrahedraOnlyOn()
        tri.Update()
        tets = tri.GetOutput()
        tess_name = "vtkDataSetTriangleFilter"
    tess_time = time.perf_counter() - t0
    prop, ctf = issue4_property(smin, smax, ds["unit"])
    camera = vtkCamera()
    camera.SetFocalPoint(*ds["focal"])
    camera.SetPosition(*ds["position"])
    camera.SetViewUp(*ds["up"])
    camera.SetViewAngle(ds["angle"])
    camera.SetClippingRange(*ds["clip"])

    def ours():
        m = vtkHighOrderVolumeMapper()
        m.SetOpacitySemanticsToVTKUnstructured()
        return m

    rc = vtkUnstructuredGridVolumeRayCastMapper()
    rc.SetRayIntegrator(vtkUnstructuredGridLinearRayIntegrator())
    rc.SetAutoAdjustSampleDistances(0)
    rc.SetImageSampleDistance(1.0)
    native = "native (%d cells)" % grid.GetNumberOfCells()
    tessellated = "tetrahedra (%d)" % tets.GetNumberOfCells()
    cases = [
        {"key": "hov", "mapper": ours(), "grid": grid, "input": native,
         "name": "vtkHighOrderVolumeMapper (reference)", "label": "HighOrderVolume, native cells"},
        {"key": "hov_tets", "mapper": ours(), "grid": tets, "input": tessellated,
         "name": "vtkHighOrderVolumeMapper", "label": "HighOrderVolume, tetrahedra"},
        {"key": "projected_tetrahedra", "mapper": vtkProjectedTetrahedraMapper(), "grid": tets,
         "input": tessellated, "name": "vtkProjectedTetrahedraMapper",
         "label": "vtkProjectedTetrahedraMapper, tetrahedra"},
        {"key": "ug_raycast", "mapper": rc, "grid": tets, "input": tessellated,
         "name": "vtkUnstructuredGridVolumeRayCastMapper (Bunyk, linear integrator)",
         "label": "vtkUnstructuredGridVolumeRayCastMapper, tetrahedra"},
    ]
    for case in cases:
        case["semantics"] = "VTK-unstructured"
        key = "%s_%s" % (ds["tag"], case["key"])
        try:
            case["result"] = demo.render_case(case, case["grid"], prop, camera, args.size, frames,
                                         catcher)
        except Exception as exc:  # a failed render must fail the demo
            failures.append("%s: exception %r" % (key, exc))
            continue
        res = case["result"]
        printed_all = log.GetOutput() or ""
        printed, log.seen = printed_all[log.seen:], len(printed_all)
        if printed:
            sys.stderr.write("[%s] VTK output:\n%s\n" % (key, printed.strip()))
            if "ERROR" in printed:
                failures.append("%s: VTK printed an error" % key)
        for msg in res["errors"]:
            failures.append("%s: VTK error: %s" % (key, msg.strip()))
        if res["screen_rgb"].max() <= 0.0:
            failures.append("%s: the screen capture is all black" % key)
        demo.write_png(res["png"], os.path.join(args.out, "hov_demo_%s.png" % key))
    ok_cases = [c for c in cases if "result" in c]
    lines = ["", "## %s, array '%s' (range %.4g..%.4g), %s" % (
        ds["file"], ds["array"], smin, smax, native), ""]
    if "result" not in cases[0]:
        return lines
    panels = [c["result"]["labelled"] for c in ok_cases]
    panels.append(demo.legend_image(ctf, smin, smax, args.size, ds["array"], ds["label_format"]))
    demo.write_png(demo.montage(panels, 3, args.size),
              os.path.join(args.out, "hov_demo_%s_montage.png" % ds["tag"]))
    lines.append("VTK's mappers render the %s made by %s in %.3f s "
                 "(not included in their frame times). Reference: our float image of the "
                 "native cells (%s), VTK-unstructured semantics, 5 colour/opacity nodes at the "
                 "same scalars, unit distance %.3g." % (
                     tessellated, tess_name, tess_time, describe_types(grid), ds["unit"]))
    lines.append("")
    lines.extend(demo.comparison_rows(ok_cases, cases[0]["result"]["float_rgb"],
                                 cases[0]["result"]["float_alpha"], failures,
                                 input_column=True))
    lines.append("- Frame times per render [s]: " + "; ".join(
        "%s %s" % (c["key"], ", ".join("%.3f" % t for t in c["result"]["times"]))
        for c in ok_cases))
    return lines


def describe_types(grid):
    names = {10: "tetrahedra", 12: "hexahedra", 13: "wedges", 14: "pyramids",
             24: "quadratic tetrahedra"}
    counts = {}
    for i in range(grid.GetNumberOfCells()):
        t = grid.GetCellType(i)
        counts[t] = counts.get(t, 0) + 1
    return ", ".join("%d %s" % (n, names.get(t, "type %d" % t)) for t, n in sorted(counts.items()))


# Issue 6: the curved order-4 Lagrange datasets (Testing/Data) in the RAY_CAST render mode.
# Small images: the ray caster costs ~1 ms (plate) to ~15-50 ms (T-junction) per ray on one core
# of this machine (hovCurvedRayCaster.h), so the demo stays within a minute or so. Same transfer
# function scheme as the issue-4 datasets; camera: oblique, 1.6 bounding-box diagonals away.
RAYCAST_DATASETS = [
    {"tag": "platehole_raycast", "file": "platehole_lagrange_hex_q4.vtu", "array": "von_mises",
     "direction": (0.3, -0.5, 0.81), "size": 192},
    {"tag": "tjunction_p4_raycast", "file": "tjunction_lagrange_tet_p4.vtu", "array": "speed",
     "direction": (0.35, -0.8, 0.49), "size": 128},
]


def raycast_dataset(ds, args, catcher, log, failures):
    """RAY_CAST image of a Lagrange dataset (RenderImage, no window): PNG and a table row."""
    from vtkmodules.vtkCommonDataModel import vtkImageData
    from vtkmodules.vtkRenderingCore import vtkVolume
    from vtkmodules.util.numpy_support import numpy_to_vtk
    path = os.path.join(demo.HERE, os.pardir, "Testing", "Data", ds["file"])
    reader = vtkXMLUnstructuredGridReader()
    reader.SetFileName(path)
    reader.Update()
    grid = reader.GetOutput()
    grid.GetPointData().SetActiveScalars(ds["array"])
    smin, smax = grid.GetPointData().GetArray(ds["array"]).GetRange(0)
    b = grid.GetBounds()
    centre = [0.5 * (b[2 * k] + b[2 * k + 1]) for k in range(3)]
    diag = sum((b[2 * k + 1] - b[2 * k]) ** 2 for k in range(3)) ** 0.5
    prop, _ = issue4_property(smin, smax, 0.05 * (b[1] - b[0]))
    camera = vtkCamera()
    camera.SetFocalPoint(*centre)
    camera.SetPosition(*[centre[k] + 1.6 * diag * ds["direction"][k] for k in range(3)])
    camera.SetViewUp(0, 0, 1)
    camera.SetViewAngle(30.0)
    camera.SetClippingRange(0.5 * diag, 4.0 * diag)
    mapper = vtkHighOrderVolumeMapper()
    mapper.SetOpacitySemanticsToVTKUnstructured()
    mapper.SetRenderModeToRayCast()
    mapper.SetInputData(grid)
    catcher.watch(mapper)
    volume = vtkVolume()
    volume.SetMapper(mapper)
    volume.SetProperty(prop)
    size = ds["size"]
    errors_before = len(catcher.messages)
    t0 = time.perf_counter()
    status = mapper.RenderImage(camera, volume, size, size)
    seconds = time.perf_counter() - t0
    img = mapper.GetFloatImage()
    rgba = vtk_to_numpy(img.GetPointData().GetArray("RGBA")).reshape(size, size, 4)
    err = vtk_to_numpy(mapper.GetRayCastErrorImage().GetPointData().GetScalars())
    printed_all = log.GetOutput() or ""
    printed, log.seen = printed_all[log.seen:], len(printed_all)
    if printed:
        sys.stderr.write("[%s] VTK output:\n%s\n" % (ds["tag"], printed.strip()))
        if "ERROR" in printed:
            failures.append("%s: VTK printed an error" % ds["tag"])
    for msg in catcher.messages[errors_before:]:
        failures.append("%s: VTK error: %s" % (ds["tag"], msg.strip()))
    covered = int((rgba[..., 3] > 1e-6).sum())
    if status != 1 or not np.isfinite(rgba).all() or covered == 0:
        failures.append("%s: RAY_CAST status %d, covered %d" % (ds["tag"], status, covered))
    png = vtkImageData()
    png.SetDimensions(size, size, 1)
    rgb8 = (np.clip(rgba[..., :3], 0.0, 1.0) * 255.0 + 0.5).astype(np.uint8).reshape(-1, 3)
    png.GetPointData().SetScalars(numpy_to_vtk(rgb8, deep=1))
    demo.write_png(png, os.path.join(args.out, "hov_demo_%s.png" % ds["tag"]))
    return ["", "## %s, array '%s', RAY_CAST (curved order-4 Lagrange cells, issue 6)" % (
        ds["file"], ds["array"]), "",
        "| cells | skipped | image | time [s] | covered pixels | max error estimate |",
        "|---|---|---|---|---|---|",
        "| %d | %d | %dx%d | %.2f | %d | %.2g |" % (
            grid.GetNumberOfCells(), mapper.GetNumberOfSkippedCells(), size, size, seconds,
            covered, float(err.max()) if err.size else -1.0)]
