"""One PNG per feature of vtkHighOrderVolumeMapper's accurate CPU path.

  isosurfaces.png  tjunction (P2 tetrahedra, array `speed`): three shaded
                   semitransparent isosurfaces embedded in a faint volume
  clipping.png     the same with a clipping plane (half the pipe removed)
  fields.png       the same pipe, extinction from `speed`, colour from a second array,
                   `velocity_potential` (three-field rendering, HIAC 4)
  splat_off.png / splat_on.png
                   the bracket (56071 linear tetrahedra) at a size where most
                   cells are smaller than a pixel, exact and splatted
  splat_off_on.png the two side by side, enlarged 3x

Run (the images are the mapper's float images, composited over black):
  PYTHONPATH=<build>/lib/python3/dist-packages \\
    xvfb-run -a -s "-screen 0 1280x1024x24 -noreset" /usr/bin/python3 Utilities/hov_features.py --out /tmp/features
"""
import argparse
import os
import sys

import numpy as np
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.vtkCommonDataModel import vtkImageData, vtkPiecewiseFunction, vtkPlane
from vtkmodules.vtkFiltersCore import vtkImageAppend
from vtkmodules.vtkImagingCore import vtkImageResize
from vtkmodules.vtkIOImage import vtkPNGReader, vtkPNGWriter
from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader
from vtkmodules.vtkRenderingCore import (vtkCamera, vtkColorTransferFunction, vtkVolume,
                                         vtkVolumeProperty)

try:
    from highordervolume import vtkHighOrderVolumeMapper
except ImportError:
    sys.exit("cannot import highordervolume (set PYTHONPATH=<build>/lib/python3/dist-packages)")

HERE = os.path.dirname(os.path.abspath(__file__))
DATA = os.path.join(HERE, "..", "Testing", "Data")


def read(name, array):
    reader = vtkXMLUnstructuredGridReader()
    reader.SetFileName(os.path.join(DATA, name))
    reader.Update()
    grid = reader.GetOutput()
    grid.GetPointData().SetActiveScalars(array)
    return grid


def write(mapper, path):
    img = mapper.GetFloatImage()
    w, h, _ = img.GetDimensions()
    rgba = vtk_to_numpy(img.GetPointData().GetArray("RGBA")).reshape(h * w, 4)
    rgb = (np.clip(rgba[:, :3], 0.0, 1.0) * 255.0 + 0.5).astype(np.uint8)
    out = vtkImageData()
    out.SetDimensions(w, h, 1)
    out.GetPointData().SetScalars(numpy_to_vtk(rgb, deep=1))
    writer = vtkPNGWriter()
    writer.SetFileName(path)
    writer.SetInputData(out)
    writer.Write()
    print("wrote", path, "(%.2f s)" % mapper.GetLastImageTime())


def volume_for(mapper, lo, hi, opacity, unit):
    color = vtkColorTransferFunction()
    color.AddRGBPoint(lo, 0.1, 0.2, 0.8)
    color.AddRGBPoint(0.5 * (lo + hi), 0.9, 0.9, 0.9)
    color.AddRGBPoint(hi, 0.8, 0.2, 0.1)
    alpha = vtkPiecewiseFunction()
    alpha.AddPoint(lo, opacity)
    alpha.AddPoint(hi, opacity)
    prop = vtkVolumeProperty()
    prop.SetColor(color)
    prop.SetScalarOpacity(alpha)
    prop.SetScalarOpacityUnitDistance(unit)
    prop.SetInterpolationTypeToLinear()
    prop.ShadeOn()
    prop.SetAmbient(0.25)
    prop.SetDiffuse(0.7)
    prop.SetSpecular(0.3)
    prop.SetSpecularPower(20)
    volume = vtkVolume()
    volume.SetMapper(mapper)
    volume.SetProperty(prop)
    return volume


def pipe_camera():
    """The view of the T-junction used by every pipe image."""
    cam = vtkCamera()
    cam.SetFocalPoint(0.0, 0.6, 0.0)
    cam.SetPosition(1.4, 2.2, 3.4)
    cam.SetViewUp(0, 1, 0)
    cam.SetViewAngle(35)
    cam.SetClippingRange(1, 20)
    return cam


