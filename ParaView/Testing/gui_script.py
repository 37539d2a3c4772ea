"""Run inside the ParaView GUI (paraview --script=...): load the plugin, pick "Accurate Volume"
for the zoo in the GUI's render view, render in two modes, save a screenshot, write what it
saw as JSON to $HOV_GUI_RESULT and quit the application."""
import json
import os
import sys

result = {}
try:
    sys.path.insert(0, os.environ["HOV_GUI_PLUGIN_DIR"])
    import hov_paraview_plugin
    hov_paraview_plugin.load(globals())
    from paraview.simple import (ColorBy, GetActiveViewOrCreate, GetColorTransferFunction,
                                 Render, SaveScreenshot, Show, XMLUnstructuredGridReader)
    reader = XMLUnstructuredGridReader(FileName=[os.environ["HOV_GUI_DATA"]])
    view = GetActiveViewOrCreate("RenderView")
    display = Show(reader, view)
    result["available"] = list(display.Representation.Available)
    display.Representation = "Accurate Volume"
    ColorBy(display, ("POINTS", "temperature"))
    lut = GetColorTransferFunction("temperature")
    lut.RescaleTransferFunction(15.0, 120.0)
    lut.ColorSpace = "RGB"  # 3 nodes: a quick frame in the GUI's large view
    display.OpacitySemantics = "VTK unstructured"  # few nodes: a quick frame in a large view
    view.ResetCamera()
    for mode in ("CPU accurate", "OpenGL projection"):
        display.RenderMode = mode
        Render(view)
        display.UpdatePropertyInformation()
        result[mode] = {name: display.GetProperty(name).GetData() for name in (
            "PieceCells", "PieceCellTypes", "RenderedCells", "LastImageTime", "RenderCalls")}
    SaveScreenshot(os.environ["HOV_GUI_PNG"], view, ImageResolution=[320, 240])
except Exception as error:  # reported through the JSON; the test fails on it
    result["error"] = repr(error)
with open(os.environ["HOV_GUI_RESULT"], "w") as f:
    json.dump(result, f)
os._exit(0)  # the GUI has no quit command for scripts
