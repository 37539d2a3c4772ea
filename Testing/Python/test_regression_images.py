"""Regression image tests from Python (highordervolume.regression) against the C++ baselines.

Three scenes of Testing/Regression are rebuilt here from the same description (dataset, array,
transfer function, unit distance, camera, size, render mode): TestHOVBracketCPU (CPU_ACCURATE),
TestHOVZooProjection (OPENGL_PROJECTION) and TestHOVPlateRayCast (RAY_CAST, curved Lagrange
hexahedra). Each is rendered in a window from highordervolume.offscreen (X or Mesa EGL) and
checked with check_window: VTK's comparison (vtkTesting, threshold 0.15) and the strict one
with the C++ tests' tolerances, against Testing/Data/Baseline/<test>.png: Python and C++ give
the same image. A missing baseline fails with a message and writes the candidate.
"""
import math
import os
import sys

from vtkmodules.vtkCommonDataModel import vtkPiecewiseFunction
from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader
from vtkmodules.vtkRenderingCore import vtkColorTransferFunction, vtkRenderer, vtkVolume

from highordervolume import vtkHighOrderVolumeMapper
from highordervolume.offscreen import offscreen_window
from highordervolume.regression import check_window

from hov_pytest import arguments, check, finish

# render_tools.DEFAULT_NODES, as hovRegression.cxx: fraction of the range, r, g, b, opacity.
NODES = [(0.00, 0.15, 0.25, 0.90, 0.02), (0.03, 0.20, 0.50, 1.00, 0.04),
         (0.09, 0.10, 0.90, 0.90, 0.10), (0.20, 0.30, 1.00, 0.30, 0.25),
         (0.35, 1.00, 1.00, 0.10, 0.50), (0.60, 1.00, 0.50, 0.00, 0.80),
         (1.00, 1.00, 0.05, 0.05, 1.00)]
SCENES = {
    "TestHOVBracketCPU": dict(data="bracket_tet4_ccx.vtu", array="von_mises", mode="cpu",
                              size=(128, 128), unit=0.02, semantics=1, tolerance=(0, 0.0)),
    "TestHOVZooProjection": dict(data="zoo_mixed_ccx.vtu", array="temperature", mode="projection",
                                 size=(128, 128), unit=0.15, semantics=1, tolerance=(1, 0.002)),
    "TestHOVPlateRayCast": dict(data="platehole_lagrange_hex_q4.vtu", array="von_mises",
                                mode="ray", size=(64, 64), unit=0.01, semantics=0,
                                tolerance=(0, 0.0)),
}


def render_scene(args, scene):
    reader = vtkXMLUnstructuredGridReader()
    reader.SetFileName(os.path.join(args.data, scene["data"]))
    reader.Update()
    grid = reader.GetOutput()
    smin, smax = grid.GetPointData().GetArray(scene["array"]).GetRange(0)
    b = grid.GetBounds()
    diagonal = math.sqrt((b[1] - b[0]) ** 2 + (b[3] - b[2]) ** 2 + (b[5] - b[4]) ** 2)
    mapper = vtkHighOrderVolumeMapper()
    mapper.SetInputData(grid)
    mapper.SetScalarModeToUsePointFieldData()
    mapper.SelectScalarArray(scene["array"])
    {"cpu": mapper.SetRenderModeToCPUAccurate, "projection": mapper.SetRenderModeToOpenGLProjection,
     "ray": mapper.SetRenderModeToRayCast}[scene["mode"]]()
    mapper.SetOpacitySemantics(scene["semantics"])
    color, opacity = vtkColorTransferFunction(), vtkPiecewiseFunction()
    for f, r, g, bl, a in NODES:
        s = smin + f * (smax - smin)
        color.AddRGBPoint(s, r, g, bl)
        opacity.AddPoint(s, a)
    volume = vtkVolume()
    volume.SetMapper(mapper)
    prop = volume.GetProperty()
    prop.SetColor(color)
    prop.SetScalarOpacity(opacity)
    prop.SetScalarOpacityUnitDistance(scene["unit"] * diagonal)
    prop.SetInterpolationTypeToLinear()
    prop.ShadeOff()
    renderer = vtkRenderer()
    renderer.SetBackground(0.1, 0.1, 0.1)
    renderer.AddVolume(volume)
    camera = renderer.GetActiveCamera()  # fitted before the renderer has a window, as in C++
    camera.SetFocalPoint(0, 0, 0)
    camera.SetPosition(0, -1, 0)
    camera.SetViewUp(0, 0, 1)
    renderer.ResetCamera(b)
    camera.Azimuth(30)
    camera.Elevation(20)
    camera.OrthogonalizeViewUp()
    camera.Zoom(1.3)
    renderer.ResetCameraClippingRange(b)
    window = offscreen_window(*scene["size"])
    window.SetMultiSamples(0)
    window.AddRenderer(renderer)
    return window, (mapper, volume, renderer)


def main():
    args = arguments()
    temp = os.path.join(args.temp, "python_regression" + ("" if os.environ.get("DISPLAY")
                                                           else "_headless"))
    baselines = os.path.join(args.data, "Baseline")
    for name, scene in SCENES.items():
        window, keep = render_scene(args, scene)
        levels, fraction = scene["tolerance"]
        ok, lines = check_window(window, os.path.join(baselines, name + ".png"), temp, name,
                                 levels, fraction)
        print("\n".join(lines))
        check(ok, "%s from Python (%s window) matches the C++ test's baseline" % (
            name, window.GetClassName()))
    window, keep = render_scene(args, SCENES["TestHOVBracketCPU"])
    ok, lines = check_window(window, os.path.join(temp, "no-such-baseline.png"), temp,
                             "MissingBaseline")
    print("\n".join(lines))
    check(not ok and "not found" in lines[0] and
          os.path.exists(os.path.join(temp, "MissingBaseline.png")),
          "a missing baseline fails with a message and writes the candidate")
    return finish()


if __name__ == "__main__":
    sys.exit(main())
