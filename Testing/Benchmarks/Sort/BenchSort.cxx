// hovBenchSort: vtkSteinVisibilitySort vs vtkCellCenterDepthSort (see CMakeLists.txt).
// Per mesh: the first sort of each (cell centres / view-independent set-up
// included) and a re-sort after a 5 degree azimuth, for CCD, the Stein sort's
// ADJACENCY_GRAPH algorithm (default) and its published MULTITILED_MERGE
// (tuned tiles; by default only up to 200k cells, --published for all).
// --repeat N (default 1): N first sorts (fresh sort objects) and N re-sorts
// (each after a further 5 degrees), medians printed; --bracket-only skips the
// RT meshes. --heatsink adds the boundary-heavy finned heatsinks of issue 20
// (BenchSortMeshes.h: 0.5M and 2M tetrahedra; --heatsink-only: only them).
// Memory (Linux): per sort object, the resident memory it still holds after
// its first sort ("held") and the peak above the start during it (VmHWM,
// reset through /proc/self/clear_refs), in MB.
// --threads N (N >= 1; smaller values mean 1): vtkSMPTools' thread count for
// both sorts (without the option: vtkSMPTools' default; --threads 1 measures
// the work of one core).
#include "BenchSortMeshes.h" // the heatsinks

#include "vtkCamera.h"
#include "vtkCellCenterDepthSort.h"
#include "vtkDataSetTriangleFilter.h"
#include "vtkIdTypeArray.h"
#include "vtkNew.h"
#include "vtkRTAnalyticSource.h"
#include "vtkSMPTools.h"
#include "vtkSteinVisibilitySort.h"
#include "vtkUnstructuredGrid.h"
#include "vtkXMLUnstructuredGridReader.h"

#include <algorithm> // std::nth_element for medians
#include <chrono>
#include <fstream> // /proc/self/status
#include <iostream> // --help
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

namespace
{
double Now()
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

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

/// Resets the peak resident size (VmHWM) to the current one; returns the current (MB).
double ResetPeak()
{
  std::ofstream("/proc/self/clear_refs") << "5";
  return StatusMB("VmRSS");
}

/// InitTraversal + GetNextCells loop; returns seconds.
double Traverse(vtkVisibilitySort* sort)
{
  const double t0 = Now();
  sort->InitTraversal();
  vtkIdType sum = 0;
  for (vtkIdTypeArray* a = sort->GetNextCells(); a; a = sort->GetNextCells())
  {
    sum += a->GetNumberOfTuples();
  }
  const double t = Now() - t0;
  if (sum != sort->GetInput()->GetNumberOfCells())
  {
    std::fprintf(stderr, "cell count mismatch: %lld\n", static_cast<long long>(sum));
  }
  return t;
}

vtkSmartPointer<vtkUnstructuredGrid> RTMesh(int e)
{
  vtkNew<vtkRTAnalyticSource> rt;
  rt->SetWholeExtent(-e, e, -e, e, -e, e);
  vtkNew<vtkDataSetTriangleFilter> tri;
  tri->SetInputConnection(rt->GetOutputPort());
  tri->Update();
  return tri->GetOutput();
}

void FixedView(vtkDataSet* d, vtkCamera* cam)
{
  double b[6];
  d->GetBounds(b);
  const double c[3] = { (b[0] + b[1]) / 2, (b[2] + b[3]) / 2, (b[4] + b[5]) / 2 };
  const double diag = std::sqrt((b[1] - b[0]) * (b[1] - b[0]) + (b[3] - b[2]) * (b[3] - b[2]) +
    (b[5] - b[4]) * (b[5] - b[4]));
  const double dir[3] = { 0.74, 0.52, 0.42 }; // roughly normalised, oblique
  cam->SetFocalPoint(c);
  cam->SetPosition(c[0] + 1.6 * diag * dir[0], c[1] + 1.6 * diag * dir[1], c[2] + 1.6 * diag * dir[2]);
  cam->SetViewUp(0, 0, 1);
  cam->SetViewAngle(30);
  cam->OrthogonalizeViewUp();
}

struct SteinRun
{
  double First = 0, Resort = 0, Setup = 0;
  vtkIdType Tests = 0, Moves = 0, Cycles = 0, Edges = 0, Boundary = 0;
  int Tiles[2] = { 0, 0 };
  double HeldMB = 0, PeakMB = 0; ///< after / during the first sort, above the start
};

/// --view-buffer-cell-limit N: vtkSteinVisibilitySort::SetViewBufferCellLimit (-1: its default).
vtkIdType ViewBufferCellLimit = -1;

/// One first sort and @p resorts re-sorts of the view turned by 5 degrees (the
/// camera turns back between them); re-sort times appended to @p times, the
/// counters are those of the first re-sort.
SteinRun RunSteinOnce(vtkDataSet* d, int algorithm, int tiles, int resorts, std::vector<double>& times)
{
  vtkNew<vtkCamera> cam;
  FixedView(d, cam);
  vtkNew<vtkSteinVisibilitySort> s;
  s->SetInput(d);
  s->SetCamera(cam);
  s->SetMaxCellsReturned(1000);
  s->SetAlgorithm(algorithm);
  s->SetNumberOfTiles(tiles, tiles);
  if (ViewBufferCellLimit >= 0)
  {
    s->SetViewBufferCellLimit(ViewBufferCellLimit);
  }
  SteinRun r;
  const double before = ResetPeak();
  r.First = Traverse(s);
  r.PeakMB = StatusMB("VmHWM") - before;
  r.HeldMB = StatusMB("VmRSS") - before;
  r.Setup = s->GetLastSetupSeconds();
  cam->Azimuth(5);
  r.Resort = Traverse(s);
  times.push_back(r.Resort);
  r.Tests = s->GetNumberOfObstructsTests();
  r.Moves = s->GetNumberOfMoves();
  r.Cycles = s->GetNumberOfCycles();
  r.Edges = s->GetNumberOfGraphEdges();
  r.Boundary = s->GetNumberOfBoundaryCells();
  s->GetUsedTiles(r.Tiles);
  for (int k = 1; k < resorts; ++k)
  {
    cam->Azimuth(-5);
    Traverse(s);
    cam->Azimuth(5);
    times.push_back(Traverse(s));
  }
  return r;
}

double Median(std::vector<double> v)
{
  std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
  return v[v.size() / 2];
}

/// Medians of @p repeat runs of RunSteinOnce with @p repeat re-sorts each.
SteinRun RunStein(vtkDataSet* d, int algorithm, int tiles, int repeat)
{
  std::vector<double> first, resort, setup;
  SteinRun r;
  double held = 0, peak = 0;
  for (int k = 0; k < repeat; ++k)
  {
    r = RunSteinOnce(d, algorithm, tiles, repeat, resort);
    first.push_back(r.First);
    setup.push_back(r.Setup);
    held = std::max(held, r.HeldMB);
    peak = std::max(peak, r.PeakMB);
  }
  r.HeldMB = held;
  r.PeakMB = peak;
  r.First = Median(first);
  r.Setup = Median(setup);
  r.Resort = Median(resort);
  return r;
}

}

