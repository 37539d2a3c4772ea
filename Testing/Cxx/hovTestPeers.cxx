// The bundled-dataset comparisons of hovTestReferencePeers.h.
#include "hovTestPeers.h"

#include "hovTestScenes.h"

#include "vtkCamera.h"
#include "vtkProjectedTetrahedraMapper.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkUnstructuredGrid.h"
#include "vtkUnstructuredGridLinearRayIntegrator.h"
#include "vtkUnstructuredGridVolumeRayCastMapper.h"

#include <algorithm>
#include <chrono>
#include <iomanip>
#include <iostream>

namespace hovTestRef
{
namespace
{
double Since(std::chrono::steady_clock::time_point t0)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

/// Screen capture of @p mapper's volume rendered in @p win (its one renderer
/// emptied afterwards); seconds of Render(). One window serves both peers:
/// fewer X connections (under a loaded shared Xvfb, creating a second window
/// has failed with "bad X server connection").
hovTest::Image PeerImage(vtkAbstractVolumeMapper* mapper, vtkVolumeProperty* property,
  vtkRenderWindow* win, vtkRenderer* ren, double& seconds, vtkTest::ErrorObserver* observer)
{
  vtkNew<vtkVolume> volume;
  volume->SetMapper(mapper);
  volume->SetProperty(property);
  hovTest::ObserveMessages(mapper, observer);
  ren->AddVolume(volume);
  const auto t0 = std::chrono::steady_clock::now();
  win->Render();
  seconds = Since(t0);
  hovTest::Image img = hovTest::Capture(win);
  mapper->ReleaseGraphicsResources(win);
  ren->RemoveAllViewProps();
  return img;
}
}

PeerRun RenderWithPeers(vtkUnstructuredGrid* native, vtkUnstructuredGrid* tessellated,
  vtkVolumeProperty* property, vtkCamera* cam, int size, int cellOrdering, const std::string& tmp,
  const std::string& tag)
{
  PeerRun run;
  {
    hovTest::VolumeScene ours(native);
    ours.Volume->SetProperty(property);
    ours.Mapper->SetOpacitySemanticsToVTKUnstructured();
    ours.Mapper->SetCellOrdering(cellOrdering);
    auto t0 = std::chrono::steady_clock::now();
    run.OurStatus = ours.Mapper->RenderImage(cam, ours.Volume, size, size);
    run.OursSeconds = Since(t0);
    run.Ours = hovTest::FloatImage(ours.Mapper);
    run.WitnessViolations = ours.Mapper->GetWitnessViolations();
    run.OurWarnings = hovTest::Msg(ours.Observer->GetWarningMessage());
    run.OurErrors = hovTest::Msg(ours.Observer->GetErrorMessage());
    vtkNew<vtkCamera> shifted;
    shifted->DeepCopy(cam);
    shifted->SetWindowCenter(-1.0 / size, -1.0 / size);
    ours.Mapper->RenderImage(shifted, ours.Volume, size, size);
    run.OursCorners = hovTest::FloatImage(ours.Mapper);
  }
  {
    hovTest::VolumeScene ours(tessellated);
    ours.Volume->SetProperty(property);
    ours.Mapper->SetOpacitySemanticsToVTKUnstructured();
    ours.Mapper->SetCellOrderingToPerPixelSort();
    auto t0 = std::chrono::steady_clock::now();
    ours.Mapper->RenderImage(cam, ours.Volume, size, size);
    run.OursTessellatedSeconds = Since(t0);
    run.OursTessellated = hovTest::FloatImage(ours.Mapper);
  }
  vtkNew<vtkTest::ErrorObserver> peerObserver;
  vtkSmartPointer<vtkRenderer> ren = hovTest::BlackRenderer(cam);
  vtkSmartPointer<vtkRenderWindow> win = hovTest::OffscreenWindow(ren, size, size, 0);
  vtkNew<vtkProjectedTetrahedraMapper> pt;
  pt->SetInputData(tessellated);
  run.PT = PeerImage(pt, property, win, ren, run.PTSeconds, peerObserver);
  vtkNew<vtkUnstructuredGridVolumeRayCastMapper> rc;
  rc->SetInputData(tessellated);
  vtkNew<vtkUnstructuredGridLinearRayIntegrator> integrator;
  rc->SetRayIntegrator(integrator);
  rc->AutoAdjustSampleDistancesOff();
  rc->SetImageSampleDistance(1.0);
  run.RC = PeerImage(rc, property, win, ren, run.RCSeconds, peerObserver);
  run.PeerMessages =
    hovTest::Msg(peerObserver->GetErrorMessage() + peerObserver->GetWarningMessage());
  hovTest::WritePNG(run.Ours, tmp + "/" + tag + "_ours.png");
  hovTest::WritePNG(run.OursTessellated, tmp + "/" + tag + "_ours_tess.png");
  hovTest::WritePNG(run.PT, tmp + "/" + tag + "_pt.png");
  hovTest::WritePNG(run.RC, tmp + "/" + tag + "_rc.png");
  return run;
}

double MeanDiff255(const hovTest::Image& a, const hovTest::Image& b)
{
  double worst = 0;
  for (int c = 0; c < 3; ++c)
  {
    worst = std::max(worst, hovTest::Diff(a, b, c, c + 1, 1.5 / 255).Mean * 255);
  }
  return worst;
}

void PrintPeerTable(const PeerRun& run)
{
  auto row = [](const char* name, const hovTest::Image& a, const hovTest::Image& b) {
    std::cout << "  " << std::left << std::setw(44) << name << std::right << std::fixed
              << std::setprecision(2);
    for (auto m : { &hovTest::DiffStats::Mean, &hovTest::DiffStats::P99, &hovTest::DiffStats::Max })
    {
      std::cout << "   ";
      for (int c = 0; c < 3; ++c)
      {
        std::cout << (c ? "/" : "") << hovTest::Diff(a, b, c, c + 1, 1.5 / 255).*m * 255;
      }
    }
    std::cout << std::defaultfloat << "\n";
  };
  std::cout << "  comparison (x255 per channel R/G/B)             mean / p99 / max\n";
  row("ours native vs ours tessellated", run.Ours, run.OursTessellated);
  row("RC screen vs ours tessellated", run.RC, run.OursTessellated);
  row("RC screen vs ours native", run.RC, run.Ours);
  row("RC screen vs ours native, corner rays", run.RC, run.OursCorners);
  row("PT screen vs ours tessellated", run.PT, run.OursTessellated);
  row("PT screen vs ours native", run.PT, run.Ours);
  std::cout << "  times (s): ours native " << run.OursSeconds << ", ours tessellated "
            << run.OursTessellatedSeconds << ", PT " << run.PTSeconds << ", RC " << run.RCSeconds
            << "; mean intensity x255: ours " << hovTest::MeanIntensity(run.Ours) * 255 << ", PT "
            << hovTest::MeanIntensity(run.PT) * 255 << ", RC "
            << hovTest::MeanIntensity(run.RC) * 255 << "\n";
}
}
