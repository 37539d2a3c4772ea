// Google Benchmark of the segment kernels: nanoseconds per segment.
//
// One benchmark iteration integrates one segment taken round-robin from a
// pre-generated table of 4096 inputs (fixed seed), so "Time" is ns/segment
// including a cache-resident load of the inputs. Cases:
//  - Exact_WM_Mix: IntegrateSegment, exact, Williams-Max, over a realistic mix
//    of 50% thin segments (total depth <= 1/8, Taylor branch), 40% medium
//    (1/8 .. 10) and 10% thick (10 .. 1000) closed-form segments, with both
//    signs of the extinction slope and some constant-extinction ones;
//  - Exact_WM_Thin / Exact_WM_ClosedForm: the two branches alone;
//  - Exact_WVG_Mix: Wilhelms-Van Gelder (also computes K1) on the same mix;
//  - Approximate_WM_Mix: HIAC's approximate method on the same mix;
//  - LinearScalar_10Nodes (per ray; also ns/piece): IntegrateLinearScalar
//    through a 10-node table (VTK-unstructured semantics), random s ranges in
//    [0,1] in both directions; LinearScalar_GPU_10Nodes: the same opacity
//    nodes with GPU-compatible semantics (refined table, tolerance 1e-4);
//  - Batch_WM_Tile (ns/segment): hov::SegmentBatch on blocks of 256 segments
//    as the tile loop queues them (each within one interval of the 10-node
//    table, VTK-unstructured semantics, lengths 1e-3..0.2: mostly thin).

#include "hovRayIntegrator.h"
#include "hovSegmentBatch.h"
#include "hovSegmentIntegral.h"
#include "hovTransferFunction.h"

#include "hovBenchTables.h" // the shared 10-node table

#include <benchmark/benchmark.h>

#include <cmath>
#include <random>
#include <vector>

namespace
{
constexpr size_t N = 4096; // power of two
constexpr size_t Mask = N - 1;

struct Input
{
  double Length;
  hov::SegmentEnd Front, Back;
};

enum class Mix
{
  Realistic,
  Thin,
  ClosedForm
};

std::vector<Input> MakeInputs(Mix mix)
{
  std::mt19937_64 rng(12345);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  auto logUniform = [&](double lo, double hi) { return std::exp(std::log(lo) + (std::log(hi) - std::log(lo)) * u01(rng)); };
  std::vector<Input> in(N);
  for (Input& s : in)
  {
    s.Length = logUniform(0.01, 1.0);
    double depth; // total optical depth D(1) of the segment
    const double r = u01(rng);
    if (mix == Mix::Thin || (mix == Mix::Realistic && r < 0.5))
    {
      depth = logUniform(1e-4, 0.125);
    }
    else if (mix == Mix::ClosedForm || r < 0.9)
    {
      depth = logUniform(0.13, 10.0);
    }
    else
    {
      depth = logUniform(10.0, 1000.0);
    }
    // Split the depth between the ends: front share f in [0,1]; 10% constant.
    const double f = u01(rng) < 0.1 ? 0.5 : u01(rng);
    s.Front.Tau = 2.0 * depth * f / s.Length;
    s.Back.Tau = 2.0 * depth * (1.0 - f) / s.Length;
    for (int c = 0; c < 3; ++c)
    {
      s.Front.Color[c] = u01(rng);
      s.Back.Color[c] = u01(rng);
    }
  }
  return in;
}

void RunSegments(benchmark::State& state, Mix mix, hov::EmissionModel model, hov::SegmentMethod method)
{
  const std::vector<Input> in = MakeInputs(mix);
  size_t i = 0;
  for (auto _ : state)
  {
    const Input& s = in[i++ & Mask];
    benchmark::DoNotOptimize(hov::IntegrateSegment(s.Length, s.Front, s.Back, model, method));
  }
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations()));
  state.SetLabel("ns/segment = Time");
}

