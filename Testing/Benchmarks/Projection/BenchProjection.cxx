// hovBenchProjection: OPENGL_PROJECTION (M1, M3; approximate centroid order
// and exact Stein order) vs vtkProjectedTetrahedraMapper (its default
// vtkCellCenterDepthSort) at 512x512 on llvmpipe, one process. Each
// configuration has its own volume and mapper; the configurations are
// interleaved frame by frame (every frame: rotate the camera by 3 degrees,
// then render each configuration once, timed until the image is complete:
// Render + WaitForCompletion), so that the load of a shared machine affects
// all of them alike. Prints the median frame time over --frames frames
// (default 5, after one warm-up frame each), the median CPU time of the
// process per frame (all threads: ours, TBB's, llvmpipe's) and the ratios
// VTK / ours (PT/ours > 1: ours faster).
// VTK-unstructured opacity semantics (what VTK's mapper computes).
// Datasets: the bundled bracket (56071 tets), cube46 (46^3 x 6 = 584016 Kuhn
// tets) and rt (vtkRTAnalyticSource [-24,24]^3 -> vtkDataSetTriangleFilter:
// 552960 tets, RTData). Prints `uptime` before and after each dataset.
// Options: --frames N, --data bracket|cube46|rt, --method 1|3, --order 1|0
// (approximate|Stein), --lookup 0|1 (opacity texture|analytic), --no-vtk
// (ours only, for profiling), --semantics vtk|gpu (ours in VTK-unstructured,
// the default, or GPU-compatible semantics).
#include "vtkHighOrderOffscreenWindow.h" // windows with X (Xvfb) or without (Mesa EGL)
#include "vtkHighOrderVolumeMapper.h"

#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkDataSetTriangleFilter.h"
#include "vtkDoubleArray.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkProjectedTetrahedraMapper.h"
#include "vtkRTAnalyticSource.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkTimerLog.h"
#include "vtkUnstructuredGrid.h"
#include "vtkVolume.h"
#include "vtkVolumeCollection.h"
#include "vtkVolumeProperty.h"
#include "vtkXMLUnstructuredGridReader.h"

#include <sys/resource.h> // getrusage: CPU time of all threads

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <string>
#include <vector>

