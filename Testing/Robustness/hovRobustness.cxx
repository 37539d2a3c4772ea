/**
 * @file   hovRobustness.cxx
 * @brief  Property-based robustness test of vtkHighOrderVolumeMapper (issue 21).
 *
 *   hovRobustness [--seed S] [--seconds T] [--cases N] [--case C] [--verbose] [--dump DIR]
 *
 * Renders random, mostly malformed cases (hovRobustnessCase.h: grids, scalars,
 * transfer functions, cameras, settings, every render mode, RenderImage and a
 * window) one after the other, case k with seed S * 1000003 + k, until T
 * seconds or N cases have passed; --case C renders that one case only (its
 * seed, as printed by a failure). Each case must hold the mapper's rule
 * (vtkHighOrderVolumeMapperChecks.cxx):
 *  - no crash, and no hang: a watchdog aborts a case that runs longer than
 *    HangSeconds, printing it;
 *  - RenderImage returns 0 or 1; 0 comes with an error message;
 *  - the float image has the requested size (status 1) and no NaN/Inf value;
 *  - an image that is empty (all zero) comes with a message (error or warning).
 * On the first violation it prints the case and exits 1. Everything VTK prints
 * goes into a string window (and is counted as a message), so the log shows
 * only verdicts.
 */
#include "hovRobustnessCase.h"

#include "vtkColorTransferFunction.h"
#include "vtkCommand.h"
#include "vtkFloatArray.h"
#include "vtkHighOrderOffscreenWindow.h" // X or EGL windows
#include "vtkImageData.h"
#include "vtkLogger.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOutputWindow.h"
#include "vtkPointData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkTestErrorObserver.h"
#include "vtkXMLUnstructuredGridWriter.h"

#include <algorithm> // std::max
#include <atomic>   // the watchdog's clock
#include <chrono>   // time budget
#include <cmath>    // std::isfinite
#include <cstdlib>  // std::abort, std::strtoull
#include <cstring>  // std::strcmp
#include <fstream>  // --dump
#include <iostream> // verdicts
#include <mutex>    // the description the watchdog prints
#include <string>   // arguments
#include <thread>   // the watchdog

namespace
{
/// A case longer than this is a hang. The slowest seen: 4603043616 (a table refined to
/// 16,384 nodes, unshaded polynomial pieces, one per node crossed: 55 s until the sampled
/// route stepped over smooth nodes, now 9.8 s) and 4502017930 (the same table, shaded
/// general cells: 80 s, now 6.3 s).
constexpr double HangSeconds = 120.0;

/// Swallows everything VTK prints, counting it as a message of the case.
class CountingOutputWindow : public vtkOutputWindow
{
public:
  static CountingOutputWindow* New();
  vtkTypeMacro(CountingOutputWindow, vtkOutputWindow);
  void DisplayText(const char*) override { ++this->Count; }
  void DisplayErrorText(const char*) override { ++this->Count; }
  void DisplayWarningText(const char*) override { ++this->Count; }
  void DisplayGenericWarningText(const char*) override { ++this->Count; }
  void DisplayDebugText(const char*) override {}
  int Count = 0;
};
vtkStandardNewMacro(CountingOutputWindow);

struct Watchdog
{
  std::atomic<double> CaseStart{ -1.0 };
  std::mutex Lock;
  std::string Current;
  std::atomic<bool> Stop{ false };
};

double Now()
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

/// The verdict on one rendered case: empty if it holds the rule.
std::string Judge(hovRobustness::Case& c, int status, bool messages)
{
  vtkImageData* image = c.Mapper->GetFloatImage();
  auto* rgba = vtkFloatArray::SafeDownCast(image->GetPointData()->GetScalars());
  if (status != 0 && status != 1)
  {
    return "RenderImage returned " + std::to_string(status);
  }
  if (status == 0 && !messages)
  {
    return "status 0 without an error message";
  }
  const vtkIdType n = rgba ? rgba->GetNumberOfValues() : 0;
  if (c.InWindow && n == 0)
  {
    return std::string(); // VTK's frustum culler did not call the mapper: nothing drawn
  }
  if (status == 1 && !c.InWindow && n != 4 * static_cast<vtkIdType>(c.Width) * c.Height)
  {
    return "status 1 but the float image holds " + std::to_string(n) + " values";
  }
  bool empty = true;
  for (vtkIdType i = 0; i < n; ++i)
  {
    const float v = rgba->GetValue(i);
    if (!std::isfinite(v))
    {
      return "a non-finite value in the float image (value " + std::to_string(i) + ")";
    }
    empty = empty && v == 0.0f;
  }
  if (empty && !messages)
  {
    return "an empty image without any message";
  }
  return std::string();
}
}

