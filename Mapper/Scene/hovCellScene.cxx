#include "hovCellScene.h"

#include "vtkCamera.h"                       // order cache key
#include "vtkDataArray.h"                    // array name and components
#include "vtkIdTypeArray.h"                  // the sort's output
#include "vtkMatrix4x4.h"                    // order cache key
#include "vtkSteinVisibilitySort.h"          // cycles of the exact sort
#include "vtkUnstructuredGridBase.h"         // the input
#include "vtkUnstructuredGridVolumeMapper.h" // (complete type of the frame's mapper)
#include "vtkVisibilitySort.h"               // the order
#include "vtkVolume.h"                       // matrix, property

#include <algorithm> // std::reverse
#include <sstream>   // messages

bool hov::CellScene::Prepare(RenderFrame& frame)
{
  if (!frame.Input)
  {
    frame.Error("No input.");
    return false;
  }
  if (!frame.Volume->GetProperty())
  {
    frame.Error("The volume has no vtkVolumeProperty.");
    return false;
  }
  const ScalarSelection& scalars = frame.Scalars;
  if (!scalars.Array)
  {
    frame.Error("No numeric scalars to render: set point scalars on the input or select a "
                "numeric point/cell array with SelectScalarArray().");
    this->CellsValid = false;
    return false;
  }
  if (scalars.ComponentClamped)
  {
    std::ostringstream text;
    text << "VectorComponent " << frame.Settings.VectorComponent << " out of range for array '"
         << (scalars.Array->GetName() ? scalars.Array->GetName() : "") << "' with "
         << scalars.Array->GetNumberOfComponents() << " components; using " << scalars.Component;
    frame.Warning(text.str());
  }
  const InputKey key = frame.Key();
  if (!this->CellsValid || key != this->CellsKey)
  {
    this->CellsKey = key;
    this->CellsValid = true;
    ++this->CellsGeneration;
    std::string error;
    if (!this->Cells.Build(frame.Input, scalars.Array, scalars.CellScalars, scalars.Component,
          &error) &&
      !error.empty())
    {
      frame.Error("Cannot render: " + error + ".");
      this->CellsValid = false;
      return false;
    }
    this->ReportCells(frame);
    frame.InputReported = true;
  }
  const CellSetup::Statistics& st = this->Cells.GetStatistics();
  frame.Stats.RenderedCells = st.Rendered;
  frame.Stats.SkippedCells = st.Cells - st.Rendered;
  return true;
}

void hov::CellScene::ReportCells(const RenderFrame& frame) const
{
  const CellSetup::Statistics& st = this->Cells.GetStatistics();
  if (st.Cells == 0)
  {
    frame.Warning("The input grid has no cells: nothing to render.");
  }
  std::ostringstream text;
  auto warn = [&]() {
    frame.Warning(text.str());
    text.str("");
  };
  if (st.Unsupported)
  {
    text << st.Unsupported << " of " << st.Cells << " cells are of types not yet supported by "
         << "the CPU projection path (first type: " << st.FirstUnsupportedType
         << "; supported: 10-14, 24-27, 29); they are skipped.";
    warn();
  }
  if (st.NonFinitePoints || st.NonFiniteScalars || st.Degenerate)
  {
    text << "Skipped cells: " << st.NonFinitePoints << " with NaN/Inf points or bad "
         << "connectivity, " << st.NonFiniteScalars << " with NaN/Inf scalars, " << st.Degenerate
         << " degenerate (zero-volume or tangled) cells.";
    warn();
  }
  if (st.Inverted)
  {
    text << st.Inverted << " tetrahedra are inverted (negative orientation); they are "
         << "rendered as the convex hull of their vertices.";
    warn();
  }
  if (st.InvertedGeneral)
  {
    text << st.InvertedGeneral << " non-tetrahedral cells are inverted (mirrored node "
         << "order); they are rendered as the region their corners bound.";
    warn();
  }
  if (st.Curved)
  {
    text << st.Curved << " quadratic cells have curved geometry (max node deviation "
         << st.MaxCurvature << " of the cell size); they are rendered with straight "
         << "edges and their quadratic field (curved geometry needs the ray caster).";
    warn();
  }
}

