// hovBenchMemory: peak resident memory of one frame per mapper (issue 20, acceptance 2), not a
// ctest case.
//
// Every mapper runs in a fresh process (this program started again with --mapper KEY), so the
// peaks do not mix: the process makes the mesh (vtkRTAnalyticSource [-E,E]^3 through
// vtkDataSetTriangleFilter; E = 37 by default: 2,026,120 tetrahedra), opens a S x S offscreen
// window (1024 by default) and renders it once without the volume (GL context), then renders
// --frames frames (the first, then each after a 7-degree azimuth: the re-sort included) with
// the same camera and vtkVolumeProperty as hovBenchRender. Peak RSS is the process's VmHWM
// (/proc/self/status) at the end; "base" is VmHWM after the mesh and the window, before the
// mapper's first frame.
//   cpu   vtkHighOrderVolumeMapper CPU_ACCURATE (exact, VTK-unstructured, Stein order)
//   proj  vtkHighOrderVolumeMapper OPENGL_PROJECTION (same settings)
//   pt    vtkProjectedTetrahedraMapper
//   rc    vtkUnstructuredGridVolumeRayCastMapper + linear integrator
// The table gives each peak and its ratio to pt's (the acceptance: cpu and proj <= 1.2x).
//
// Usage: hovBenchMemory [--mapper cpu|proj|pt|rc|all] [--extent E] [--size S] [--frames N]
// Run under xvfb-run -a -s "-screen 0 1280x1024x24 -noreset".
#include "BenchRender.h"

#include "vtkHighOrderVolumeMapper.h"

#include "vtkCamera.h"
#include "vtkProjectedTetrahedraMapper.h"
#include "vtkRenderWindow.h"
#include "vtkUnstructuredGridLinearRayIntegrator.h"
#include "vtkUnstructuredGridVolumeRayCastMapper.h"

#include <algorithm>
#include <cstdio>  // popen: one child process per mapper
#include <cstdlib>
#include <fstream> // /proc/self/status
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

using namespace hovBench;

namespace
{
/// A line "key: value kB" of /proc/self/status, in MB (0 if unavailable).
double StatusMB(const char* key)
{
  std::ifstream in("/proc/self/status");
  std::string line;
  const std::string k = std::string(key) + ":";
  while (std::getline(in, line))
  {
    if (line.compare(0, k.size(), k) == 0)
    {
      return std::atof(line.c_str() + k.size()) / 1024.0;
    }
  }
  return 0.0;
}

vtkSmartPointer<vtkAbstractVolumeMapper> MakeMapper(const std::string& key)
{
  if (key == "cpu" || key == "proj")
  {
    auto m = vtkSmartPointer<vtkHighOrderVolumeMapper>::New();
    m->SetIntegrationMethodToExact();
    m->SetOpacitySemanticsToVTKUnstructured();
    if (key == "proj")
    {
      m->SetRenderModeToOpenGLProjection();
    }
    return m;
  }
  if (key == "pt")
  {
    return vtkSmartPointer<vtkProjectedTetrahedraMapper>::New();
  }
  if (key == "rc")
  {
    auto m = vtkSmartPointer<vtkUnstructuredGridVolumeRayCastMapper>::New();
    vtkNew<vtkUnstructuredGridLinearRayIntegrator> integrator;
    m->SetRayIntegrator(integrator);
    m->SetAutoAdjustSampleDistances(0);
    m->SetImageSampleDistance(1.0);
    return m;
  }
  return nullptr;
}

/// One mapper in this process; prints "RESULT key base peak ok".
int RunOne(const Options& opt, const std::string& key, int frames)
{
  vtkSmartPointer<vtkAbstractVolumeMapper> mapper = MakeMapper(key);
  if (!mapper)
  {
    std::cerr << "--mapper must be cpu, proj, pt, rc or all\n";
    return 2;
  }
  Mesh mesh;
  if (!MakeRTMesh(opt, mesh))
  {
    return 1;
  }
  const double meshMB = StatusMB("VmHWM");
  ErrorCounter errors;
  std::unique_ptr<Run> run = Prepare(opt, mesh, key, key, mapper, errors);
  const double baseMB = StatusMB("VmHWM");
  for (int f = 0; f < frames; ++f)
  {
    if (f > 0)
    {
      run->Camera->Azimuth(opt.AzimuthStep);
      run->Camera->OrthogonalizeViewUp();
    }
    run->Result.RotatingTimes.push_back(TimeFrame(*run));
  }
  const double peakMB = StatusMB("VmHWM");
  const double coverage = Coverage(run->Window, "");
  const bool ok = errors.Messages.empty() && coverage > 0.0;
  std::cout << "RESULT " << key << " " << meshMB << " " << baseMB << " " << peakMB << " "
            << (ok ? 1 : 0) << " " << Median(run->Result.RotatingTimes) << "\n";
  run->Window->Finalize();
  return ok ? 0 : 1;
}

struct Result
{
  double Mesh = 0, Base = 0, Peak = 0, Seconds = 0;
  bool Ok = false;
  std::vector<double> Peaks; ///< one per process (the median is Peak)
};
} // namespace

