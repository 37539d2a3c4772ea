#include "hovSegmentBatchLanes.h"

#include <cstring> // memcpy into vector registers
#include <type_traits> // integral_constant
#include <utility>     // integer_sequence (one unrolled series per term count)

namespace hov
{
namespace detail
{
inline namespace HOV_LANES_NAMESPACE
{
// With GCC or Clang on x86-64 (HOV_FMA_CLONES) the lane loops are also
// compiled for FMA3 (with it AVX: four lanes per instruction), chosen at load
// time by the same test as FusedSeries(), and, where the compiler knows
// x86-64-v3 as a clone (GCC 12, Clang 18), for x86-64-v3 (AVX2 and more: 4-6%
// faster in the batch, hovBenchSegment), chosen first where the CPU has it.
// Every variant performs the same IEEE operations: the kernels are compiled
// with -ffp-contract=off (Kernels/CMakeLists.txt), so the only fused
// multiply-adds are the thin series' explicit ones (FusedMulAdd, used where
// FusedSeries() says so, as in the scalar kernel, hence only in the FMA
// variants in practice). So the result does not depend on which one runs.
//
// A test build of one variant (HOV_LANES_ONLY, see hovSegmentBatchLanes.h):
// the same functions with what target_clones gives that clone.
#if defined(HOV_LANES_ONLY) && HOV_LANES_ONLY == 1
#define HOV_LANES_TARGET_CLONES
#elif defined(HOV_LANES_ONLY) && HOV_LANES_ONLY == 2
#if HOV_FMA_CLONES
#define HOV_LANES_TARGET_CLONES __attribute__((target("fma")))
#else
#define HOV_LANES_TARGET_CLONES // no clones here: the module's one variant
#endif
#elif HOV_FMA_CLONES && ((defined(__clang__) && __clang_major__ >= 18) ||                        \
                       (!defined(__clang__) && __GNUC__ >= 12))
#define HOV_LANES_TARGET_CLONES                                                                    \
  __attribute__((target_clones("arch=x86-64-v3", "fma", "default")))
#elif HOV_FMA_CLONES
#define HOV_LANES_TARGET_CLONES __attribute__((target_clones("fma", "default")))
#else
#define HOV_LANES_TARGET_CLONES
#endif

namespace
{
/// Four doubles in a GCC/Clang vector: one AVX instruction, or two SSE2 ones.
typedef double V4 __attribute__((vector_size(4 * sizeof(double))));
static_assert(Lanes == 4, "one V4 per block");

/// The thin series (hovThinSeries.h: ThinWilliamsMaxSeries) of Lanes segments
/// with N terms: each lane's w = WFront (before clamping) and alpha equal the
/// scalar kernel's bit for bit (each Horner step rounded as @p Mad).
template <int N, typename Mad>
inline __attribute__((always_inline)) void ThinWilliamsMaxLanes(
  const double* a, const double* d1, double* w, double* alpha)
{
  V4 va, vd1, vw, valpha;
  std::memcpy(&va, a, sizeof(V4));
  std::memcpy(&vd1, d1, sizeof(V4));
  ThinWilliamsMaxSeries<N, Mad>(va, vd1, vw, valpha);
  std::memcpy(w, &vw, sizeof(V4));
  std::memcpy(alpha, &valpha, sizeof(V4));
}

/// ThinWilliamsMaxLanes<N, Mad>() on @p blocks consecutive blocks of Lanes segments.
template <int N, typename Mad>
inline __attribute__((always_inline)) void ThinBlocks(
  const double* a, const double* d1, int blocks, double* w, double* alpha)
{
  for (int b = 0; b < blocks; ++b)
  {
    ThinWilliamsMaxLanes<N, Mad>(a + b * Lanes, d1 + b * Lanes, w + b * Lanes, alpha + b * Lanes);
  }
}

/// @p f(std::integral_constant<int, terms>()) for the run-time number of
/// series terms 1 <= @p terms <= MaxThinOrder: each count is its own fully
/// unrolled series, chosen once per call (a group of lanes, or a block).
template <typename F, int... N>
inline __attribute__((always_inline)) void ForTermCount(
  int terms, const F& f, std::integer_sequence<int, N...>)
{
  // Exactly one N + 1 equals terms.
  (void)((terms == N + 1 ? (f(std::integral_constant<int, N + 1>()), true) : false) || ...);
}

template <typename F>
inline __attribute__((always_inline)) void ForTermCount(int terms, const F& f)
{
  ForTermCount(terms, f, std::make_integer_sequence<int, MaxThinOrder>());
}

/**
 * ThinWilliamsMaxSeries()'s keep for four lanes that need different numbers
 * of terms: lane l takes term n iff @p AtLeast[n] <= d1[l]
 * (ThinTermByExponent::AtLeast: iff it has n terms or more), else an exact
 * zero. So each lane equals the scalar kernel with its own number of terms,
 * bit for bit, and a block of mixed term counts needs no sorting.
 */
struct KeepOwnTerms
{
  const V4& D1;
  const double* AtLeast;
  void operator()(int n, V4& c) const { c = this->AtLeast[n] <= this->D1 ? c : V4{}; }
};

/**
 * EvaluatePiece() and the thin series for the Lanes segments from @p i, all
 * in the same interior interval @p k (0 <= k < n - 1), side by side: per lane
 * TransferFunction::Evaluate()'s operations on node k, then the depths and
 * the thin test (std::min/max as (b < a ? b : a)/(a < b ? b : a), isfinite as
 * x - x == 0), the series with each lane's own number of terms
 * (KeepOwnTerms) and WriteThin()'s weights and colours, so each
 * lane's RGBA is the scalar code's. Writes @p out and returns true only if
 * every segment is valid and thin (the caller takes the others one by one):
 * nothing of these lanes is left for the sorted series.
 */
template <typename Mad>
inline __attribute__((always_inline)) bool EvaluateBlock(const TransferFunction& tf, int k,
  const SegmentBatch::Arrays& jobs, int i, const ThinTermByExponent& thinTerms,
  const SegmentBatch::ThinArrays& t, RGBA* out)
{
  const double* x = tf.GetNodes().data();
  const double x0 = x[k], width = x[k + 1] - x[k];
  const TransferFunction::Node& node = tf.GetNode(k);
  V4 s0, s1, length;
  std::memcpy(&s0, jobs.SFront + i, sizeof(V4));
  std::memcpy(&s1, jobs.SBack + i, sizeof(V4));
  std::memcpy(&length, jobs.Length + i, sizeof(V4));
  const V4 zero = {};
  // ds = std::min(std::max(s - x0, 0.0), width) at both ends.
  const V4 d0 = s0 - x0, d1s = s1 - x0;
  const V4 above0 = d0 < 0.0 ? zero : d0, above1 = d1s < 0.0 ? zero : d1s;
  const V4 ds0 = width < above0 ? zero + width : above0;
  const V4 ds1 = width < above1 ? zero + width : above1;
  const V4 tau0 = node.Tau + node.DTau * ds0;
  const V4 tau1 = node.Tau + node.DTau * ds1;
  const V4 depthFront = (tau0 < 0.0 ? zero : tau0) * length;
  const V4 depthBack = (tau1 < 0.0 ? zero : tau1) * length;
  const V4 a = DepthCap < depthFront ? zero + DepthCap : depthFront;
  const V4 c = DepthCap < depthBack ? zero + DepthCap : depthBack;
  const V4 d1 = 0.5 * (a + c);
  const auto valid = (length > 0.0) & (s0 - s0 == 0.0) & (s1 - s1 == 0.0);
  const auto thin = valid & (depthFront - depthFront == 0.0) & (depthBack - depthBack == 0.0) &
    (d1 > 0.0) & (d1 <= ThinDepth);
  if (!(thin[0] & thin[1] & thin[2] & thin[3]))
  {
    return false;
  }
  // The block's number of terms: that of its deepest lane (the count grows with d1).
  const double deepest = std::max(std::max(d1[0], d1[1]), std::max(d1[2], d1[3]));
  V4 w, alpha;
  const KeepOwnTerms keep{ d1, thinTerms.AtLeast };
  ForTermCount(thinTerms(deepest), [&](auto n) __attribute__((always_inline)) {
    ThinWilliamsMaxSeries<decltype(n)::value, Mad>(a, d1, w, alpha, keep);
  });
  // WriteThin(): wf = std::max(0.0, w), wb = std::max(0.0, alpha - w).
  const V4 back = alpha - w;
  const V4 wf = 0.0 < w ? w : zero;
  const V4 wb = 0.0 < back ? back : zero;
  const double base[3] = { node.R, node.G, node.B };
  const double slope[3] = { node.DR, node.DG, node.DB };
  V4 rgb[3];
  for (int ch = 0; ch < 3; ++ch)
  {
    const V4 f = base[ch] + slope[ch] * ds0;
    const V4 b = base[ch] + slope[ch] * ds1;
    rgb[ch] = wf * f + wb * b;
  }
  for (int l = 0; l < Lanes; ++l)
  {
    out[i + l] = RGBA{ rgb[0][l], rgb[1][l], rgb[2][l], alpha[l] };
  }
  return true;
}

}

/// The thin series of @p blocks blocks of Lanes segments, all with @p terms
/// terms, each step rounded as FusedSeries() says.
HOV_LANES_TARGET_CLONES
void ThinWilliamsMaxBlocks(
  int terms, const double* a, const double* d1, int blocks, double* w, double* alpha)
{
  const bool fused = FusedSeries();
  ForTermCount(terms, [&](auto n) __attribute__((always_inline)) {
    if (fused)
    {
      ThinBlocks<decltype(n)::value, FusedMulAdd>(a, d1, blocks, w, alpha);
    }
    else
    {
      ThinBlocks<decltype(n)::value, SeparateMulAdd>(a, d1, blocks, w, alpha);
    }
  });
}

/**
 * With the nodes sorted, the largest k with X[k] <= s is #{X <= s} - 1 and
 * the largest with X[k] < s is #{X < s} - 1 (FindIntervalUpward / Downward,
 * wherever a walk would start). With lo and hi the segment's smaller and
 * larger end, an upward segment (sBack - sFront >= 0, starting at lo) starts
 * in #{X <= lo} - 1, a downward one in #{X < hi} - 1, and either stays in its
 * interval iff no node lies strictly between its ends: #{X < hi} <= #{X <= lo}.
 * So two comparisons per node and block, exact counts in doubles, and no
 * branch per segment. Compiled also for FMA3 (and AVX).
 */
HOV_LANES_TARGET_CLONES
int CountIntervals(const double* x, int n, const SegmentBatch::Arrays& jobs, int count,
  int* resolved, int* splitStart, int* left)
{
  int numLeft = 0;
  int i = 0;
  for (; i + Lanes <= count; i += Lanes)
  {
    const int* interval = jobs.Interval + i;
    std::memcpy(resolved + i, interval, Lanes * sizeof(int));
    const int unknown = (interval[0] < -1) + (interval[1] < -1) + (interval[2] < -1) +
      (interval[3] < -1);
    if (unknown == 0)
    {
      continue; // the common case: a cell inside one interval
    }
    V4 front, back, length;
    std::memcpy(&front, jobs.SFront + i, sizeof(V4));
    std::memcpy(&back, jobs.SBack + i, sizeof(V4));
    std::memcpy(&length, jobs.Length + i, sizeof(V4));
    const auto valid = (length > 0.0) & (front - front == 0.0) & (back - back == 0.0);
    if (unknown < Lanes || !(valid[0] & valid[1] & valid[2] & valid[3]) || n == 0 ||
      n > MaxCountedNodes)
    {
      for (int l = i; l < i + Lanes; ++l)
      {
        left[numLeft] = l;
        numLeft += resolved[l] < -1;
      }
      continue;
    }
    const auto up = back - front >= 0.0;
    const V4 lo = up ? front : back, hi = up ? back : front;
    const V4 zero = {}, one = zero + 1.0;
    V4 atOrBelowLo = zero, belowHi = zero;
    for (int j = 0; j < n; ++j)
    {
      atOrBelowLo += x[j] <= lo ? one : zero;
      belowHi += x[j] < hi ? one : zero;
    }
    const V4 start = (up ? atOrBelowLo : belowHi) - 1.0;
    const auto stays = belowHi <= atOrBelowLo;
    for (int l = 0; l < Lanes; ++l)
    {
      const int k = static_cast<int>(start[l]);
      resolved[i + l] = stays[l] ? k : NeedsSplit;
      splitStart[i + l] = k;
      left[numLeft] = i + l;
      numLeft += stays[l] ? 0 : 1;
    }
  }
  for (; i < count; ++i)
  {
    resolved[i] = jobs.Interval[i];
    left[numLeft] = i;
    numLeft += resolved[i] < -1;
  }
  return numLeft;
}

namespace
{
/// EvaluatePiece() for segment @p i if it is valid (the early return of
/// IntegrateLinearScalarInInterval() otherwise); none if resolved[i] is @p skip.
inline __attribute__((always_inline)) void EvaluateSegment(const TransferFunction& tf,
  const int* resolved, int skip, const SegmentBatch::Arrays& jobs, int i,
  const ThinTermByExponent& thinTerms, const SegmentBatch::ThinArrays& t, RGBA* out)
{
  const double s0 = jobs.SFront[i], s1 = jobs.SBack[i], length = jobs.Length[i];
  if (resolved[i] == skip || !(length > 0.0) || !std::isfinite(s0) || !std::isfinite(s1))
  {
    if (resolved[i] != skip)
    {
      out[i] = RGBA();
    }
    return;
  }
  EvaluatePiece(tf, resolved[i], s0, s1, length, thinTerms, t, i, out[i]);
}

/// EvaluateSegments() with the series' steps rounded as @p Mad.
template <typename Mad>
inline __attribute__((always_inline)) void EvaluateSegmentsWith(const TransferFunction& tf,
  const int* resolved, int skip, const SegmentBatch::Arrays& jobs, int count,
  const SegmentBatch::ThinArrays& t, RGBA* out)
{
  const ThinTermByExponent& thinTerms = ThinTerms();
  const int last = tf.GetNumberOfNodes() - 2; // the last interior interval
  int i = 0;
  for (; i + Lanes <= count; i += Lanes)
  {
    const int k = resolved[i];
    const bool same = (resolved[i + 1] == k) & (resolved[i + 2] == k) & (resolved[i + 3] == k);
    if (same && k >= 0 && k <= last && EvaluateBlock<Mad>(tf, k, jobs, i, thinTerms, t, out))
    {
      continue;
    }
    for (int l = i; l < i + Lanes; ++l)
    {
      EvaluateSegment(tf, resolved, skip, jobs, l, thinTerms, t, out);
    }
  }
  for (; i < count; ++i)
  {
    EvaluateSegment(tf, resolved, skip, jobs, i, thinTerms, t, out);
  }
}
}

/// EvaluateSegments(): blocks through EvaluateBlock(). Compiled also for FMA3 (and AVX).
HOV_LANES_TARGET_CLONES
void EvaluateSegments(const TransferFunction& tf, const int* resolved, int skip,
  const SegmentBatch::Arrays& jobs, int count, const SegmentBatch::ThinArrays& t, RGBA* out)
{
  if (FusedSeries())
  {
    EvaluateSegmentsWith<FusedMulAdd>(tf, resolved, skip, jobs, count, t, out);
  }
  else
  {
    EvaluateSegmentsWith<SeparateMulAdd>(tf, resolved, skip, jobs, count, t, out);
  }
}
}
}
}
