"""hov.ParaView.BadInput: faults inside ParaView give clear messages, never a crash or a hang.

1. A mesh of tetrahedra (x in [0, 1]) beside a block of triangles (x in [2, 3]: 2D cells,
   which the volume mapper rejects), on 1 and on 2 ranks: the kd-tree split gives rank 1
   a piece of triangles only. Both runs must print the mapper's message about the
   unsupported cells and draw the same image (the tetrahedra) within 3/255.
2. One hexahedron on 3 ranks: two ranks get an empty piece. They must say so (rank named)
   and the image must equal the 1-rank image within 3/255.
3. No array to colour by ("Solid Color"; ParaView then draws no volume at all): the
   representation says what is missing, the image is empty, pvbatch exits normally.
4. The ParaView version check of the examples' loader (hov_paraview_plugin.py): a plugin
   built for another ParaView is refused with a message naming both versions.
Every pvbatch run has a timeout: a hang fails the test.
"""
import os
import subprocess
import sys

import numpy as np

import hov_pv_testing as hpt

SIZE = (160, 160)


def write_grid(path, with_triangles):
    """Tetrahedra on [0,1]^3 (5 per cube, 6^3 cubes) with a linear field, and optionally
    a block of triangles on x in [2, 3] (VTK_TRIANGLE, unsupported by the volume mapper)."""
    from vtkmodules.vtkCommonCore import vtkDoubleArray, vtkPoints
    from vtkmodules.vtkCommonDataModel import vtkUnstructuredGrid, VTK_TETRA, VTK_TRIANGLE
    from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridWriter
    n = 6
    pts = vtkPoints()
    field = vtkDoubleArray()
    field.SetName("f")
    index = {}
    for k in range(n + 1):
        for j in range(n + 1):
            for i in range(n + 1):
                x, y, z = i / n, j / n, k / n
                index[i, j, k] = pts.InsertNextPoint(x, y, z)
                field.InsertNextValue(x + 2 * y + 3 * z)
    grid = vtkUnstructuredGrid()
    tets = [(0, 1, 3, 5), (0, 3, 2, 6), (0, 5, 4, 6), (3, 5, 6, 7), (0, 3, 5, 6)]
    for k in range(n):
        for j in range(n):
            for i in range(n):
                c = [index[i + a, j + b, k + d] for d in (0, 1) for b in (0, 1) for a in (0, 1)]
                for t in tets:
                    grid.InsertNextCell(VTK_TETRA, 4, [c[v] for v in t])
    if with_triangles:
        for k in range(n + 1):
            for j in range(n + 1):
                for i in range(n + 1):
                    x, y, z = 2 + i / n, j / n, k / n
                    index["t", i, j, k] = pts.InsertNextPoint(x, y, z)
                    field.InsertNextValue(3.0)
        for k in range(n + 1):
            for j in range(n):
                for i in range(n):
                    a, b = index["t", i, j, k], index["t", i + 1, j, k]
                    c, d = index["t", i, j + 1, k], index["t", i + 1, j + 1, k]
                    grid.InsertNextCell(VTK_TRIANGLE, 3, [a, b, d])
                    grid.InsertNextCell(VTK_TRIANGLE, 3, [a, d, c])
    grid.SetPoints(pts)
    grid.GetPointData().AddArray(field)
    writer = vtkXMLUnstructuredGridWriter()
    writer.SetFileName(path)
    writer.SetInputData(grid)
    writer.Write()


def write_hexahedron(path):
    from vtkmodules.vtkCommonCore import vtkDoubleArray, vtkPoints
    from vtkmodules.vtkCommonDataModel import vtkUnstructuredGrid, VTK_HEXAHEDRON
    from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridWriter
    pts = vtkPoints()
    field = vtkDoubleArray()
    field.SetName("f")
    for z in (0, 1):
        for y in (0, 1):
            for x in (0, 1):
                pts.InsertNextPoint(x, y, z)
                field.InsertNextValue(x + y + z)
    grid = vtkUnstructuredGrid()
    grid.SetPoints(pts)
    grid.InsertNextCell(VTK_HEXAHEDRON, 8, [0, 1, 3, 2, 4, 5, 7, 6])
    grid.GetPointData().AddArray(field)
    writer = vtkXMLUnstructuredGridWriter()
    writer.SetFileName(path)
    writer.SetInputData(grid)
    writer.Write()


def custom_case(name, path, camera, lo, hi, **extra):
    case = {"name": name, "dataset": name, "data": path, "array": "f", "association": "POINTS",
            "color": [[lo, 0.1, 0.3, 0.9], [0.5 * (lo + hi), 0.9, 0.9, 0.3], [hi, 0.9, 0.1, 0.1]],
            "opacity": [[lo, 0.1], [hi, 0.6]], "unit_distance": 0.3, "camera": camera,
            "properties": {"RenderMode": "CPU accurate"}, "mode": 0}
    case.update(extra)
    return case