def tjunction(out, size):
    grid = read("tjunction_tet10_dolfinx.vtu", "speed")
    lo, hi = grid.GetPointData().GetArray("speed").GetRange()
    mapper = vtkHighOrderVolumeMapper()
    mapper.SetInputData(grid)
    volume = volume_for(mapper, lo, hi, 0.35, 0.5)
    for value, rgb, opacity in ((0.75, (0.3, 0.6, 1.0), 0.3), (1.3, (1.0, 0.8, 0.3), 0.5),
                                (2.0, (1.0, 0.3, 0.2), 0.9)):
        mapper.AddIsosurface(value, *rgb, opacity)
    cam = pipe_camera()
    mapper.RenderImage(cam, volume, size, size)
    write(mapper, os.path.join(out, "isosurfaces.png"))
    plane = vtkPlane()
    plane.SetOrigin(0, 0, 0)
    plane.SetNormal(0, 0, -1)  # keep z <= 0: the pipe cut open along its axis
    mapper.AddClippingPlane(plane)
    mapper.RenderImage(cam, volume, size, size)
    write(mapper, os.path.join(out, "clipping.png"))


def fields(out, size):
    grid = read("tjunction_tet10_dolfinx.vtu", "speed")
    lo, hi = grid.GetPointData().GetArray("speed").GetRange()
    plo, phi = grid.GetPointData().GetArray("velocity_potential").GetRange()
    mapper = vtkHighOrderVolumeMapper()
    mapper.SetInputData(grid)
    volume = volume_for(mapper, lo, hi, 0.35, 0.5)
    alpha = volume.GetProperty().GetScalarOpacity()
    alpha.RemoveAllPoints()  # extinction grows with the speed
    alpha.AddPoint(lo, 0.05)
    alpha.AddPoint(hi, 0.9)
    color = volume.GetProperty().GetRGBTransferFunction()
    color.RemoveAllPoints()  # colour follows the potential
    color.AddRGBPoint(plo, 0.2, 0.4, 1.0)
    color.AddRGBPoint(0.5 * (plo + phi), 0.95, 0.95, 0.95)
    color.AddRGBPoint(phi, 1.0, 0.5, 0.1)
    mapper.SetColorArrayName("velocity_potential")
    cam = pipe_camera()
    mapper.RenderImage(cam, volume, size, size)
    write(mapper, os.path.join(out, "fields.png"))


def bracket(out, size):
    grid = read("bracket_tet4_ccx.vtu", "von_mises")
    mapper = vtkHighOrderVolumeMapper()
    mapper.SetInputData(grid)
    volume = volume_for(mapper, 0.0, 170.0, 0.3, 20.0)
    cam = vtkCamera()
    bounds = grid.GetBounds()
    centre = [0.5 * (bounds[2 * k] + bounds[2 * k + 1]) for k in range(3)]
    diag = sum((bounds[2 * k + 1] - bounds[2 * k]) ** 2 for k in range(3)) ** 0.5
    cam.SetFocalPoint(*centre)
    cam.SetPosition(centre[0] + 1.2 * diag, centre[1] + 1.8 * diag, centre[2] + 3.2 * diag)
    cam.SetViewUp(0, 0, 1)
    cam.SetViewAngle(30)
    cam.SetClippingRange(0.5 * diag, 8 * diag)
    for splat in (False, True):
        mapper.SetSplatting(splat)
        mapper.RenderImage(cam, volume, size, size)
        print("  splatted %d of %d cells" % (mapper.GetNumberOfSplattedCells(),
                                               mapper.GetNumberOfRenderedCells()))
        write(mapper, os.path.join(out, "splat_on.png" if splat else "splat_off.png"))
    side_by_side([os.path.join(out, n) for n in ("splat_off.png", "splat_on.png")],
                 os.path.join(out, "splat_off_on.png"), 3)


def side_by_side(paths, path, magnification):
    """The PNGs next to each other, each enlarged by an integer factor."""
    append = vtkImageAppend()
    append.SetAppendAxis(0)
    for name in paths:
        reader = vtkPNGReader()
        reader.SetFileName(name)
        resize = vtkImageResize()
        resize.SetInputConnection(reader.GetOutputPort())
        resize.SetResizeMethodToMagnificationFactors()
        resize.SetMagnificationFactors(magnification, magnification, 1)
        append.AddInputConnection(resize.GetOutputPort())
    writer = vtkPNGWriter()
    writer.SetFileName(path)
    writer.SetInputConnection(append.GetOutputPort())
    writer.Write()
    print("wrote", path)


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--out", default="features")
    parser.add_argument("--size", type=int, default=384)
    parser.add_argument("--splat-size", type=int, default=128)
    args = parser.parse_args()
    os.makedirs(args.out, exist_ok=True)
    tjunction(args.out, args.size)
    fields(args.out, args.size)
    bracket(args.out, args.splat_size)


if __name__ == "__main__":
    main()
