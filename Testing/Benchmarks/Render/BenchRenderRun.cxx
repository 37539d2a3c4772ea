// hovBenchRender: one timed run of a mapper (see BenchRender.h).
#include "BenchRender.h"

#include "vtkHighOrderOffscreenWindow.h" // windows with X (Xvfb) or without (Mesa EGL)
#include "vtkHighOrderVolumeMapper.h"

#include "vtkAbstractVolumeMapper.h"
#include "vtkCamera.h"
#include "vtkCommand.h"
#include "vtkImageData.h"
#include "vtkPNGWriter.h"
#include "vtkPointData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkUnsignedCharArray.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"
#include "vtkWindowToImageFilter.h"

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cstdlib>  // std::exit without a window
#include <iostream>

namespace hovBench
{
ErrorCounter::ErrorCounter()
{
  this->Callback->SetClientData(this);
  this->Callback->SetCallback(&ErrorCounter::OnEvent);
}

void ErrorCounter::Watch(vtkObject* obj)
{
  obj->AddObserver(vtkCommand::ErrorEvent, this->Callback);
}

void ErrorCounter::OnEvent(vtkObject* caller, unsigned long, void* clientData, void* callData)
{
  auto* self = static_cast<ErrorCounter*>(clientData);
  std::string msg = callData ? static_cast<const char*>(callData) : "";
  while (!msg.empty() && (msg.back() == '\n' || msg.back() == '\r'))
  {
    msg.pop_back();
  }
  self->Messages.push_back(std::string(caller->GetClassName()) + ": " + msg);
  std::cerr << "VTK ERROR (" << caller->GetClassName() << "): " << msg << "\n";
}

double Median(std::vector<double> v)
{
  if (v.empty())
  {
    return 0.0;
  }
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

double Seconds(const std::function<void()>& f)
{
  const auto t0 = std::chrono::steady_clock::now();
  f();
  const auto t1 = std::chrono::steady_clock::now();
  return std::chrono::duration<double>(t1 - t0).count();
}

double Coverage(vtkRenderWindow* win, const std::string& png)
{
  vtkNew<vtkWindowToImageFilter> w2i;
  w2i->SetInput(win);
  w2i->SetInputBufferTypeToRGB();
  w2i->ReadFrontBufferOff();
  w2i->ShouldRerenderOff();
  w2i->Update();
  vtkUnsignedCharArray* rgb =
    vtkUnsignedCharArray::SafeDownCast(w2i->GetOutput()->GetPointData()->GetScalars());
  if (!rgb)
  {
    return 0.0;
  }
  const vtkIdType n = rgb->GetNumberOfTuples();
  const unsigned char* p = rgb->GetPointer(0);
  vtkIdType lit = 0;
  for (vtkIdType i = 0; i < n; ++i)
  {
    lit += (p[3 * i] | p[3 * i + 1] | p[3 * i + 2]) ? 1 : 0;
  }
  if (!png.empty())
  {
    vtkNew<vtkPNGWriter> writer;
    writer->SetFileName(png.c_str());
    writer->SetInputConnection(w2i->GetOutputPort());
    writer->Write();
  }
  return n ? static_cast<double>(lit) / n : 0.0;
}

std::string FileSafe(std::string s)
{
  for (char& c : s)
  {
    if (!std::isalnum(static_cast<unsigned char>(c)))
    {
      c = '_';
    }
  }
  return s;
}

std::unique_ptr<Run> Prepare(const Options& opt, const Mesh& mesh, const std::string& key,
  const std::string& label, vtkAbstractVolumeMapper* mapper, ErrorCounter& errors)
{
  auto run = std::make_unique<Run>();
  Row& row = run->Result;
  row.Mesh = mesh.Name;
  row.Mapper = label;
  row.Key = key;
  row.Ran = true;
  run->ErrorsBefore = errors.Messages.size();
  run->Mapper = mapper;
  errors.Watch(mapper);
  mapper->SetInputDataObject(mesh.Grid);
  vtkSmartPointer<vtkVolumeProperty> prop =
    MakeProperty(mesh.Range, mesh.UnitDistance, opt.TransparentBelow);
  vtkNew<vtkVolume> volume;
  volume->SetMapper(mapper);
  volume->SetProperty(prop);
  vtkNew<vtkRenderer> ren;
  ren->SetBackground(0.0, 0.0, 0.0);
  ren->AddVolume(volume);
  run->Camera = vtkSmartPointer<vtkCamera>::New();
  SetupCamera(run->Camera, mesh.Grid->GetBounds());
  ren->SetActiveCamera(run->Camera);
  vtkNew<vtkHighOrderOffscreenWindow> factory; // X if DISPLAY is set, Mesa EGL if not
  run->Window = vtkSmartPointer<vtkRenderWindow>::Take(factory->NewRenderWindow(opt.Size, opt.Size));
  if (!run->Window)
  {
    std::cerr << "hovBenchRender: " << factory->GetErrorMessage() << "\n";
    std::exit(1);
  }
  vtkRenderWindow* win = run->Window;
  win->SetMultiSamples(0);
  win->AddRenderer(ren);
  errors.Watch(win);
  errors.Watch(ren);

  // Create the OpenGL context first, without the volume, so the first frame measures the
  // mapper (its setup, sort, shaders, integrator tables), not window creation.
  volume->VisibilityOff();
  win->Render();
  win->WaitForCompletion();
  volume->VisibilityOn();
  return run;
}

double TimeFrame(Run& run)
{
  return Seconds([&]() {
    run.Window->Render();
    run.Window->WaitForCompletion();
  });
}

void TimeInterleaved(const Options& opt, std::vector<std::unique_ptr<Run>>& runs)
{
  for (auto& run : runs)
  {
    std::cout << "  " << run->Result.Mapper << ": first frame ..." << std::flush;
    run->Result.First = TimeFrame(*run);
    std::cout << " " << run->Result.First << " s\n";
  }
  std::cout << "  interleaved rounds:" << std::flush;
  for (int i = 0; i < opt.Frames; ++i)
  {
    for (auto& run : runs)
    {
      run->Same.push_back(TimeFrame(*run));
    }
    std::cout << " s" << i + 1 << std::flush;
  }
  for (int i = 0; i < opt.Frames; ++i)
  {
    for (auto& run : runs)
    {
      run->Camera->Azimuth(opt.AzimuthStep);
      run->Camera->OrthogonalizeViewUp();
      run->Result.RotatingTimes.push_back(TimeFrame(*run));
      if (auto* hov = vtkHighOrderVolumeMapper::SafeDownCast(run->Mapper))
      {
        run->Cpu.push_back(hov->GetLastImageTime());
      }
    }
    std::cout << " r" << i + 1 << std::flush;
  }
  std::cout << "\n";
}

Row Finish(const Options& opt, const Mesh& mesh, Run& run, ErrorCounter& errors)
{
  Row& row = run.Result;
  row.Same = Median(run.Same);
  row.Rotating = Median(row.RotatingTimes);
  if (auto* hov = vtkHighOrderVolumeMapper::SafeDownCast(run.Mapper))
  {
    row.CpuRotating = Median(run.Cpu);
    row.Witness = hov->GetWitnessViolations();
  }
  std::string png;
  if (!opt.OutDir.empty())
  {
    png = opt.OutDir + "/bench_" + FileSafe(mesh.Name) + "_" + row.Key + ".png";
  }
  row.Coverage = Coverage(run.Window, png);
  // Errors of this run (the runs of a mesh share the counter: attribute by emitter).
  for (size_t e = run.ErrorsBefore; e < errors.Messages.size() && row.Ok; ++e)
  {
    const std::string& msg = errors.Messages[e];
    if (msg.rfind(run.Mapper->GetClassName(), 0) == 0 ||
      msg.rfind(run.Window->GetClassName(), 0) == 0 || msg.rfind("vtkOpenGLRenderer", 0) == 0)
    {
      row.Ok = false;
      row.Problem = msg;
    }
  }
  if (row.Ok && row.Coverage <= 0.0)
  {
    row.Ok = false;
    row.Problem = "all-black image";
  }
  std::cout << "  " << row.Mapper << ": first " << row.First << " s, rotating median "
            << row.Rotating << " s, same-view median " << row.Same << " s"
            << (row.Ok ? "" : "  FAILED: ") << row.Problem << "\n";
  run.Window->Finalize();
  return row;
}
}
