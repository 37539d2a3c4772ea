// hovBenchProjector: the CPU image of vtkHighOrderVolumeMapper alone (not a ctest case).
//
// Renders the meshes of hovBenchRender (same transfer function and camera) with
// vtkHighOrderVolumeMapper::RenderImage() (no OpenGL, no X server needed) for both
// cell orderings, over N frames each after a camera azimuth step, and prints per
// ordering the median wall time, the median process CPU time per frame (robust when
// other jobs load the machine), segments and pieces per frame.
//
// --dump DIR writes every frame's float RGBA image to DIR; --compare DIR reads such
// files back and prints the largest absolute difference per channel (to check that
// an optimisation leaves the image unchanged within round-off).
//
// Usage: hovBenchProjector [--data DIR] [--frames N] [--size S] [--extent E]
//                          [--mesh bracket|rt|all] [--order vis|pix|all]
//                          [--tile PIXELS] [--record-memory MIB] [--threads N]
//                          [--dump DIR | --compare DIR]
//
// --threads 1 gives the CPU time of the work alone (idle TBB workers spin, which
// adds CPU time that depends on the machine's load).
#include "BenchRender.h"

#include "vtkHighOrderVolumeMapper.h"

#include "vtkCamera.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkPointData.h"
#include "vtkSMPTools.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"
#include "vtkSteinVisibilitySort.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <ctime>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

using namespace hovBench;

