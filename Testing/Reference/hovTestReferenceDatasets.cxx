// Bundled issue-4 datasets of hovTestReferenceDatasets.h.
#include "hovTestReferenceDatasets.h"

#include "hovTestReferenceGeneral.h"

#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkDataSetTriangleFilter.h" // the peers' tetrahedra of linear cells
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkUnstructuredGrid.h"
#include "vtkVolumeProperty.h"
#include "vtkXMLUnstructuredGridReader.h"

#include <chrono>
#include <sstream>

namespace hovTestRef
{
vtkSmartPointer<vtkUnstructuredGrid> LoadDataset(
  const std::string& dataDir, const std::string& file, const std::string& array)
{
  vtkNew<vtkXMLUnstructuredGridReader> reader;
  reader->SetFileName((dataDir + "/" + file).c_str());
  reader->Update();
  vtkSmartPointer<vtkUnstructuredGrid> grid = reader->GetOutput();
  grid->GetPointData()->SetActiveScalars(array.c_str());
  return grid;
}

std::map<int, long long> CellTypeCounts(vtkUnstructuredGrid* grid)
{
  std::map<int, long long> counts;
  for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c)
  {
    ++counts[grid->GetCellType(c)];
  }
  return counts;
}

std::string DescribeCellTypes(vtkUnstructuredGrid* grid)
{
  std::ostringstream os;
  for (const auto& kv : CellTypeCounts(grid))
  {
    os << " type " << kv.first << ": " << kv.second;
  }
  return os.str();
}

vtkSmartPointer<vtkUnstructuredGrid> TetrahedralizeLinear(vtkUnstructuredGrid* grid, double& seconds)
{
  const auto t0 = std::chrono::steady_clock::now();
  vtkNew<vtkDataSetTriangleFilter> tri;
  tri->SetInputData(grid);
  tri->TetrahedraOnlyOn();
  tri->Update();
  seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return tri->GetOutput();
}

vtkSmartPointer<vtkUnstructuredGrid> TessellateQuadratic(vtkUnstructuredGrid* grid, double& seconds)
{
  const auto t0 = std::chrono::steady_clock::now();
  vtkSmartPointer<vtkUnstructuredGrid> out = SubdivideQuadraticTetras(grid, 1);
  seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

void DatasetTF(vtkVolumeProperty* property, double lo, double hi, double unit)
{
  vtkNew<vtkColorTransferFunction> color;
  vtkNew<vtkPiecewiseFunction> opacity;
  const double nodes[5][5] = { { 0.0, 0.05, 0.1, 0.9, 0.02 }, { 0.25, 0.1, 0.7, 0.9, 0.08 },
    { 0.5, 0.2, 0.9, 0.3, 0.25 }, { 0.75, 1.0, 0.85, 0.1, 0.5 }, { 1.0, 0.95, 0.15, 0.1, 0.85 } };
  for (const auto& n : nodes)
  {
    const double s = lo + n[0] * (hi - lo);
    color->AddRGBPoint(s, n[1], n[2], n[3]);
    opacity->AddPoint(s, n[4]);
  }
  property->SetColor(color);
  property->SetScalarOpacity(opacity);
  property->SetScalarOpacityUnitDistance(unit);
}

void TJunctionCamera(vtkCamera* cam)
{
  // Bounds [-2, 2] x [-0.5, 1.8] x [-0.5, 0.5].
  cam->SetFocalPoint(0.0, 0.55, 0.0);
  cam->SetPosition(2.2, 2.6, 5.2);
  cam->SetViewUp(0, 1, 0);
  cam->SetViewAngle(40);
  cam->SetClippingRange(2.0, 12.0);
}

void ZooCamera(vtkCamera* cam)
{
  // Bounds [0, 4] x [0, 2] x [0, 1.8].
  cam->SetFocalPoint(2.0, 1.0, 0.9);
  cam->SetPosition(5.2, -3.6, 4.4);
  cam->SetViewUp(0, 0, 1);
  cam->SetViewAngle(38);
  cam->SetClippingRange(2.0, 14.0);
}
}
