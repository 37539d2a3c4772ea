// hovBenchRayCast: speed of hov::CurvedRayCaster (issue 6) on the real
// curved Lagrange datasets platehole_lagrange_hex_q4.vtu (192 Q4 hexahedra)
// and tjunction_lagrange_tet_p4.vtu (3790 P4 tetrahedra): Build() time, then
// an orthographic size x size view along -z through the mesh bounds, every
// step-th pixel in each direction traced (so the cost sample covers the whole
// image), with 1 and 2 std::threads (rows interleaved); prints ms per ray,
// rays per second, segments per ray and the worst error estimate. Each
// configuration is run --repeat times (interleaved) and the median printed.
// --mapper: the settings vtkHighOrderVolumeMapper's RAY_CAST uses by default
// (segment tolerance --tolerance, default 1e-3; GPU-compatible opacity with
// GPUTolerance 1e-4; the README's 7-node table over the range) instead of the
// kernel defaults; the generated curved meshes of hovBenchHighOrder join with
// --only "hex Q3" / "tet P6". The one-thread frame also prints its CPU time
// (getrusage of the thread: robust to other processes on a shared machine).
// --transparent-below F: no opacity over the lowest fraction F of the range
// (nodes below it at 0, one at F); the cells whose field hull is invisible
// there are flagged (CurvedRayCaster::IsCellInvisible, as the mapper's
// SkipTransparentCells does) and the one-thread frame is also timed with
// every cell traced: both ms/ray and their ratio.
// Not a test: no pass/fail.
#include "BenchHighOrderMeshes.h" // generated curved meshes
#include "hovCurvedRayCaster.h"
#include "hovTransferFunction.h"

#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkUnstructuredGrid.h"
#include "vtkXMLUnstructuredGridReader.h"

#include <sys/resource.h> // getrusage: CPU time of the one-thread frame

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <string>
#include <thread>
#include <vector>

