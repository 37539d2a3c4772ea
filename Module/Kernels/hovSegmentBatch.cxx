#include "hovSegmentBatch.h"

#include "hovThinSeries.h"       // the scalar kernel's series and term counts
#include "hovTransferFunction.h" // Evaluate, interval search

#include <algorithm> // std::max, std::min
#include <cmath>     // std::isfinite
#include <cstring>   // memcpy into vector registers
#include <utility>   // integer_sequence (one unrolled series per term count)

namespace hov
{
namespace
{
using detail::Thin;

/// Segments evaluated side by side (a multiple of the SIMD width the
/// compiler vectorises the lane loops to: 2 for SSE2, 4 for AVX).
constexpr int Lanes = 4;

// With GCC or Clang on x86-64 the lane loops are also compiled for AVX2 (four
// lanes per instruction) and the variant is chosen at load time; both variants
// perform the same IEEE operations (the "avx2" target does not enable FMA, so
// nothing is contracted into fused multiply-adds; -std=c++17 alone would not
// prevent it: GCC 12 contracts wherever FMA is enabled), so the result does
// not depend on the CPU.
#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__)) && !defined(__APPLE__)
#define HOV_LANES_TARGET_CLONES __attribute__((target_clones("avx2", "default")))
#else
#define HOV_LANES_TARGET_CLONES
#endif

/// Four doubles in a GCC/Clang vector: one AVX2 instruction, or two SSE2 ones.
typedef double V4 __attribute__((vector_size(4 * sizeof(double))));
static_assert(Lanes == 4, "one V4 per block");

/**
 * The thin Williams-Max series of hovSegmentIntegral.cxx (ThinWilliamsMax<N>)
 * with N terms for Lanes segments: the same operations in the same order per
 * lane, so each lane's w = WFront (before clamping) and alpha equal the
 * scalar kernel's bit for bit. N is a compile-time constant, so that both
 * loops unroll completely (no loop overhead, independent chains interleaved).
 */
template <int N>
inline __attribute__((always_inline)) void ThinWilliamsMaxLanes(
  const double* a, const double* d1, double* w, double* alpha)
{
  V4 va, vd1;
  std::memcpy(&va, a, sizeof(V4));
  std::memcpy(&vd1, d1, sizeof(V4));
  const V4 r = va / vd1;
  const V4 d2 = vd1 * vd1;
  V4 wOdd = {}, wEven = {}, aOdd = {}, aEven = {};
#pragma GCC unroll 16
  for (int n = N; n >= 1; --n)
  {
    // q_n(r) = sum_j P0[n][n-j] r^j by Horner's rule (the scalar kernel's q[n]).
    const double* p = Thin.P0[n];
    V4 h = V4{} + p[0];
#pragma GCC unroll 16
    for (int j = 1; j <= n; ++j)
    {
      h = h * r + p[j];
    }
    // Outer Horner chains in d1^2 on odd and even terms.
    const double f = Thin.InvFactorial[n];
    if (n % 2)
    {
      wOdd = wOdd * d2 + h;
      aOdd = aOdd * d2 + f;
    }
    else
    {
      wEven = wEven * d2 + h;
      aEven = aEven * d2 + f;
    }
  }
  const V4 vw = vd1 * wOdd - d2 * wEven;
  const V4 valpha = vd1 * aOdd - d2 * aEven;
  std::memcpy(w, &vw, sizeof(V4));
  std::memcpy(alpha, &valpha, sizeof(V4));
}

/// ThinWilliamsMaxLanes<N>() on @p blocks consecutive blocks of Lanes segments.
template <int N>
inline __attribute__((always_inline)) void ThinBlocks(
  const double* a, const double* d1, int blocks, double* w, double* alpha)
{
  for (int b = 0; b < blocks; ++b)
  {
    ThinWilliamsMaxLanes<N>(a + b * Lanes, d1 + b * Lanes, w + b * Lanes, alpha + b * Lanes);
  }
}

/// ThinBlocks<N>() for the run-time N = @p terms (one call per group of
/// equal term counts: one dispatch per group, not per block).
template <int... N>
inline __attribute__((always_inline)) void ThinBlocksDispatch(int terms, const double* a,
  const double* d1, int blocks, double* w, double* alpha, std::integer_sequence<int, N...>)
{
  // Exactly one N + 1 equals terms (1 <= terms <= MaxThinOrder).
  (void)((terms == N + 1 ? (ThinBlocks<N + 1>(a, d1, blocks, w, alpha), true) : false) || ...);
}

/// The thin series of @p blocks blocks of Lanes segments, all with @p terms terms.
HOV_LANES_TARGET_CLONES
void ThinWilliamsMaxBlocks(
  int terms, const double* a, const double* d1, int blocks, double* w, double* alpha)
{
  ThinBlocksDispatch(
    terms, a, d1, blocks, w, alpha, std::make_integer_sequence<int, detail::MaxThinOrder>());
}
}

long long SegmentBatch::Integrate(const TransferFunction& tf, const IntegrationSettings& settings,
  const SegmentJob* jobs, int count, RGBA* out, int* piecesOut)
{
  const bool batched =
    settings.Emission == EmissionModel::WilliamsMax && settings.Method == SegmentMethod::Exact;
  long long total = 0;
  auto count1 = [&](int i, int p) {
    total += p;
    if (piecesOut)
    {
      piecesOut[i] = p;
    }
  };
  if (this->Items.size() < static_cast<size_t>(count))
  {
    this->Items.resize(count); // grows only: no allocation in steady state
    this->Order.resize(count);
  }
  int numItems = 0;
  int perTerms[detail::MaxThinOrder + 2] = {};
  const detail::ThinTermByExponent& thinTerms = detail::ThinTerms();
  for (int i = 0; i < count; ++i)
  {
    const SegmentJob& job = jobs[i];
    int k = job.Interval;
    if (k < -1)
    {
      // IntegrateLinearScalar(): nothing for invalid input, a walk over the
      // intervals if the segment crosses a node, else one piece in k.
      if (!(job.Length > 0.0) || !std::isfinite(job.SFront) || !std::isfinite(job.SBack) ||
        tf.GetNumberOfNodes() == 0)
      {
        out[i] = RGBA();
        count1(i, 0);
        continue;
      }
      k = OnePieceInterval(tf, job.SFront, job.SBack);
      if (k < -1)
      {
        int p = 0;
        out[i] = IntegrateLinearScalar(tf, job.SFront, job.SBack, job.Length, settings, &p);
        count1(i, p);
        continue;
      }
    }
    count1(i, 1);
    if (!batched || !(job.Length > 0.0) || !std::isfinite(job.SFront) || !std::isfinite(job.SBack))
    {
      out[i] = IntegrateLinearScalarInInterval(tf, k, job.SFront, job.SBack, job.Length, settings);
      continue;
    }
    // IntegrateLinearScalarInInterval() -> IntegrateSegment() -> ExactSegmentWeights(),
    // taking the thin branch aside for the lanes.
    // Evaluated straight into the next item's slot (taken only if the segment
    // is thin): copying a SegmentEnd off the stack stalled on store forwarding.
    ThinItem& item = this->Items[numItems];
    const SegmentEnd& front = item.Front;
    const SegmentEnd& back = item.Back;
    tf.Evaluate(k, job.SFront, false, item.Front);
    tf.Evaluate(k, job.SBack, false, item.Back);
    const double depthFront = std::max(front.Tau, 0.0) * job.Length;
    const double depthBack = std::max(back.Tau, 0.0) * job.Length;
    const double a = std::min(depthFront, detail::DepthCap);
    const double c = std::min(depthBack, detail::DepthCap);
    const double d1 = 0.5 * (a + c);
    if (!std::isfinite(depthFront) || !std::isfinite(depthBack) || !(d1 > 0.0) ||
      d1 > detail::ThinDepth)
    {
      out[i] = IntegrateSegment(job.Length, front, back, settings.Emission, settings.Method);
      continue;
    }
    ++numItems;
    item.A = a;
    item.D1 = d1;
    item.Index = i;
    item.Terms = thinTerms(d1);
    ++perTerms[item.Terms + 1];
  }

  // Group the thin segments by number of terms (counting sort), their depths
  // contiguous, then each group Lanes at a time (lanes are independent: the
  // grouping does not change any result).
  for (int t = 0; t <= detail::MaxThinOrder; ++t)
  {
    perTerms[t + 1] += perTerms[t];
  }
  int groupStart[detail::MaxThinOrder + 2];
  std::copy(perTerms, perTerms + detail::MaxThinOrder + 2, groupStart);
  if (this->SortedA.size() < static_cast<size_t>(numItems + Lanes))
  {
    this->SortedA.resize(numItems + Lanes);
    this->SortedD1.resize(numItems + Lanes);
  }
  for (int n = 0; n < numItems; ++n)
  {
    const ThinItem& item = this->Items[n];
    const int pos = perTerms[item.Terms]++;
    this->Order[pos] = n;
    this->SortedA[pos] = item.A;
    this->SortedD1[pos] = item.D1;
  }
  if (this->W.size() < static_cast<size_t>(numItems + Lanes))
  {
    this->W.resize(numItems + Lanes);
    this->Alpha.resize(numItems + Lanes);
  }
  for (int terms = 1; terms <= detail::MaxThinOrder; ++terms)
  {
    const int first = groupStart[terms], last = groupStart[terms + 1];
    const int full = (last - first) / Lanes;
    ThinWilliamsMaxBlocks(terms, this->SortedA.data() + first, this->SortedD1.data() + first,
      full, this->W.data() + first, this->Alpha.data() + first);
    const int tail = first + full * Lanes;
    if (tail < last)
    {
      double a[Lanes], d1[Lanes];
      for (int l = 0; l < Lanes; ++l)
      {
        a[l] = tail + l < last ? this->SortedA[tail + l] : 0.0; // padding: any valid thin segment
        d1[l] = tail + l < last ? this->SortedD1[tail + l] : 1.0 / 8.0;
      }
      double w[Lanes], alpha[Lanes];
      ThinWilliamsMaxBlocks(terms, a, d1, 1, w, alpha);
      std::copy(w, w + (last - tail), this->W.data() + tail);
      std::copy(alpha, alpha + (last - tail), this->Alpha.data() + tail);
    }
  }
  for (int m = 0; m < numItems; ++m)
  {
    const ThinItem& item = this->Items[this->Order[m]];
    // As ThinWeights() and IntegrateSegment().
    const double wf = std::max(0.0, this->W[m]);
    const double wb = std::max(0.0, this->Alpha[m] - this->W[m]);
    RGBA& o = out[item.Index];
    o.A = this->Alpha[m];
    o.R = wf * item.Front.Color[0] + wb * item.Back.Color[0];
    o.G = wf * item.Front.Color[1] + wb * item.Back.Color[1];
    o.B = wf * item.Front.Color[2] + wb * item.Back.Color[2];
  }
  return total;
}
}
