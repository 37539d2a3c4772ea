// hovBenchMixed (issue 4, acceptance 5): wall-clock frame times of
// vtkHighOrderVolumeMapper on the bundled quadratic-tet and mixed-cell
// datasets (native cells) against vtkProjectedTetrahedraMapper (PT) and
// vtkUnstructuredGridVolumeRayCastMapper (RC, Bunyk + linear ray integrator,
// image sample distance 1) on the linear tetrahedra they need:
//  - tjunction_tet10_dolfinx.vtu ("speed", 10521 quadratic tets): the
//    conforming 8-way split of every cell (hovTestReferenceGeneral.h,
//    SubdivideQuadraticTetras, as in the tests; the demo splits at the nodes).
//    vtkDataSetTriangleFilter's time is printed too, but its tessellation is
//    not used: it runs the ordered (Delaunay) triangulator on the 10 nodes of
//    these non-primary cells, which on the curved boundary cells gives 83031
//    instead of 84168 tetrahedra, non-conforming and overlapping;
//  - zoo_mixed_ccx.vtu ("temperature", tets/hexahedra/wedges/pyramids):
//    vtkDataSetTriangleFilter.
// The tessellation time is reported separately (done once, not per frame).
// Every mapper renders in one shared offscreen S x S window (default 512) with
// the same vtkVolumeProperty (opacity nodes = colour nodes); ours with
// VTK_UNSTRUCTURED semantics (the peers' extinction a/u) and its default
// ordering (visibility sort). Frame 0 (set-up, sort, GL resources) is
// reported apart; frames 1..N turn the camera by --turn degrees (azimuth)
// before each render; the table shows the median of frames 1..N and the
// ratios peer / ours. Ours is also timed on the tessellated input.
//
//   xvfb-run -a -s "-screen 0 1280x1024x24 -noreset" bin/hovBenchMixed [--frames N]
//     [--size S] [--turn DEG] [--data DIR] [--skip-rc] [--shade]
// --shade: ours is also timed with Shade on (the same property otherwise; the
// peers do not shade), with the shaded / unshaded ratio.
#include "hovTestReferenceDatasets.h"

#include "vtkHighOrderOffscreenWindow.h" // windows with X (Xvfb) or without (Mesa EGL)
#include "vtkHighOrderVolumeMapper.h"

