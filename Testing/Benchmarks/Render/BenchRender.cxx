// hovBenchRender: wall-clock render benchmark (not a ctest case).
//
// In one process, offscreen at 512x512 (default), renders
//   (a) the bundled bracket (Testing/Data/bracket_tet4_ccx.vtu, point array von_mises),
//   (b) a generated mesh: vtkRTAnalyticSource, whole extent [-E,E]^3 (E = 24 by default:
//       48^3 = 110,592 voxels) -> vtkDataSetTriangleFilter (5 tetrahedra per voxel),
// with
//   - vtkHighOrderVolumeMapper, exact integral, VTK_UNSTRUCTURED opacity semantics,
//     VISIBILITY_SORT (the exact vtkSteinVisibilitySort, the default) and PER_PIXEL_SORT,
//   - vtkProjectedTetrahedraMapper (OpenGL, vtkCellCenterDepthSort),
//   - vtkUnstructuredGridVolumeRayCastMapper + vtkUnstructuredGridLinearRayIntegrator,
// all with the same camera and the same vtkVolumeProperty, each in its own offscreen window,
// and prints a Markdown table: first frame (fresh mapper, GL context already created),
// median of N frames each after a camera azimuth step (view-dependent caches cannot be
// reused), median of N frames of the same view, and the ratios mapper time / our mapper
// time. The timed frames are interleaved: in each round every mapper renders one frame, so
// a change of machine load (other processes, a noisy host) hits all mappers alike; the
// per-round ratios of the rotating frames are paired and reported as median [min, max].
// Every timed frame is renderWindow->Render() followed by WaitForCompletion() (glFinish),
// so asynchronous OpenGL work is counted.
//
// With --transparent-below F the transfer function has no opacity over the lowest fraction
// F of the scalar range, and a row hov_full renders as hov_vis with SkipTransparentCells off
// (every cell integrated): what skipping the cells that lie there saves.
//
// Usage: hovBenchRender [--data DIR] [--frames N] [--size S] [--extent E] [--azimuth DEG]
//                       [--mesh bracket|rt|all] [--skip-raycast-large] [--out DIR]
//                       [--transparent-below F] [--only KEYS]
// Run under xvfb-run -a -s "-screen 0 1280x1024x24 -noreset" (Debian's VTK renders only via GLX).
// Exit status: 0 if every render succeeded without VTK errors and gave a non-black image.
//
// Sources: this file (options, main), BenchRenderScene.cxx (meshes, transfer function,
// camera), BenchRenderRun.cxx (one timed run), BenchRenderTable.cxx (the table).

#include "BenchRender.h"

#include "vtkHighOrderVolumeMapper.h"

#include "vtkNew.h"
#include "vtkProjectedTetrahedraMapper.h"
#include "vtkSMPTools.h"
#include "vtkUnstructuredGridLinearRayIntegrator.h"
#include "vtkUnstructuredGridVolumeRayCastMapper.h"
#include "vtkVersion.h"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

using namespace hovBench;

namespace
{
void Usage(const char* argv0)
{
  std::cout
    << "Usage: " << argv0
    << " [--data DIR] [--frames N] [--size S] [--extent E] [--azimuth DEG]\n"
       "          [--mesh bracket|rt|all] [--skip-raycast-large] [--out DIR]\n"
       "  --data DIR            directory with bracket_tet4_ccx.vtu (default " HOV_BENCH_DATA_DIR
       ")\n"
       "  --frames N            timed frames per median (default 3)\n"
       "  --size S              window width and height (default 512)\n"
       "  --extent E            vtkRTAnalyticSource whole extent [-E,E]^3 (default 24: 552,960 "
       "tets)\n"
       "  --azimuth DEG         camera azimuth step between rotating frames (default 7)\n"
       "  --mesh M              bracket, rt or all (default all)\n"
       "  --skip-raycast-large  skip vtkUnstructuredGridVolumeRayCastMapper on the generated mesh\n"
       "  --out DIR             write the last frame of every run as PNG into DIR\n"
       "  --transparent-below F no opacity over the lowest fraction F of the scalar range\n"
       "                        (our mapper skips the cells that lie there: hov_full does not)\n"
       "  --only KEYS           run only these mappers (comma-separated: hov_vis, hov_pix,\n"
       "                        hov_full, pt, rc; e.g. to profile one of them)\n"
       "Run under xvfb-run -a -s \"-screen 0 1280x1024x24 -noreset\".\n";
}
/// True if --only is not given or lists @p key.
bool Wanted(const Options& opt, const std::string& key)
{
  return opt.Only.empty() || ("," + opt.Only + ",").find("," + key + ",") != std::string::npos;
}
} // namespace