void Exact_WM_Mix(benchmark::State& state)
{
  RunSegments(state, Mix::Realistic, hov::EmissionModel::WilliamsMax, hov::SegmentMethod::Exact);
}
void Exact_WM_Thin(benchmark::State& state)
{
  RunSegments(state, Mix::Thin, hov::EmissionModel::WilliamsMax, hov::SegmentMethod::Exact);
}
void Exact_WM_ClosedForm(benchmark::State& state)
{
  RunSegments(state, Mix::ClosedForm, hov::EmissionModel::WilliamsMax, hov::SegmentMethod::Exact);
}
void Exact_WVG_Mix(benchmark::State& state)
{
  RunSegments(state, Mix::Realistic, hov::EmissionModel::WilhelmsVanGelder, hov::SegmentMethod::Exact);
}
void Approximate_WM_Mix(benchmark::State& state)
{
  RunSegments(state, Mix::Realistic, hov::EmissionModel::WilliamsMax, hov::SegmentMethod::Approximate);
}

void RunLinearScalar(benchmark::State& state, hov::OpacitySemantics semantics)
{
  // 10 nodes: colour and opacity nodes at the same 10 positions.
  const hov::TransferFunction tf = hovBench::TenNodeTable(semantics);
  std::mt19937_64 rng(778);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  struct Ray
  {
    double S0, S1, L;
  };
  std::vector<Ray> rays(N);
  for (Ray& r : rays)
  {
    r = { u01(rng), u01(rng), 0.05 + 0.5 * u01(rng) };
  }
  hov::IntegrationSettings settings;
  size_t i = 0;
  int64_t pieces = 0;
  for (auto _ : state)
  {
    const Ray& r = rays[i++ & Mask];
    int p = 0;
    benchmark::DoNotOptimize(hov::IntegrateLinearScalar(tf, r.S0, r.S1, r.L, settings, &p));
    pieces += p;
  }
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations()));
  state.counters["table_nodes"] = tf.GetNumberOfNodes();
  state.counters["pieces_per_ray"] = benchmark::Counter(static_cast<double>(pieces) / state.iterations());
  // Seconds per piece, shown with an SI prefix (e.g. 30n = 30 ns).
  state.counters["time_per_piece"] = benchmark::Counter(static_cast<double>(pieces),
    benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  state.SetLabel("ns/ray = Time");
}

void LinearScalar_10Nodes(benchmark::State& state)
{
  RunLinearScalar(state, hov::OpacitySemantics::VTKUnstructured);
}
void LinearScalar_GPU_10Nodes(benchmark::State& state)
{
  RunLinearScalar(state, hov::OpacitySemantics::GPUCompatible);
}

void Batch_WM_Tile(benchmark::State& state)
{
  const hov::TransferFunction tf = hovBench::TenNodeTable(hov::OpacitySemantics::VTKUnstructured);
  std::mt19937_64 rng(779);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  std::vector<hov::SegmentJob> jobs(N);
  for (hov::SegmentJob& job : jobs)
  {
    job.Interval = static_cast<int>(9 * u01(rng)) % 9;
    const double x0 = job.Interval / 9.0, w = 1.0 / 9.0;
    job.SFront = x0 + w * (0.01 + 0.98 * u01(rng));
    job.SBack = x0 + w * (0.01 + 0.98 * u01(rng));
    job.Length = std::exp(std::log(1e-3) + (std::log(0.2) - std::log(1e-3)) * u01(rng));
  }
  constexpr int Block = 256;
  std::vector<hov::RGBA> out(Block);
  std::vector<int> pieces(Block);
  hov::SegmentBatch batch;
  hov::IntegrationSettings settings;
  size_t i = 0;
  for (auto _ : state)
  {
    batch.Integrate(tf, settings, jobs.data() + (i & Mask), Block, out.data(), pieces.data());
    benchmark::DoNotOptimize(out.data());
    i += Block;
  }
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations()) * Block);
  state.SetLabel("ns/segment = 1/items_per_second");
}
}

BENCHMARK(Exact_WM_Mix);
BENCHMARK(Exact_WM_Thin);
BENCHMARK(Exact_WM_ClosedForm);
BENCHMARK(Exact_WVG_Mix);
BENCHMARK(Approximate_WM_Mix);
BENCHMARK(LinearScalar_10Nodes);
BENCHMARK(LinearScalar_GPU_10Nodes);
BENCHMARK(Batch_WM_Tile);