#include "vtkCamera.h"
#include "vtkNew.h"
#include "vtkProjectedTetrahedraMapper.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkUnstructuredGrid.h"
#include "vtkUnstructuredGridLinearRayIntegrator.h"
#include "vtkUnstructuredGridVolumeRayCastMapper.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace
{
struct Options
{
  int Frames = 5;
  int Size = 512;
  double Turn = 10.0;
  std::string Data = HOV_BENCH_DATA_DIR;
  bool SkipRC = false;
  bool Shade = false; ///< also time ours with vtkVolumeProperty::ShadeOn()
};

struct Timing
{
  double First = 0;  ///< frame 0 (set-up included), s
  double Median = 0; ///< median of frames 1..N, s
};

double Since(std::chrono::steady_clock::time_point t0)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

/// One offscreen window (X if DISPLAY is set, Mesa EGL if not) shared by every measurement.
struct Window
{
  vtkNew<vtkRenderer> Renderer;
  vtkSmartPointer<vtkRenderWindow> RenderWindow;
  explicit Window(int size)
  {
    vtkNew<vtkHighOrderOffscreenWindow> factory;
    this->RenderWindow.TakeReference(factory->NewRenderWindow(size, size));
    if (!this->RenderWindow)
    {
      std::cerr << "hovBenchMixed: " << factory->GetErrorMessage() << "\n";
      std::exit(1);
    }
    this->Renderer->SetBackground(0, 0, 0);
    this->RenderWindow->SetMultiSamples(0);
    this->RenderWindow->AddRenderer(this->Renderer);
  }
};

/// Frame times of @p mapper on @p property from @p camera (copied, then turned).
Timing TimeFrames(vtkAbstractVolumeMapper* mapper, vtkVolumeProperty* property, vtkCamera* camera,
  const Options& opt, Window& window)
{
  vtkNew<vtkVolume> volume;
  volume->SetMapper(mapper);
  volume->SetProperty(property);
  vtkNew<vtkCamera> cam;
  cam->DeepCopy(camera);
  vtkRenderer* ren = window.Renderer;
  vtkRenderWindow* win = window.RenderWindow;
  ren->RemoveAllViewProps();
  ren->SetActiveCamera(cam);
  ren->AddVolume(volume);
  Timing t;
  auto t0 = std::chrono::steady_clock::now();
  win->Render();
  t.First = Since(t0);
  std::vector<double> frames;
  for (int f = 0; f < opt.Frames; ++f)
  {
    cam->Azimuth(opt.Turn);
    cam->OrthogonalizeViewUp();
    t0 = std::chrono::steady_clock::now();
    win->Render();
    frames.push_back(Since(t0));
  }
  std::sort(frames.begin(), frames.end());
  t.Median = frames.empty() ? 0 : frames[frames.size() / 2];
  mapper->ReleaseGraphicsResources(win);
  ren->RemoveAllViewProps();
  return t;
}

struct Row
{
  std::string Name;
  long long Cells = 0, Tets = 0;
  double TessSeconds = 0;
  Timing Ours, OursTess, PT, RC;
  Timing OursShaded; ///< --shade only
};

Row Run(const std::string& name, vtkUnstructuredGrid* grid, vtkUnstructuredGrid* tess,
  double tessSeconds, vtkVolumeProperty* property, vtkCamera* cam, const Options& opt,
  Window& window)
{
  Row r;
  r.Name = name;
  r.Cells = grid->GetNumberOfCells();
  r.Tets = tess->GetNumberOfCells();
  r.TessSeconds = tessSeconds;
  std::cout << "== " << name << ": " << r.Cells << " cells (" << hovTestRef::DescribeCellTypes(grid)
            << "), tessellated to " << r.Tets << " tets in " << tessSeconds << " s\n"
            << std::flush;
  {
    vtkNew<vtkHighOrderVolumeMapper> ours;
    ours->SetInputData(grid);
    ours->SetOpacitySemanticsToVTKUnstructured();
    r.Ours = TimeFrames(ours, property, cam, opt, window);
    std::cout << "  ours (native)       first " << r.Ours.First << " s, median " << r.Ours.Median
              << " s (" << ours->GetNumberOfRenderedCells() << " cells rendered, "
              << ours->GetNumberOfSkippedCells() << " skipped)\n"
              << std::flush;
  }
  if (opt.Shade)
  {
    // Ours only: the peers do not shade unstructured grids.
    vtkNew<vtkHighOrderVolumeMapper> ours;
    ours->SetInputData(grid);
    ours->SetOpacitySemanticsToVTKUnstructured();
    property->ShadeOn();
    r.OursShaded = TimeFrames(ours, property, cam, opt, window);
    property->ShadeOff();
    std::cout << "  ours (native, Shade on) first " << r.OursShaded.First << " s, median "
              << r.OursShaded.Median << " s (shading error estimate "
              << ours->GetShadingErrorEstimate() << ")\n"
              << std::flush;
  }
  {
    vtkNew<vtkHighOrderVolumeMapper> ours;
    ours->SetInputData(tess);
    ours->SetOpacitySemanticsToVTKUnstructured();
    r.OursTess = TimeFrames(ours, property, cam, opt, window);
    std::cout << "  ours (tessellated)  first " << r.OursTess.First << " s, median "
              << r.OursTess.Median << " s\n"
              << std::flush;
  }
  {
    vtkNew<vtkProjectedTetrahedraMapper> pt;
    pt->SetInputData(tess);
    r.PT = TimeFrames(pt, property, cam, opt, window);
    std::cout << "  PT (tessellated)    first " << r.PT.First << " s, median " << r.PT.Median
              << " s\n"
              << std::flush;
  }
  if (!opt.SkipRC)
  {
    vtkNew<vtkUnstructuredGridVolumeRayCastMapper> rc;
    rc->SetInputData(tess);
    vtkNew<vtkUnstructuredGridLinearRayIntegrator> integrator;
    rc->SetRayIntegrator(integrator);
    rc->AutoAdjustSampleDistancesOff();
    rc->SetImageSampleDistance(1.0);
    r.RC = TimeFrames(rc, property, cam, opt, window);
    std::cout << "  RC (tessellated)    first " << r.RC.First << " s, median " << r.RC.Median
              << " s\n"
              << std::flush;
  }
  return r;
}

void PrintTable(const std::vector<Row>& rows, const Options& opt)
{
  std::cout << "\n" << opt.Size << "x" << opt.Size << ", median of " << opt.Frames
            << " frames turning " << opt.Turn << " deg each (ms; frame 0 in brackets)\n\n"
            << "| dataset | cells | linear tets | tessellation ms | ours native | ours on tets | PT on tets | RC on tets | PT / ours | RC / ours |\n"
            << "|---|---|---|---|---|---|---|---|---|---|\n";
  auto ms = [](const Timing& t) {
    std::ostringstream os;
    os << std::fixed << std::setprecision(0) << 1000 * t.Median << " (" << 1000 * t.First << ")";
    return os.str();
  };
  for (const Row& r : rows)
  {
    std::cout << std::fixed << "| " << r.Name << " | " << r.Cells << " | " << r.Tets << " | "
              << std::setprecision(0) << 1000 * r.TessSeconds << " | " << ms(r.Ours) << " | "
              << ms(r.OursTess) << " | " << ms(r.PT) << " | "
              << (opt.SkipRC ? std::string("-") : ms(r.RC)) << " | " << std::setprecision(2)
              << r.PT.Median / r.Ours.Median << " | ";
    if (opt.SkipRC)
    {
      std::cout << "- |\n";
    }
    else
    {
      std::cout << r.RC.Median / r.Ours.Median << " |\n";
    }
  }
  if (opt.Shade)
  {
    std::cout << "\n| dataset | ours native | ours native, Shade on | shaded / unshaded |\n"
              << "|---|---|---|---|\n";
    for (const Row& r : rows)
    {
      std::cout << "| " << r.Name << " | " << ms(r.Ours) << " | " << ms(r.OursShaded) << " | "
                << std::setprecision(2) << r.OursShaded.Median / r.Ours.Median << " |\n";
    }
  }
  std::cout << std::defaultfloat;
}
}

