// vtkCellVisibilitySortFilter as a pipeline filter (independent of which
// order the sort produces):
//  - output = input cells permuted: vtkOriginalCellIds is a permutation,
//    connectivity, cell types and cell data follow their cells, points and
//    point data are shared, SortRank matches the direction;
//  - the field data diagnostics exist and match the getters;
//  - its interior-face violation count equals the independent oracle's face
//    count for the same order (both for Stein and for vtkCellCenterDepthSort,
//    on a conforming mixed mesh, with and without a model transform);
//  - MTime: a camera or model-transform change re-executes, nothing else does;
//  - bad input: no camera -> an error (captured), an empty grid -> empty output.
#include "hovSortCases.h"
#include "hovTestScenes.h"

#include "vtkCamera.h"
#include "vtkCellCenterDepthSort.h"
#include "vtkCellData.h"
#include "vtkCellVisibilitySortFilter.h"
#include "vtkExecutive.h"
#include "vtkFieldData.h"
#include "vtkIdList.h"
#include "vtkIdTypeArray.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkSteinVisibilitySort.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <string>

using namespace hovTest;

namespace
{
std::vector<vtkIdType> OriginalIds(vtkUnstructuredGrid* out)
{
  std::vector<vtkIdType> v;
  auto* a = vtkIdTypeArray::SafeDownCast(out->GetCellData()->GetArray("vtkOriginalCellIds"));
  for (vtkIdType i = 0; a && i < a->GetNumberOfTuples(); ++i)
  {
    v.push_back(a->GetValue(i));
  }
  return v;
}

bool Follows(vtkUnstructuredGrid* in, vtkUnstructuredGrid* out, const std::vector<vtkIdType>& orig)
{
  auto* tagIn = vtkIdTypeArray::SafeDownCast(in->GetCellData()->GetArray("tag"));
  auto* tagOut = vtkIdTypeArray::SafeDownCast(out->GetCellData()->GetArray("tag"));
  if (!tagIn || !tagOut || static_cast<vtkIdType>(orig.size()) != in->GetNumberOfCells())
  {
    return false;
  }
  vtkNew<vtkIdList> a, b;
  for (vtkIdType i = 0; i < out->GetNumberOfCells(); ++i)
  {
    in->GetCellPoints(orig[i], a);
    out->GetCellPoints(i, b);
    bool same = a->GetNumberOfIds() == b->GetNumberOfIds() &&
      in->GetCellType(orig[i]) == out->GetCellType(i) && tagOut->GetValue(i) == tagIn->GetValue(orig[i]);
    for (vtkIdType k = 0; same && k < a->GetNumberOfIds(); ++k)
    {
      same = a->GetId(k) == b->GetId(k);
    }
    if (!same)
    {
      return false;
    }
  }
  return true;
}
}

