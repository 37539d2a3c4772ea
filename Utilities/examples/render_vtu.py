"""Render a .vtu with vtkHighOrderVolumeMapper and save a PNG and the float image.

A ParaView-style script on the plain ``vtkmodules`` API:

    /usr/bin/python3 Utilities/examples/render_vtu.py \
        --data Testing/Data/bracket_tet4_ccx.vtu --array von_mises --out bracket

writes bracket.png (the window, off screen) and bracket.vti (the mapper's
float premultiplied RGBA image, array "RGBA"). PYTHONPATH must contain the
folder of the ``highordervolume`` package (the build tree's or the installed one).
"""
import argparse
import os

from vtkmodules.vtkCommonDataModel import vtkPiecewiseFunction
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkIOXML import vtkXMLImageDataWriter, vtkXMLUnstructuredGridReader
from vtkmodules.vtkRenderingCore import (vtkColorTransferFunction, vtkRenderer, vtkVolume,
                                         vtkVolumeProperty, vtkWindowToImageFilter)

import highordervolume  # noqa: F401  (also loads the OpenGL2 overrides)
from highordervolume import vtkHighOrderVolumeMapper
from highordervolume.offscreen import offscreen_window

HERE = os.path.dirname(os.path.abspath(__file__))
BRACKET = os.path.join(HERE, "..", "..", "Testing", "Data", "bracket_tet4_ccx.vtu")


def load(path, array):
    reader = vtkXMLUnstructuredGridReader()
    reader.SetFileName(path)
    reader.Update()
    grid = reader.GetOutput()
    grid.GetPointData().SetActiveScalars(array)
    return grid


def make_property(lo, hi, unit_distance):
    """A cool-to-warm colour map and a rising opacity over [lo, hi]."""
    color = vtkColorTransferFunction()
    for t, r, g, b in ((0.0, 0.23, 0.30, 0.75), (0.5, 0.87, 0.87, 0.87), (1.0, 0.71, 0.02, 0.15)):
        color.AddRGBPoint(lo + t * (hi - lo), r, g, b)
    opacity = vtkPiecewiseFunction()
    opacity.AddPoint(lo, 0.02)
    opacity.AddPoint(lo + 0.5 * (hi - lo), 0.2)
    opacity.AddPoint(hi, 0.9)
    prop = vtkVolumeProperty()
    prop.SetColor(color)
    prop.SetScalarOpacity(opacity)
    prop.SetScalarOpacityUnitDistance(unit_distance)
    prop.SetInterpolationTypeToLinear()
    return prop


def make_view(grid, mapper, prop, size):
    """An off-screen window showing ``mapper`` on a fitted, slightly turned camera."""
    volume = vtkVolume()
    volume.SetMapper(mapper)
    volume.SetProperty(prop)
    renderer = vtkRenderer()
    renderer.SetBackground(0.0, 0.0, 0.0)
    renderer.AddVolume(volume)
    # Offscreen, with an X server (DISPLAY set) or without one (Mesa EGL).
    window = offscreen_window(size[0], size[1])
    window.AddRenderer(renderer)
    camera = renderer.GetActiveCamera()
    camera.SetPosition(0, -1, 0)  # front view, z up (like ParaView's "-Y" view)
    camera.SetFocalPoint(0, 0, 0)
    camera.SetViewUp(0, 0, 1)
    renderer.ResetCamera(grid.GetBounds())
    camera.Azimuth(35)
    camera.Elevation(25)
    camera.OrthogonalizeViewUp()
    renderer.ResetCameraClippingRange(grid.GetBounds())
    return window


def save_png(window, path):
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.ReadFrontBufferOff()
    grab.Update()
    writer = vtkPNGWriter()
    writer.SetFileName(path)
    writer.SetInputConnection(grab.GetOutputPort())
    writer.Write()
    return grab.GetOutput()


def save_vti(image, path):
    writer = vtkXMLImageDataWriter()
    writer.SetFileName(path)
    writer.SetInputData(image)
    writer.Write()


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--data", default=BRACKET)
    parser.add_argument("--array", default="von_mises")
    parser.add_argument("--size", type=int, nargs=2, default=(640, 480))
    parser.add_argument("--unit-distance", type=float, default=1.0)
    parser.add_argument("--out", default="render_vtu", help="output prefix (.png, .vti)")
    args = parser.parse_args(argv)
    grid = load(args.data, args.array)
    lo, hi = grid.GetPointData().GetArray(args.array).GetRange(-1)
    mapper = vtkHighOrderVolumeMapper()
    mapper.SetInputData(grid)
    mapper.SetRenderModeToCPUAccurate()
    window = make_view(grid, mapper, make_property(lo, hi, args.unit_distance), args.size)
    window.Render()
    save_png(window, args.out + ".png")
    save_vti(mapper.GetFloatImage(), args.out + ".vti")
    print("wrote %s.png and %s.vti (%d cells, %.2f s)" % (
        args.out, args.out, mapper.GetNumberOfRenderedCells(), mapper.GetLastImageTime()))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
