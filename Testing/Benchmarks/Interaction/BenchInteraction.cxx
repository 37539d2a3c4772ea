// hovBenchInteraction (issue 19): see CMakeLists.txt beside this file.
//
// Per mesh and render mode, in a size x size X window with an initialized
// vtkRenderWindowInteractor (not started: the benchmark drives it):
//  1. the exact frame's cost: a warm-up still frame, then a timed one;
//  2. interaction: the trackball style's StartRotate (the window's desired
//     update rate becomes the interactor's, 15 frames/s), steps x (camera
//     azimuth + the interactor's Render), EndRotate (the still rate, a
//     render); per frame: wall time (Render + WaitForCompletion) and the
//     mapper's pixels per ray;
//  3. the still frame after interaction: progressive levels driven by the
//     interactor's event loop (Start(), ended at the exact level, or after a
//     time limit: a failed row); its float
//     image against a non-interactive render of the same view (the same
//     mapper with AutoAdjustImageSampleDistance off, ProgressiveTime 0):
//     equal bit for bit?
//  4. abort of a long still frame: another thread requests the abort 0.3 s
//     into the frame, through (a) the window's AbortCheckEvent and (b) the
//     mapper's SetAbortExecute from its ProgressEvent; the time from the
//     request to the end of Render().
#include "BenchRender.h"

