#include "hovFrameLevel.h"

#include "hovInteractionBudget.h" // the cost model
#include "hovProgressiveStill.h"  // progressive levels
#include "hovRenderFrame.h"       // the frame

#include "vtkAbstractMapper.h"         // the input
#include "vtkCellType.h"               // linear cell types
#include "vtkRenderWindow.h"           // its interactor
#include "vtkUnsignedCharArray.h"      // the input's cell types
#include "vtkUnstructuredGrid.h"       // the input
#include "vtkRenderWindowInteractor.h" // the interactive rate
#include "vtkRenderer.h"               // its window
#include "vtkVolume.h"                 // the allocated render time

#include <algorithm> // std::max

namespace
{
/// RAY_CAST input that the CPU path renders exactly and with every feature
/// set: linear cells only (curved geometry is the ray caster's job), no
/// CPU-only feature that the ray caster's still frame would not show.
bool CPUPathRendersSame(vtkAbstractMapper* mapper, const hov::FrameSettings& settings)
{
  if (!settings.Isosurfaces.empty() || !settings.ColorArray.empty() ||
    !settings.IsosurfaceArray.empty() || settings.Splatting)
  {
    return false;
  }
  auto* grid = vtkUnstructuredGrid::SafeDownCast(mapper->GetInputDataObject(0, 0));
  if (!grid || grid->GetNumberOfCells() == 0)
  {
    return false;
  }
  // One byte per cell (a fraction of a millisecond for a million cells).
  vtkUnsignedCharArray* types = grid->GetCellTypesArray();
  if (!types)
  {
    return false;
  }
  const unsigned char* type = types->GetPointer(0);
  for (vtkIdType i = 0; i < types->GetNumberOfValues(); ++i)
  {
    switch (type[i])
    {
      case VTK_TETRA:
      case VTK_HEXAHEDRON:
      case VTK_VOXEL:
      case VTK_WEDGE:
      case VTK_PYRAMID:
        break;
      default:
        return false;
    }
  }
  return true;
}
}

int hov::ChooseFrameLevel(RenderFrame& frame, const LevelSettings& s,
  const InteractionBudget& budget, ProgressiveStill& progressive, vtkRenderer* ren,
  vtkVolume* vol, vtkAbstractMapper* mapper)
{
  constexpr int CPU = static_cast<int>(RenderMode::CPUAccurate);
  constexpr int Projection = static_cast<int>(RenderMode::OpenGLProjection);
  int costMode = s.Mode;
  const double allocated = vol->GetAllocatedRenderTime();
  const InteractionBudget::Choice choice =
    budget.Choose(s.Mode, allocated, frame.Width, frame.Height, s.Fixed, s.AutoAdjust);
  frame.Interactive = choice.Interactive;
  frame.Subsampling = choice.Subsampling;
  double levelBudget = allocated;
  if (choice.Interactive)
  {
    progressive.Cancel();
  }
  else
  {
    // A slow still frame: coarse first (the factor fitting the interactor's rate).
    vtkRenderWindowInteractor* iren = ren->GetRenderWindow()->GetInteractor();
    const double rate = iren ? iren->GetDesiredUpdateRate() : 0.0;
    levelBudget = rate > 0.0 ? 1.0 / rate : 0.0;
    const int coarse = rate > 0.0
      ? std::max(2, budget.Choose(s.Mode, levelBudget, frame.Width, frame.Height, 0, true).Subsampling)
      : 1;
    frame.Subsampling =
      progressive.Level(ren, vol, mapper, choice.Estimate, s.ProgressiveTime, coarse, s.AfterInteraction);
  }
  // A reduced frame drawn by the CPU path instead: the factor from the CPU
  // path's own costs, for a progressive level never coarser than the one
  // scheduled (each level is then finer than the last drawn, so the
  // refinement reaches the exact level).
  auto byCPU = [&]() {
    costMode = CPU;
    frame.Settings.Mode = RenderMode::CPUAccurate;
    const int fixed = frame.Interactive ? s.Fixed : 0;
    int f = budget.Choose(CPU, levelBudget, frame.Width, frame.Height, fixed, true).Subsampling;
    if (!frame.Interactive)
    {
      f = std::min(f, frame.Subsampling);
    }
    frame.Subsampling = std::max(2, f);
  };
  constexpr int Ray = static_cast<int>(RenderMode::RayCast);
  if (frame.Subsampling > 1 && s.Mode == Projection &&
    budget.FixedSeconds(Projection) >= levelBudget)
  {
    // The regions alone exceed the budget at any resolution: the exact rays
    // of the CPU path at reduced resolution instead.
    byCPU();
  }
  else if (frame.Subsampling > 1 && s.Mode == Ray && s.RayCastEveryCell &&
    CPUPathRendersSame(mapper, frame.Settings))
  {
    // Linear cells: the CPU path's exact rays cost a fraction of the ray
    // caster's (no cell search, no root isolation) and use the same closed
    // forms: reduced levels by the CPU path, the exact level by the ray caster.
    byCPU();
  }
  if (!frame.Interactive && progressive.Active())
  {
    progressive.Drawn(frame.Subsampling); // the factor of this level, if changed above
  }
  if (frame.Subsampling > 1 && costMode == CPU)
  {
    // Each pixel composites its own segments in depth order (exact per ray):
    // no visibility sort, the largest fixed part of a reduced frame.
    frame.Settings.Ordering = CellOrdering::PerPixelSort;
  }
  return costMode;
}