namespace
{
using Clock = std::chrono::steady_clock;

struct Mesh
{
  std::vector<double> Points, Scalars;
  std::vector<unsigned char> Types;
  std::vector<std::int64_t> Offsets{ 0 }, Connectivity;
  std::vector<int> Degrees;
  hov::CurvedMeshInput Input() const
  {
    hov::CurvedMeshInput in;
    in.Points = this->Points.data();
    in.NumberOfPoints = static_cast<std::int64_t>(this->Scalars.size());
    in.Scalars = this->Scalars.data();
    in.CellTypes = this->Types.data();
    in.Offsets = this->Offsets.data();
    in.Connectivity = this->Connectivity.data();
    in.NumberOfCells = static_cast<std::int64_t>(this->Types.size());
    in.Degrees = this->Degrees.size() == 3 * this->Types.size() ? this->Degrees.data() : nullptr;
    return in;
  }
};

bool Convert(vtkUnstructuredGrid* grid, const char* array, Mesh& m)
{
  vtkDataArray* s = grid ? grid->GetPointData()->GetArray(array) : nullptr;
  if (!grid || !s || grid->GetNumberOfCells() == 0)
  {
    return false;
  }
  const vtkIdType np = grid->GetNumberOfPoints(), nc = grid->GetNumberOfCells();
  m.Points.resize(3 * np);
  m.Scalars.resize(np);
  for (vtkIdType i = 0; i < np; ++i)
  {
    grid->GetPoints()->GetPoint(i, &m.Points[3 * i]);
    m.Scalars[i] = s->GetComponent(i, 0);
  }
  vtkDataArray* degrees = grid->GetCellData()->GetHigherOrderDegrees();
  for (vtkIdType c = 0; c < nc; ++c)
  {
    vtkIdType n;
    const vtkIdType* ids;
    grid->GetCellPoints(c, n, ids);
    m.Connectivity.insert(m.Connectivity.end(), ids, ids + n);
    m.Offsets.push_back(static_cast<std::int64_t>(m.Connectivity.size()));
    m.Types.push_back(static_cast<unsigned char>(grid->GetCellType(c)));
    for (int k = 0; degrees && degrees->GetNumberOfComponents() == 3 && k < 3; ++k)
    {
      m.Degrees.push_back(static_cast<int>(degrees->GetComponent(c, k)));
    }
  }
  return true;
}

bool Load(const std::string& file, const char* array, Mesh& m)
{
  vtkNew<vtkXMLUnstructuredGridReader> reader;
  reader->SetFileName(file.c_str());
  reader->Update();
  return Convert(reader->GetOutput(), array, m);
}

double ThreadCPUSeconds()
{
  rusage u;
  getrusage(RUSAGE_THREAD, &u);
  return u.ru_utime.tv_sec + 1e-6 * u.ru_utime.tv_usec + u.ru_stime.tv_sec + 1e-6 * u.ru_stime.tv_usec;
}

struct Frame
{
  double Seconds = 0.0, WorstError = 0.0, CPUSeconds = 0.0;
  long Rays = 0, Segments = 0, Hit = 0;
};

Frame Render(const hov::CurvedRayCaster& caster, const hov::TransferFunction& tf,
  const hov::CurvedSegmentSettings& settings, int size, int step, int threads,
  const unsigned char* skip = nullptr)
{
  const double* B = caster.GetBounds();
  std::vector<Frame> parts(threads);
  std::atomic<int> nextRow{ 0 };
  auto work = [&](int id) {
    Frame& f = parts[id];
    for (int j = nextRow.fetch_add(step); j < size; j = nextRow.fetch_add(step))
    {
      for (int i = 0; i < size; i += step)
      {
        const double o[3] = { B[0] + (i + 0.5) / size * (B[1] - B[0]),
          B[2] + (j + 0.5) / size * (B[3] - B[2]), B[5] + 1.0 };
        const double d[3] = { 0.0, 0.0, -1.0 };
        double error = 0.0;
        hov::CurvedRayStats stats;
        const hov::RGBA c =
          caster.TraceRay(o, d, 0.0, B[5] - B[4] + 2.0, tf, settings, &error, &stats, skip);
        f.WorstError = std::max(f.WorstError, error);
        f.Segments += stats.Segments;
        f.Hit += c.A > 0.0 ? 1 : 0;
        ++f.Rays;
      }
    }
  };
  const auto start = Clock::now();
  const double cpuStart = ThreadCPUSeconds();
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t)
  {
    pool.emplace_back(work, t);
  }
  work(0);
  const double cpu = ThreadCPUSeconds() - cpuStart;
  for (std::thread& t : pool)
  {
    t.join();
  }
  Frame total;
  total.Seconds = std::chrono::duration<double>(Clock::now() - start).count();
  total.CPUSeconds = cpu; // the calling thread's (all of it with one thread)
  for (const Frame& f : parts)
  {
    total.Rays += f.Rays;
    total.Segments += f.Segments;
    total.Hit += f.Hit;
    total.WorstError = std::max(total.WorstError, f.WorstError);
  }
  return total;
}

double Median(std::vector<double> v)
{
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}
}