namespace
{
double CpuSeconds()
{
  timespec ts;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

struct Args
{
  Options Opt;
  std::string Order = "all";
  std::string Dump, Compare;
  int TileSize = 0; // 0: the mapper's default
  int RecordMemory = -1; // MiB; -1: the mapper's default
  int Threads = 0;  // 0: vtkSMPTools' default
};

/// Max |difference| between @p img and the file @p path (or -1 if unreadable).
double CompareImage(const std::string& path, const float* img, size_t n)
{
  std::ifstream in(path, std::ios::binary);
  std::vector<float> ref(n);
  if (!in.read(reinterpret_cast<char*>(ref.data()), static_cast<std::streamsize>(n * sizeof(float))))
  {
    return -1.0;
  }
  double worst = 0.0;
  for (size_t i = 0; i < n; ++i)
  {
    worst = std::max(worst, std::abs(static_cast<double>(img[i]) - ref[i]));
  }
  return worst;
}

void RunMesh(const Args& args, const Mesh& mesh, bool perPixel)
{
  const Options& opt = args.Opt;
  vtkNew<vtkHighOrderVolumeMapper> mapper;
  mapper->SetIntegrationMethodToExact();
  mapper->SetOpacitySemanticsToVTKUnstructured();
  mapper->SetCellOrdering(
    perPixel ? vtkHighOrderVolumeMapper::PER_PIXEL_SORT : vtkHighOrderVolumeMapper::VISIBILITY_SORT);
  if (args.RecordMemory >= 0)
  {
    mapper->SetCellRecordMemory(args.RecordMemory);
  }
  if (args.TileSize > 0)
  {
    mapper->SetTileSize(args.TileSize);
  }
  mapper->SetInputDataObject(mesh.Grid);
  vtkSmartPointer<vtkVolumeProperty> prop = MakeProperty(mesh.Range, mesh.UnitDistance);
  vtkNew<vtkVolume> volume;
  volume->SetMapper(mapper);
  volume->SetProperty(prop);
  vtkNew<vtkCamera> cam;
  SetupCamera(cam, mesh.Grid->GetBounds());
  mapper->RenderImage(cam, volume, opt.Size, opt.Size); // set-up, caches
  std::vector<double> wall, cpu, sortWall;
  double worst = 0.0;
  for (int f = 0; f < opt.Frames; ++f)
  {
    cam->Azimuth(opt.AzimuthStep);
    cam->OrthogonalizeViewUp();
    const double c0 = CpuSeconds();
    mapper->RenderImage(cam, volume, opt.Size, opt.Size);
    cpu.push_back(CpuSeconds() - c0);
    wall.push_back(mapper->GetLastImageTime());
    auto* stein = vtkSteinVisibilitySort::SafeDownCast(mapper->GetVisibilitySort());
    sortWall.push_back(stein && !perPixel ? stein->GetLastSortSeconds() : 0.0);
    auto* rgba = vtkFloatArray::SafeDownCast(mapper->GetFloatImage()->GetPointData()->GetScalars());
    const size_t n = static_cast<size_t>(rgba->GetNumberOfValues());
    const std::string file = FileSafe(mesh.Name) + (perPixel ? "_pix_" : "_vis_") +
      std::to_string(f) + ".f32";
    if (!args.Dump.empty())
    {
      std::ofstream out(args.Dump + "/" + file, std::ios::binary);
      out.write(reinterpret_cast<const char*>(rgba->GetPointer(0)),
        static_cast<std::streamsize>(n * sizeof(float)));
    }
    if (!args.Compare.empty())
    {
      const double d = CompareImage(args.Compare + "/" + file, rgba->GetPointer(0), n);
      worst = d < 0 ? d : std::max(worst, d);
    }
  }
  std::cout << "  " << (perPixel ? "per-pixel " : "visibility") << "  wall " << Fmt(Median(wall))
            << " s  (sort " << Fmt(Median(sortWall)) << " s)  cpu " << Fmt(Median(cpu)) << " s  segments " << mapper->GetNumberOfSegments()
            << "  pieces " << mapper->GetNumberOfPieces() << "  witness "
            << mapper->GetWitnessViolations();
  if (!args.Compare.empty())
  {
    std::cout << "  max |diff| " << worst;
  }
  std::cout << "\n";
}
}

int main(int argc, char* argv[])
{
  Args args;
  Options& opt = args.Opt;
  for (int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    const char* v = i + 1 < argc ? argv[i + 1] : nullptr;
    if (!v && a != "--help")
    {
      std::cerr << a << " needs a value\n";
      return 2;
    }
    if (a == "--data") opt.DataDir = argv[++i];
    else if (a == "--frames") opt.Frames = std::max(1, std::atoi(argv[++i]));
    else if (a == "--size") opt.Size = std::max(16, std::atoi(argv[++i]));
    else if (a == "--extent") opt.Extent = std::max(1, std::atoi(argv[++i]));
    else if (a == "--mesh") opt.Meshes = argv[++i];
    else if (a == "--order") args.Order = argv[++i];
    else if (a == "--dump") args.Dump = argv[++i];
    else if (a == "--compare") args.Compare = argv[++i];
    else if (a == "--tile") args.TileSize = std::atoi(argv[++i]);
    else if (a == "--record-memory") args.RecordMemory = std::atoi(argv[++i]);
    else if (a == "--threads") args.Threads = std::max(1, std::atoi(argv[++i]));
    else
    {
      std::cout << "Usage: " << argv[0]
                << " [--data DIR] [--frames N] [--size S] [--extent E] [--mesh bracket|rt|all]\n"
                   "          [--order vis|pix|all] [--tile PIXELS] [--record-memory MIB] [--threads N]\n"
                   "          [--dump DIR | --compare DIR]\n";
      return a == "--help" ? 0 : 2;
    }
  }
  if (args.Threads > 0)
  {
    vtkSMPTools::Initialize(args.Threads);
  }
  std::cout << "hovBenchProjector: " << opt.Size << "x" << opt.Size << ", " << opt.Frames
            << " rotating frames, " << vtkSMPTools::GetBackend() << " with "
            << vtkSMPTools::GetEstimatedNumberOfThreads() << " threads\n";
  std::vector<Mesh> meshes;
  Mesh m;
  if ((opt.Meshes == "all" || opt.Meshes == "bracket") && LoadBracket(opt, m))
  {
    meshes.push_back(m);
  }
  if ((opt.Meshes == "all" || opt.Meshes == "rt") && MakeRTMesh(opt, m))
  {
    meshes.push_back(m);
  }
  for (const Mesh& mesh : meshes)
  {
    std::cout << mesh.Name << " (" << mesh.Tetras << " tets):\n";
    for (const bool perPixel : { false, true })
    {
      if (args.Order == "all" || args.Order == (perPixel ? "pix" : "vis"))
      {
        RunMesh(args, mesh, perPixel);
      }
    }
  }
  return meshes.empty() ? 1 : 0;
}
