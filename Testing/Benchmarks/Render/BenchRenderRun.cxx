// hovBenchRender: one timed run of a mapper (see BenchRender.h).
#include "BenchRender.h"

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

Row RunOne(const Options& opt, const Mesh& mesh, const std::string& key, const std::string& label,
  vtkAbstractVolumeMapper* mapper, ErrorCounter& errors)
{
  Row row;
  row.Mesh = mesh.Name;
  row.Mapper = label;
  row.Key = key;
  row.Ran = true;
  const size_t errorsBefore = errors.Messages.size();
  std::cout << "  " << label << " ..." << std::flush;

  auto* hov = vtkHighOrderVolumeMapper::SafeDownCast(mapper);
  errors.Watch(mapper);
  mapper->SetInputDataObject(mesh.Grid);
  vtkSmartPointer<vtkVolumeProperty> prop = MakeProperty(mesh.Range, mesh.UnitDistance);
  vtkNew<vtkVolume> volume;
  volume->SetMapper(mapper);
  volume->SetProperty(prop);
  vtkNew<vtkRenderer> ren;
  ren->SetBackground(0.0, 0.0, 0.0);
  ren->AddVolume(volume);
  vtkNew<vtkCamera> cam;
  SetupCamera(cam, mesh.Grid->GetBounds());
  ren->SetActiveCamera(cam);
  vtkNew<vtkRenderWindow> win;
  win->SetOffScreenRendering(1);
  win->SetMultiSamples(0);
  win->SetSize(opt.Size, opt.Size);
  win->AddRenderer(ren);
  errors.Watch(win);
  errors.Watch(ren);

  // Create the OpenGL context first, without the volume, so the first frame measures the
  // mapper (its setup, sort, shaders, integrator tables), not window creation.
  volume->VisibilityOff();
  win->Render();
  win->WaitForCompletion();
  volume->VisibilityOn();

  auto frame = [&]() {
    win->Render();
    win->WaitForCompletion();
  };
  row.First = Seconds(frame);

  std::vector<double> same, rotating, cpu;
  for (int i = 0; i < opt.Frames; ++i)
  {
    same.push_back(Seconds(frame));
  }
  for (int i = 0; i < opt.Frames; ++i)
  {
    cam->Azimuth(opt.AzimuthStep);
    cam->OrthogonalizeViewUp();
    rotating.push_back(Seconds(frame));
    if (hov)
    {
      cpu.push_back(hov->GetLastImageTime());
    }
  }
  row.Same = Median(same);
  row.Rotating = Median(rotating);
  if (hov)
  {
    row.CpuRotating = Median(cpu);
    row.Witness = hov->GetWitnessViolations();
  }
  std::string png;
  if (!opt.OutDir.empty())
  {
    png = opt.OutDir + "/bench_" + FileSafe(mesh.Name) + "_" + key + ".png";
  }
  row.Coverage = Coverage(win, png);
  if (errors.Messages.size() != errorsBefore)
  {
    row.Ok = false;
    row.Problem = errors.Messages[errorsBefore];
  }
  else if (row.Coverage <= 0.0)
  {
    row.Ok = false;
    row.Problem = "all-black image";
  }
  std::cout << " first " << row.First << " s, rotating median " << row.Rotating
            << " s, same-view median " << row.Same << " s" << (row.Ok ? "" : "  FAILED: ")
            << row.Problem << "\n";
  win->Finalize();
  return row;
}
}
