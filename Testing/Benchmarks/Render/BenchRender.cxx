// hovBenchRender: wall-clock render benchmark (not a ctest case).
//
// In one process, offscreen at 512x512 (default), renders
//   (a) the bundled bracket (Testing/Data/bracket_tet4_ccx.vtu, point array von_mises),
//   (b) a generated mesh: vtkRTAnalyticSource, whole extent [-E,E]^3 (E = 24 by default:
//       48^3 = 110,592 voxels) -> vtkDataSetTriangleFilter (5 tetrahedra per voxel),
// with
//   - vtkHighOrderVolumeMapper, exact integral, VTK_UNSTRUCTURED opacity semantics,
//     VISIBILITY_SORT (vtkCellCenterDepthSort, the default) and PER_PIXEL_SORT,
//   - vtkProjectedTetrahedraMapper (OpenGL, vtkCellCenterDepthSort),
//   - vtkUnstructuredGridVolumeRayCastMapper + vtkUnstructuredGridLinearRayIntegrator,
// all with the same camera and the same vtkVolumeProperty, and prints a Markdown table:
//   first frame (fresh mapper, GL context already created), median of N frames each after
//   a camera azimuth step (view-dependent caches cannot be reused), median of N frames of
//   the same view, and the ratios mapper time / our mapper time.
// Every timed frame is renderWindow->Render() followed by WaitForCompletion() (glFinish),
// so asynchronous OpenGL work is counted.
//
// Usage: hovBenchRender [--data DIR] [--frames N] [--size S] [--extent E] [--azimuth DEG]
//                       [--mesh bracket|rt|all] [--skip-raycast-large] [--out DIR]
// Run under xvfb-run -a -s "-screen 0 1280x1024x24" (Debian's VTK renders only via GLX).
// Exit status: 0 if every render succeeded without VTK errors and gave a non-black image.

#include "vtkHighOrderVolumeMapper.h"

#include "vtkCallbackCommand.h"
#include "vtkCamera.h"
#include "vtkCellType.h"
#include "vtkColorTransferFunction.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkDataSetTriangleFilter.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPNGWriter.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkProjectedTetrahedraMapper.h"
#include "vtkRTAnalyticSource.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"
#include "vtkUnstructuredGridLinearRayIntegrator.h"
#include "vtkUnstructuredGridVolumeRayCastMapper.h"
#include "vtkVersion.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"
#include "vtkWindowToImageFilter.h"
#include "vtkXMLUnstructuredGridReader.h"

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#ifndef HOV_BENCH_DATA_DIR
#define HOV_BENCH_DATA_DIR "."
#endif

