#include "hovOpacityRefinement.h"

#include <algorithm> // std::max, std::sort
#include <cmath>     // log, log1p
#include <queue>     // priority_queue

namespace hov
{
namespace
{
// Samples per piece for the chord error (see file doc).
constexpr int ChordSamples = 33;

struct Piece
{
  int Interval;
  double S0, A0, P0, S1, A1, P1;
  double Error;
  bool operator<(const Piece& o) const { return this->Error < o.Error; }
};

/// Largest relative error of the chord of tau over a piece (a, p linear in s).
double ChordError(const Piece& pc, double invUnit)
{
  if (pc.A0 == pc.A1)
  {
    return 0.0;
  }
  const double t0 = GPUExtinction(pc.A0, pc.P0, invUnit);
  const double t1 = GPUExtinction(pc.A1, pc.P1, invUnit);
  double worst = 0.0;
  // At a zero end, chord/tau -> (chord slope in a) / (tau'(0) = 1/u).
  if (t0 == 0.0)
  {
    worst = std::max(worst, t1 / (pc.A1 * invUnit) - 1.0);
  }
  if (t1 == 0.0)
  {
    worst = std::max(worst, t0 / (pc.A0 * invUnit) - 1.0);
  }
  for (int j = 1; j < ChordSamples; ++j)
  {
    const double w = static_cast<double>(j) / ChordSamples;
    const double exact = GPUExtinction(pc.A0 + (pc.A1 - pc.A0) * w, pc.P0 + (pc.P1 - pc.P0) * w, invUnit);
    const double chord = t0 + (t1 - t0) * w;
    worst = std::max(worst, std::abs(chord - exact) / exact);
  }
  return worst;
}
}

double GPUExtinction(double a, double p, double invUnit)
{
  if (p <= OpaqueClamp)
  {
    return -std::log(OpaqueClamp) * invUnit;
  }
  // log1p(-a) is accurate for small a, log(p) for p = 1 - a small.
  return (a < 0.5 ? -std::log1p(-a) : -std::log(p)) * invUnit;
}

RefinementResult RefineGPUExtinction(
  const std::vector<OpacityInterval>& intervals, double unit, double tol, int budget)
{
  const double invUnit = 1.0 / unit;
  RefinementResult result;
  result.Interior.resize(intervals.size());
  std::priority_queue<Piece> heap;
  std::vector<Piece> done;
  for (size_t i = 0; i < intervals.size(); ++i)
  {
    const OpacityInterval& iv = intervals[i];
    Piece pc{ static_cast<int>(i), iv.S0, iv.A0, 1.0 - iv.A0, iv.S1, iv.A1, 1.0 - iv.A1, 0.0 };
    pc.Error = ChordError(pc, invUnit);
    heap.push(pc);
  }
  while (!heap.empty())
  {
    Piece pc = heap.top();
    if (pc.Error <= tol)
    {
      break; // every remaining piece meets the tolerance
    }
    const double sm = 0.5 * (pc.S0 + pc.S1);
    if (result.Added >= budget || !(sm > pc.S0 && sm < pc.S1))
    {
      result.Exhausted = result.Exhausted || result.Added >= budget;
      heap.pop();
      done.push_back(pc); // cannot be split further
      continue;
    }
    heap.pop();
    const double am = 0.5 * (pc.A0 + pc.A1), pm = 0.5 * (pc.P0 + pc.P1);
    Piece left{ pc.Interval, pc.S0, pc.A0, pc.P0, sm, am, pm, 0.0 };
    Piece right{ pc.Interval, sm, am, pm, pc.S1, pc.A1, pc.P1, 0.0 };
    left.Error = ChordError(left, invUnit);
    right.Error = ChordError(right, invUnit);
    heap.push(left);
    heap.push(right);
    ++result.Added;
  }
  while (!heap.empty())
  {
    done.push_back(heap.top());
    heap.pop();
  }
  std::sort(done.begin(), done.end(), [](const Piece& p, const Piece& q) {
    return p.Interval != q.Interval ? p.Interval < q.Interval : p.S0 < q.S0;
  });
  for (const Piece& pc : done)
  {
    result.WorstError = std::max(result.WorstError, pc.Error);
    if (pc.S1 < intervals[pc.Interval].S1)
    {
      result.Interior[pc.Interval].emplace_back(pc.S1, GPUExtinction(pc.A1, pc.P1, invUnit));
    }
  }
  return result;
}
}
