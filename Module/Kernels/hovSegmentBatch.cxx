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
  const SegmentJob* jobs, int count, RGBA* out, int* pieces)
{
  this->JobS.resize(2 * static_cast<size_t>(count) + 1);
  this->JobL.resize(count + 1);
  this->JobK.resize(count + 1);
  for (int i = 0; i < count; ++i)
  {
    this->JobS[i] = jobs[i].SFront;
    this->JobS[count + i] = jobs[i].SBack;
    this->JobL[i] = jobs[i].Length;
    this->JobK[i] = jobs[i].Interval;
  }
  const Arrays arrays{ this->JobS.data(), this->JobS.data() + count, this->JobL.data(),
    this->JobK.data() };
  return this->Integrate(tf, settings, arrays, count, out, pieces);
}

long long SegmentBatch::Integrate(const TransferFunction& tf, const IntegrationSettings& settings,
  const Arrays& jobs, int count, RGBA* out, int* pieces)
{
  if (settings.Emission != EmissionModel::WilliamsMax || settings.Method != SegmentMethod::Exact)
  {
    return this->IntegrateScalar(tf, settings, jobs, count, out, pieces);
  }
  long long total = this->ResolveIntervals(tf, jobs, count, out, pieces);
  this->EvaluateLanes(tf, settings, jobs, count, out);
  this->ThinSeries(count + this->NumPieces);
  this->WriteThin(count, out);
  total += this->CompositeSplits(out, pieces);
  return total;
}

long long SegmentBatch::IntegrateScalar(const TransferFunction& tf,
  const IntegrationSettings& settings, const Arrays& jobs, int count, RGBA* out, int* pieces)
{
  long long total = 0;
  for (int i = 0; i < count; ++i)
  {
    int p = 1;
    if (jobs.Interval[i] >= -1)
    {
      out[i] = IntegrateLinearScalarInInterval(
        tf, jobs.Interval[i], jobs.SFront[i], jobs.SBack[i], jobs.Length[i], settings);
    }
    else
    {
      out[i] = IntegrateLinearScalar(tf, jobs.SFront[i], jobs.SBack[i], jobs.Length[i], settings, &p);
    }
    total += p;
    if (pieces)
    {
      pieces[i] = p;
    }
  }
  return total;
}

/**
 * The interval of each segment (Resolved): its known one, or the one
 * OnePieceInterval() finds; segments crossing nodes are split into Pieces
 * (SplitSegment()) and invalid ones (IntegrateLinearScalar()'s and
 * IntegrateLinearScalarInInterval()'s early returns) written as zero here,
 * both marked Skip. Returns the pieces of the unsplit segments (split ones
 * are counted when composited).
 */
long long SegmentBatch::ResolveIntervals(
  const TransferFunction& tf, const Arrays& jobs, int count, RGBA* out, int* pieces)
{
  this->NumPieces = 0;
  this->Splits.clear();
  this->SplitOut.clear();
  if (this->Resolved.size() < static_cast<size_t>(count))
  {
    this->Resolved.resize(count); // grows only: none in steady state
  }
  int* __restrict resolved = this->Resolved.data();
  const std::vector<double>& nodes = tf.GetNodes();
  const int n = static_cast<int>(nodes.size());
  long long total = 0;
  for (int i = 0; i < count; ++i)
  {
    const double sFront = jobs.SFront[i], sBack = jobs.SBack[i], length = jobs.Length[i];
    const bool valid = length > 0.0 && std::isfinite(sFront) && std::isfinite(sBack);
    int k = jobs.Interval[i];
    int p = 1;
    if (k < -1)
    {
      p = valid && n > 0 ? 1 : 0;
      if (p)
      {
        // OnePieceInterval(), inline; the walk starts from the same interval.
        const bool up = sBack - sFront >= 0.0;
        k = up ? tf.FindIntervalUpward(sFront) : tf.FindIntervalDownward(sFront);
        const bool one =
          up ? (k + 1 >= n || nodes[k + 1] >= sBack) : (k < 0 || nodes[k] <= sBack);
        if (!one)
        {
          this->SplitSegment(tf, i, k, sFront, sBack, length);
          resolved[i] = Skip;
          continue; // counted when composited
        }
      }
    }
    total += p;
    if (pieces)
    {
      pieces[i] = p;
    }
    resolved[i] = valid && p ? k : Skip;
    if (resolved[i] == Skip)
    {
      out[i] = RGBA();
    }
  }
  return total;
}