int main(int argc, char* argv[])
{
  std::uint64_t seed = 21, single = 0;
  double seconds = 60.0;
  long long maxCases = -1;
  bool one = false, verbose = false;
  std::string dump; // write each case's grid to <dump>/case<seed>.vtu
  for (int i = 1; i < argc; ++i)
  {
    const bool more = i + 1 < argc;
    if (!std::strcmp(argv[i], "--seed") && more)
      seed = std::strtoull(argv[++i], nullptr, 10);
    else if (!std::strcmp(argv[i], "--seconds") && more)
      seconds = std::atof(argv[++i]);
    else if (!std::strcmp(argv[i], "--cases") && more)
      maxCases = std::atoll(argv[++i]);
    else if (!std::strcmp(argv[i], "--case") && more)
    {
      single = std::strtoull(argv[++i], nullptr, 10);
      one = true;
    }
    else if (!std::strcmp(argv[i], "--verbose"))
      verbose = true;
    else if (!std::strcmp(argv[i], "--dump") && more)
      dump = argv[++i];
    else
    {
      std::cerr << "usage: hovRobustness [--seed S] [--seconds T] [--cases N] [--case C] "
                   "[--verbose] [--dump DIR]\n";
      return 2;
    }
  }
  vtkNew<CountingOutputWindow> log;
  vtkOutputWindow::SetInstance(log);
  vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF); // VTK 9.1 logs to stderr besides

  Watchdog dog;
  std::thread watcher([&dog] {
    while (!dog.Stop)
    {
      std::this_thread::sleep_for(std::chrono::milliseconds(200));
      const double start = dog.CaseStart;
      if (start > 0.0 && Now() - start > HangSeconds)
      {
        std::lock_guard<std::mutex> guard(dog.Lock);
        std::cout << "HANG (> " << HangSeconds << " s):\n" << dog.Current << std::flush;
        std::abort();
      }
    }
  });

  // The window from the module's factory: X under Xvfb, Mesa EGL without DISPLAY.
  vtkNew<vtkRenderer> renderer;
  vtkNew<vtkHighOrderOffscreenWindow> factory;
  auto window = vtkSmartPointer<vtkRenderWindow>::Take(factory->NewRenderWindow(16, 16));
  if (!window)
  {
    std::cerr << "hovRobustness: no render window: " << factory->GetErrorMessage() << "\n";
    return 1;
  }
  window->AddRenderer(renderer);
  const double begin = Now();
  long long cases = 0, empty = 0, failed = 0, windowCases = 0;
  double slowest = 0.0;
  std::uint64_t slowestSeed = 0;
  int result = 0;
  for (long long k = 0;; ++k)
  {
    if (one ? k > 0 : ((maxCases >= 0 && k >= maxCases) || Now() - begin > seconds))
    {
      break;
    }
    const std::uint64_t caseSeed = one ? single : seed * 1000003ull + static_cast<std::uint64_t>(k);
    hovRobustness::Case c;
    hovRobustness::Build(caseSeed, c);
    const std::string header = "case " + std::to_string(caseSeed) +
      " (reproduce: hovRobustness --case " + std::to_string(caseSeed) + ")\n" + c.Description;
    {
      std::lock_guard<std::mutex> guard(dog.Lock);
      dog.Current = header;
    }
    if (verbose)
    {
      std::cout << header << std::flush;
    }
    if (!dump.empty())
    {
      vtkNew<vtkXMLUnstructuredGridWriter> writer;
      writer->SetFileName((dump + "/case" + std::to_string(caseSeed) + ".vtu").c_str());
      writer->SetInputData(c.Grid);
      writer->Write();
      std::ofstream settings(dump + "/case" + std::to_string(caseSeed) + ".txt");
      c.Mapper->Print(settings);
      c.Property->Print(settings);
      c.Property->GetRGBTransferFunction()->Print(settings);
      c.Camera->Print(settings);
    }
    vtkNew<vtkTest::ErrorObserver> observer;
    c.Mapper->AddObserver(vtkCommand::ErrorEvent, observer);
    c.Mapper->AddObserver(vtkCommand::WarningEvent, observer);
    log->Count = 0;
    dog.CaseStart = Now();
    int status = 1;
    if (c.InWindow)
    {
      ++windowCases;
      renderer->SetActiveCamera(c.Camera);
      renderer->AddVolume(c.Volume);
      window->SetSize(c.Width, c.Height);
      window->Render();
      renderer->RemoveVolume(c.Volume);
    }
    else
    {
      status = c.Mapper->RenderImage(c.Camera, c.Volume, c.Width, c.Height);
    }
    const double caseSeconds = Now() - dog.CaseStart;
    dog.CaseStart = -1.0;
    if (caseSeconds > slowest)
    {
      slowest = caseSeconds;
      slowestSeed = caseSeed;
    }
    const bool messages = observer->GetError() || observer->GetWarning() || log->Count > 0;
    const std::string verdict = Judge(c, status, messages);
    ++cases;
    auto* rgba = vtkFloatArray::SafeDownCast(c.Mapper->GetFloatImage()->GetPointData()->GetScalars());
    bool allZero = true;
    for (vtkIdType i = 0; rgba && i < rgba->GetNumberOfValues() && allZero; ++i)
    {
      allZero = rgba->GetValue(i) == 0.0f;
    }
    empty += allZero;
    if (!verdict.empty())
    {
      ++failed;
      std::cout << "FAILED: " << verdict << "\n" << header << "messages: "
                << observer->GetErrorMessage() << observer->GetWarningMessage() << "\n";
      result = 1;
      break;
    }
    if (verbose)
    {
      std::cout << "  ok: status " << status << (allZero ? ", empty (with a message)" : "")
                << ", " << caseSeconds << " s\n";
      if (messages)
      {
        std::cout << "  messages: " << observer->GetErrorMessage() << observer->GetWarningMessage()
                  << (log->Count > 0 ? " (and " + std::to_string(log->Count) + " logged)" : "")
                  << "\n";
      }
    }
  }
  dog.Stop = true;
  watcher.join();
  std::cout << "[measured] hovRobustness: " << cases << " cases in " << Now() - begin
            << " s (seed " << seed << "; " << windowCases << " in a window, " << empty
            << " empty images, each with a message; slowest case " << slowestSeed << ": " << slowest
            << " s), " << failed
            << " failed\n";
  return result;
}