int main(int argc, char* argv[])
{
  std::string data = HOV_BENCH_DATA_DIR;
  vtkIdType maxCells = 2000000;
  vtkIdType publishedMax = 200000; // the published merge takes minutes beyond this
  int tuned = -1;                  // -1: n^(1/3)/2 per direction
  int repeat = 1, threads = 0;
  bool bracketOnly = false, heatsink = false, heatsinkOnly = false;
  for (int i = 1; i < argc; ++i)
  {
    if (!std::strcmp(argv[i], "--published"))
      publishedMax = maxCells;
    else if (i + 1 < argc && !std::strcmp(argv[i], "--data"))
      data = argv[++i];
    else if (i + 1 < argc && !std::strcmp(argv[i], "--max-cells"))
      maxCells = std::atoll(argv[++i]);
    else if (i + 1 < argc && !std::strcmp(argv[i], "--published-max-cells"))
      publishedMax = std::atoll(argv[++i]);
    else if (i + 1 < argc && !std::strcmp(argv[i], "--tiles"))
      tuned = std::atoi(argv[++i]);
    else if (i + 1 < argc && !std::strcmp(argv[i], "--repeat"))
      repeat = std::max(1, std::atoi(argv[++i]));
    else if (i + 1 < argc && !std::strcmp(argv[i], "--threads"))
      threads = std::max(1, std::atoi(argv[++i]));
    else if (!std::strcmp(argv[i], "--bracket-only"))
      bracketOnly = true;
    else if (!std::strcmp(argv[i], "--heatsink"))
      heatsink = true;
    else if (i + 1 < argc && !std::strcmp(argv[i], "--view-buffer-cell-limit"))
      ViewBufferCellLimit = std::max<vtkIdType>(0, std::atoll(argv[++i]));
    else if (!std::strcmp(argv[i], "--heatsink-only"))
      heatsink = heatsinkOnly = true;
    else
    {
      // --help, or an argument this benchmark does not know: say how to run
      // it instead of running minutes of sorts.
      const bool help = !std::strcmp(argv[i], "--help") || !std::strcmp(argv[i], "-h");
      (help ? std::cout : std::cerr)
        << (help ? "" : std::string("unknown argument: ") + argv[i] + "\n")
        << "hovBenchSort [--data DIR] [--repeat N] [--bracket-only] [--heatsink] "
           "[--heatsink-only]\n"
           "             [--published] [--max-cells N] [--published-max-cells N] [--tiles N]\n"
           "             [--view-buffer-cell-limit N] [--threads N]\n";
      return help ? 0 : 1;
    }
  }
  if (publishedMax > maxCells)
    publishedMax = maxCells;
  if (threads > 0)
  {
    vtkSMPTools::Initialize(threads);
  }
  std::printf("hovBenchSort: %d vtkSMPTools threads (%s)\n",
    vtkSMPTools::GetEstimatedNumberOfThreads(), vtkSMPTools::GetBackend());
  struct Mesh
  {
    std::string Name;
    vtkSmartPointer<vtkUnstructuredGrid> Grid;
  };
  std::vector<Mesh> meshes;
  vtkNew<vtkXMLUnstructuredGridReader> reader;
  if (!heatsinkOnly)
  {
    reader->SetFileName((data + "/bracket_tet4_ccx.vtu").c_str());
    reader->Update();
    meshes.push_back({ "bracket", reader->GetOutput() });
  }
  for (int e : { 7, 17, 25, 29 })
  {
    if (!bracketOnly && !heatsinkOnly && 5.0 * std::pow(2 * e, 3) <= maxCells)
      meshes.push_back({ "RT [-" + std::to_string(e) + "," + std::to_string(e) + "]^3", RTMesh(e) });
  }
  if (heatsink)
  {
    // 16 fins 2 thick (gaps 2) on a 4-layer base, 28 high, 73 deep: 504k tets;
    // 24 fins, 6-layer base, 42 high, 130 deep: 2.02M tets.
    meshes.push_back({ "heatsink 0.5M", hovBench::Heatsink(16, 2, 2, 73, 4, 28) });
    if (maxCells >= 2000000)
      meshes.push_back({ "heatsink 2M", hovBench::Heatsink(24, 2, 2, 130, 6, 42) });
  }
  std::printf("Graph = ADJACENCY_GRAPH (default), merge = MULTITILED_MERGE (published, tuned "
              "tiles; only up to %lld cells, --published for all). 'first' includes the "
              "view-independent set-up (in parentheses); '5deg' is the re-sort after a 5 degree "
              "azimuth; ratios are re-sort times over CCD's re-sort.\n\n",
    static_cast<long long>(publishedMax));
  std::printf("| mesh | cells | CCD first s | CCD 5deg s | graph first s (setup) | graph 5deg s | "
              "graph first/CCD | graph/CCD | graph MB held (peak) | CCD MB held (peak) | boundary cells | "
              "tests | edges | cycles | merge first s | merge 5deg s "
              "| merge/CCD | merge tests |\n|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"
              "---|---|---|---|\n");
  for (const Mesh& m : meshes)
  {
    vtkUnstructuredGrid* g = m.Grid;
    const vtkIdType n = g->GetNumberOfCells();
    std::vector<double> ccdFirsts, ccdResorts;
    double ccdHeld = 0, ccdPeak = 0;
    for (int k = 0; k < repeat; ++k)
    {
      vtkNew<vtkCamera> ccdCam;
      FixedView(g, ccdCam);
      vtkNew<vtkCellCenterDepthSort> ccd;
      ccd->SetInput(g);
      ccd->SetCamera(ccdCam);
      ccd->SetMaxCellsReturned(1000);
      const double before = ResetPeak();
      ccdFirsts.push_back(Traverse(ccd));
      ccdPeak = std::max(ccdPeak, StatusMB("VmHWM") - before);
      ccdHeld = std::max(ccdHeld, StatusMB("VmRSS") - before);
      ccdCam->Azimuth(5);
      ccdResorts.push_back(Traverse(ccd));
    }
    const double ccdFirst = Median(ccdFirsts), ccdResort = Median(ccdResorts);
    const SteinRun gr = RunStein(g, vtkSteinVisibilitySort::ADJACENCY_GRAPH, 0, repeat);
    std::printf("| %s | %lld | %.4f | %.4f | %.4f (%.4f) | %.4f | %.2f | %.2f | %.0f (%.0f) | "
                "%.0f (%.0f) | %lld | %lld | %lld | %lld |",
      m.Name.c_str(), static_cast<long long>(n), ccdFirst, ccdResort, gr.First, gr.Setup, gr.Resort,
      gr.First / ccdFirst, gr.Resort / ccdResort, gr.HeldMB, gr.PeakMB, ccdHeld, ccdPeak,
      static_cast<long long>(gr.Boundary), static_cast<long long>(gr.Tests),
      static_cast<long long>(gr.Edges), static_cast<long long>(gr.Cycles));
    if (n <= publishedMax)
    {
      const int t = tuned > 0 ? tuned : std::max(1, static_cast<int>(std::cbrt(double(n)) / 2));
      const SteinRun mg = RunStein(g, vtkSteinVisibilitySort::MULTITILED_MERGE, t, 1);
      std::printf(" %.4f | %.4f | %.2f | %lld |\n", mg.First, mg.Resort, mg.Resort / ccdResort,
        static_cast<long long>(mg.Tests));
    }
    else
    {
      std::printf(" - | - | - | - |\n");
    }
    std::fflush(stdout);
  }
  return 0;
}
