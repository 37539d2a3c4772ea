"""vtkCellVisibilitySortFilter from Python on the bundled bracket.

The bracket (56071 linear tetrahedra, CalculiX) is reordered for an oblique
perspective camera by the default vtkSteinVisibilitySort: the output has
every cell, "vtkOriginalCellIds" is a permutation of the input ids, "SortRank"
is consistent with it, cell data follow their cells, no cycle is reported and
the filter's interior-face check counts 0 violations; front to back is the
reverse of back to front. The same
filter with vtkCellCenterDepthSort reports its violation count (>= 0,
printed). Moving the camera re-executes the filter (its MTime includes the
camera's).
"""
import os
import sys

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkIdTypeArray
from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader
from vtkmodules.vtkRenderingCore import vtkCamera, vtkCellCenterDepthSort

import highordervolume

from hov_pytest import arguments, check, FAILURES


def field(grid, name):
    return vtk_to_numpy(grid.GetFieldData().GetArray(name))


def main():
    args = arguments()

    reader = vtkXMLUnstructuredGridReader()
    reader.SetFileName(os.path.join(args.data, "bracket_tet4_ccx.vtu"))
    reader.Update()
    grid = reader.GetOutput()
    n = grid.GetNumberOfCells()
    # A cell array to follow: the input id itself.
    ids = vtkIdTypeArray()
    ids.SetName("input_id")
    for c in range(n):
        ids.InsertNextValue(c)
    grid.GetCellData().AddArray(ids)

    camera = vtkCamera()
    camera.SetFocalPoint(50, 30, 40)
    camera.SetPosition(160, 120, 180)
    camera.SetViewUp(0, 1, 0)
    camera.SetViewAngle(40)

    sorter = highordervolume.vtkCellVisibilitySortFilter()
    sorter.SetInputData(grid)
    sorter.SetCamera(camera)
    check(sorter.GetVisibilitySort().GetClassName() == "vtkSteinVisibilitySort",
          "default sort is vtkSteinVisibilitySort")
    sorter.Update()
    out = sorter.GetOutput()
    check(out.GetNumberOfCells() == n, f"output has all {n} cells ({out.GetNumberOfCells()})")
    check(out.GetNumberOfPoints() == grid.GetNumberOfPoints(), "points shared")
    orig = vtk_to_numpy(out.GetCellData().GetArray("vtkOriginalCellIds"))
    rank = vtk_to_numpy(out.GetCellData().GetArray("SortRank"))
    follow = vtk_to_numpy(out.GetCellData().GetArray("input_id"))
    check(np.array_equal(np.sort(orig), np.arange(n)), "vtkOriginalCellIds is a permutation")
    check(np.array_equal(rank, np.arange(n)), "SortRank = output index (back to front)")
    check(np.array_equal(follow, orig), "cell data follow their cells")
    # Connectivity follows too (sample).
    ok = True
    for i in range(0, n, 997):
        a = [out.GetCell(i).GetPointId(k) for k in range(4)]
        b = [grid.GetCell(int(orig[i])).GetPointId(k) for k in range(4)]
        ok = ok and a == b
    check(ok, "connectivity follows the cells")
    cycles = int(field(out, "NumberOfCycles")[0])
    violations = int(field(out, "NumberOfViolations")[0])
    faces = int(field(out, "NumberOfCheckedFaces")[0])
    seconds = float(field(out, "SortSeconds")[0])
    print(f"Stein: cycles {cycles}, violations {violations} over {faces} interior faces, "
          f"unordered {int(field(out, 'NumberOfUnorderedCells')[0])}, sort {seconds:.3f} s")
    check(cycles == 0 and len(field(out, "CycleCellIds")) == 0, "no cycles")
    check(faces > 50000 and violations == 0, "Stein: 0 interior-face violations")

    # Front to back is the reverse order.
    sorter.SetDirectionToFrontToBack()
    sorter.Update()
    ftb = vtk_to_numpy(sorter.GetOutput().GetCellData().GetArray("vtkOriginalCellIds"))
    check(np.array_equal(ftb, orig[::-1]), "FRONT_TO_BACK is the reverse of BACK_TO_FRONT")
    check(int(field(sorter.GetOutput(), "NumberOfViolations")[0]) == 0,
          "Stein, front to back: 0 violations")
    # VTK's cell-centre sort through the same filter.
    sorter.SetVisibilitySort(vtkCellCenterDepthSort())
    sorter.Update()
    center = int(field(sorter.GetOutput(), "NumberOfViolations")[0])
    print(f"vtkCellCenterDepthSort: violations {center} over "
          f"{int(field(sorter.GetOutput(), 'NumberOfCheckedFaces')[0])} interior faces, "
          f"cycles field {int(field(sorter.GetOutput(), 'NumberOfCycles')[0])}")
    check(center >= 0, "vtkCellCenterDepthSort: violations reported (>= 0)")
    check(int(field(sorter.GetOutput(), "NumberOfCycles")[0]) == -1,
          "vtkCellCenterDepthSort: cycles not reported (-1)")

    # A camera change re-executes (MTime includes the camera's); checked with
    # the cheap cell-centre sort to keep the test short.
    sorter.SetDirectionToBackToFront()
    sorter.Update()
    first = vtk_to_numpy(sorter.GetOutput().GetCellData().GetArray("vtkOriginalCellIds")).copy()
    before = sorter.GetOutput().GetMTime()
    sorter.Update()
    check(sorter.GetOutput().GetMTime() == before, "no re-execution without a change")
    camera.Azimuth(60)
    sorter.Update()
    moved = vtk_to_numpy(sorter.GetOutput().GetCellData().GetArray("vtkOriginalCellIds"))
    check(sorter.GetOutput().GetMTime() > before and not np.array_equal(moved, first),
          "a camera change re-executes the filter with a new order")

    print(f"{len(FAILURES)} failures")
    return 1 if FAILURES else 0


if __name__ == "__main__":
    sys.exit(main())