namespace
{

struct Options
{
  std::string DataDir = HOV_BENCH_DATA_DIR;
  std::string OutDir; // empty: no images written
  std::string Meshes = "all";
  int Frames = 3;
  int Size = 512;
  int Extent = 24;
  double AzimuthStep = 7.0;
  bool SkipRayCastLarge = false;
};

struct Mesh
{
  std::string Name;
  vtkSmartPointer<vtkUnstructuredGrid> Grid;
  std::string Array;
  double Range[2] = { 0, 1 };
  double UnitDistance = 1.0;
  vtkIdType Tetras = 0;
};

struct Row
{
  std::string Mesh;
  std::string Mapper;
  std::string Key; // hov_vis, hov_pix, pt, rc
  bool Ran = false;
  bool Ok = true;
  std::string Problem;
  double First = 0, Rotating = 0, Same = 0;
  double CpuRotating = -1; // our mapper: median GetLastImageTime() of the rotating frames
  vtkIdType Witness = -1;  // our mapper: witness violations of the last rotating frame
  double Coverage = 0;     // fraction of non-black pixels of the last frame
};

/// Collects VTK errors of the objects it observes (the message is not printed twice).
class ErrorCounter
{
public:
  ErrorCounter() { this->Callback->SetClientData(this); this->Callback->SetCallback(&ErrorCounter::OnEvent); }
  void Watch(vtkObject* obj) { obj->AddObserver(vtkCommand::ErrorEvent, this->Callback); }
  std::vector<std::string> Messages;

private:
  static void OnEvent(vtkObject* caller, unsigned long, void* clientData, void* callData)
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
  vtkNew<vtkCallbackCommand> Callback;
};

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

vtkIdType CountTetras(vtkUnstructuredGrid* grid)
{
  vtkIdType n = 0;
  for (vtkIdType i = 0; i < grid->GetNumberOfCells(); ++i)
  {
    n += grid->GetCellType(i) == VTK_TETRA ? 1 : 0;
  }
  return n;
}

/// The demo's transfer function (Utilities/hov_demo.py): 7 colour and opacity nodes at the
/// same scalars, low faint blue -> cyan -> green -> yellow -> orange -> red, opacity rising.
vtkSmartPointer<vtkVolumeProperty> MakeProperty(const double range[2], double unitDistance)
{
  static const double nodes[7][5] = {
    { 0.00, 0.15, 0.25, 0.90, 0.02 },
    { 0.03, 0.20, 0.50, 1.00, 0.04 },
    { 0.09, 0.10, 0.90, 0.90, 0.10 },
    { 0.20, 0.30, 1.00, 0.30, 0.25 },
    { 0.35, 1.00, 1.00, 0.10, 0.50 },
    { 0.60, 1.00, 0.50, 0.00, 0.80 },
    { 1.00, 1.00, 0.05, 0.05, 1.00 },
  };
  vtkNew<vtkColorTransferFunction> ctf;
  vtkNew<vtkPiecewiseFunction> otf;
  const double span = range[1] - range[0];
  for (const auto& n : nodes)
  {
    const double s = range[0] + n[0] * span;
    ctf->AddRGBPoint(s, n[1], n[2], n[3]);
    otf->AddPoint(s, n[4]);
  }
  auto prop = vtkSmartPointer<vtkVolumeProperty>::New();
  prop->SetColor(ctf);
  prop->SetScalarOpacity(otf);
  prop->SetScalarOpacityUnitDistance(unitDistance);
  prop->SetInterpolationTypeToLinear();
  prop->ShadeOff();
  return prop;
}

/// Oblique view (azimuth 35, elevation 30 from +z) of the bounding box, fitted like
/// vtkRenderer::ResetCamera, with a fixed clipping range enclosing the bounding sphere.
void SetupCamera(vtkCamera* cam, const double b[6])
{
  const double c[3] = { 0.5 * (b[0] + b[1]), 0.5 * (b[2] + b[3]), 0.5 * (b[4] + b[5]) };
  const double r = 0.5 *
    std::sqrt((b[1] - b[0]) * (b[1] - b[0]) + (b[3] - b[2]) * (b[3] - b[2]) +
      (b[5] - b[4]) * (b[5] - b[4]));
  cam->SetViewAngle(30.0);
  cam->SetFocalPoint(c);
  cam->SetPosition(c[0], c[1], c[2] + 1.0);
  cam->SetViewUp(0.0, 1.0, 0.0);
  cam->Azimuth(35.0);
  cam->Elevation(30.0);
  cam->OrthogonalizeViewUp();
  const double d = r / std::sin(0.5 * 30.0 * 3.14159265358979323846 / 180.0);
  double dir[3];
  cam->GetDirectionOfProjection(dir);
  cam->SetPosition(c[0] - d * dir[0], c[1] - d * dir[1], c[2] - d * dir[2]);
  cam->SetClippingRange(std::max(0.01 * d, d - 1.5 * r), d + 1.5 * r);
}

bool LoadBracket(const Options& opt, Mesh& mesh)
{
  const std::string file = opt.DataDir + "/bracket_tet4_ccx.vtu";
  vtkNew<vtkXMLUnstructuredGridReader> reader;
  if (!reader->CanReadFile(file.c_str()))
  {
    std::cerr << "Cannot read " << file << " (use --data DIR)\n";
    return false;
  }
  reader->SetFileName(file.c_str());
  reader->Update();
  mesh.Name = "bracket";
  mesh.Grid = reader->GetOutput();
  mesh.Array = "von_mises";
  vtkDataArray* a = mesh.Grid->GetPointData()->GetArray(mesh.Array.c_str());
  if (!a)
  {
    std::cerr << file << " has no point array von_mises\n";
    return false;
  }
  mesh.Grid->GetPointData()->SetActiveScalars(mesh.Array.c_str());
  a->GetRange(mesh.Range, 0);
  mesh.UnitDistance = 2.5; // as in the demo; the bracket is 100 x 60 x 80
  mesh.Tetras = CountTetras(mesh.Grid);
  return true;
}

bool MakeRTMesh(const Options& opt, Mesh& mesh)
{
  const int e = opt.Extent;
  vtkNew<vtkRTAnalyticSource> source;
  source->SetWholeExtent(-e, e, -e, e, -e, e);
  source->SetCenter(0.0, 0.0, 0.0);
  vtkNew<vtkDataSetTriangleFilter> tets;
  tets->SetInputConnection(source->GetOutputPort());
  tets->TetrahedraOnlyOn();
  tets->Update();
  std::ostringstream name;
  name << "RTAnalytic [-" << e << "," << e << "]^3";
  mesh.Name = name.str();
  mesh.Grid = tets->GetOutput();
  mesh.Array = "RTData";
  vtkDataArray* a = mesh.Grid->GetPointData()->GetArray(mesh.Array.c_str());
  if (!a)
  {
    std::cerr << "vtkRTAnalyticSource gave no RTData\n";
    return false;
  }
  mesh.Grid->GetPointData()->SetActiveScalars(mesh.Array.c_str());
  a->GetRange(mesh.Range, 0);
  mesh.UnitDistance = e; // semi-transparent over the 2e-wide cube
  mesh.Tetras = CountTetras(mesh.Grid);
  std::cout << "Generated mesh: " << mesh.Name << ", " << (2 * e) * (2 * e) * (2 * e)
            << " voxels -> " << mesh.Tetras << " tetrahedra, " << mesh.Grid->GetNumberOfPoints()
            << " points, RTData range [" << mesh.Range[0] << ", " << mesh.Range[1] << "]\n";
  return true;
}

/// Fraction of non-black pixels in the window (RGB read back).
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

std::string Fmt(double v, int prec = 3)
{
  char buf[64];
  std::snprintf(buf, sizeof(buf), "%.*f", prec, v);
  return buf;
}

std::string Ratio(double a, double b)
{
  if (!(b > 0.0) || !(a > 0.0))
  {
    return "-";
  }
  char buf[64];
  std::snprintf(buf, sizeof(buf), "%.2fx", a / b);
  return buf;
}

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
       "Run under xvfb-run -a -s \"-screen 0 1280x1024x24\".\n";
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
    {
      vtkNew<vtkHighOrderVolumeMapper> m;
      m->SetIntegrationMethodToExact();
      m->SetOpacitySemanticsToVTKUnstructured();
      m->SetCellOrderingToVisibilitySort();
      rows.push_back(RunOne(opt, mesh, "hov_vis",
        "vtkHighOrderVolumeMapper (exact, VTK-unstructured, visibility sort)", m, errors));
    }
    {
      vtkNew<vtkHighOrderVolumeMapper> m;
      m->SetIntegrationMethodToExact();
      m->SetOpacitySemanticsToVTKUnstructured();
      m->SetCellOrderingToPerPixelSort();
      rows.push_back(RunOne(opt, mesh, "hov_pix",
        "vtkHighOrderVolumeMapper (exact, VTK-unstructured, per-pixel sort)", m, errors));
    }
    {
      vtkNew<vtkProjectedTetrahedraMapper> m;
      rows.push_back(RunOne(opt, mesh, "pt", "vtkProjectedTetrahedraMapper", m, errors));
    }
    const bool large = mesh.Name != "bracket";
    if (large && opt.SkipRayCastLarge)
    {
      Row r;
      r.Mesh = mesh.Name;
      r.Key = "rc";
      r.Mapper = "vtkUnstructuredGridVolumeRayCastMapper + linear integrator";
      r.Problem = "skipped (--skip-raycast-large)";
      rows.push_back(r);
    }
    else
    {
      vtkNew<vtkUnstructuredGridVolumeRayCastMapper> m;
      vtkNew<vtkUnstructuredGridLinearRayIntegrator> integrator;
      m->SetRayIntegrator(integrator);
      m->SetAutoAdjustSampleDistances(0); // one ray per pixel, no LOD
      m->SetImageSampleDistance(1.0);
      rows.push_back(RunOne(opt, mesh, "rc",
        "vtkUnstructuredGridVolumeRayCastMapper + linear integrator", m, errors));
    }
  }

  // The table.
  std::ostringstream t;
  t << "\n## hovBenchRender: " << opt.Size << "x" << opt.Size << ", N = " << opt.Frames
    << " frames per median, azimuth step " << opt.AzimuthStep
    << " deg; opacity semantics: VTK-unstructured (extinction a(s)/u) for every mapper\n\n";
  t << "Times in seconds, wall clock of renderWindow->Render() + WaitForCompletion(). "
       "First: first frame of a fresh mapper (window already created). Rotating: median of N "
       "frames, each after a camera azimuth step. Same view: median of N frames without a camera "
       "change. CPU image: our mapper's GetLastImageTime() (median, rotating). Ratios: this "
       "mapper's time / our mapper's time (>1: ours is faster); 'vis' = our visibility sort, "
       "'pix' = our per-pixel sort.\n\n";
  t << "| mesh | tets | mapper | first | rotating median | same-view median | CPU image "
       "| first / vis | rotating / vis | same-view / vis | rotating / pix | witness | covered px "
       "| status |\n";
  t << "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  bool allOk = true;
  for (const Mesh& mesh : meshes)
  {
    const Row* vis = nullptr;
    const Row* pix = nullptr;
    for (const Row& r : rows)
    {
      if (r.Mesh == mesh.Name && r.Key == "hov_vis" && r.Ran)
      {
        vis = &r;
      }
      if (r.Mesh == mesh.Name && r.Key == "hov_pix" && r.Ran)
      {
        pix = &r;
      }
    }
    for (const Row& r : rows)
    {
      if (r.Mesh != mesh.Name)
      {
        continue;
      }
      t << "| " << r.Mesh << " | " << mesh.Tetras << " | " << r.Mapper << " | ";
      if (!r.Ran)
      {
        t << "- | - | - | - | - | - | - | - | - | - | - | " << r.Problem << " |\n";
        continue;
      }
      allOk = allOk && r.Ok;
      t << Fmt(r.First) << " | " << Fmt(r.Rotating) << " | " << Fmt(r.Same) << " | "
        << (r.CpuRotating >= 0 ? Fmt(r.CpuRotating) : std::string("-")) << " | "
        << (vis ? Ratio(r.First, vis->First) : "-") << " | "
        << (vis ? Ratio(r.Rotating, vis->Rotating) : "-") << " | "
        << (vis ? Ratio(r.Same, vis->Same) : "-") << " | "
        << (pix ? Ratio(r.Rotating, pix->Rotating) : "-") << " | "
        << (r.Witness >= 0 ? std::to_string(r.Witness) : std::string("-")) << " | "
        << Fmt(100.0 * r.Coverage, 1) << "% | " << (r.Ok ? "ok" : "FAILED: " + r.Problem)
        << " |\n";
    }
  }
  std::cout << t.str() << std::flush;
  return allOk ? 0 : 1;
}