int main(int argc, char* argv[])
{
  Options opt;
  for (int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    auto next = [&](const char* what) -> const char* {
      if (i + 1 >= argc)
      {
        std::cerr << a << " needs " << what << "\n";
        std::exit(2);
      }
      return argv[++i];
    };
    if (a == "--data" || a == "-D")
    {
      opt.DataDir = next("a directory");
    }
    else if (a == "--frames" || a == "-n")
    {
      opt.Frames = std::max(1, std::atoi(next("a count")));
    }
    else if (a == "--size")
    {
      opt.Size = std::max(16, std::atoi(next("a size")));
    }
    else if (a == "--extent")
    {
      opt.Extent = std::max(1, std::atoi(next("an extent")));
    }
    else if (a == "--azimuth")
    {
      opt.AzimuthStep = std::atof(next("degrees"));
    }
    else if (a == "--mesh")
    {
      opt.Meshes = next("bracket, rt or all");
    }
    else if (a == "--skip-raycast-large")
    {
      opt.SkipRayCastLarge = true;
    }
    else if (a == "--only")
    {
      opt.Only = next("mapper keys");
      opt.Only.erase(std::remove(opt.Only.begin(), opt.Only.end(), ' '), opt.Only.end());
      std::string list = opt.Only + ",";
      for (size_t at; (at = list.find(',')) != std::string::npos; list.erase(0, at + 1))
      {
        const std::string key = list.substr(0, at);
        if (key != "hov_vis" && key != "hov_pix" && key != "hov_full" && key != "pt" &&
          key != "rc")
        {
          std::cerr << "--only: unknown mapper key '" << key
                    << "' (hov_vis, hov_pix, hov_full, pt, rc)\n";
          return 2;
        }
      }
    }
    else if (a == "--transparent-below")
    {
      const char* text = next("a fraction");
      char* end = nullptr;
      opt.TransparentBelow = std::strtod(text, &end);
      const double f = opt.TransparentBelow;
      if (end == text || *end != '\0' || !(f >= 0.0 && f < 1.0))
      {
        std::cerr << "--transparent-below must be in [0, 1)\n";
        return 2;
      }
    }
    else if (a == "--out")
    {
      opt.OutDir = next("a directory");
    }
    else if (a == "--help" || a == "-h")
    {
      Usage(argv[0]);
      return 0;
    }
    else if (std::isdigit(static_cast<unsigned char>(a[0])))
    {
      opt.Frames = std::max(1, std::atoi(a.c_str())); // bare N: number of frames
    }
    else
    {
      std::cerr << "Unknown argument " << a << "\n";
      Usage(argv[0]);
      return 2;
    }
  }

  std::cout << "hovBenchRender: VTK " << vtkVersion::GetVTKVersion() << ", " << opt.Size << "x"
            << opt.Size << " offscreen, " << opt.Frames << " frames per median, azimuth step "
            << opt.AzimuthStep << " deg, vtkSMPTools backend " << vtkSMPTools::GetBackend()
            << " with " << vtkSMPTools::GetEstimatedNumberOfThreads() << " threads\n";

  std::vector<Mesh> meshes;
  if (opt.Meshes == "all" || opt.Meshes == "bracket")
  {
    Mesh m;
    if (!LoadBracket(opt, m))
    {
      return 1;
    }
    std::cout << "Bracket: " << m.Tetras << " tetrahedra, " << m.Grid->GetNumberOfPoints()
              << " points, von_mises range [" << m.Range[0] << ", " << m.Range[1] << "]\n";
    meshes.push_back(m);
  }
  if (opt.Meshes == "all" || opt.Meshes == "rt")
  {
    Mesh m;
    if (!MakeRTMesh(opt, m))
    {
      return 1;
    }
    meshes.push_back(m);
  }
  if (meshes.empty())
  {
    std::cerr << "--mesh must be bracket, rt or all\n";
    return 2;
  }

  ErrorCounter errors;
  std::vector<Row> rows;
  for (const Mesh& mesh : meshes)
  {
    std::cout << mesh.Name << " (" << mesh.Tetras << " tets):\n";
    std::vector<std::unique_ptr<Run>> runs;
    for (const bool perPixel : { false, true })
    {
      if (!Wanted(opt, perPixel ? "hov_pix" : "hov_vis"))
      {
        continue;
      }
      auto m = vtkSmartPointer<vtkHighOrderVolumeMapper>::New();
      m->SetIntegrationMethodToExact();
      m->SetOpacitySemanticsToVTKUnstructured();
      m->SetCellOrdering(perPixel ? vtkHighOrderVolumeMapper::PER_PIXEL_SORT
                                  : vtkHighOrderVolumeMapper::VISIBILITY_SORT);
      runs.push_back(Prepare(opt, mesh, perPixel ? "hov_pix" : "hov_vis",
        std::string("vtkHighOrderVolumeMapper (exact, VTK-unstructured, ") +
          (perPixel ? "per-pixel" : "visibility") + " sort)",
        m, errors));
    }
    // (By default only with --transparent-below; --only hov_full asks for it anyway.)
    if ((opt.TransparentBelow > 0.0 && Wanted(opt, "hov_full")) ||
      ("," + opt.Only + ",").find(",hov_full,") != std::string::npos)
    {
      // Every cell integrated, the transparent ones too: what the skip saves.
      auto m = vtkSmartPointer<vtkHighOrderVolumeMapper>::New();
      m->SetIntegrationMethodToExact();
      m->SetOpacitySemanticsToVTKUnstructured();
      m->SkipTransparentCellsOff();
      runs.push_back(Prepare(opt, mesh, "hov_full",
        "vtkHighOrderVolumeMapper (as hov_vis, SkipTransparentCells off)", m, errors));
    }
    if (Wanted(opt, "pt"))
    {
      runs.push_back(Prepare(opt, mesh, "pt", "vtkProjectedTetrahedraMapper",
        vtkSmartPointer<vtkProjectedTetrahedraMapper>::New(), errors));
    }
    const std::string rcLabel = "vtkUnstructuredGridVolumeRayCastMapper + linear integrator";
    Row skipped;
    const bool large = mesh.Name != "bracket";
    const bool rc = Wanted(opt, "rc");
    if (rc && large && opt.SkipRayCastLarge)
    {
      skipped.Mesh = mesh.Name;
      skipped.Key = "rc";
      skipped.Mapper = rcLabel;
      skipped.Problem = "skipped (--skip-raycast-large)";
    }
    else if (rc)
    {
      auto m = vtkSmartPointer<vtkUnstructuredGridVolumeRayCastMapper>::New();
      vtkNew<vtkUnstructuredGridLinearRayIntegrator> integrator;
      m->SetRayIntegrator(integrator);
      m->SetAutoAdjustSampleDistances(0); // one ray per pixel, no LOD
      m->SetImageSampleDistance(1.0);
      runs.push_back(Prepare(opt, mesh, "rc", rcLabel, m, errors));
    }
    TimeInterleaved(opt, runs);
    for (auto& run : runs)
    {
      rows.push_back(Finish(opt, mesh, *run, errors));
    }
    if (!skipped.Mesh.empty())
    {
      rows.push_back(skipped);
    }
  }

  const bool allOk = PrintTable(opt, meshes, rows);
  return allOk ? 0 : 1;
}
