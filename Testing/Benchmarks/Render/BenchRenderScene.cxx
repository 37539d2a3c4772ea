// hovBenchRender: the meshes, their transfer function and the camera (see BenchRender.h).
#include "BenchRender.h"

#include "vtkCamera.h"
#include "vtkCellType.h"
#include "vtkColorTransferFunction.h"
#include "vtkDataArray.h"
#include "vtkDataSetTriangleFilter.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkRTAnalyticSource.h"
#include "vtkVolumeProperty.h"
#include "vtkXMLUnstructuredGridReader.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <sstream>

namespace hovBench
{
vtkIdType CountTetras(vtkUnstructuredGrid* grid)
{
  vtkIdType n = 0;
  for (vtkIdType i = 0; i < grid->GetNumberOfCells(); ++i)
  {
    n += grid->GetCellType(i) == VTK_TETRA ? 1 : 0;
  }
  return n;
}

vtkSmartPointer<vtkVolumeProperty> MakeProperty(
  const double range[2], double unitDistance, double transparentBelow)
{
  static const double nodes[7][5] = {
    { 0.00, 0.15, 0.25, 0.90, 0.02 },
    { 0.03, 0.20, 0.50, 1.00, 0.04 },
    { 0.09, 0.10, 0.90, 0.90, 0.10 },
    { 0.20, 0.30, 1.00, 0.30, 0.25 },
    { 0.35, 1.00, 1.00, 0.10, 0.50 },
    { 0.60, 1.00, 0.50, 0.00, 0.80 },
    { 1.00, 1.00, 0.05, 0.05, 1.00 },
  };
  vtkNew<vtkColorTransferFunction> ctf;
  vtkNew<vtkPiecewiseFunction> otf;
  const double span = range[1] - range[0];
  for (const auto& n : nodes)
  {
    const double s = range[0] + n[0] * span;
    ctf->AddRGBPoint(s, n[1], n[2], n[3]);
    otf->AddPoint(s, n[0] <= transparentBelow ? 0.0 : n[4]);
  }
  if (transparentBelow > 0.0 && transparentBelow < 1.0)
  {
    otf->AddPoint(range[0] + transparentBelow * span, 0.0);
  }
  auto prop = vtkSmartPointer<vtkVolumeProperty>::New();
  prop->SetColor(ctf);
  prop->SetScalarOpacity(otf);
  prop->SetScalarOpacityUnitDistance(unitDistance);
  prop->SetInterpolationTypeToLinear();
  prop->ShadeOff();
  return prop;
}

void SetupCamera(vtkCamera* cam, const double b[6])
{
  const double c[3] = { 0.5 * (b[0] + b[1]), 0.5 * (b[2] + b[3]), 0.5 * (b[4] + b[5]) };
  const double r = 0.5 *
    std::sqrt((b[1] - b[0]) * (b[1] - b[0]) + (b[3] - b[2]) * (b[3] - b[2]) +
      (b[5] - b[4]) * (b[5] - b[4]));
  cam->SetViewAngle(30.0);
  cam->SetFocalPoint(c);
  cam->SetPosition(c[0], c[1], c[2] + 1.0);
  cam->SetViewUp(0.0, 1.0, 0.0);
  cam->Azimuth(35.0);
  cam->Elevation(30.0);
  cam->OrthogonalizeViewUp();
  const double d = r / std::sin(0.5 * 30.0 * 3.14159265358979323846 / 180.0);
  double dir[3];
  cam->GetDirectionOfProjection(dir);
  cam->SetPosition(c[0] - d * dir[0], c[1] - d * dir[1], c[2] - d * dir[2]);
  cam->SetClippingRange(std::max(0.01 * d, d - 1.5 * r), d + 1.5 * r);
}

bool LoadBracket(const Options& opt, Mesh& mesh)
{
  const std::string file = opt.DataDir + "/bracket_tet4_ccx.vtu";
  vtkNew<vtkXMLUnstructuredGridReader> reader;
  if (!reader->CanReadFile(file.c_str()))
  {
    std::cerr << "Cannot read " << file << " (use --data DIR)\n";
    return false;
  }
  reader->SetFileName(file.c_str());
  reader->Update();
  mesh.Name = "bracket";
  mesh.Grid = reader->GetOutput();
  mesh.Array = "von_mises";
  vtkDataArray* a = mesh.Grid->GetPointData()->GetArray(mesh.Array.c_str());
  if (!a)
  {
    std::cerr << file << " has no point array von_mises\n";
    return false;
  }
  mesh.Grid->GetPointData()->SetActiveScalars(mesh.Array.c_str());
  a->GetRange(mesh.Range, 0);
  mesh.UnitDistance = 2.5; // as in the demo; the bracket is 100 x 60 x 80
  mesh.Tetras = CountTetras(mesh.Grid);
  return true;
}

bool MakeRTMesh(const Options& opt, Mesh& mesh)
{
  const int e = opt.Extent;
  vtkNew<vtkRTAnalyticSource> source;
  source->SetWholeExtent(-e, e, -e, e, -e, e);
  source->SetCenter(0.0, 0.0, 0.0);
  vtkNew<vtkDataSetTriangleFilter> tets;
  tets->SetInputConnection(source->GetOutputPort());
  tets->TetrahedraOnlyOn();
  tets->Update();
  std::ostringstream name;
  name << "RTAnalytic [-" << e << "," << e << "]^3";
  mesh.Name = name.str();
  mesh.Grid = tets->GetOutput();
  mesh.Array = "RTData";
  vtkDataArray* a = mesh.Grid->GetPointData()->GetArray(mesh.Array.c_str());
  if (!a)
  {
    std::cerr << "vtkRTAnalyticSource gave no RTData\n";
    return false;
  }
  mesh.Grid->GetPointData()->SetActiveScalars(mesh.Array.c_str());
  a->GetRange(mesh.Range, 0);
  mesh.UnitDistance = e; // semi-transparent over the 2e-wide cube
  mesh.Tetras = CountTetras(mesh.Grid);
  std::cout << "Generated mesh: " << mesh.Name << ", " << (2 * e) * (2 * e) * (2 * e)
            << " voxels -> " << mesh.Tetras << " tetrahedra, " << mesh.Grid->GetNumberOfPoints()
            << " points, RTData range [" << mesh.Range[0] << ", " << mesh.Range[1] << "]\n";
  return true;
}
}
