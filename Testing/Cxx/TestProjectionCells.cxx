// OPENGL_PROJECTION mode on hexahedra, wedges, pyramids and voxels (issue 5,
// acceptance 4): each cell is projected whole from its own faces (no
// tetrahedralization) when no transfer-function node lies inside its scalar
// range. Scene: one cell of each type side by side (affine shapes, a linear
// field, every transfer-function node outside the field's range, so colour
// and extinction are linear along every ray), against the CPU path's float
// image: M3 within 2/255 at every covered pixel, one slab per cell (no
// splitting) in both projections; then a transfer function with a node
// inside every cell (slabs with approximate caps): the error is printed and
// must stay below 8/255; the same bound in GPU-compatible semantics, where
// the coarse refinement of -ln(1 - a) cuts the cells.
#include "hovTestScenes.h"

#include "vtkCamera.h"
#include "vtkCellType.h"
#include "vtkDoubleArray.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkUnstructuredGrid.h"

#include <cmath>
#include <iostream>
#include <string>

using namespace hovTest;

namespace
{
vtkSmartPointer<vtkUnstructuredGrid> Zoo()
{
  // Unit cells shifted along x; scalar s = 0.3 + 0.2 x' + 0.15 y + 0.1 z (x' local).
  const double hex[8][3] = { { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 0 }, { 0, 0, 1 },
    { 1, 0, 1 }, { 1, 1, 1 }, { 0, 1, 1 } };
  const double voxel[8][3] = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 1, 1, 0 }, { 0, 0, 1 },
    { 1, 0, 1 }, { 0, 1, 1 }, { 1, 1, 1 } };
  // VTK's wedge: the (0,1,2) normal points away from (3,4,5).
  const double wedge[6][3] = { { 0, 0, 0 }, { 0, 1, 0 }, { 1, 0, 0 }, { 0, 0, 1 }, { 0, 1, 1 },
    { 1, 0, 1 } };
  const double pyramid[5][3] = { { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 0 },
    { 0.5, 0.5, 1 } };
  struct C
  {
    int Type, N;
    const double (*P)[3];
  };
  const C cells[] = { { VTK_HEXAHEDRON, 8, hex }, { VTK_VOXEL, 8, voxel }, { VTK_WEDGE, 6, wedge },
    { VTK_PYRAMID, 5, pyramid } };
  vtkNew<vtkPoints> pts;
  vtkNew<vtkDoubleArray> s;
  s->SetName("s");
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  grid->Allocate(4);
  double x0 = -2.4;
  for (const C& c : cells)
  {
    vtkIdType ids[8];
    for (int i = 0; i < c.N; ++i)
    {
      ids[i] = pts->InsertNextPoint(x0 + c.P[i][0], c.P[i][1] - 0.5, c.P[i][2] - 0.5);
      s->InsertNextValue(0.3 + 0.2 * c.P[i][0] + 0.15 * c.P[i][1] + 0.1 * c.P[i][2]);
    }
    grid->InsertNextCell(c.Type, c.N, ids);
    x0 += 1.25;
  }
  grid->SetPoints(pts);
  grid->GetPointData()->SetScalars(s);
  return grid;
}

}

int TestProjectionCells(int, char*[])
{
  Checker ck;
  VolumeScene scene(Zoo());
  scene.Tf.Color->AddRGBPoint(0.0, 0.9, 0.3, 0.1);
  scene.Tf.Color->AddRGBPoint(1.0, 0.1, 0.4, 0.9);
  scene.Tf.Opacity->AddPoint(0.0, 0.1);
  scene.Tf.Opacity->AddPoint(1.0, 0.9);
  scene.Tf.Property->SetScalarOpacityUnitDistance(0.6);
  scene.Mapper->SetOpacitySemanticsToVTKUnstructured();
  vtkNew<vtkCamera> cam;
  vtkSmartPointer<vtkRenderer> ren = BlackRenderer(cam);
  ren->AddVolume(scene.Volume);
  vtkSmartPointer<vtkRenderWindow> win = OffscreenWindow(ren, 200, 90, 0);
  for (int parallel = 0; parallel < 2; ++parallel)
  {
    for (int inside = 0; inside < 2; ++inside)
    {
      if (inside)
      {
        scene.Tf.Opacity->AddPoint(0.5, 0.2); // a node inside every cell's range
      }
      cam->SetFocalPoint(0, 0, 0);
      cam->SetPosition(1.5, -4.0, 2.5);
      cam->SetViewUp(0, 0, 1);
      cam->SetParallelProjection(parallel);
      cam->SetParallelScale(1.3);
      cam->SetViewAngle(35);
      cam->SetClippingRange(1, 10);
      const CPUAndProjection images = RenderCPUAndProjectionM3(scene.Mapper, win);
      const Image &cpu = images.CPU, &proj = images.Projection;
      const double err = Diff(proj, cpu).Max;
      const std::string label = std::string(parallel ? "parallel" : "perspective") +
        (inside ? ", node inside the cells" : ", no node inside");
      std::cout << label << ": max |M3 - CPU| = " << err * 255 << "/255, slabs "
                << scene.Mapper->GetNumberOfProjectedSlabs() << ", triangles "
                << scene.Mapper->GetNumberOfProjectedTriangles() << ", covered "
                << CheckImage(cpu).Covered << "\n";
      ck.Check(CheckImage(cpu).Covered > 2000, label + ": volume drawn");
      if (!inside)
      {
        ck.Check(err <= 2.0 / 255, label + ": M3 within 2/255 of the CPU image");
        ck.Check(scene.Mapper->GetNumberOfProjectedSlabs() == 4, label + ": each cell whole");
      }
      else
      {
        ck.Check(err <= 8.0 / 255, label + ": M3 within 8/255 (approximate caps)");
      }
      if (inside)
      {
        scene.Tf.Opacity->RemovePoint(0.5);
      }
    }
  }
  // GPU-compatible semantics: -ln(1 - a) bends, so the projection's slabs
  // include coarse refinement nodes (vtkHighOrderTransferFunction::
  // SlabTolerance) and the cells are cut (approximate caps) even without a
  // node of the property inside; the extinction per fragment is exact.
  scene.Mapper->SetOpacitySemanticsToGPUCompatible();
  cam->SetParallelProjection(0);
  const CPUAndProjection gpu = RenderCPUAndProjectionM3(scene.Mapper, win);
  const double errGPU = Diff(gpu.Projection, gpu.CPU).Max;
  std::cout << "GPU-compatible semantics, perspective: max |M3 - CPU| = " << errGPU * 255
            << "/255, slabs " << scene.Mapper->GetNumberOfProjectedSlabs() << "\n";
  ck.Check(errGPU <= 8.0 / 255 && scene.Mapper->GetNumberOfProjectedSlabs() > 4,
    "GPU-compatible semantics: cells cut at the slab nodes, M3 within 8/255 (approximate caps)");
  if (!scene.NoMessages())
  {
    std::cout << "message: " << Msg(scene.Observer->GetWarningMessage()) << "\n";
  }
  ck.Check(scene.NoMessages(), "no messages");
  return ck.Result();
}
