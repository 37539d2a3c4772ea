#include "vtkCellVisibilitySortFilter.h"

#include "hovSortFaceCheck.h"      // the interior-face violation check
#include "vtkSteinVisibilitySort.h" // the default sort and its diagnostics

#include "vtkCamera.h"
#include "vtkCellData.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIdList.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMatrix4x4.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkTimerLog.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm> // std::max
#include <vector>    // buffers

vtkStandardNewMacro(vtkCellVisibilitySortFilter);
vtkCxxSetObjectMacro(vtkCellVisibilitySortFilter, Camera, vtkCamera);
vtkCxxSetObjectMacro(vtkCellVisibilitySortFilter, ModelTransform, vtkMatrix4x4);


//------------------------------------------------------------------------------
vtkCellVisibilitySortFilter::vtkCellVisibilitySortFilter()
{
  this->SetVisibilitySort(nullptr); // installs the default
}

vtkCellVisibilitySortFilter::~vtkCellVisibilitySortFilter()
{
  this->SetCamera(nullptr);
  this->SetModelTransform(nullptr);
  if (this->VisibilitySort)
  {
    this->VisibilitySort->UnRegister(this);
    this->VisibilitySort = nullptr;
  }
}

void vtkCellVisibilitySortFilter::SetVisibilitySort(vtkVisibilitySort* sort)
{
  vtkSmartPointer<vtkVisibilitySort> next = sort;
  if (!next)
  {
    next = vtkSmartPointer<vtkSteinVisibilitySort>::New();
  }
  if (next == this->VisibilitySort)
  {
    return;
  }
  if (this->VisibilitySort)
  {
    this->VisibilitySort->UnRegister(this);
  }
  this->VisibilitySort = next;
  this->VisibilitySort->Register(this);
  this->SortConfiguredTime = 0;
  this->Modified();
}

vtkMTimeType vtkCellVisibilitySortFilter::GetMTime()
{
  vtkMTimeType t = this->Superclass::GetMTime();
  if (this->Camera)
  {
    t = std::max(t, this->Camera->GetMTime());
  }
  if (this->ModelTransform)
  {
    t = std::max(t, this->ModelTransform->GetMTime());
  }
  if (this->VisibilitySort && this->VisibilitySort->GetMTime() > this->SortConfiguredTime)
  {
    t = std::max(t, this->VisibilitySort->GetMTime());
  }
  return t;
}

//------------------------------------------------------------------------------
bool vtkCellVisibilitySortFilter::RunSort(vtkUnstructuredGrid* input, vtkIdTypeArray* order)
{
  vtkVisibilitySort* sort = this->VisibilitySort;
  vtkNew<vtkMatrix4x4> identity;
  sort->SetInput(input);
  sort->SetCamera(this->Camera);
  sort->SetModelTransform(this->ModelTransform ? this->ModelTransform : identity.Get());
  sort->SetDirectionToBackToFront();
  vtkSteinVisibilitySort* stein = vtkSteinVisibilitySort::SafeDownCast(sort);
  if (stein)
  {
    stein->SetNumberOfTiles(this->NumberOfTilesX, this->NumberOfTilesY);
  }
  vtkNew<vtkTimerLog> timer;
  timer->StartTimer();
  const vtkIdType n = input->GetNumberOfCells();
  std::vector<char> seen(static_cast<size_t>(n), 0);
  order->SetNumberOfComponents(1);
  order->Allocate(n);
  vtkIdType bad = 0, duplicates = 0;
  sort->InitTraversal();
  while (vtkIdTypeArray* cells = sort->GetNextCells())
  {
    const vtkIdType m = cells->GetNumberOfTuples();
    if (m == 0)
    {
      break;
    }
    for (vtkIdType i = 0; i < m; ++i)
    {
      const vtkIdType c = cells->GetValue(i);
      if (c < 0 || c >= n)
      {
        ++bad;
      }
      else if (seen[c])
      {
        ++duplicates;
      }
      else
      {
        seen[c] = 1;
        order->InsertNextValue(c);
      }
    }
  }
  timer->StopTimer();
  this->SortSeconds = timer->GetElapsedTime();
  // The filter's own settings must not count as a user change of the sort.
  this->SortConfiguredTime = sort->GetMTime();
  const vtkIdType missing = n - order->GetNumberOfTuples();
  if (bad || duplicates || missing)
  {
    vtkErrorMacro(<< sort->GetClassName() << " returned " << bad << " ids out of range, "
                  << duplicates << " duplicates and missed " << missing << " of " << n
                  << " cells; the missing cells are appended at the end (back to front).");
    for (vtkIdType c = 0; c < n; ++c)
    {
      if (!seen[c])
      {
        order->InsertNextValue(c);
      }
    }
  }
  this->NumberOfCycles = stein ? stein->GetNumberOfCycles() : -1;
  this->NumberOfUnorderedCells = stein ? stein->GetNumberOfUnorderedCells() : -1;
  return true;
}

//------------------------------------------------------------------------------
void vtkCellVisibilitySortFilter::CheckFaces(vtkUnstructuredGrid* input, vtkIdTypeArray* order)
{
  const hovSort::FaceCheckResult r =
    hovSort::CheckInteriorFaces(input, this->Camera, this->ModelTransform, order);
  this->NumberOfViolations = r.Violations;
  this->NumberOfCheckedFaces = r.Checked;
}

