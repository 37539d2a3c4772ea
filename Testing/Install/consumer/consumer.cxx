// Uses the installed module: one tetrahedron with a constant field, rendered
// without OpenGL; the centre pixel must equal the closed form 1 - exp(-tau L).
#include "vtkHighOrderVolumeMapper.h"
#include "hovSegmentIntegral.h" // installed kernel header

#include "vtkCamera.h"
#include "vtkCellType.h"
#include "vtkColorTransferFunction.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkUnstructuredGrid.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <cmath>
#include <cstdio>

int main()
{
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(-1, -1, -1);
  points->InsertNextPoint(1, -1, -1);
  points->InsertNextPoint(0, 1, -1);
  points->InsertNextPoint(0, 0, 1);
  vtkNew<vtkUnstructuredGrid> grid;
  grid->SetPoints(points);
  const vtkIdType ids[4] = { 0, 1, 2, 3 };
  grid->InsertNextCell(VTK_TETRA, 4, ids);
  vtkNew<vtkDoubleArray> s;
  s->SetName("s");
  for (int i = 0; i < 4; ++i)
  {
    s->InsertNextValue(0.5);
  }
  grid->GetPointData()->SetScalars(s);

  vtkNew<vtkColorTransferFunction> ctf;
  ctf->AddRGBPoint(0.0, 1.0, 1.0, 1.0);
  vtkNew<vtkPiecewiseFunction> otf;
  otf->AddPoint(0.0, 0.4);
  vtkNew<vtkVolumeProperty> property;
  property->SetColor(ctf);
  property->SetScalarOpacity(otf);
  vtkNew<vtkHighOrderVolumeMapper> mapper;
  mapper->SetInputData(grid);
  mapper->SetOpacitySemanticsToVTKUnstructured();
  vtkNew<vtkVolume> volume;
  volume->SetMapper(mapper);
  volume->SetProperty(property);
  vtkNew<vtkCamera> camera;
  camera->SetPosition(0, 0, 10);
  camera->SetFocalPoint(0, 0, 0);
  camera->ParallelProjectionOn();
  camera->SetParallelScale(2.0);
  camera->SetClippingRange(1, 20);
  mapper->RenderImage(camera, volume, 3, 3);
  auto* rgba = vtkFloatArray::SafeDownCast(mapper->GetFloatImage()->GetPointData()->GetScalars());
  // Centre pixel ray: x = y = 0 runs from z = -1 to z = 1 inside the tetrahedron
  // (the apex (0,0,1) lies on it): L = 2, tau = 0.4.
  const double expected = 1.0 - std::exp(-0.4 * 2.0);
  const double alpha = rgba ? rgba->GetComponent(4, 3) : -1.0;
  std::printf("centre alpha %.9f expected %.9f\n", alpha, expected);
  hov::SegmentEnd end;
  end.Tau = 0.4;
  const hov::RGBA kernel = hov::IntegrateSegment(2.0, end, end, hov::EmissionModel::WilliamsMax,
    hov::SegmentMethod::Exact);
  return (std::abs(alpha - expected) < 1e-6 && std::abs(kernel.A - expected) < 1e-12) ? 0 : 1;
}