int main(int argc, char* argv[])
{
  Options opt;
  for (int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    auto next = [&]() { return i + 1 < argc ? std::string(argv[++i]) : std::string(); };
    if (a == "--frames")
    {
      opt.Frames = std::max(1, std::atoi(next().c_str()));
    }
    else if (a == "--size")
    {
      opt.Size = std::max(16, std::atoi(next().c_str()));
    }
    else if (a == "--turn")
    {
      opt.Turn = std::atof(next().c_str());
    }
    else if (a == "--data")
    {
      opt.Data = next();
    }
    else if (a == "--skip-rc")
    {
      opt.SkipRC = true;
    }
    else if (a == "--shade")
    {
      opt.Shade = true;
    }
    else
    {
      std::cout << "usage: hovBenchMixed [--frames N] [--size S] [--turn DEG] [--data DIR] "
                   "[--skip-rc] [--shade]\n";
      return a == "--help" ? EXIT_SUCCESS : EXIT_FAILURE;
    }
  }
  std::vector<Row> rows;
  Window window(opt.Size);
  {
    auto grid = hovTestRef::LoadDataset(opt.Data, "tjunction_tet10_dolfinx.vtu", "speed");
    double tessSeconds = 0, filterSeconds = 0;
    auto tess = hovTestRef::TessellateQuadratic(grid, tessSeconds);
    auto filtered = hovTestRef::TetrahedralizeLinear(grid, filterSeconds);
    std::cout << "(vtkDataSetTriangleFilter, not used: " << filtered->GetNumberOfCells()
              << " tets in " << filterSeconds << " s)\n";
    vtkNew<vtkVolumeProperty> property;
    hovTestRef::DatasetTF(property, 0.1, 2.7, 0.6);
    vtkNew<vtkCamera> cam;
    hovTestRef::TJunctionCamera(cam);
    rows.push_back(
      Run("tjunction (quadratic tets)", grid, tess, tessSeconds, property, cam, opt, window));
  }
  {
    auto grid = hovTestRef::LoadDataset(opt.Data, "zoo_mixed_ccx.vtu", "temperature");
    double tessSeconds = 0;
    auto tess = hovTestRef::TetrahedralizeLinear(grid, tessSeconds);
    vtkNew<vtkVolumeProperty> property;
    hovTestRef::DatasetTF(property, 15.0, 120.0, 0.8);
    vtkNew<vtkCamera> cam;
    hovTestRef::ZooCamera(cam);
    rows.push_back(Run("zoo (mixed cells)", grid, tess, tessSeconds, property, cam, opt, window));
  }
  PrintTable(rows, opt);
  return EXIT_SUCCESS;
}
