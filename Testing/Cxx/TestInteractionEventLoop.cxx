// Progressive still frames refined by VTK's own X event loop (issue 19;
// README, "Interaction"): the bundled bracket at 96 x 72, CPU_ACCURATE, in X
// windows with VTK 9.1's X interactor (TestInteraction fires the timers
// itself; here Start() does). ProgressiveTime 1e-9 makes every still frame
// after interaction progressive. An observer of the interactor's timer
// counts the levels and ends the loop at the exact one; a one-shot watchdog
// timer ends it after 60 s (and the check fails).
//  1. Two windows with interactors in the process (VTK 9.1's X loop serves
//     every initialized X interactor and Start() returns when all of them are
//     terminated): the release's coarse level is refined to the exact frame,
//     equal bit for bit to the non-interactive render, and Start() returns
//     once the observer terminates both.
//  2. A new window and interactor afterwards (the first two have left VTK's
//     list of X interactors when their loop ended): the same again.
// hovBenchInteraction hung before it let each run's interactor end in a
// loop: an interactor initialized but never terminated inside Start() stays
// in VTK 9.1's list, and every later Start() waits for it. (VTK 9.1's
// ProcessEvents() does not fire timers: only Start() refines.)
// Without an X display (the headless twin) there is no X interactor: the
// test says so and passes.
#include "hovTestScenes.h"

#include "vtkCallbackCommand.h"
#include "vtkCamera.h"
#include "vtkCommand.h"
#include "vtkRenderWindow.h"
#include "vtkRenderWindowInteractor.h"
#include "vtkRenderer.h"

#include <chrono>
#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

using namespace hovTest;

namespace
{
const int W = 96, H = 72;
using Clock = std::chrono::steady_clock;

double Since(Clock::time_point t)
{
  return std::chrono::duration<double>(Clock::now() - t).count();
}

/// Follows the mapper's levels from the interactor's TimerEvents.
struct Watch
{
  vtkHighOrderVolumeMapper* Mapper = nullptr;
  int Levels = 1;
  int Last = 0;
  bool Exact = false;
  std::vector<vtkRenderWindowInteractor*> Terminate; ///< ended at the exact level
  int Watchdog = -1;      ///< the timer that ends a loop that would not end
  bool WatchdogFired = false;
};

void OnTimer(vtkObject*, unsigned long, void* clientData, void* callData)
{
  auto* w = static_cast<Watch*>(clientData);
  const int f = w->Mapper->GetLastSubsampling();
  if (f != w->Last)
  {
    w->Last = f;
    ++w->Levels;
  }
  w->Exact = f == 1 && !w->Mapper->GetLastRenderAborted();
  const bool watchdog = callData && *static_cast<int*>(callData) == w->Watchdog;
  w->WatchdogFired = w->WatchdogFired || watchdog;
  if (w->Exact || watchdog)
  {
    for (vtkRenderWindowInteractor* iren : w->Terminate)
    {
      iren->TerminateApp();
    }
  }
}

/// A new view: an interactive frame, then the release (a still frame).
void InteractThenRelease(vtkRenderWindow* win, vtkCamera* cam)
{
  cam->Azimuth(10.0);
  win->SetDesiredUpdateRate(1e6);
  win->Render();
  win->SetDesiredUpdateRate(0.0001);
  win->Render();
}

/// An on-screen X window (the interactor needs its X window) of W x H.
vtkSmartPointer<vtkRenderWindow> XWindow(vtkRenderer* ren)
{
  auto win = vtkSmartPointer<vtkRenderWindow>::New();
  win->SetSize(W, H);
  win->SetMultiSamples(0);
  if (ren)
  {
    win->AddRenderer(ren);
  }
  return win;
}
}

int TestInteractionEventLoop(int argc, char* argv[])
{
  Checker ck;
  const char* display = std::getenv("DISPLAY");
  if (!display || !*display)
  {
    std::cout << "[skipped] no X display: VTK 9.1's X interactor needs one (the X pass runs "
                 "this test)\n";
    return ck.Result();
  }
  std::unique_ptr<VolumeScene> bracket = BracketScene(ck, argc, argv);
  if (!bracket)
  {
    return ck.Result();
  }
  VolumeScene& scene = *bracket;
  vtkHighOrderVolumeMapper* mapper = scene.Mapper;
  mapper->SetRenderMode(vtkHighOrderVolumeMapper::CPU_ACCURATE);
  mapper->SetProgressiveTime(1e-9);

  vtkNew<vtkCamera> cam;
  BracketCamera(cam);
  auto renderer = BlackRenderer(cam);
  renderer->AddVolume(scene.Volume);
  auto other = BlackRenderer(cam);
  for (int part = 1; part <= 2; ++part)
  {
    auto win = XWindow(renderer);
    vtkNew<vtkRenderWindowInteractor> iren;
    iren->SetRenderWindow(win);
    iren->Initialize();
    auto win2 = XWindow(other);
    vtkNew<vtkRenderWindowInteractor> bystander;
    if (part == 1)
    {
      bystander->SetRenderWindow(win2);
      bystander->Initialize();
    }
    if (!ck.Check(std::string(iren->GetClassName()) == "vtkXRenderWindowInteractor",
          std::string("VTK's X interactor (") + iren->GetClassName() + ")"))
    {
      return ck.Result();
    }
    Watch watch;
    watch.Mapper = mapper;
    watch.Terminate.push_back(iren);
    if (part == 1)
    {
      watch.Terminate.push_back(bystander);
    }
    vtkNew<vtkCallbackCommand> observer;
    observer->SetCallback(OnTimer);
    observer->SetClientData(&watch);
    // After the mapper's own timer observer (priority 0): sees the new level.
    iren->AddObserver(vtkCommand::TimerEvent, observer, -1.0);
    const int tick = iren->CreateRepeatingTimer(5);
    watch.Watchdog = iren->CreateOneShotTimer(60000);

    InteractThenRelease(win, cam);
    const int coarse = mapper->GetLastSubsampling();
    watch.Last = coarse;
    const auto t0 = Clock::now();
    iren->Start();
    const double seconds = Since(t0);
    const Image refined = FloatImage(mapper);
    iren->DestroyTimer(tick);
    std::cout << "[measured] part " << part << ": f = " << coarse << " at the release, "
              << watch.Levels << " levels, Start() returned after " << seconds << " s"
              << (watch.WatchdogFired ? " (WATCHDOG)" : "") << "\n";
    // Start() finalizes the windows of the interactors it ends: the reference
    // is rendered in a new window of the same size.
    win->RemoveRenderer(renderer);
    auto refWindow = XWindow(renderer);
    const Image ref = NonInteractiveRender(refWindow, mapper);
    refWindow->RemoveRenderer(renderer);
    ck.Check(coarse > 1 && watch.Exact && watch.Levels >= 2 && !watch.WatchdogFired &&
        refined.V == ref.V && CheckImage(ref).Covered > 1000,
      "part " + std::to_string(part) + (part == 1 ? " (two interactors)" : " (one interactor)") +
        ": Start() refines the release's coarse level to the exact frame and returns");
  }
  renderer->RemoveVolume(scene.Volume);
  return ck.Result();
}