namespace
{
/// n^3 cubes over [0,1]^3, 6 Kuhn tetrahedra each, scalar s = x + 0.5 y + 0.25 z.
vtkSmartPointer<vtkUnstructuredGrid> Cube(int n)
{
  vtkNew<vtkPoints> pts;
  vtkNew<vtkDoubleArray> s;
  s->SetName("s");
  const int m = n + 1;
  for (int k = 0; k < m; ++k)
    for (int j = 0; j < m; ++j)
      for (int i = 0; i < m; ++i)
      {
        const double x = double(i) / n, y = double(j) / n, z = double(k) / n; // (half the Kuhn tets come out inverted: VTK renders them, ours warns once)
        pts->InsertNextPoint(x, y, z);
        s->InsertNextValue(x + 0.5 * y + 0.25 * z);
      }
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  grid->Allocate(6 * n * n * n);
  auto id = [m](int i, int j, int k) { return vtkIdType(i + m * (j + m * k)); };
  static const int paths[6][3] = { { 0, 1, 2 }, { 0, 2, 1 }, { 1, 0, 2 }, { 1, 2, 0 }, { 2, 0, 1 },
    { 2, 1, 0 } };
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
        for (const auto& p : paths)
        {
          int c[3] = { i, j, k };
          vtkIdType t[4];
          t[0] = id(c[0], c[1], c[2]);
          for (int a = 0; a < 3; ++a)
          {
            ++c[p[a]];
            t[a + 1] = id(c[0], c[1], c[2]);
          }
          grid->InsertNextCell(VTK_TETRA, 4, t);
        }
  grid->SetPoints(pts);
  grid->GetPointData()->SetScalars(s);
  return grid;
}

/// vtkRTAnalyticSource over [-e,e]^3, tetrahedralized (5 or 6 per voxel), scalars RTData.
vtkSmartPointer<vtkUnstructuredGrid> RT(int e)
{
  vtkNew<vtkRTAnalyticSource> source;
  source->SetWholeExtent(-e, e, -e, e, -e, e);
  source->SetCenter(0.0, 0.0, 0.0);
  vtkNew<vtkDataSetTriangleFilter> tets;
  tets->SetInputConnection(source->GetOutputPort());
  tets->TetrahedraOnlyOn();
  tets->Update();
  vtkSmartPointer<vtkUnstructuredGrid> grid = tets->GetOutput();
  grid->GetPointData()->SetActiveScalars("RTData");
  return grid;
}

/// The machine's load (`uptime`), for the record beside the timings.
void PrintLoad()
{
  std::cout << std::flush;
  if (std::system("uptime") != 0)
  {
    std::cout << "(uptime failed)\n";
  }
  std::fflush(stdout);
}

double Median(std::vector<double> v)
{
  std::sort(v.begin(), v.end());
  return v.empty() ? 0.0 : v[v.size() / 2];
}

/// One timed configuration.
struct Config
{
  std::string Name;
  vtkSmartPointer<vtkVolume> Volume;
  vtkHighOrderVolumeMapper* Ours = nullptr; ///< null for VTK's mapper
  std::vector<double> Times;
  std::vector<double> CpuTimes; ///< CPU seconds of the process (all threads) per frame
};

/// User + system CPU seconds of the process so far (every thread, llvmpipe's too).
double ProcessCpuSeconds()
{
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_utime.tv_sec + usage.ru_stime.tv_sec +
    1e-6 * (usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
}

/// Render @p volume alone in @p win until the image is complete; seconds.
/// (Every configuration stays in the renderer, only @p volume visible:
/// removing a prop would release its graphics resources every frame.)
double RenderOnce(vtkRenderWindow* win, vtkRenderer* ren, vtkVolume* volume, double* cpu = nullptr)
{
  vtkCollectionSimpleIterator it;
  vtkVolumeCollection* volumes = ren->GetVolumes();
  volumes->InitTraversal(it);
  while (vtkVolume* v = volumes->GetNextVolume(it))
  {
    v->SetVisibility(v == volume);
  }
  vtkNew<vtkTimerLog> timer;
  const double cpu0 = ProcessCpuSeconds();
  timer->StartTimer();
  win->Render();
  win->WaitForCompletion();
  timer->StopTimer();
  if (cpu)
  {
    *cpu = ProcessCpuSeconds() - cpu0;
  }
  return timer->GetElapsedTime();
}

/// Interleaved timing of @p configs (see file doc).
void TimeAll(vtkRenderWindow* win, vtkRenderer* ren, std::vector<Config>& configs,
  const double bounds[6], int frames)
{
  vtkCamera* cam = ren->GetActiveCamera();
  const double c[3] = { 0.5 * (bounds[0] + bounds[1]), 0.5 * (bounds[2] + bounds[3]),
    0.5 * (bounds[4] + bounds[5]) };
  cam->SetFocalPoint(c);
  cam->SetPosition(c[0] + 1.0, c[1] - 2.0, c[2] + 1.5);
  cam->SetViewUp(0, 0, 1);
  ren->ResetCamera(bounds);
  ren->RemoveAllViewProps();
  for (Config& config : configs)
  {
    ren->AddVolume(config.Volume);
  }
  for (Config& config : configs)
  {
    RenderOnce(win, ren, config.Volume); // warm-up: set-up, sort structures, shaders
  }
  for (int f = 0; f < frames; ++f)
  {
    cam->Azimuth(3.0);
    for (Config& config : configs)
    {
      double cpu = 0.0;
      config.Times.push_back(RenderOnce(win, ren, config.Volume, &cpu));
      config.CpuTimes.push_back(cpu);
    }
  }
}
}

int main(int argc, char* argv[])
{
  int frames = 5;
  std::string only;   // --data NAME: one dataset
  int onlyMethod = -1; // --method M: one colour method (1 or 3)
  int onlyOrder = -1;  // --order O: 1 approximate, 0 Stein
  int onlyLookup = -1; // --lookup K: 0 opacity texture, 1 analytic
  bool skipVTK = false; // --no-vtk: ours only (profiling)
  bool gpuSemantics = false; // --semantics gpu: ours in GPU-compatible semantics
  for (int i = 1; i < argc; ++i)
  {
    const bool next = i + 1 < argc;
    if (!std::strcmp(argv[i], "--frames") && next)
    {
      frames = std::max(1, std::atoi(argv[++i]));
    }
    else if (!std::strcmp(argv[i], "--data") && next)
    {
      only = argv[++i];
    }
    else if (!std::strcmp(argv[i], "--method") && next)
    {
      onlyMethod = std::atoi(argv[++i]);
    }
    else if (!std::strcmp(argv[i], "--order") && next)
    {
      onlyOrder = std::atoi(argv[++i]);
    }
    else if (!std::strcmp(argv[i], "--lookup") && next)
    {
      onlyLookup = std::atoi(argv[++i]);
    }
    else if (!std::strcmp(argv[i], "--no-vtk"))
    {
      skipVTK = true;
    }
    else if (!std::strcmp(argv[i], "--semantics") && next)
    {
      gpuSemantics = !std::strcmp(argv[++i], "gpu");
    }

  }
  vtkNew<vtkXMLUnstructuredGridReader> reader;
  reader->SetFileName(HOV_BENCH_DATA_DIR "/bracket_tet4_ccx.vtu");
  reader->Update();
  vtkSmartPointer<vtkUnstructuredGrid> bracket = reader->GetOutput();
  bracket->GetPointData()->SetActiveScalars("von_mises");
  struct Data
  {
    const char* Name;
    vtkSmartPointer<vtkUnstructuredGrid> Grid;
    double Lo, Hi;
  };
  std::vector<Data> data;
  if (only.empty() || only == "bracket")
  {
    data.push_back({ "bracket", bracket, 0.0, 170.0 });
  }
  if (only.empty() || only == "cube46")
  {
    data.push_back({ "cube46", Cube(46), 0.0, 1.75 });
  }
  if (only.empty() || only == "rt")
  {
    vtkSmartPointer<vtkUnstructuredGrid> rt = RT(24);
    double range[2];
    rt->GetPointData()->GetScalars()->GetRange(range);
    data.push_back({ "rt", rt, range[0], range[1] });
  }

  vtkNew<vtkRenderer> ren;
  ren->SetBackground(0, 0, 0);
  vtkNew<vtkHighOrderOffscreenWindow> factory; // X if DISPLAY is set, Mesa EGL if not
  vtkSmartPointer<vtkRenderWindow> win =
    vtkSmartPointer<vtkRenderWindow>::Take(factory->NewRenderWindow(512, 512));
  if (!win)
  {
    std::cerr << "hovBenchProjection: " << factory->GetErrorMessage() << "\n";
    return 1;
  }
  win->SetMultiSamples(0);
  win->AddRenderer(ren);
  std::cout << "hovBenchProjection: 512x512, median of " << frames
            << " interleaved frames (rotating camera), seconds per frame\n";
  for (const Data& d : data)
  {
    const double r = d.Hi - d.Lo;
    vtkNew<vtkColorTransferFunction> ctf;
    ctf->AddRGBPoint(d.Lo, 0.2, 0.3, 0.9);
    ctf->AddRGBPoint(d.Lo + 0.5 * r, 0.2, 0.9, 0.3);
    ctf->AddRGBPoint(d.Hi, 0.9, 0.3, 0.1);
    vtkNew<vtkPiecewiseFunction> otf;
    otf->AddPoint(d.Lo, 0.05);
    otf->AddPoint(d.Lo + 0.5 * r, 0.3);
    otf->AddPoint(d.Hi, 0.8);
    vtkNew<vtkVolumeProperty> prop;
    prop->SetColor(ctf);
    prop->SetScalarOpacity(otf);
    double bounds[6];
    d.Grid->GetBounds(bounds);
    prop->SetScalarOpacityUnitDistance(0.05 * (bounds[1] - bounds[0]));

    std::vector<Config> configs;
    if (!skipVTK)
    {
      vtkNew<vtkProjectedTetrahedraMapper> pt;
      pt->SetInputData(d.Grid);
      Config config;
      config.Name = "vtkProjectedTetrahedraMapper";
      config.Volume = vtkSmartPointer<vtkVolume>::New();
      config.Volume->SetMapper(pt);
      config.Volume->SetProperty(prop);
      configs.push_back(config);
    }
    for (int order : { 1, 0 })
    {
      for (int method : { 1, 3 })
      {
        for (int lookup : { 0, 1 })
        {
        if ((onlyOrder >= 0 && order != onlyOrder) || (onlyMethod >= 0 && method != onlyMethod) ||
          (onlyLookup >= 0 && lookup != onlyLookup))
        {
          continue;
        }
        vtkNew<vtkHighOrderVolumeMapper> ours;
        ours->SetInputData(d.Grid);
        if (gpuSemantics)
        {
          ours->SetOpacitySemanticsToGPUCompatible();
        }
        else
        {
          ours->SetOpacitySemanticsToVTKUnstructured();
        }
        ours->SetRenderModeToOpenGLProjection();
        ours->SetProjectionOrder(order);
        ours->SetProjectionColorMethod(method);
        ours->SetProjectionOpacityLookup(lookup);
        Config config;
        config.Name = std::string("ours M") + std::to_string(method) +
          (order ? " approximate order" : " Stein order      ") +
          (lookup ? " analytic" : " texture ");
        config.Volume = vtkSmartPointer<vtkVolume>::New();
        config.Volume->SetMapper(ours);
        config.Volume->SetProperty(prop);
        config.Ours = ours;
        configs.push_back(config);
        }
      }
    }
    PrintLoad();
    TimeAll(win, ren, configs, bounds, frames);
    const double tPT = skipVTK ? 1.0 : Median(configs[0].Times);
    std::cout << d.Name << " (" << d.Grid->GetNumberOfCells() << " tets):\n";
    for (const Config& config : configs)
    {
      const double t = Median(config.Times);
      std::cout << "  " << config.Name << " " << t << " s (CPU " << Median(config.CpuTimes)
                << " s)";
      if (config.Ours)
      {
        std::vector<double> paired; // per-frame ratio: load changes hit both alike
        for (size_t f = 0; !skipVTK && f < config.Times.size(); ++f)
        {
          paired.push_back(configs[0].Times[f] / config.Times[f]);
        }
        std::sort(paired.begin(), paired.end());
        if (!paired.empty())
        {
          std::cout << "  paired PT/ours " << Median(paired) << " [" << paired.front() << ", "
                    << paired.back() << "]";
        }
        std::cout << "  (PT/ours = " << tPT / t << ", triangles "
                  << config.Ours->GetNumberOfProjectedTriangles() << ", slabs "
                  << config.Ours->GetNumberOfProjectedSlabs() << ")";
      }
      std::cout << "\n";
    }
    PrintLoad();
  }
  return 0;
}