/// IntegrateLinearScalar()'s walk over the intervals from @p sFront toward
/// @p sBack (starting in interval @p k): the same piece ends and lengths.
void SegmentBatch::SplitSegment(const TransferFunction& tf, int job, int k, double sFront,
  double sBack, double length)
{
  const std::vector<double>& nodes = tf.GetNodes();
  const int n = static_cast<int>(nodes.size());
  const double ds = sBack - sFront;
  const bool up = ds > 0.0;
  const double scale = std::isfinite(ds) ? 1.0 : 0.5;
  const double invDs = 1.0 / (scale * sBack - scale * sFront);
  Split split{ job, static_cast<int>(this->SplitOut.size()), 0 };
  double xPrev = 0.0, sPrev = sFront;
  while (true)
  {
    double sNext = sBack, xNext = 1.0;
    bool last = true;
    if (up && k + 1 < n && nodes[k + 1] < sBack)
    {
      sNext = nodes[k + 1];
      last = false;
    }
    else if (!up && k >= 0 && nodes[k] > sBack)
    {
      sNext = nodes[k];
      last = false;
    }
    if (!last)
    {
      xNext = (scale * sNext - scale * sFront) * invDs;
    }
    const double pieceLength = length * (xNext - xPrev);
    if (pieceLength > 0.0)
    {
      this->AddPiece(Piece{ sPrev, sNext, pieceLength, k }); // its result: SplitOut[piece]
      this->SplitOut.emplace_back();
      ++split.Count;
    }
    if (last)
    {
      break;
    }
    xPrev = xNext;
    sPrev = sNext;
    k += up ? 1 : -1;
  }
  this->Splits.push_back(split);
}

/// The lane arrays for @p n pieces (and a block of padding lanes).
SegmentBatch::ThinArrays SegmentBatch::ThinLanes(int n)
{
  const size_t stride = static_cast<size_t>(n) + Lanes;
  if (this->ThinStore.size() < static_cast<size_t>(ThinFields) * stride)
  {
    this->ThinStore.resize(static_cast<size_t>(ThinFields) * stride); // grows only
  }
  if (this->ThinTerms.size() < stride)
  {
    this->ThinTerms.resize(stride);
    this->Order.resize(stride);
  }
  double* f = this->ThinStore.data();
  return ThinArrays{ f, f + stride, f + 2 * stride, f + 3 * stride, f + 4 * stride,
    f + 5 * stride, f + 6 * stride, f + 7 * stride, f + 8 * stride, f + 9 * stride,
    this->ThinTerms.data() };
}