bool hov::CellScene::PrepareOrder(const RenderFrame& frame, bool needVisibilitySort)
{
  if (frame.Settings.Ordering == CellOrdering::PerPixelSort && !needVisibilitySort)
  {
    // Any order will do: each pixel sorts its own segments.
    const vtkIdType n = this->Cells.GetNumberOfRenderedCells();
    if (this->OrderGeneration != this->CellsGeneration || this->OrderCamera != nullptr ||
      static_cast<vtkIdType>(this->FrontToBack.size()) != n)
    {
      this->FrontToBack.resize(n);
      for (vtkIdType i = 0; i < n; ++i)
      {
        this->FrontToBack[i] = i;
      }
      this->OrderGeneration = this->CellsGeneration;
      this->OrderCamera = nullptr;
    }
    this->HasCycles = false;
    return true;
  }
  vtkVisibilitySort* sort = frame.VisibilitySort;
  if (!sort)
  {
    frame.Error("No visibility sort set.");
    return false;
  }
  vtkCamera* camera = frame.Camera;
  vtkMatrix4x4* matrix = frame.Volume->GetMatrix();
  if (this->OrderGeneration == this->CellsGeneration && this->OrderCamera == camera &&
    this->OrderCameraTime == camera->GetMTime() && this->OrderMatrixTime == matrix->GetMTime() &&
    this->OrderSortTime == sort->GetMTime())
  {
    return true; // same view: reuse the order (also keeps ties deterministic)
  }
  // The sort sees only the valid cells (never a cell with broken
  // connectivity or NaN points), and its ids are rendered-cell indices.
  sort->SetInput(this->Cells.GetSortGrid());
  sort->SetCamera(camera);
  sort->SetModelTransform(matrix);
  sort->SetDirectionToBackToFront();
  sort->InitTraversal();
  this->FrontToBack.clear();
  const vtkIdType numRendered = this->Cells.GetNumberOfRenderedCells();
  this->FrontToBack.reserve(numRendered);
  while (vtkIdTypeArray* cells = sort->GetNextCells())
  {
    const vtkIdType n = cells->GetNumberOfTuples();
    for (vtkIdType i = 0; i < n; ++i)
    {
      const vtkIdType cell = cells->GetValue(i);
      if (cell >= 0 && cell < numRendered)
      {
        this->FrontToBack.push_back(cell);
      }
    }
  }
  std::reverse(this->FrontToBack.begin(), this->FrontToBack.end());
  vtkSteinVisibilitySort* stein = vtkSteinVisibilitySort::SafeDownCast(sort);
  this->HasCycles = stein && stein->GetNumberOfCycles() > 0;
  std::ostringstream text;
  if (this->HasCycles && this->CycleWarningGeneration != this->CellsGeneration)
  {
    this->CycleWarningGeneration = this->CellsGeneration; // once per input
    text << "The visibility order of this view has " << stein->GetNumberOfCycles()
         << " cycle(s); frames with cycles are composited with PER_PIXEL_SORT.";
    frame.Warning(text.str());
  }
  if (static_cast<vtkIdType>(this->FrontToBack.size()) != numRendered)
  {
    text.str("");
    text << "The visibility sort returned " << this->FrontToBack.size() << " of " << numRendered
         << " cells.";
    frame.Warning(text.str());
  }
  this->OrderGeneration = this->CellsGeneration;
  this->OrderCamera = camera;
  this->OrderCameraTime = camera->GetMTime();
  this->OrderMatrixTime = matrix->GetMTime();
  this->OrderSortTime = sort->GetMTime();
  return true;
}