int main(int argc, char* argv[])
{
  int size = 256, step = 8, repeat = 3;
  std::string data = HOV_BENCH_DATA_DIR, method = "ours", only;
  bool mapper = false;
  double tolerance = 1e-3, transparentBelow = -1.0;
  for (int i = 1; i < argc; i += 2)
  {
    const std::string a = argv[i];
    if (a == "--mapper")
    {
      mapper = true;
      --i;
      continue;
    }
    if (i + 1 >= argc)
      break;
    if (a == "--tolerance")
      tolerance = std::atof(argv[i + 1]);
    else if (a == "--size")
      size = std::atoi(argv[i + 1]);
    else if (a == "--step")
      step = std::max(1, std::atoi(argv[i + 1]));
    else if (a == "--repeat")
      repeat = std::max(1, std::atoi(argv[i + 1]));
    else if (a == "--data")
      data = argv[i + 1];
    else if (a == "--method")
      method = argv[i + 1];
    else if (a == "--transparent-below")
      transparentBelow = std::atof(argv[i + 1]);
    else if (a == "--only")
      only = argv[i + 1]; // run the datasets whose file name contains this
  }
  hov::CurvedSegmentSettings settings;
  settings.Method = method == "elvis" ? hov::CurvedQuadrature::ElVis
    : method == "riemann"             ? hov::CurvedQuadrature::Riemann
                                      : hov::CurvedQuadrature::LocatedBreakpoints;
  if (mapper)
  {
    settings.Quadrature.Tolerance = tolerance;
  }
  struct Set
  {
    const char* File;
    const char* Array;
    double Lo, Hi;
  };
  const Set sets[4] = { { "platehole_lagrange_hex_q4.vtu", "von_mises", 1.8, 361.0 },
    { "tjunction_lagrange_tet_p4.vtu", "speed", 0.05, 2.63 }, { "hex Q3", "f", 0.0, 0.0 },
    { "tet P6", "f", 0.0, 0.0 } };
  std::cout << "hovBenchRayCast: " << size << "x" << size << " view along -z, every " << step
            << "-th pixel, method " << method << ", median of " << repeat << std::endl;
  for (const Set& s : sets)
  {
    const bool generated = s.Lo == s.Hi;
    if ((only.empty() && generated) ||
      (!only.empty() && std::string(s.File).find(only) == std::string::npos))
    {
      continue;
    }
    Mesh mesh;
    double range[2] = { s.Lo, s.Hi };
    if (generated)
    {
      vtkSmartPointer<vtkUnstructuredGrid> grid = std::string(s.File) == "hex Q3"
        ? hovBench::CurvedHexMesh(10, 3)
        : hovBench::CurvedTetMesh(6, 6);
      grid->GetPointData()->GetArray(s.Array)->GetRange(range);
      Convert(grid, s.Array, mesh);
    }
    else if (!Load(data + "/" + s.File, s.Array, mesh))
    {
      std::cerr << "cannot read " << data << "/" << s.File << std::endl;
      return 1;
    }
    hov::CurvedRayCaster caster;
    std::string message;
    const auto buildStart = Clock::now();
    const bool built = caster.Build(mesh.Input(), &message);
    const double build = std::chrono::duration<double>(Clock::now() - buildStart).count();
    if (!built)
    {
      std::cerr << s.File << ": " << message << std::endl;
      return 1;
    }
    hov::TransferFunctionSpec spec;
    const double lo = range[0], span = range[1] - range[0];
    if (mapper)
    {
      // hovBenchHighOrder's table (the README's) in the mapper's default semantics.
      static const double nodes[7][5] = { { 0.00, 0.15, 0.25, 0.90, 0.02 },
        { 0.03, 0.20, 0.50, 1.00, 0.04 }, { 0.09, 0.10, 0.90, 0.90, 0.10 },
        { 0.20, 0.30, 1.00, 0.30, 0.25 }, { 0.35, 1.00, 1.00, 0.10, 0.50 },
        { 0.60, 1.00, 0.50, 0.00, 0.80 }, { 1.00, 1.00, 0.05, 0.05, 1.00 } };
      spec.Semantics = hov::OpacitySemantics::GPUCompatible;
      spec.GPUTolerance = std::max(1e-4, 0.1 * tolerance);
      for (const auto& n : nodes)
      {
        spec.Color.push_back({ lo + n[0] * span, n[1], n[2], n[3] });
        spec.Opacity.push_back({ lo + n[0] * span, n[4] });
      }
      const double* b = caster.GetBounds();
      spec.UnitDistance = 0.08 * std::sqrt((b[1] - b[0]) * (b[1] - b[0]) +
                                   (b[3] - b[2]) * (b[3] - b[2]) + (b[5] - b[4]) * (b[5] - b[4]));
    }
    else
    {
      spec.Semantics = hov::OpacitySemantics::VTKUnstructured;
      spec.Color = { { lo, 0.1, 0.2, 0.9 }, { lo + 0.5 * span, 0.2, 0.9, 0.2 },
        { lo + span, 0.9, 0.1, 0.1 } };
      spec.Opacity = { { lo, 0.0 }, { lo + 0.3 * span, 0.2 }, { lo + 0.6 * span, 0.6 },
        { lo + span, 1.0 } };
      spec.UnitDistance = 0.05 * (caster.GetBounds()[1] - caster.GetBounds()[0]);
    }
    if (transparentBelow > 0.0)
    {
      // No opacity below the fraction: nodes below it at 0, one node at it.
      const double cut = lo + std::min(transparentBelow, 1.0) * span;
      for (auto& n : spec.Opacity)
      {
        n.Opacity = n.X <= cut ? 0.0 : n.Opacity;
      }
      spec.Opacity.push_back({ cut, 0.0 });
      std::sort(spec.Opacity.begin(), spec.Opacity.end(),
        [](const hov::OpacityNode& a, const hov::OpacityNode& b) { return a.X < b.X; });
    }
    hov::TransferFunction tf;
    tf.Build(spec);
    std::vector<unsigned char> invisible;
    long flagged = 0;
    if (transparentBelow > 0.0)
    {
      for (std::int64_t c = 0; c < caster.GetNumberOfCells(); ++c)
      {
        invisible.push_back(caster.IsCellInvisible(c, tf, settings.Quadrature.Emission) ? 1 : 0);
        flagged += invisible.back();
      }
      std::cout << "  no opacity below " << transparentBelow << " of the range: " << flagged
                << " of " << caster.GetNumberOfCells() << " cells invisible" << std::endl;
    }
    const unsigned char* skip = invisible.empty() ? nullptr : invisible.data();
    std::cout << s.File << ": " << caster.GetNumberOfCells() << " cells, Build " << build << " s"
              << std::endl;
    // The first frame pays the lazily computed per-cell bounds: reported apart.
    const Frame first = Render(caster, tf, settings, size, step, 2, skip);
    std::cout << "  first frame (2 threads, includes lazy cell bounds): " << first.Seconds
              << " s, " << first.Rays << " rays, " << first.Hit << " hit, "
              << static_cast<double>(first.Segments) / std::max(first.Hit, 1L)
              << " segments per hit ray, worst error estimate " << first.WorstError << std::endl;
    std::vector<double> times[2], cpu, everyCell;
    long rays = first.Rays;
    for (int r = 0; r < repeat; ++r)
    {
      for (int threads : { 1, 2 })
      {
        const Frame f = Render(caster, tf, settings, size, step, threads, skip);
        times[threads - 1].push_back(f.Seconds);
        if (threads == 1)
        {
          cpu.push_back(f.CPUSeconds);
        }
      }
      if (skip)
      {
        everyCell.push_back(Render(caster, tf, settings, size, step, 1).CPUSeconds);
      }
    }
    std::cout << "  1 thread CPU time: " << 1e3 * Median(cpu) / rays << " ms/ray" << std::endl;
    if (skip)
    {
      std::cout << "  1 thread CPU time, every cell traced: " << 1e3 * Median(everyCell) / rays
                << " ms/ray (every cell / invisible cells skipped: "
                << Median(everyCell) / Median(cpu) << ")" << std::endl;
    }
    for (int threads : { 1, 2 })
    {
      const double t = Median(times[threads - 1]);
      std::cout << "  " << threads << " thread(s): " << 1e3 * t / rays << " ms/ray, "
                << rays / t << " rays/s (full " << size << "x" << size << " image ~"
                << t * size * size / rays << " s)" << std::endl;
    }
  }
  return 0;
}