namespace
{
/**
 * IntegrateLinearScalarInInterval() -> IntegrateSegment() ->
 * ExactSegmentWeights() for one piece (valid: length > 0, finite ends),
 * taking the thin branch aside for the lanes: a thin piece's depths, colours
 * and number of terms go to lane @p m of @p t, any other piece is integrated
 * here by the scalar kernel into @p dest (its Terms 0).
 */
inline __attribute__((always_inline)) void EvaluatePiece(const TransferFunction& tf, int k,
  double s0, double s1, double length, const detail::ThinTermByExponent& thinTerms,
  const SegmentBatch::ThinArrays& t, int m, RGBA& dest)
{
  SegmentEnd f, b;
  tf.Evaluate(k, s0, false, f);
  tf.Evaluate(k, s1, false, b);
  const double depthFront = std::max(f.Tau, 0.0) * length;
  const double depthBack = std::max(b.Tau, 0.0) * length;
  const double a = std::min(depthFront, detail::DepthCap);
  const double c = std::min(depthBack, detail::DepthCap);
  const double d1 = 0.5 * (a + c);
  if (!std::isfinite(depthFront) || !std::isfinite(depthBack) || !(d1 > 0.0) ||
    d1 > detail::ThinDepth)
  {
    // Copies: the ends above stay in registers (their address would escape).
    const SegmentEnd front = f, back = b;
    dest = IntegrateSegment(length, front, back, EmissionModel::WilliamsMax, SegmentMethod::Exact);
    t.Terms[m] = 0;
    return;
  }
  t.A[m] = a;
  t.D1[m] = d1;
  t.Terms[m] = thinTerms(d1);
  t.FrontR[m] = f.Color[0];
  t.FrontG[m] = f.Color[1];
  t.FrontB[m] = f.Color[2];
  t.BackR[m] = b.Color[0];
  t.BackG[m] = b.Color[1];
  t.BackB[m] = b.Color[2];
}

/**
 * EvaluatePiece() for the Lanes segments from @p i, all valid and in the
 * same interior interval @p k (0 <= k < n - 1), side by side: per lane
 * TransferFunction::Evaluate()'s operations on node k, then the depths and
 * the thin test (std::min/max as (b < a ? b : a)/(a < b ? b : a), isfinite as
 * x - x == 0), so each lane's values are the scalar code's. Writes the lanes
 * and returns true only if every segment is thin (the caller takes the
 * others one by one).
 */
inline __attribute__((always_inline)) bool EvaluateBlock(const TransferFunction& tf, int k,
  const SegmentBatch::Arrays& jobs, int i, const detail::ThinTermByExponent& thinTerms,
  const SegmentBatch::ThinArrays& t)
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
  const V4 a = detail::DepthCap < depthFront ? zero + detail::DepthCap : depthFront;
  const V4 c = detail::DepthCap < depthBack ? zero + detail::DepthCap : depthBack;
  const V4 d1 = 0.5 * (a + c);
  const auto thin = (depthFront - depthFront == 0.0) & (depthBack - depthBack == 0.0) &
    (d1 > 0.0) & (d1 <= detail::ThinDepth);
  if (!(thin[0] & thin[1] & thin[2] & thin[3]))
  {
    return false;
  }
  std::memcpy(t.A + i, &a, sizeof(V4));
  std::memcpy(t.D1 + i, &d1, sizeof(V4));
  const double base[3] = { node.R, node.G, node.B };
  const double slope[3] = { node.DR, node.DG, node.DB };
  double* front[3] = { t.FrontR, t.FrontG, t.FrontB };
  double* back[3] = { t.BackR, t.BackG, t.BackB };
  for (int ch = 0; ch < 3; ++ch)
  {
    const V4 f = base[ch] + slope[ch] * ds0;
    const V4 b = base[ch] + slope[ch] * ds1;
    std::memcpy(front[ch] + i, &f, sizeof(V4));
    std::memcpy(back[ch] + i, &b, sizeof(V4));
  }
  for (int l = 0; l < Lanes; ++l)
  {
    t.Terms[i + l] = thinTerms(d1[l]);
  }
  return true;
}

/**
 * EvaluatePiece() for the resolved segments (lane i for segment i;
 * resolved[i] == @p skip: none), Lanes at a time where they share an
 * interior interval (EvaluateBlock()). Compiled also for AVX2.
 */
HOV_LANES_TARGET_CLONES
void EvaluateSegments(const TransferFunction& tf, const int* resolved, int skip,
  const SegmentBatch::Arrays& jobs, int count, const SegmentBatch::ThinArrays& t, RGBA* out)
{
  const detail::ThinTermByExponent& thinTerms = detail::ThinTerms();
  const int last = tf.GetNumberOfNodes() - 2; // the last interior interval
  int i = 0;
  for (; i + Lanes <= count; i += Lanes)
  {
    const int k = resolved[i];
    const bool same = (resolved[i + 1] == k) & (resolved[i + 2] == k) & (resolved[i + 3] == k);
    if (same && k >= 0 && k <= last && EvaluateBlock(tf, k, jobs, i, thinTerms, t))
    {
      continue;
    }
    for (int l = i; l < i + Lanes; ++l)
    {
      if (resolved[l] == skip)
      {
        t.Terms[l] = 0;
        continue;
      }
      EvaluatePiece(tf, resolved[l], jobs.SFront[l], jobs.SBack[l], jobs.Length[l], thinTerms, t,
        l, out[l]);
    }
  }
  for (; i < count; ++i)
  {
    if (resolved[i] == skip)
    {
      t.Terms[i] = 0;
      continue;
    }
    EvaluatePiece(
      tf, resolved[i], jobs.SFront[i], jobs.SBack[i], jobs.Length[i], thinTerms, t, i, out[i]);
  }
}
}

