// hovBenchHighOrder (issue 20, acceptance 1): high-order RAY_CAST frames of
// vtkHighOrderVolumeMapper (public API only) against the route a user can
// script: vtkTessellatorFilter on the same curved cells, rendered by our own
// exact CPU path (CPU_ACCURATE, Stein sort) as linear tetrahedra.
//
// Datasets: the bundled plate Q4 (192 Lagrange hexahedra, von_mises) and
// T-junction P4 (3790 Lagrange tetrahedra, speed), and generated curved meshes
// (BenchHighOrderMeshes.h): order-3 hexahedra (10^3 = 1000) and order-6
// tetrahedra (6 x 6^3 = 1296).
// Per dataset, at S x S (default 256), one oblique perspective camera, the
// mapper's defaults (GPU-compatible opacity, RayCastTolerance 1e-3) and a
// 7-node transfer function over the scalar range:
//  - ours: a fresh mapper's still RAY_CAST frame (RenderImage: conversion,
//    face nets, BVH, lazy cell bounds included), then the same frame again
//    (cached input; the median of --repeats such frames, default 3); its
//    per-pixel error bound (max of GetRayCastErrorImage);
//  - tessellation route: for 1..--levels subdivision levels (chord error
//    1e-6 of the diagonal: every level subdivides), the tessellation time
//    (NOT counted), a fresh CPU_ACCURATE mapper's first frame (sort set-up
//    included) and the median of --repeats more; the image error against ours (max and
//    mean |difference| per channel of the premultiplied float RGBA). The
//    route's reference level is the coarsest whose max error <= 1/255 (its
//    true error is within ours' bound of that: <= 1e-3 more);
//  - ratio = ours' first frame / the reference level's first frame (and the
//    cached frames' ratio);
//  - interactive: an offscreen window of S x S, DesiredUpdateRate 15 (what
//    vtkRenderWindowInteractor sets while the camera moves), 1 degree azimuth
//    per frame, --frames frames after a still frame: median wall time, fps and
//    the subsampling the mapper chose.
// Image checks between code versions: --save-images DIR writes ours' float
// RGBA (raw float32, S x S x 4, row 0 at the bottom) per dataset (and the
// tessellation route's per level, NAME_tessL_...), and
// --compare-images DIR prints the max |difference| per channel against such
// a file (and the pixels off by more than the tolerance). --semantics vtk
// renders in VTK_UNSTRUCTURED opacity semantics instead of the default.
// Not a test: no pass/fail. Wall times (shared machine: run it twice).
//
//   bin/hovBenchHighOrder [--size 256] [--only NAME] [--levels 4] [--frames 8]
//     [--repeats 3] [--skip-tess] [--skip-interactive] [--data DIR] [--tolerance 1e-3]
//     [--save-images DIR] [--compare-images DIR] [--semantics gpu|vtk]
#include "BenchHighOrderMeshes.h"

#include "vtkHighOrderOffscreenWindow.h" // windows with X (Xvfb) or without (Mesa EGL)
#include "vtkHighOrderVolumeMapper.h"

#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkTessellatorFilter.h"
#include "vtkUnstructuredGrid.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"
#include "vtkXMLUnstructuredGridReader.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream> // --save-images, --compare-images
#include <string>
#include <vector>

