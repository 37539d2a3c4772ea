"""Volume shading on non-affine cells (distorted hexahedra, a general wedge, pyramids):
CPU_ACCURATE restricts the gradient to polynomial pieces (hov::RestrictCellGradient) and
integrates each as an affine cell's; RAY_CAST (tolerance 1e-9) samples the field and gradient
pointwise on its own curved-cell path. The two must agree per pixel and channel within 1e-6
(float image rounding and both quadratures' estimates are far below), with the headlight and
with a positional light (whose position along each sub-piece's ray matters), with gradient
opacity, in both emission models. Each case must cover a good part of the image and give
finite pixels only; CPU_ACCURATE's shading error estimate must stay below 1e-6.
"""
import sys

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkDoubleArray, vtkPoints
from vtkmodules.vtkCommonDataModel import (VTK_HEXAHEDRON, VTK_PYRAMID, VTK_WEDGE,
                                           vtkPiecewiseFunction, vtkUnstructuredGrid)
from vtkmodules.vtkRenderingCore import (vtkColorTransferFunction, vtkLight, vtkRenderer,
                                         vtkVolume, vtkVolumeProperty)

from highordervolume import vtkHighOrderVolumeMapper
from highordervolume.offscreen import offscreen_window

from hov_pytest import arguments, check, finish

SIZE = 72
TOLERANCE = 1e-6


def field(x):
    return 0.3 + 0.5 * x[0] - 0.4 * x[1] + 0.6 * x[2] + 0.35 * x[0] * x[1] * x[2] - 0.2 * x[2] ** 2


def grid():
    """Cells apart from each other (no overlap), corners moved by up to 0.12."""
    rng = np.random.default_rng(2026)
    points = vtkPoints()
    scalars = vtkDoubleArray()
    scalars.SetName("s")
    out = vtkUnstructuredGrid()

    def cell(kind, corners, offset):
        ids = []
        for c in corners:
            q = np.array(c, float) + offset + 0.12 * rng.uniform(-1.0, 1.0, 3)
            ids.append(points.InsertNextPoint(*q))
            scalars.InsertNextValue(field(q))
        out.InsertNextCell(kind, len(ids), ids)

    cube = [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [0, 0, 1], [1, 0, 1], [1, 1, 1], [0, 1, 1]]
    for i in range(3):
        cell(VTK_HEXAHEDRON, cube, np.array([1.4 * i, 0.0, 0.0]))
    # VTK's wedge order: (0, 1, 2)'s normal points away from (3, 4, 5).
    cell(VTK_WEDGE, [[0, 0, 0], [0, 1, 0], [1, 0, 0], [0, 0, 1], [0, 1, 1], [1, 0, 1]],
         np.array([0.0, 1.5, 0.0]))
    cell(VTK_PYRAMID, [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [0.5, 0.5, 1.0]],
         np.array([1.4, 1.5, 0.0]))
    cell(VTK_PYRAMID, [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [0.3, 0.6, 1.2]],
         np.array([2.8, 1.5, 0.0]))
    out.SetPoints(points)
    out.GetPointData().SetScalars(scalars)
    return out


def render(data, mode, positional, emission):
    mapper = vtkHighOrderVolumeMapper()
    mapper.SetInputData(data)
    mapper.SetRenderMode(mode)
    mapper.SetRayCastTolerance(1e-9)
    mapper.SetEmissionModel(emission)
    lo, hi = data.GetPointData().GetScalars().GetRange()
    prop = vtkVolumeProperty()
    prop.ShadeOn()
    prop.SetAmbient(0.3)
    prop.SetDiffuse(0.5)
    prop.SetSpecular(0.2)
    prop.SetSpecularPower(8.0)
    color = vtkColorTransferFunction()
    color.AddRGBPoint(lo - 0.1, 0.1, 0.5, 0.2)
    color.AddRGBPoint(hi + 0.1, 0.6, 0.1, 0.4)
    opacity = vtkPiecewiseFunction()
    opacity.AddPoint(lo - 0.1, 0.3)
    opacity.AddPoint(hi + 0.1, 0.9)
    gradient = vtkPiecewiseFunction()
    gradient.AddPoint(0.0, 0.4)
    gradient.AddPoint(2.0, 1.0)
    prop.SetColor(color)
    prop.SetScalarOpacity(opacity)
    prop.SetGradientOpacity(gradient)
    volume = vtkVolume()
    volume.SetMapper(mapper)
    volume.SetProperty(prop)
    renderer = vtkRenderer()
    renderer.AddVolume(volume)
    if positional:
        light = vtkLight()
        light.SetPositional(True)
        light.SetPosition(1.5, -2.0, 3.0)
        light.SetFocalPoint(1.5, 1.0, 0.5)
        light.SetConeAngle(120.0)
        renderer.AddLight(light)
    renderer.ResetCamera()
    renderer.GetActiveCamera().Azimuth(25.0)
    renderer.GetActiveCamera().Elevation(30.0)
    window = offscreen_window(SIZE, SIZE)  # X or, without a display, EGL
    window.AddRenderer(renderer)
    window.Render()
    image = vtkDoubleArray()
    mapper.GetDoubleImage(image)
    return vtk_to_numpy(image).copy(), mapper.GetShadingErrorEstimate()


def main():
    arguments()
    data = grid()
    for positional in (False, True):
        for emission in (vtkHighOrderVolumeMapper.WILLIAMS_MAX,
                         vtkHighOrderVolumeMapper.WILHELMS_VAN_GELDER):
            name = "%s light, emission %d" % ("positional" if positional else "head", emission)
            cpu, estimate = render(data, vtkHighOrderVolumeMapper.CPU_ACCURATE, positional,
                                   emission)
            ray, _ = render(data, vtkHighOrderVolumeMapper.RAY_CAST, positional, emission)
            covered = int((cpu[:, 3] > 0).sum())
            check(cpu.shape == (SIZE * SIZE, 4) and ray.shape == cpu.shape,
                  "%s: both images %dx%d RGBA" % (name, SIZE, SIZE))
            check(np.isfinite(cpu).all() and np.isfinite(ray).all(), "%s: finite pixels" % name)
            check(covered > SIZE * SIZE // 8, "%s: %d pixels covered" % (name, covered))
            diff = np.abs(cpu - ray).max(axis=0)
            check(bool((diff <= TOLERANCE).all()),
                  "%s: CPU_ACCURATE vs RAY_CAST max difference per channel %s <= %g"
                  % (name, np.array2string(diff, precision=2), TOLERANCE))
            check(0.0 <= estimate <= TOLERANCE,
                  "%s: CPU_ACCURATE shading error estimate %.3g" % (name, estimate))
    return finish()


if __name__ == "__main__":
    sys.exit(main())
