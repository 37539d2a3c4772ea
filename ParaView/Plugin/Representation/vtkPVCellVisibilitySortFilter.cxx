#include "vtkPVCellVisibilitySortFilter.h"

#include "hovParaViewStartup.h"     // threaded SMP backend, version check
#include "vtkSteinVisibilitySort.h" // the exact sort

#include "vtkCamera.h"              // the camera
#include "vtkCellCenterDepthSort.h" // VTK's approximate sort
#include "vtkObjectFactory.h"       // vtkStandardNewMacro

vtkStandardNewMacro(vtkPVCellVisibilitySortFilter);

vtkPVCellVisibilitySortFilter::vtkPVCellVisibilitySortFilter()
{
  hov::ParaViewStartup();
  this->SetCamera(this->SortCamera);
  this->SetSortAlgorithm(STEIN_ADJACENCY_GRAPH);
}

vtkPVCellVisibilitySortFilter::~vtkPVCellVisibilitySortFilter()
{
  this->SetCamera(nullptr);
}

void vtkPVCellVisibilitySortFilter::SetCameraPosition(double x, double y, double z)
{
  this->SortCamera->SetPosition(x, y, z);
}

void vtkPVCellVisibilitySortFilter::SetCameraFocalPoint(double x, double y, double z)
{
  this->SortCamera->SetFocalPoint(x, y, z);
}

void vtkPVCellVisibilitySortFilter::SetCameraViewUp(double x, double y, double z)
{
  this->SortCamera->SetViewUp(x, y, z);
}

void vtkPVCellVisibilitySortFilter::SetCameraViewAngle(double degrees)
{
  this->SortCamera->SetViewAngle(degrees);
}

void vtkPVCellVisibilitySortFilter::SetCameraParallelProjection(int parallel)
{
  this->SortCamera->SetParallelProjection(parallel);
}

void vtkPVCellVisibilitySortFilter::SetCameraParallelScale(double scale)
{
  this->SortCamera->SetParallelScale(scale);
}

void vtkPVCellVisibilitySortFilter::SetSortAlgorithm(int algorithm)
{
  if (algorithm == this->SortAlgorithm || algorithm < STEIN_ADJACENCY_GRAPH ||
    algorithm > CELL_CENTER_DEPTH)
  {
    return;
  }
  this->SortAlgorithm = algorithm;
  if (algorithm == CELL_CENTER_DEPTH)
  {
    vtkNew<vtkCellCenterDepthSort> sort;
    this->SetVisibilitySort(sort);
    return;
  }
  vtkNew<vtkSteinVisibilitySort> sort;
  sort->SetAlgorithm(algorithm == STEIN_ADJACENCY_GRAPH ? vtkSteinVisibilitySort::ADJACENCY_GRAPH
                                                        : vtkSteinVisibilitySort::MULTITILED_MERGE);
  this->SetVisibilitySort(sort);
}

void vtkPVCellVisibilitySortFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "SortAlgorithm: " << this->SortAlgorithm << "\n";
}