namespace
{
/// MemAvailable of /proc/meminfo in bytes (0 if unknown).
double AvailableBytes()
{
  std::ifstream in("/proc/meminfo");
  std::string key;
  double kb = 0;
  while (in >> key)
  {
    if (key == "MemAvailable:" && (in >> kb))
    {
      return 1024.0 * kb;
    }
    in.ignore(1 << 10, '\n');
  }
  return 0;
}

/// Peak bytes per tetrahedron of a tessellation level: the tessellator's
/// output plus our CPU path's frame (hovBenchMemory: ~1.0 KB per tet at 2M).
constexpr double BytesPerTet = 1300.0;

using Clock = std::chrono::steady_clock;

double Seconds(Clock::time_point start)
{
  return std::chrono::duration<double>(Clock::now() - start).count();
}

struct Options
{
  int Size = 256;
  int Levels = 4;
  int Frames = 8;
  int Repeats = 3; ///< cached frames per route (their median is reported)
  bool SkipTess = false;
  bool SkipInteractive = false;
  double Tolerance = 1e-3;
  std::string Only;
  std::string Data = HOV_BENCH_DATA_DIR;
  std::string Save, Compare;
  bool VTKSemantics = false;
};

struct Dataset
{
  std::string Name;
  vtkSmartPointer<vtkUnstructuredGrid> Grid;
  std::string Array;
};

/// The README's default table (fraction of the range, r, g, b, opacity).
void MakeProperty(vtkVolumeProperty* property, double lo, double hi, double unit)
{
  static const double nodes[7][5] = { { 0.00, 0.15, 0.25, 0.90, 0.02 },
    { 0.03, 0.20, 0.50, 1.00, 0.04 }, { 0.09, 0.10, 0.90, 0.90, 0.10 },
    { 0.20, 0.30, 1.00, 0.30, 0.25 }, { 0.35, 1.00, 1.00, 0.10, 0.50 },
    { 0.60, 1.00, 0.50, 0.00, 0.80 }, { 1.00, 1.00, 0.05, 0.05, 1.00 } };
  vtkNew<vtkColorTransferFunction> color;
  vtkNew<vtkPiecewiseFunction> opacity;
  for (const auto& n : nodes)
  {
    const double s = lo + n[0] * (hi - lo);
    color->AddRGBPoint(s, n[1], n[2], n[3]);
    opacity->AddPoint(s, n[4]);
  }
  property->SetColor(color);
  property->SetScalarOpacity(opacity);
  property->SetScalarOpacityUnitDistance(unit);
  property->SetInterpolationTypeToLinear();
  property->ShadeOff();
}

void MakeCamera(vtkDataSet* grid, vtkCamera* cam)
{
  double b[6];
  grid->GetBounds(b);
  const double c[3] = { 0.5 * (b[0] + b[1]), 0.5 * (b[2] + b[3]), 0.5 * (b[4] + b[5]) };
  const double diag = std::sqrt((b[1] - b[0]) * (b[1] - b[0]) + (b[3] - b[2]) * (b[3] - b[2]) +
    (b[5] - b[4]) * (b[5] - b[4]));
  const double dir[3] = { 0.35, -0.8, 0.49 };
  cam->SetFocalPoint(c);
  cam->SetPosition(c[0] + 1.9 * diag * dir[0], c[1] + 1.9 * diag * dir[1], c[2] + 1.9 * diag * dir[2]);
  cam->SetViewUp(0, 0, 1);
  cam->SetViewAngle(30);
  cam->SetClippingRange(0.3 * diag, 4.0 * diag);
}

double Diagonal(vtkDataSet* grid)
{
  double b[6];
  grid->GetBounds(b);
  return std::sqrt((b[1] - b[0]) * (b[1] - b[0]) + (b[3] - b[2]) * (b[3] - b[2]) +
    (b[5] - b[4]) * (b[5] - b[4]));
}

struct Frame
{
  double First = 0.0, Second = 0.0, MaxErrorBound = -1.0;
  std::vector<float> RGBA;
};

std::vector<float> FloatImage(vtkHighOrderVolumeMapper* mapper)
{
  vtkDataArray* a = mapper->GetFloatImage()->GetPointData()->GetScalars();
  std::vector<float> v(a ? 4 * a->GetNumberOfTuples() : 0);
  for (vtkIdType i = 0; a && i < a->GetNumberOfTuples(); ++i)
  {
    for (int c = 0; c < 4; ++c)
    {
      v[4 * i + c] = static_cast<float>(a->GetComponent(i, c));
    }
  }
  return v;
}

/// A fresh mapper in @p mode: first frame, second frame, image (and error bound).
Frame RenderStill(vtkUnstructuredGrid* grid, const char* array, vtkVolumeProperty* property,
  int mode, const Options& o)
{
  vtkNew<vtkHighOrderVolumeMapper> mapper;
  mapper->SetInputData(grid);
  mapper->SetScalarModeToUsePointFieldData();
  mapper->SelectScalarArray(array);
  mapper->SetRenderMode(mode);
  mapper->SetRayCastTolerance(o.Tolerance);
  if (o.VTKSemantics)
  {
    mapper->SetOpacitySemanticsToVTKUnstructured();
  }
  vtkNew<vtkVolume> volume;
  volume->SetMapper(mapper);
  volume->SetProperty(property);
  vtkNew<vtkCamera> cam;
  MakeCamera(grid, cam);
  Frame f;
  auto start = Clock::now();
  mapper->RenderImage(cam, volume, o.Size, o.Size);
  f.First = Seconds(start);
  // Cached: the median of --repeats frames (the machine is shared).
  std::vector<double> cached;
  for (int r = 0; r < o.Repeats; ++r)
  {
    start = Clock::now();
    mapper->RenderImage(cam, volume, o.Size, o.Size);
    cached.push_back(Seconds(start));
  }
  std::sort(cached.begin(), cached.end());
  f.Second = cached[cached.size() / 2];
  f.RGBA = FloatImage(mapper);
  if (mode == vtkHighOrderVolumeMapper::RAY_CAST)
  {
    vtkDataArray* e = mapper->GetRayCastErrorImage()->GetPointData()->GetScalars();
    for (vtkIdType i = 0; e && i < e->GetNumberOfTuples(); ++i)
    {
      f.MaxErrorBound = std::max(f.MaxErrorBound, e->GetComponent(i, 0));
    }
  }
  return f;
}

void Difference(const std::vector<float>& a, const std::vector<float>& b, double& maxDiff,
  double& meanDiff)
{
  maxDiff = meanDiff = 0.0;
  if (a.size() != b.size() || a.empty())
  {
    maxDiff = meanDiff = 1.0;
    return;
  }
  for (size_t i = 0; i < a.size(); ++i)
  {
    const double d = std::abs(static_cast<double>(a[i]) - b[i]);
    maxDiff = std::max(maxDiff, d);
    meanDiff += d;
  }
  meanDiff /= static_cast<double>(a.size());
}

/// Interactive frames in an offscreen window at DesiredUpdateRate 15.
void Interactive(vtkUnstructuredGrid* grid, const char* array, vtkVolumeProperty* property,
  const Options& o)
{
  vtkNew<vtkHighOrderOffscreenWindow> factory;
  vtkSmartPointer<vtkRenderWindow> win =
    vtkSmartPointer<vtkRenderWindow>::Take(factory->NewRenderWindow(o.Size, o.Size));
  if (!win)
  {
    std::printf("  interactive: no window (%s)\n", factory->GetErrorMessage());
    return;
  }
  vtkNew<vtkRenderer> ren;
  win->AddRenderer(ren);
  vtkNew<vtkHighOrderVolumeMapper> mapper;
  mapper->SetInputData(grid);
  mapper->SetScalarModeToUsePointFieldData();
  mapper->SelectScalarArray(array);
  mapper->SetRenderModeToRayCast();
  mapper->SetRayCastTolerance(o.Tolerance);
  if (o.VTKSemantics)
  {
    mapper->SetOpacitySemanticsToVTKUnstructured();
  }
  vtkNew<vtkVolume> volume;
  volume->SetMapper(mapper);
  volume->SetProperty(property);
  ren->AddVolume(volume);
  MakeCamera(grid, ren->GetActiveCamera());
  win->SetDesiredUpdateRate(0.0001); // still
  auto start = Clock::now();
  win->Render();
  const double still = Seconds(start);
  win->SetDesiredUpdateRate(15.0);
  std::vector<double> times;
  int f = 0;
  for (int k = 0; k < o.Frames; ++k)
  {
    ren->GetActiveCamera()->Azimuth(1.0);
    start = Clock::now();
    win->Render();
    times.push_back(Seconds(start));
    f = mapper->GetLastRayCastSubsampling();
  }
  std::sort(times.begin(), times.end());
  const double median = times.empty() ? 0.0 : times[times.size() / 2];
  std::printf("  interactive (window %dx%d, DesiredUpdateRate 15): still frame %.3f s; %d moving "
              "frames: median %.4f s (%.1f fps), max %.4f s, subsampling %d\n",
    o.Size, o.Size, still, o.Frames, median, median > 0 ? 1.0 / median : 0.0,
    times.empty() ? 0.0 : times.back(), f);
}

/// File name of a dataset's image: its name without spaces, the size and semantics.
std::string ImageFile(const std::string& dir, const std::string& name, const Options& o)
{
  std::string slug;
  for (char c : name)
  {
    slug += c == ' ' ? '_' : c;
  }
  return dir + "/" + slug + "_" + std::to_string(o.Size) + (o.VTKSemantics ? "_vtk" : "_gpu") + ".f32";
}

void SaveOrCompare(const std::string& name, const std::vector<float>& rgba, const Options& o)
{
  if (!o.Save.empty())
  {
    std::ofstream out(ImageFile(o.Save, name, o), std::ios::binary);
    out.write(reinterpret_cast<const char*>(rgba.data()), rgba.size() * sizeof(float));
  }
  if (!o.Compare.empty())
  {
    std::ifstream in(ImageFile(o.Compare, name, o), std::ios::binary);
    std::vector<float> ref(rgba.size());
    in.read(reinterpret_cast<char*>(ref.data()), ref.size() * sizeof(float));
    if (!in)
    {
      std::printf("  compare: no image %s\n", ImageFile(o.Compare, name, o).c_str());
      return;
    }
    double maxDiff[4] = { 0, 0, 0, 0 }, sum = 0.0;
    long over = 0;
    for (size_t i = 0; i < rgba.size(); ++i)
    {
      const double d = std::abs(static_cast<double>(rgba[i]) - ref[i]);
      maxDiff[i % 4] = std::max(maxDiff[i % 4], d);
      sum += d;
      over += d > o.Tolerance ? 1 : 0;
    }
    std::printf("  compare with %s: max |diff| R %.3e G %.3e B %.3e A %.3e, mean %.3e, %ld "
                "channel values > tolerance %g\n",
      ImageFile(o.Compare, name, o).c_str(), maxDiff[0], maxDiff[1], maxDiff[2], maxDiff[3],
      sum / std::max<size_t>(1, rgba.size()), over, o.Tolerance);
  }
}

void Run(const Dataset& d, const Options& o)
{
  vtkUnstructuredGrid* grid = d.Grid;
  double range[2];
  grid->GetPointData()->GetArray(d.Array.c_str())->GetRange(range);
  vtkNew<vtkVolumeProperty> property;
  MakeProperty(property, range[0], range[1], 0.08 * Diagonal(grid));
  std::printf("\n## %s: %lld cells, %lld points, %dx%d\n", d.Name.c_str(),
    static_cast<long long>(grid->GetNumberOfCells()),
    static_cast<long long>(grid->GetNumberOfPoints()), o.Size, o.Size);
  const Frame ours = RenderStill(grid, d.Array.c_str(), property, vtkHighOrderVolumeMapper::RAY_CAST, o);
  double alpha = 0.0;
  for (size_t i = 3; i < ours.RGBA.size(); i += 4)
  {
    alpha += ours.RGBA[i];
  }
  std::printf("  ours RAY_CAST still: first %.3f s (set-up included), cached %.3f s, per-pixel "
              "error bound max %.2e (1/255 = %.2e), mean alpha %.3f\n",
    ours.First, ours.Second, ours.MaxErrorBound, 1.0 / 255.0,
    alpha / std::max<size_t>(1, ours.RGBA.size() / 4));
  std::fflush(stdout);
  SaveOrCompare(d.Name, ours.RGBA, o);
  if (!o.SkipTess)
  {
    std::printf("  | levels | tets | tessellation s (not counted) | CPU first s | CPU cached s | max "
                "err x255 | mean err x255 | ours/first | ours cached/cached |\n"
                "  |---|---|---|---|---|---|---|---|---|\n");
    bool reached = false;
    std::vector<double> counts; // tets per level done
    for (int level = 1; level <= o.Levels && !reached; ++level)
    {
      // A level that would not fit in memory is skipped (the 21.8M-tet level
      // of the curved hexahedra peaks near 24 GB): its size from the growth
      // of the last two levels (x8 after the first).
      const size_t done = counts.size();
      const double growth = done >= 2 ? counts[done - 1] / std::max(1.0, counts[done - 2]) : 8.0;
      const double expected = done >= 1 ? counts[done - 1] * growth : 0.0;
      const double available = AvailableBytes();
      if (available > 0 && expected * BytesPerTet > 0.8 * available)
      {
        std::printf("  | %d | ~%.0fM (expected) | - | - | - | - | - | - | - | skipped: would need "
                    "~%.1f GB, %.1f GB available\n",
          level, expected / 1e6, expected * BytesPerTet / 1e9, available / 1e9);
        std::fflush(stdout);
        break;
      }
      vtkNew<vtkTessellatorFilter> tess;
      tess->SetInputData(grid);
      tess->SetOutputDimension(3);
      tess->SetMaximumNumberOfSubdivisions(level);
      tess->SetChordError(1e-6 * Diagonal(grid));
      tess->MergePointsOn();
      auto start = Clock::now();
      tess->Update();
      const double tessSeconds = Seconds(start);
      vtkUnstructuredGrid* tets = tess->GetOutput();
      tets->GetPointData()->SetActiveScalars(d.Array.c_str());
      const Frame cpu =
        RenderStill(tets, d.Array.c_str(), property, vtkHighOrderVolumeMapper::CPU_ACCURATE, o);
      double maxDiff, meanDiff;
      Difference(ours.RGBA, cpu.RGBA, maxDiff, meanDiff);
      if (!o.Save.empty())
      {
        // The route's image per level (to locate where it and ours differ).
        std::ofstream out(
          ImageFile(o.Save, d.Name + " tess" + std::to_string(level), o), std::ios::binary);
        out.write(reinterpret_cast<const char*>(cpu.RGBA.data()), cpu.RGBA.size() * sizeof(float));
      }
      reached = maxDiff <= 1.0 / 255.0;
      counts.push_back(static_cast<double>(tets->GetNumberOfCells()));
      std::printf("  | %d%s | %lld | %.3f | %.4f | %.4f | %.3f | %.4f | %.1f | %.1f |\n", level,
        reached ? " (reference)" : "", static_cast<long long>(tets->GetNumberOfCells()),
        tessSeconds, cpu.First, cpu.Second, 255.0 * maxDiff, 255.0 * meanDiff,
        ours.First / cpu.First, ours.Second / cpu.Second);
      std::fflush(stdout);
    }
    if (!reached)
    {
      std::printf("  (no level up to %d reached max error <= 1/255)\n", o.Levels);
    }
  }
  if (!o.SkipInteractive)
  {
    Interactive(grid, d.Array.c_str(), property, o);
  }
  std::fflush(stdout);
}

vtkSmartPointer<vtkUnstructuredGrid> Read(const std::string& file)
{
  vtkNew<vtkXMLUnstructuredGridReader> reader;
  reader->SetFileName(file.c_str());
  reader->Update();
  return reader->GetOutput();
}
}