#include "vtkCallbackCommand.h"
#include "vtkCamera.h"
#include "vtkCommand.h"
#include "vtkFloatArray.h"
#include "vtkHighOrderVolumeMapper.h"
#include "vtkImageData.h"
#include "vtkInteractorStyleTrackballCamera.h"
#include "vtkPointData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderWindowInteractor.h"
#include "vtkRenderer.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <cmath>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace
{
using Clock = std::chrono::steady_clock;
double Since(Clock::time_point t)
{
  return std::chrono::duration<double>(Clock::now() - t).count();
}

struct Args
{
  hovBench::Options Bench;
  int Steps = 20;
  double Rate = 15.0;
  std::string Modes = "cpu,proj,ray";
  std::string Meshes = "bracket,rt";
  bool Abort = true;
};

std::vector<float> Copy(vtkHighOrderVolumeMapper* m)
{
  vtkDataArray* a = m->GetFloatImage()->GetPointData()->GetScalars();
  auto* f = vtkFloatArray::SafeDownCast(a);
  return f ? std::vector<float>(f->GetPointer(0), f->GetPointer(0) + 4 * f->GetNumberOfTuples())
           : std::vector<float>();
}

std::string Fmt(double v)
{
  char text[32];
  std::snprintf(text, sizeof(text), "%.3f", v);
  return text;
}

double MaxDiff(const std::vector<float>& a, const std::vector<float>& b)
{
  if (a.size() != b.size() || a.empty())
  {
    return -1.0;
  }
  double d = 0.0;
  for (size_t i = 0; i < a.size(); ++i)
  {
    d = std::max(d, static_cast<double>(std::abs(a[i] - b[i])));
  }
  return d;
}

struct AbortRequest
{
  std::atomic<bool> Requested{ false };
  Clock::time_point At;
  bool ViaWindow = true;
};

void OnAbortCheck(vtkObject* caller, unsigned long, void* cd, void*)
{
  auto* r = static_cast<AbortRequest*>(cd);
  if (r->ViaWindow && r->Requested)
  {
    static_cast<vtkRenderWindow*>(caller)->SetAbortRender(1);
  }
}

void OnProgress(vtkObject* caller, unsigned long, void* cd, void*)
{
  auto* r = static_cast<AbortRequest*>(cd);
  if (!r->ViaWindow && r->Requested)
  {
    static_cast<vtkHighOrderVolumeMapper*>(caller)->SetAbortExecute(1);
  }
}

/// Counts the progressive levels shown; ends the event loop once the exact
/// one is done (or after Limit seconds from Start).
struct Watch
{
  vtkHighOrderVolumeMapper* Mapper;
  int Levels;
  int LastFactor = -1;
  bool Exact = false;
  double ExactAt = -1.0;
  double Limit = 60.0;
  Clock::time_point Start;
};

void OnWatch(vtkObject* caller, unsigned long, void* cd, void*)
{
  auto* w = static_cast<Watch*>(cd);
  const int f = w->Mapper->GetLastSubsampling();
  if (f != w->LastFactor)
  {
    w->LastFactor = f;
    ++w->Levels;
  }
  w->Exact = f == 1 && !w->Mapper->GetLastRenderAborted();
  if (w->Exact && w->ExactAt < 0.0)
  {
    w->ExactAt = Since(w->Start);
  }
  if (w->Exact || Since(w->Start) > w->Limit)
  {
    static_cast<vtkRenderWindowInteractor*>(caller)->TerminateApp();
  }
}

struct Result
{
  std::string Mesh, Mode;
  double Exact = 0, InteractiveMedian = 0, InteractiveMax = 0, FirstStill = 0, ExactStill = 0;
  std::vector<int> Factors;
  int Levels = 0;
  double StillDiff = -1;
  double AbortWindow = -1, AbortMapper = -1;
  bool AbortedWindow = false, AbortedMapper = false, NextComplete = false;
  bool RefinementEnded = true;
};

double Frame(vtkRenderWindowInteractor* iren)
{
  const auto t = Clock::now();
  iren->Render();
  iren->GetRenderWindow()->WaitForCompletion();
  return Since(t);
}

Result RunMode(const Args& args, const hovBench::Mesh& mesh, int mode, const std::string& label)
{
  Result r;
  r.Mesh = mesh.Name;
  r.Mode = label;
  const int size = args.Bench.Size;
  vtkNew<vtkHighOrderVolumeMapper> mapper;
  mapper->SetInputDataObject(mesh.Grid);
  mapper->SetRenderMode(mode);
  vtkSmartPointer<vtkVolumeProperty> prop = hovBench::MakeProperty(mesh.Range, mesh.UnitDistance);
  vtkNew<vtkVolume> volume;
  volume->SetMapper(mapper);
  volume->SetProperty(prop);
  vtkNew<vtkRenderer> ren;
  ren->AddVolume(volume);
  hovBench::SetupCamera(ren->GetActiveCamera(), mesh.Grid->GetBounds());
  vtkNew<vtkRenderWindow> win;
  win->SetSize(size, size);
  win->SetMultiSamples(0);
  win->AddRenderer(ren);
  vtkNew<vtkRenderWindowInteractor> iren;
  iren->SetRenderWindow(win);
  iren->SetDesiredUpdateRate(args.Rate);
  vtkNew<vtkInteractorStyleTrackballCamera> style;
  iren->SetInteractorStyle(style);
  iren->Initialize();
  vtkCamera* cam = ren->GetActiveCamera();

  // 1. The exact frame's cost (no progressive levels: ProgressiveTime 0).
  mapper->SetProgressiveTime(0.0);
  Frame(iren);
  r.Exact = Frame(iren);
  mapper->SetProgressiveTime(0.5);

  // 2. Interaction.
  style->StartRotate();
  std::vector<double> times;
  for (int i = 0; i < args.Steps; ++i)
  {
    cam->Azimuth(3.0);
    times.push_back(Frame(iren));
    r.Factors.push_back(mapper->GetLastSubsampling());
  }
  std::vector<double> sorted = times;
  std::sort(sorted.begin(), sorted.end());
  r.InteractiveMedian = sorted[sorted.size() / 2];
  r.InteractiveMax = sorted.back();

  // 3. EndRotate renders the still frame; VTK's event loop (Start()) runs the
  // mapper's timer, which renders the next levels; a watcher ends the loop
  // at the exact level (at once if the first still frame is exact), or after
  // a time limit, so a refinement that never ends shows up as a failed row.
  // Every run's interactor ends in a loop: VTK 9.1's X loop serves all the
  // initialized X interactors of the process and returns only when all are
  // terminated, so one left behind would keep a later run waiting forever.
  auto t0 = Clock::now();
  style->EndRotate();
  win->WaitForCompletion();
  r.FirstStill = Since(t0);
  Watch watch{ mapper, 1, mapper->GetLastSubsampling() };
  vtkNew<vtkCallbackCommand> watcher;
  watcher->SetCallback(OnWatch);
  watcher->SetClientData(&watch);
  iren->AddObserver(vtkCommand::TimerEvent, watcher, -1.0);
  iren->CreateRepeatingTimer(5);
  watch.Limit = 60.0 + 20.0 * r.Exact;
  watch.Start = t0;
  iren->Start();
  r.Levels = watch.Levels;
  r.RefinementEnded = watch.Exact;
  r.ExactStill = r.Levels > 1 ? watch.ExactAt : r.FirstStill;
  const std::vector<float> still = Copy(mapper);
  // The loop finalized the window: the rest is drawn in a new one, without
  // an interactor (the non-interactive render, the aborted still frames).
  win->RemoveRenderer(ren);
  vtkNew<vtkRenderWindow> view;
  view->SetSize(size, size);
  view->SetMultiSamples(0);
  view->AddRenderer(ren);
  mapper->AutoAdjustImageSampleDistanceOff();
  mapper->SetProgressiveTime(0.0);
  view->Render();
  r.StillDiff = MaxDiff(still, Copy(mapper));

  // 4. Abort 0.3 s into a still frame (the exact frame of a new view).
  if (args.Abort && r.Exact > 0.5)
  {
    AbortRequest request;
    vtkNew<vtkCallbackCommand> onCheck, onProgress;
    onCheck->SetCallback(OnAbortCheck);
    onCheck->SetClientData(&request);
    onProgress->SetCallback(OnProgress);
    onProgress->SetClientData(&request);
    view->AddObserver(vtkCommand::AbortCheckEvent, onCheck);
    mapper->AddObserver(vtkCommand::ProgressEvent, onProgress);
    for (int via = 0; via < 2; ++via)
    {
      request.ViaWindow = via == 0;
      request.Requested = false;
      cam->Azimuth(3.0);
      std::thread requester([&request]() {
        std::this_thread::sleep_for(std::chrono::milliseconds(300));
        request.At = Clock::now();
        request.Requested = true;
      });
      view->Render();
      const auto end = Clock::now();
      requester.join();
      const double latency = std::chrono::duration<double>(end - request.At).count();
      (via == 0 ? r.AbortWindow : r.AbortMapper) = request.Requested ? latency : -1.0;
      (via == 0 ? r.AbortedWindow : r.AbortedMapper) = mapper->GetLastRenderAborted();
    }
    request.Requested = false;
    view->Render();
    r.NextComplete = !mapper->GetLastRenderAborted();
    view->RemoveObserver(onCheck);
  }
  view->RemoveRenderer(ren);
  return r;
}

void Usage()
{
  std::cout << "hovBenchInteraction [--size 512] [--extent 24] [--steps 20] [--rate 15]\n"
               "  [--modes cpu,proj,ray] [--meshes bracket,rt] [--no-abort] [--data DIR]\n";
}
}