//------------------------------------------------------------------------------
namespace
{
template <class ArrayT, class T>
void AddFieldValue(vtkFieldData* fd, const char* name, T value)
{
  vtkNew<ArrayT> a;
  a->SetName(name);
  a->SetNumberOfTuples(1);
  a->SetValue(0, value);
  fd->AddArray(a);
}
}

int vtkCellVisibilitySortFilter::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkUnstructuredGrid* input = vtkUnstructuredGrid::GetData(inputVector[0], 0);
  vtkUnstructuredGrid* output = vtkUnstructuredGrid::GetData(outputVector, 0);
  this->NumberOfCycles = this->NumberOfUnorderedCells = this->NumberOfViolations = 0;
  this->NumberOfCheckedFaces = 0;
  this->SortSeconds = 0.0;
  if (!input || !output)
  {
    return 0;
  }
  if (!this->Camera)
  {
    vtkErrorMacro("No camera: call SetCamera() before updating.");
    return 0;
  }
  const vtkIdType n = input->GetNumberOfCells();
  vtkNew<vtkIdTypeArray> order; // back to front, input ids
  if (n > 0 && !this->RunSort(input, order))
  {
    return 0;
  }
  if (this->ComputeViolations && n > 0)
  {
    this->CheckFaces(input, order);
  }
  else if (!this->ComputeViolations)
  {
    this->NumberOfViolations = -1;
  }

  // The output: shared points and point data, cells and cell data reordered.
  output->SetPoints(input->GetPoints());
  output->GetPointData()->ShallowCopy(input->GetPointData());
  output->Allocate(n);
  vtkCellData* inCD = input->GetCellData();
  vtkCellData* outCD = output->GetCellData();
  outCD->CopyAllocate(inCD, n);
  vtkNew<vtkIdTypeArray> original;
  original->SetName("vtkOriginalCellIds");
  original->SetNumberOfTuples(n);
  vtkNew<vtkIdTypeArray> sortRank;
  sortRank->SetName("SortRank");
  sortRank->SetNumberOfTuples(n);
  vtkNew<vtkIdList> ids;
  for (vtkIdType i = 0; i < n; ++i)
  {
    const vtkIdType btf = this->Direction == BACK_TO_FRONT ? i : n - 1 - i;
    const vtkIdType c = order->GetValue(btf);
    const int type = input->GetCellType(c);
    if (type == VTK_POLYHEDRON)
    {
      input->GetFaceStream(c, ids);
    }
    else
    {
      input->GetCellPoints(c, ids);
    }
    output->InsertNextCell(type, ids);
    outCD->CopyData(inCD, c, i);
    original->SetValue(i, c);
    sortRank->SetValue(i, btf);
  }
  outCD->AddArray(original);
  outCD->AddArray(sortRank);

  vtkFieldData* fd = output->GetFieldData();
  fd->ShallowCopy(input->GetFieldData());
  AddFieldValue<vtkIdTypeArray>(fd, "NumberOfCycles", this->NumberOfCycles);
  vtkNew<vtkIdList> cycleCells;
  if (vtkSteinVisibilitySort* stein = vtkSteinVisibilitySort::SafeDownCast(this->VisibilitySort))
  {
    if (n > 0)
    {
      stein->GetCycleCells(cycleCells);
    }
  }
  vtkNew<vtkIdTypeArray> cycleArray;
  cycleArray->SetName("CycleCellIds");
  cycleArray->SetNumberOfTuples(cycleCells->GetNumberOfIds());
  for (vtkIdType i = 0; i < cycleCells->GetNumberOfIds(); ++i)
  {
    cycleArray->SetValue(i, cycleCells->GetId(i));
  }
  fd->AddArray(cycleArray);
  AddFieldValue<vtkIdTypeArray>(fd, "NumberOfUnorderedCells", this->NumberOfUnorderedCells);
  AddFieldValue<vtkDoubleArray>(fd, "SortSeconds", this->SortSeconds);
  AddFieldValue<vtkIdTypeArray>(fd, "NumberOfViolations", this->NumberOfViolations);
  AddFieldValue<vtkIdTypeArray>(fd, "NumberOfCheckedFaces", this->NumberOfCheckedFaces);
  if (this->NumberOfCycles > 0)
  {
    vtkWarningMacro(<< "The visibility relation has " << this->NumberOfCycles << " cycle(s) over "
                    << cycleCells->GetNumberOfIds() << " cells (listed in the field data "
                    << "array CycleCellIds); those cells may overlap wrongly in the image.");
  }
  return 1;
}

void vtkCellVisibilitySortFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Camera: " << this->Camera << "\n";
  os << indent << "ModelTransform: " << this->ModelTransform << "\n";
  os << indent << "VisibilitySort: "
     << (this->VisibilitySort ? this->VisibilitySort->GetClassName() : "(none)") << "\n";
  os << indent << "Direction: " << (this->Direction == BACK_TO_FRONT ? "BackToFront" : "FrontToBack")
     << "\n";
  os << indent << "NumberOfTiles: " << this->NumberOfTilesX << " x " << this->NumberOfTilesY << "\n";
  os << indent << "ComputeViolations: " << this->ComputeViolations << "\n";
  os << indent << "NumberOfCycles: " << this->NumberOfCycles << "\n";
  os << indent << "NumberOfUnorderedCells: " << this->NumberOfUnorderedCells << "\n";
  os << indent << "NumberOfViolations: " << this->NumberOfViolations << "\n";
  os << indent << "NumberOfCheckedFaces: " << this->NumberOfCheckedFaces << "\n";
  os << indent << "SortSeconds: " << this->SortSeconds << "\n";
}
