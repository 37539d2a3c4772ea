#include "hovFrameLevel.h"

#include "hovInteractionBudget.h" // the cost model
#include "hovProgressiveStill.h"  // progressive levels
#include "hovRenderFrame.h"       // the frame

#include "vtkRenderWindow.h"           // its interactor
#include "vtkRenderWindowInteractor.h" // the interactive rate
#include "vtkRenderer.h"               // its window
#include "vtkVolume.h"                 // the allocated render time

#include <algorithm> // std::max

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
  if (frame.Subsampling > 1 && s.Mode == Projection &&
    budget.FixedSeconds(Projection) >= levelBudget)
  {
    // The regions alone exceed the budget at any resolution: the exact rays
    // of the CPU path at reduced resolution instead.
    costMode = CPU;
    frame.Settings.Mode = RenderMode::CPUAccurate;
    const int fixed = frame.Interactive ? s.Fixed : 0;
    frame.Subsampling = std::max(
      2, budget.Choose(CPU, levelBudget, frame.Width, frame.Height, fixed, true).Subsampling);
  }
  if (frame.Subsampling > 1 && costMode == CPU)
  {
    // Each pixel composites its own segments in depth order (exact per ray):
    // no visibility sort, the largest fixed part of a reduced frame.
    frame.Settings.Ordering = CellOrdering::PerPixelSort;
  }
  return costMode;
}