/// EvaluateSegments() (lane i for segment i), then EvaluatePiece() for the
/// pieces of split ones (lane count + m for piece m).
void SegmentBatch::EvaluateLanes(const TransferFunction& tf,
  const IntegrationSettings& settings, const Arrays& jobs, int count, RGBA* out)
{
  (void)settings; // Williams-Max, exact (see Integrate())
  const ThinArrays t = this->ThinLanes(count + this->NumPieces);
  const detail::ThinTermByExponent& thinTerms = detail::ThinTerms();
  EvaluateSegments(tf, this->Resolved.data(), Skip, jobs, count, t, out);
  const Piece* __restrict pieces = this->Pieces.data();
  for (int m = 0; m < this->NumPieces; ++m)
  {
    EvaluatePiece(tf, pieces[m].Interval, pieces[m].S0, pieces[m].S1, pieces[m].Length, thinTerms,
      t, count + m, this->SplitOut[m]);
  }
}

/**
 * The thin lanes of the @p n pieces grouped by number of terms (counting
 * sort), their depths contiguous, then each group Lanes at a time (lanes are
 * independent: the grouping does not change any result). The weights W and
 * alpha, in that order, overwrite A and D1 (copied before).
 */
void SegmentBatch::ThinSeries(int n)
{
  constexpr int maxOrder = detail::MaxThinOrder;
  const ThinArrays t = this->ThinLanes(n);
  // Counts per number of terms, in two interleaved tables (no chain of
  // increments of one counter through memory).
  int counts[2][maxOrder + 2] = {};
  for (int m = 0; m < n; ++m)
  {
    ++counts[m & 1][t.Terms[m]];
  }
  int* __restrict start = this->GroupStart;
  start[0] = 0;
  for (int k = 1; k <= maxOrder + 1; ++k)
  {
    start[k] = start[k - 1] + (k == 1 ? 0 : counts[0][k - 1] + counts[1][k - 1]);
  }
  int next[maxOrder + 2];
  std::copy(start, start + maxOrder + 2, next);
  double* __restrict sa = t.SortedA;
  double* __restrict sd = t.SortedD1;
  int* __restrict order = this->Order.data();
  for (int m = 0; m < n; ++m)
  {
    const int terms = t.Terms[m];
    if (terms > 0)
    {
      const int pos = next[terms]++;
      order[pos] = m;
      sa[pos] = t.A[m];
      sd[pos] = t.D1[m];
    }
  }
  const int numThin = start[maxOrder + 1];
  for (int l = 0; l < Lanes; ++l)
  {
    sa[numThin + l] = 0.0; // padding after the last group: any valid thin segment
    sd[numThin + l] = 1.0 / 8.0;
  }
  for (int terms = 1; terms <= maxOrder; ++terms)
  {
    const int first = start[terms], last = start[terms + 1];
    if (first < last)
    {
      ThinWilliamsMaxBlocks(terms, sa + first, sd + first, (last - first + Lanes - 1) / Lanes,
        t.A + first, t.D1 + first);
    }
  }
}

/// The thin lanes' RGBA from their weights, as ThinWeights() and
/// IntegrateSegment(): lane m < @p count is segment m, lane count + m piece m.
void SegmentBatch::WriteThin(int count, RGBA* out)
{
  const ThinArrays t = this->ThinLanes(count + this->NumPieces);
  const int numThin = this->GroupStart[detail::MaxThinOrder + 1];
  const int* __restrict order = this->Order.data();
  RGBA* splitOut = this->SplitOut.data();
  for (int pos = 0; pos < numThin; ++pos)
  {
    const int m = order[pos];
    const double w = t.A[pos], alpha = t.D1[pos];
    const double wf = std::max(0.0, w);
    const double wb = std::max(0.0, alpha - w);
    RGBA& o = m < count ? out[m] : splitOut[m - count];
    o.A = alpha;
    o.R = wf * t.FrontR[m] + wb * t.BackR[m];
    o.G = wf * t.FrontG[m] + wb * t.BackG[m];
    o.B = wf * t.FrontB[m] + wb * t.BackB[m];
  }
}

/// The split segments: pieces composited front to back, stopping once opaque,
/// as IntegrateLinearScalar() does. Returns the pieces composited.
long long SegmentBatch::CompositeSplits(RGBA* out, int* pieces)
{
  long long total = 0;
  for (const Split& split : this->Splits)
  {
    RGBA accum;
    int count = 0;
    for (int m = split.First; m < split.First + split.Count; ++m)
    {
      CompositeBehind(accum, this->SplitOut[m]);
      ++count;
      if (accum.A >= 1.0)
      {
        break; // opaque: nothing behind is visible
      }
    }
    out[split.Job] = accum;
    total += count;
    if (pieces)
    {
      pieces[split.Job] = count;
    }
  }
  return total;
}
}