int main(int argc, char* argv[])
{
  Options o;
  for (int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    const bool value = i + 1 < argc;
    if (a == "--size" && value)
      o.Size = std::max(8, std::atoi(argv[++i]));
    else if (a == "--levels" && value)
      o.Levels = std::max(1, std::atoi(argv[++i]));
    else if (a == "--frames" && value)
      o.Frames = std::max(1, std::atoi(argv[++i]));
    else if (a == "--repeats" && value)
      o.Repeats = std::max(1, std::atoi(argv[++i]));
    else if (a == "--only" && value)
      o.Only = argv[++i];
    else if (a == "--data" && value)
      o.Data = argv[++i];
    else if (a == "--tolerance" && value)
      o.Tolerance = std::atof(argv[++i]);
    else if (a == "--save-images" && value)
      o.Save = argv[++i];
    else if (a == "--compare-images" && value)
      o.Compare = argv[++i];
    else if (a == "--semantics" && value)
      o.VTKSemantics = std::string(argv[++i]) == "vtk";
    else if (a == "--skip-tess")
      o.SkipTess = true;
    else if (a == "--skip-interactive")
      o.SkipInteractive = true;
    else
    {
      // --help, or an argument this benchmark does not know (or one missing
      // its value): say how to run it instead of running minutes of frames.
      const bool help = a == "--help" || a == "-h";
      std::fprintf(help ? stdout : stderr,
        "%shovBenchHighOrder [--size 256] [--only NAME] [--levels 4] [--frames 8]\n"
        "  [--repeats 3] [--skip-tess] [--skip-interactive] [--data DIR] [--tolerance 1e-3]\n"
        "  [--save-images DIR] [--compare-images DIR] [--semantics gpu|vtk]\n"
        "  NAME: a part of \"plate Q4\", \"T-junction P4\", \"curved hex Q3\", "
        "\"curved tet P6\"\n",
        help ? "" : ("unknown argument or missing value: " + a + "\n").c_str());
      return help ? 0 : 1;
    }
  }
  std::printf("hovBenchHighOrder: %dx%d, RayCastTolerance %g, ratios = ours / tessellation "
              "route (tessellation time excluded from that route)\n",
    o.Size, o.Size, o.Tolerance);
  const char* names[4] = { "plate Q4", "T-junction P4", "curved hex Q3", "curved tet P6" };
  if (!o.Only.empty() &&
    std::none_of(std::begin(names), std::end(names),
      [&](const char* n) { return std::string(n).find(o.Only) != std::string::npos; }))
  {
    std::fprintf(stderr, "--only %s matches no dataset (plate Q4, T-junction P4, curved hex Q3, "
                         "curved tet P6)\n", o.Only.c_str());
    return 1;
  }
  for (int k = 0; k < 4; ++k)
  {
    if (!o.Only.empty() && std::string(names[k]).find(o.Only) == std::string::npos)
    {
      continue;
    }
    Dataset d;
    d.Name = names[k];
    switch (k)
    {
      case 0:
        d.Grid = Read(o.Data + "/platehole_lagrange_hex_q4.vtu");
        d.Array = "von_mises";
        break;
      case 1:
        d.Grid = Read(o.Data + "/tjunction_lagrange_tet_p4.vtu");
        d.Array = "speed";
        break;
      case 2:
        d.Grid = hovBench::CurvedHexMesh(10, 3);
        d.Array = "f";
        break;
      default:
        d.Grid = hovBench::CurvedTetMesh(6, 6);
        d.Array = "f";
    }
    if (!d.Grid || d.Grid->GetNumberOfCells() == 0 || !d.Grid->GetPointData()->GetArray(d.Array.c_str()))
    {
      std::fprintf(stderr, "%s: no cells or no array %s\n", d.Name.c_str(), d.Array.c_str());
      return 1;
    }
    Run(d, o);
  }
  return 0;
}