int main(int argc, char* argv[])
{
  Args args;
  for (int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    auto next = [&]() { return i + 1 < argc ? std::string(argv[++i]) : std::string(); };
    if (a == "--size") args.Bench.Size = std::stoi(next());
    else if (a == "--extent") args.Bench.Extent = std::stoi(next());
    else if (a == "--steps") args.Steps = std::stoi(next());
    else if (a == "--rate") args.Rate = std::stod(next());
    else if (a == "--modes") args.Modes = next();
    else if (a == "--meshes") args.Meshes = next();
    else if (a == "--data") args.Bench.DataDir = next();
    else if (a == "--no-abort") args.Abort = false;
    else { Usage(); return a == "--help" ? 0 : 1; }
  }
  std::vector<hovBench::Mesh> meshes;
  if (args.Meshes.find("bracket") != std::string::npos)
  {
    meshes.emplace_back();
    if (!hovBench::LoadBracket(args.Bench, meshes.back())) return 1;
  }
  if (args.Meshes.find("rt") != std::string::npos)
  {
    meshes.emplace_back();
    if (!hovBench::MakeRTMesh(args.Bench, meshes.back())) return 1;
  }
  const struct { const char* Key; int Mode; const char* Label; } modes[] = {
    { "cpu", vtkHighOrderVolumeMapper::CPU_ACCURATE, "CPU_ACCURATE" },
    { "proj", vtkHighOrderVolumeMapper::OPENGL_PROJECTION, "OPENGL_PROJECTION" },
    { "ray", vtkHighOrderVolumeMapper::RAY_CAST, "RAY_CAST" },
  };
  const double budget = 1.0 / args.Rate;
  std::cout << "size " << args.Bench.Size << "^2, " << args.Steps << " rotation steps at "
            << args.Rate << " frames/s (budget " << budget << " s, 1.5x = " << 1.5 * budget
            << " s)\n\n| mesh | mode | exact frame (s) | interactive median / max (s) | "
               "within 1.5x | pixels per ray | still: first image / exact (s), levels | "
               "still = non-interactive | abort latency AbortCheckEvent / SetAbortExecute (s) |"
               "\n|---|---|---|---|---|---|---|---|---|\n";
  bool ok = true;
  for (const hovBench::Mesh& mesh : meshes)
  {
    for (const auto& m : modes)
    {
      if (args.Modes.find(m.Key) == std::string::npos)
      {
        continue;
      }
      const Result r = RunMode(args, mesh, m.Mode, m.Label);
      const int fmin = *std::min_element(r.Factors.begin(), r.Factors.end());
      const int fmax = *std::max_element(r.Factors.begin(), r.Factors.end());
      const bool within = r.InteractiveMedian <= 1.5 * budget;
      std::ostringstream abort;
      if (r.AbortWindow >= 0 || r.AbortMapper >= 0)
      {
        abort << Fmt(r.AbortWindow) << (r.AbortedWindow ? "" : " (not aborted)") << " / "
              << Fmt(r.AbortMapper) << (r.AbortedMapper ? "" : " (not aborted)")
              << (r.NextComplete ? ", next complete" : ", NEXT INCOMPLETE");
      }
      else
      {
        abort << "-";
      }
      std::cout << "| " << mesh.Name << " (" << mesh.Tetras << " tets) | " << r.Mode << " | "
                << Fmt(r.Exact) << " | " << Fmt(r.InteractiveMedian) << " / "
                << Fmt(r.InteractiveMax) << " | " << (within ? "yes" : "NO") << " | "
                << fmin << "-" << fmax << " | " << Fmt(r.FirstStill) << " / "
                << Fmt(r.ExactStill) << ", " << r.Levels << " | "
                << (r.StillDiff == 0.0 ? "yes" : "NO (" + std::to_string(r.StillDiff) + ")")
                << " | " << abort.str() << " |" << std::endl;
      ok = ok && r.StillDiff == 0.0 && r.RefinementEnded;
    }
  }
  return ok ? 0 : 1;
}
