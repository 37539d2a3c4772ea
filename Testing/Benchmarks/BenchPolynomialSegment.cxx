// Google Benchmark of hovPolynomialSegment / hovPolynomial: nanoseconds per
// segment (one iteration = one segment, taken round-robin from 4096
// pre-generated inputs, fixed seed), to compare with LinearScalar_10Nodes of
// BenchSegmentIntegral.cxx (same 10-node table, same lengths).
//  - Quadratic_WM / Quadratic_WVG: s(t) quadratic with values in [0,1] and an
//    interior extremum in half of the segments, IntegratePolynomialScalar at
//    the default tolerance 1e-9 (counters: pieces and quadrature panels per
//    segment);
//  - Cubic_WM: cubic fields (a trilinear hexahedron's restriction);
//  - Linear_WM_ViaPolynomial: degree-1 input (delegates to IntegrateLinearScalar);
//  - FindRoots_Quadratic / FindRoots_Cubic: one root isolation on [0, 1];
//  - RefinedTable/<tolerance exponent>/<route>: the 10-node table refined to
//    GPUTolerance 1e-8 (GPU-compatible, thousands of nodes), quadratic fields
//    with values in [0, 1]; route 0 = default (past MaxPanels / 2 crossings
//    the sampled route is tried first), 1 = the exact walk forced (MaxPanels
//    large enough for every crossing). Counter sampled_fraction: segments
//    the sampled route took.

#include "hovPolynomial.h"
#include "hovPolynomialSegment.h"
#include "hovTransferFunction.h"

#include "hovBenchTables.h" // the shared 10-node table

#include <benchmark/benchmark.h>

#include <cmath> // pow
#include <random>
#include <vector>

namespace
{
constexpr size_t N = 4096; // power of two
constexpr size_t Mask = N - 1;

hov::TransferFunction Table()
{
  return hovBench::TenNodeTable(hov::OpacitySemantics::VTKUnstructured);
}

struct Segment
{
  hov::Polynomial S;
  double L;
};

/// Fields of the given degree with values in [0, 1] on [0, L]: Lagrange
/// interpolation of random values at equispaced points.
std::vector<Segment> Segments(int degree)
{
  std::mt19937_64 rng(4242);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  std::vector<Segment> out(N);
  for (Segment& seg : out)
  {
    seg.L = 0.05 + 0.5 * u01(rng);
    std::vector<double> x(degree + 1), v(degree + 1);
    for (int i = 0; i <= degree; ++i)
    {
      x[i] = degree ? seg.L * i / degree : 0.0;
      v[i] = u01(rng);
    }
    // Newton form -> monomial coefficients.
    std::vector<double> c(v);
    for (int j = 1; j <= degree; ++j)
    {
      for (int i = degree; i >= j; --i)
      {
        c[i] = (c[i] - c[i - 1]) / (x[i] - x[i - j]);
      }
    }
    hov::Polynomial p;
    p.Degree = degree;
    p.C[0] = c[degree];
    for (int k = degree - 1; k >= 0; --k)
    {
      // p <- p (t - x_k) + c_k
      for (int i = degree - k; i >= 1; --i)
      {
        p.C[i] = p.C[i - 1] - x[k] * p.C[i];
      }
      p.C[0] = -x[k] * p.C[0] + c[k];
    }
    seg.S = p;
  }
  return out;
}

/// IntegratePolynomialScalar on the segments of @p degree, one per iteration.
void RunSegments(benchmark::State& state, const hov::TransferFunction& tf, int degree,
  const hov::PolynomialSegmentSettings& settings)
{
  const std::vector<Segment> segs = Segments(degree);
  size_t i = 0;
  int64_t pieces = 0, panels = 0, sampled = 0;
  for (auto _ : state)
  {
    const Segment& s = segs[i++ & Mask];
    const hov::PolynomialSegmentResult r = hov::IntegratePolynomialScalar(tf, s.S, s.L, settings);
    benchmark::DoNotOptimize(r);
    pieces += r.Pieces;
    panels += r.Panels;
    sampled += r.Sampled;
  }
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations()));
  state.counters["pieces_per_segment"] = static_cast<double>(pieces) / state.iterations();
  state.counters["panels_per_segment"] = static_cast<double>(panels) / state.iterations();
  if (sampled > 0 || tf.GetNumberOfNodes() > 1000)
  {
    state.counters["sampled_fraction"] = static_cast<double>(sampled) / state.iterations();
  }
  state.SetLabel("ns/segment = Time");
}

void RunSegments(benchmark::State& state, int degree, hov::EmissionModel model)
{
  hov::PolynomialSegmentSettings settings;
  settings.Emission = model;
  RunSegments(state, Table(), degree, settings);
}

void Quadratic_WM(benchmark::State& state)
{
  RunSegments(state, 2, hov::EmissionModel::WilliamsMax);
}
void Quadratic_WVG(benchmark::State& state)
{
  RunSegments(state, 2, hov::EmissionModel::WilhelmsVanGelder);
}
void Cubic_WM(benchmark::State& state)
{
  RunSegments(state, 3, hov::EmissionModel::WilliamsMax);
}
void Linear_WM_ViaPolynomial(benchmark::State& state)
{
  RunSegments(state, 1, hov::EmissionModel::WilliamsMax);
}

void RefinedTable(benchmark::State& state)
{
  hov::TransferFunctionSpec spec = hovBench::TenNodeSpec(hov::OpacitySemantics::GPUCompatible);
  spec.GPUTolerance = 1e-8;
  spec.RefinementBudget = 16384;
  hov::TransferFunction tf;
  tf.Build(spec);
  hov::PolynomialSegmentSettings settings;
  settings.Tolerance = std::pow(10.0, -static_cast<double>(state.range(0)));
  if (state.range(1))
  {
    settings.MaxPanels = 1 << 20;
  }
  state.counters["table_nodes"] = tf.GetNumberOfNodes();
  RunSegments(state, tf, 2, settings);
}

void RunRoots(benchmark::State& state, int degree)
{
  const std::vector<Segment> segs = Segments(degree);
  size_t i = 0;
  double roots[hov::Polynomial::MaxDegree];
  for (auto _ : state)
  {
    const Segment& s = segs[i++ & Mask];
    benchmark::DoNotOptimize(hov::FindRoots(s.S, 0.5, 0.0, s.L, roots));
  }
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations()));
}
void FindRoots_Quadratic(benchmark::State& state)
{
  RunRoots(state, 2);
}
void FindRoots_Cubic(benchmark::State& state)
{
  RunRoots(state, 3);
}
}

BENCHMARK(Quadratic_WM);
BENCHMARK(Quadratic_WVG);
BENCHMARK(Cubic_WM);
BENCHMARK(Linear_WM_ViaPolynomial);
BENCHMARK(FindRoots_Quadratic);
BENCHMARK(FindRoots_Cubic);
BENCHMARK(RefinedTable)->ArgsProduct({ { 9, 6 }, { 0, 1 } });