int main(int argc, char* argv[])
{
  Options opt;
  opt.Extent = 37;
  opt.Size = 1024;
  std::string key = "all";
  int frames = 2;
  int repeat = 3;
  for (int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    if (i + 1 >= argc && a != "--help" && a != "-h")
    {
      std::cerr << a << " needs a value\n";
      return 2;
    }
    if (a == "--mapper")
    {
      key = argv[++i];
    }
    else if (a == "--extent")
    {
      opt.Extent = std::max(1, std::atoi(argv[++i]));
    }
    else if (a == "--size")
    {
      opt.Size = std::max(16, std::atoi(argv[++i]));
    }
    else if (a == "--frames")
    {
      frames = std::max(1, std::atoi(argv[++i]));
    }
    else if (a == "--repeat")
    {
      repeat = std::max(1, std::atoi(argv[++i]));
    }
    else
    {
      std::cout << "Usage: " << argv[0]
                << " [--mapper cpu|proj|pt|rc|all] [--extent E (37)] [--size S (1024)]"
                   " [--frames N (2)] [--repeat R (3)]\n"
                   "With --mapper all, each mapper runs in R fresh processes and its peak is"
                   " their median\n(vtkProjectedTetrahedraMapper's varies from run to run)."
                   " Run under xvfb-run.\n";
      return a == "--help" || a == "-h" ? 0 : 2;
    }
  }
  if (key != "all")
  {
    return RunOne(opt, key, frames);
  }
  std::map<std::string, Result> results;
  const std::vector<std::string> keys = { "pt", "rc", "cpu", "proj" };
  for (int round = 0; round < repeat; ++round)
  {
    for (const std::string& k : keys)
    {
      std::ostringstream cmd;
      cmd << "'" << argv[0] << "' --mapper " << k << " --extent " << opt.Extent << " --size "
          << opt.Size << " --frames " << frames;
      std::cout << "== " << cmd.str() << "\n" << std::flush;
      FILE* child = popen(cmd.str().c_str(), "r");
      char line[1024];
      while (child && std::fgets(line, sizeof(line), child))
      {
        std::cout << "   " << line;
        std::istringstream in(line);
        std::string tag, got;
        Result r;
        int ok = 0;
        if (in >> tag >> got >> r.Mesh >> r.Base >> r.Peak >> ok >> r.Seconds && tag == "RESULT")
        {
          Result& kept = results[got];
          const bool okSoFar = kept.Peaks.empty() || kept.Ok;
          r.Peaks = kept.Peaks;
          r.Peaks.push_back(r.Peak);
          r.Ok = ok == 1 && okSoFar;
          kept = r;
        }
      }
      if (child)
      {
        pclose(child);
      }
    }
  }
  for (auto& entry : results)
  {
    Result& r = entry.second;
    r.Ok = r.Ok && static_cast<int>(r.Peaks.size()) == repeat; // every process reported
    r.Peak = Median(r.Peaks);
  }
  const double pt = results.count("pt") ? results["pt"].Peak : 0.0;
  std::cout << "\n| mapper | mesh made (MB) | + window (MB) | peak (MB), median of " << repeat
            << " | min - max (MB) | peak / PT | frame (s) |\n"
               "|---|---|---|---|---|---|---|\n";
  bool allOk = true;
  for (const std::string& k : keys)
  {
    if (!results.count(k))
    {
      std::cout << "| " << k << " | failed | | | | | |\n";
      allOk = false;
      continue;
    }
    const Result& r = results[k];
    allOk = allOk && r.Ok;
    std::cout << "| " << k << (r.Ok ? "" : " (FAILED)") << " | " << Fmt(r.Mesh, 0) << " | "
              << Fmt(r.Base, 0) << " | " << Fmt(r.Peak, 0) << " | "
              << Fmt(*std::min_element(r.Peaks.begin(), r.Peaks.end()), 0) << " - "
              << Fmt(*std::max_element(r.Peaks.begin(), r.Peaks.end()), 0) << " | "
              << (pt > 0 ? Fmt(r.Peak / pt, 2) + "x" : "-") << " | " << Fmt(r.Seconds, 2)
              << " |\n";
  }
  return allOk ? 0 : 1;
}