def compare_runs(failures, label, one, many, bound=3.0):
    a = hpt.read_png_rgb(one["png"])
    b = hpt.read_png_rgb(many["png"])
    dmax = float(np.abs(a - b).max())
    hpt.check(failures, dmax <= bound and a.max() > 50,
              "%s: image vs the 1-rank image: max %.0f/255 (<= %.0f), 1-rank max %.0f" % (
                  label, dmax, bound, a.max()))


def main():
    args = hpt.parse_args()
    failures = []
    tmp = os.path.join(args.temp, "paraview_bad_input")
    os.makedirs(tmp, exist_ok=True)

    # 1. A rank with only unsupported cells.
    mixed = os.path.join(tmp, "tets_and_triangles.vtu")
    write_grid(mixed, True)
    cam = {"position": [1.5, -5.0, 2.5], "focal_point": [1.5, 0.5, 0.5], "view_up": [0, 0, 1],
           "view_angle": 40.0}
    cases = [custom_case("unsupported", mixed, cam, 0.0, 6.0)]
    one, err1 = hpt.run_pvbatch(args, cases, os.path.join(tmp, "unsupported_1"), SIZE,
                                timeout=300)
    two, err2 = hpt.run_pvbatch(args, cases, os.path.join(tmp, "unsupported_2"), SIZE,
                                ranks=2, threads=1, timeout=300)
    key = "cells are of types not yet supported"
    hpt.check(failures, key in err1 and key in err2,
              "unsupported cells: the mapper's message on 1 and on 2 ranks")
    hpt.check(failures, one["cases"][0]["info"]["SkippedCells"] == 7 * 6 * 6 * 2,
              "unsupported cells: 1 rank skips the %d triangles" % (7 * 6 * 6 * 2))
    compare_runs(failures, "unsupported cells, 2 ranks", one["cases"][0], two["cases"][0])

    # 2. Empty pieces: one hexahedron on 3 ranks.
    hexa = os.path.join(tmp, "one_hexahedron.vtu")
    write_hexahedron(hexa)
    cam = {"position": [2.6, -2.2, 2.4], "focal_point": [0.5, 0.5, 0.5], "view_up": [0, 0, 1],
           "view_angle": 30.0}
    cases = [custom_case("empty", hexa, cam, 0.0, 3.0)]
    one, _ = hpt.run_pvbatch(args, cases, os.path.join(tmp, "empty_1"), SIZE, timeout=300)
    three, err3 = hpt.run_pvbatch(args, cases, os.path.join(tmp, "empty_3"), SIZE, ranks=3,
                                  threads=1, oversubscribe=True, timeout=300)
    # Once per piece; ParaView may deliver a new piece for the screenshot's second render.
    empty_ranks = sorted({line[line.find("rank"):line.find(" received")]
                          for line in err3.splitlines() if "received an empty piece" in line})
    hpt.check(failures, len(empty_ranks) == 2,
              "empty pieces: two ranks said so: %s" % empty_ranks)
    compare_runs(failures, "empty pieces, 3 ranks", one["cases"][0], three["cases"][0])

    # 3. No scalars: Solid Color.
    case = custom_case("noscalars", hexa, cam, 0.0, 3.0)
    case["association"] = "NONE"
    res, err = hpt.run_pvbatch(args, [case], os.path.join(tmp, "noscalars"), SIZE, timeout=300)
    img = hpt.read_png_rgb(res["cases"][0]["png"])
    hpt.check(failures, "needs a point or cell array to colour by" in err and img.max() == 0,
              "no scalars: a message, an empty image, pvbatch exited normally")

    # 4. Another ParaView version: the loader refuses with both versions named.
    loader = os.path.join(os.path.dirname(args.plugin), "hov_paraview_plugin.py")
    script = os.path.join(tmp, "version.py")
    with open(script, "w") as f:
        f.write("import sys\nsys.path.insert(0, %r)\nimport hov_paraview_plugin as h\n"
                "h.BUILT_FOR = (5, 10, 1)\ntry:\n    h.load(globals())\n"
                "except RuntimeError as e:\n    print('REFUSED:', e)\n" % os.path.dirname(loader))
    proc = subprocess.run([args.pvbatch, script], env=hpt.pv_env(args), capture_output=True,
                          text=True, timeout=120)
    text = proc.stdout + proc.stderr
    refused = [line for line in text.splitlines() if line.startswith("REFUSED:")]
    hpt.check(failures, proc.returncode == 0 and refused and "5.10.1" in refused[0] and
              "5.11" in refused[0], "another version: %s" % (refused[0] if refused else text[-300:]))
    hpt.finish(failures)


if __name__ == "__main__":
    main()
