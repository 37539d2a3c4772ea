"""hov.ParaView.SortFilter: ParaView's "Cell Visibility Sort" (pvbatch) gives the same order and
field data as the VTK 9.1 module's vtkCellVisibilitySortFilter for the same camera (this
process): vtkOriginalCellIds identical for Stein's exact sort, NumberOfCycles and
NumberOfViolations identical (0 violations for the exact sort on the bracket); VTK's
cell-centre depth sort runs through the same filter and its violations are counted.
"""
import json
import os
import subprocess

import numpy as np

import hov_pv_testing as hpt


def main():
    args = hpt.parse_args()
    failures = []
    out = os.path.join(args.temp, "paraview_sort_filter")
    os.makedirs(out, exist_ok=True)
    data = os.path.join(args.data, "bracket_tet4_ccx.vtu")
    proc = subprocess.run([args.pvbatch, os.path.join(hpt.HERE, "pv_sort_filter.py"), args.plugin,
                           data, out], env=hpt.pv_env(args), capture_output=True, text=True,
                          timeout=300)
    if proc.returncode != 0:
        print(proc.stdout + proc.stderr)
    hpt.check(failures, proc.returncode == 0, "pvbatch ran the filter")
    with open(os.path.join(out, "sort.json")) as f:
        pv = json.load(f)

    from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader
    from vtkmodules.vtkRenderingCore import vtkCamera
    from vtkmodules.util.numpy_support import vtk_to_numpy
    from highordervolume import vtkCellVisibilitySortFilter

    def read(path):
        reader = vtkXMLUnstructuredGridReader()
        reader.SetFileName(path)
        reader.Update()
        return reader.GetOutput()

    camera = vtkCamera()
    camera.SetPosition(*pv["camera"]["CameraPosition"])
    camera.SetFocalPoint(*pv["camera"]["CameraFocalPoint"])
    camera.SetViewUp(*pv["camera"]["CameraViewUp"])
    camera.SetViewAngle(pv["camera"]["CameraViewAngle"])
    sorter = vtkCellVisibilitySortFilter()
    sorter.SetInputData(read(data))
    sorter.SetCamera(camera)
    sorter.Update()
    ref = sorter.GetOutput()
    ref_ids = vtk_to_numpy(ref.GetCellData().GetArray("vtkOriginalCellIds"))
    grid = read(pv["stein"]["vtu"])
    ids = vtk_to_numpy(grid.GetCellData().GetArray("vtkOriginalCellIds"))
    hpt.check(failures, ids.shape == ref_ids.shape and np.array_equal(ids, ref_ids),
              "Stein: ParaView's order equals the module's (%d cells)" % ref_ids.size)
    fd = grid.GetFieldData()
    for name in ("NumberOfCycles", "NumberOfViolations", "NumberOfUnorderedCells",
                 "NumberOfCheckedFaces", "SortSeconds"):
        hpt.check(failures, fd.GetArray(name) is not None, "Stein: field data %s present" % name)
    for name in ("NumberOfCycles", "NumberOfViolations"):
        a = fd.GetArray(name).GetTuple1(0)
        b = ref.GetFieldData().GetArray(name).GetTuple1(0)
        hpt.check(failures, a == b and pv["stein"][name] == a,
                  "Stein: %s %g (field data), %g (information property), module %g" % (
                      name, a, pv["stein"][name], b))
    hpt.check(failures, pv["stein"]["NumberOfViolations"] == 0,
              "Stein: 0 violations on the bracket")
    hpt.check(failures, pv["ccd"]["NumberOfViolations"] > 0,
              "cell-centre depth: %d violations (approximate sort)" % pv["ccd"]["NumberOfViolations"])
    hpt.finish(failures)


if __name__ == "__main__":
    main()