int TestSortFilter(int, char*[])
{
  Checker ck;
  vtkSmartPointer<vtkUnstructuredGrid> mesh = MixedMesh(9);
  vtkNew<vtkIdTypeArray> tag;
  tag->SetName("tag");
  for (vtkIdType c = 0; c < mesh->GetNumberOfCells(); ++c)
  {
    tag->InsertNextValue(1000 + 7 * c);
  }
  mesh->GetCellData()->AddArray(tag);
  double b[6];
  mesh->GetBounds(b);
  const SortView view = RandomViews(b, 1, 3)[0];
  vtkNew<vtkCamera> cam;
  view.Apply(cam);

  vtkNew<vtkCellVisibilitySortFilter> filter;
  ck.Check(vtkSteinVisibilitySort::SafeDownCast(filter->GetVisibilitySort()) != nullptr,
    "default sort: vtkSteinVisibilitySort");
  filter->SetInputData(mesh);
  filter->SetCamera(cam);
  filter->Update();
  vtkUnstructuredGrid* out = filter->GetOutput();
  const std::vector<vtkIdType> orig = OriginalIds(out);
  std::vector<vtkIdType> sorted = orig;
  std::sort(sorted.begin(), sorted.end());
  bool perm = static_cast<vtkIdType>(sorted.size()) == mesh->GetNumberOfCells();
  for (size_t i = 0; perm && i < sorted.size(); ++i)
  {
    perm = sorted[i] == static_cast<vtkIdType>(i);
  }
  ck.Check(perm, "vtkOriginalCellIds is a permutation of the input ids");
  ck.Check(Follows(mesh, out, orig), "types, connectivity and cell data follow their cells");
  ck.Check(out->GetPoints() == mesh->GetPoints() &&
      out->GetPointData()->GetScalars() == mesh->GetPointData()->GetScalars(),
    "points and point data are shared");
  vtkFieldData* fd = out->GetFieldData();
  bool fields = true;
  for (const char* name : { "NumberOfCycles", "CycleCellIds", "NumberOfUnorderedCells",
         "SortSeconds", "NumberOfViolations", "NumberOfCheckedFaces" })
  {
    fields = fields && fd->GetArray(name) != nullptr;
  }
  ck.Check(fields && fd->GetArray("NumberOfViolations")->GetTuple1(0) == filter->GetNumberOfViolations() &&
      fd->GetArray("NumberOfCheckedFaces")->GetTuple1(0) == filter->GetNumberOfCheckedFaces() &&
      filter->GetNumberOfCheckedFaces() > 500,
    "field data diagnostics present and equal to the getters (" +
      std::to_string(filter->GetNumberOfCheckedFaces()) + " faces checked)");

  // Face counts against the oracle, both sorts, with and without a model transform.
  vtkNew<vtkMatrix4x4> model;
  TestModelTransform(model);
  vtkNew<vtkCellCenterDepthSort> center;
  for (int m = 0; m < 2; ++m)
  {
    SortView v = view;
    if (m)
    {
      double c[4] = { 0.5 * (b[0] + b[1]), 0.5 * (b[2] + b[3]), 0.5 * (b[4] + b[5]), 1 }, w[4];
      model->MultiplyPoint(c, w);
      for (int j = 0; j < 3; ++j)
      {
        v.Position[j] += w[j] - v.FocalPoint[j];
        v.FocalPoint[j] = w[j];
      }
    }
    v.Apply(cam);
    filter->SetModelTransform(m ? model.Get() : nullptr);
    for (int s = 0; s < 2; ++s)
    {
      filter->SetVisibilitySort(s ? static_cast<vtkVisibilitySort*>(center) : nullptr);
      filter->Update();
      const OracleResult o = CheckVisibilityOrder(mesh, cam, m ? model.Get() : nullptr,
        OriginalIds(filter->GetOutput()));
      ck.Check(o.FaceViolations == filter->GetNumberOfViolations() &&
          o.FacesChecked == filter->GetNumberOfCheckedFaces(),
        std::string(s ? "centre sort" : "Stein") + (m ? ", model transform" : "") +
          ": filter face count = oracle face count (" +
          std::to_string(filter->GetNumberOfViolations()) + "/" +
          std::to_string(filter->GetNumberOfCheckedFaces()) + " vs " +
          std::to_string(o.FaceViolations) + "/" + std::to_string(o.FacesChecked) + ")");
    }
  }
  ck.Check(filter->GetNumberOfCycles() == -1 && filter->GetNumberOfUnorderedCells() == -1,
    "vtkCellCenterDepthSort: cycles and unordered cells not reported (-1)");
  filter->SetVisibilitySort(nullptr);
  filter->SetModelTransform(nullptr);

  // Direction.
  filter->SetDirectionToFrontToBack();
  filter->Update();
  std::vector<vtkIdType> ftb = OriginalIds(filter->GetOutput());
  auto* rank = vtkIdTypeArray::SafeDownCast(filter->GetOutput()->GetCellData()->GetArray("SortRank"));
  const vtkIdType firstRank = rank ? rank->GetValue(0) : -1;
  filter->SetDirectionToBackToFront();
  filter->Update();
  std::vector<vtkIdType> btf = OriginalIds(filter->GetOutput());
  std::reverse(ftb.begin(), ftb.end());
  ck.Check(ftb == btf && firstRank == static_cast<vtkIdType>(btf.size()) - 1,
    "FRONT_TO_BACK is the reverse order; SortRank counts back to front");

  // MTime.
  vtkMTimeType t0 = filter->GetOutput()->GetMTime();
  filter->Update();
  ck.Check(filter->GetOutput()->GetMTime() == t0, "no re-execution without a change");
  cam->Elevation(20);
  cam->OrthogonalizeViewUp();
  filter->Update();
  ck.Check(filter->GetOutput()->GetMTime() > t0, "a camera change re-executes");
  t0 = filter->GetOutput()->GetMTime();
  filter->SetModelTransform(model);
  filter->Update();
  const vtkMTimeType t1 = filter->GetOutput()->GetMTime();
  model->SetElement(0, 3, 0.5);
  filter->Update();
  ck.Check(t1 > t0 && filter->GetOutput()->GetMTime() > t1,
    "setting and modifying the model transform re-executes");

  // Bad input.
  vtkNew<vtkCellVisibilitySortFilter> noCam;
  vtkNew<vtkTest::ErrorObserver> obs;
  noCam->AddObserver(vtkCommand::ErrorEvent, obs);
  noCam->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, obs);
  noCam->SetInputData(mesh);
  noCam->Update();
  ck.Check(obs->GetError() && obs->GetErrorMessage().find("camera") != std::string::npos,
    "no camera: error '" + Msg(obs->GetErrorMessage()) + "'");
  vtkNew<vtkUnstructuredGrid> empty;
  filter->SetInputData(empty);
  filter->Update();
  ck.Check(filter->GetOutput()->GetNumberOfCells() == 0 && filter->GetNumberOfViolations() == 0,
    "empty grid: empty output, no violations");
  return ck.Result();
}
