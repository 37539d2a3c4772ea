"""pvbatch side of hov.ParaView.SortFilter: the "Cell Visibility Sort" filter.

    pvbatch pv_sort_filter.py plugin data.vtu out_folder

Sorts the grid for a fixed camera with each algorithm and saves each output (.vtu); writes
<out>/sort.json with the filter's information properties.
"""
import json
import os
import sys

from paraview.simple import LoadPlugin, SaveData, UpdatePipeline, XMLUnstructuredGridReader

plugin, data, out = sys.argv[1:4]
LoadPlugin(plugin, remote=False, ns=globals())
reader = XMLUnstructuredGridReader(FileName=[data])
camera = {"CameraPosition": [160.0, -120.0, 150.0], "CameraFocalPoint": [50.0, 30.0, 40.0],
          "CameraViewUp": [0.0, 0.0, 1.0], "CameraViewAngle": 30.0}
results = {}
for algorithm in ("Stein (adjacency graph)", "Cell centre depth (VTK, approximate)"):
    sort = CellVisibilitySort(Input=reader)  # noqa: F821 (defined by LoadPlugin)
    for name, value in camera.items():
        setattr(sort, name, value)
    sort.SortAlgorithm = algorithm
    UpdatePipeline(proxy=sort)
    sort.UpdatePropertyInformation()
    tag = "stein" if algorithm.startswith("Stein") else "ccd"
    path = os.path.join(out, "sorted_%s.vtu" % tag)
    SaveData(path, proxy=sort)
    results[tag] = {"vtu": path,
                    "NumberOfCycles": sort.GetProperty("NumberOfCycles").GetData(),
                    "NumberOfViolations": sort.GetProperty("NumberOfViolations").GetData(),
                    "SortSeconds": sort.GetProperty("SortSeconds").GetData()}
results["camera"] = camera
with open(os.path.join(out, "sort.json"), "w") as f:
    json.dump(results, f, indent=1)
