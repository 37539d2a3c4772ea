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
  long long total = this->CollectPieces(tf, jobs, count, out, pieces);
  this->EvaluatePieces(tf, settings, out);
  this->ThinSeries();
  this->WriteThin(out);
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
 * Each segment becomes one piece (its interval known, or found as
 * OnePieceInterval() finds it) or several (SplitSegment()); invalid ones
 * (IntegrateLinearScalar()'s and IntegrateLinearScalarInInterval()'s early
 * returns) are written as zero here. Returns the pieces of the unsplit
 * segments (split ones are counted when composited).
 */
long long SegmentBatch::CollectPieces(
  const TransferFunction& tf, const Arrays& jobs, int count, RGBA* out, int* pieces)
{
  this->NumPieces = 0;
  this->Splits.clear();
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
      if (!valid || n == 0)
      {
        p = 0;
      }
      else
      {
        // OnePieceInterval(), inline; the walk starts from the same interval.
        const bool up = sBack - sFront >= 0.0;
        k = up ? tf.FindIntervalUpward(sFront) : tf.FindIntervalDownward(sFront);
        const bool one =
          up ? (k + 1 >= n || nodes[k + 1] >= sBack) : (k < 0 || nodes[k] <= sBack);
        if (!one)
        {
          this->SplitSegment(tf, i, k, sFront, sBack, length);
          continue; // counted when composited
        }
      }
    }
    total += p;
    if (pieces)
    {
      pieces[i] = p;
    }
    if (!valid || p == 0)
    {
      out[i] = RGBA();
      continue;
    }
    this->AddPiece(Piece{ sFront, sBack, length, k, i });
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
      this->AddPiece(
        Piece{ sPrev, sNext, pieceLength, k, -1 - static_cast<int>(this->SplitOut.size()) });
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
    this->ThinStore.resize(static_cast<size_t>(ThinFields) * stride); // grows only: none in steady state
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

/**
 * IntegrateLinearScalarInInterval() -> IntegrateSegment() ->
 * ExactSegmentWeights() per piece, taking the thin branch aside for the
 * lanes: a thin piece's depths, colours and number of terms go to the lane
 * arrays, any other piece is integrated here by the scalar kernel (Terms 0).
 */
void SegmentBatch::EvaluatePieces(
  const TransferFunction& tf, const IntegrationSettings& settings, RGBA* out)
{
  const int n = this->NumPieces;
  const ThinArrays t = this->ThinLanes(n);
  double* __restrict a = t.A;
  double* __restrict d1 = t.D1;
  double* __restrict front[3] = { t.FrontR, t.FrontG, t.FrontB };
  double* __restrict back[3] = { t.BackR, t.BackG, t.BackB };
  int* __restrict terms = t.Terms;
  int* __restrict perTerms = this->PerTerms;
  std::fill(perTerms, perTerms + detail::MaxThinOrder + 2, 0);
  const Piece* __restrict pieces = this->Pieces.data();
  const detail::ThinTermByExponent& thinTerms = detail::ThinTerms();
  for (int m = 0; m < n; ++m)
  {
    const Piece piece = pieces[m];
    SegmentEnd f, b;
    tf.Evaluate(piece.Interval, piece.S0, false, f);
    tf.Evaluate(piece.Interval, piece.S1, false, b);
    const double depthFront = std::max(f.Tau, 0.0) * piece.Length;
    const double depthBack = std::max(b.Tau, 0.0) * piece.Length;
    const double am = std::min(depthFront, detail::DepthCap);
    const double cm = std::min(depthBack, detail::DepthCap);
    const double dm = 0.5 * (am + cm);
    if (!std::isfinite(depthFront) || !std::isfinite(depthBack) || !(dm > 0.0) ||
      dm > detail::ThinDepth)
    {
      this->DestOf(piece.Dest, out) =
        IntegrateSegment(piece.Length, f, b, settings.Emission, settings.Method);
      terms[m] = 0;
      continue;
    }
    a[m] = am;
    d1[m] = dm;
    terms[m] = thinTerms(dm);
    ++perTerms[terms[m] + 1];
    for (int c = 0; c < 3; ++c)
    {
      front[c][m] = f.Color[c];
      back[c][m] = b.Color[c];
    }
  }
}

/**
 * The thin pieces grouped by number of terms (counting sort), their depths
 * contiguous, then each group Lanes at a time (lanes are independent: the
 * grouping does not change any result); the weights go back to the pieces'
 * lanes (W, Alpha).
 */
void SegmentBatch::ThinSeries()
{
  constexpr int maxOrder = detail::MaxThinOrder;
  static_assert(maxOrder + 2 <= static_cast<int>(sizeof(PerTerms) / sizeof(int)), "term counts");
  const int n = this->NumPieces;
  const ThinArrays t = this->ThinLanes(n);
  int* __restrict perTerms = this->PerTerms;
  for (int k = 0; k <= maxOrder; ++k)
  {
    perTerms[k + 1] += perTerms[k];
  }
  int groupStart[maxOrder + 2];
  std::copy(perTerms, perTerms + maxOrder + 2, groupStart);
  const int numThin = groupStart[maxOrder + 1];
  // Sorted depths and weights: the lane arrays' Sorted* fields.
  double* __restrict sa = t.SortedA;
  double* __restrict sd = t.SortedD1;
  int* __restrict order = this->Order.data();
  for (int m = 0; m < n; ++m)
  {
    if (t.Terms[m] > 0)
    {
      const int pos = perTerms[t.Terms[m]]++;
      order[pos] = m;
      sa[pos] = t.A[m];
      sd[pos] = t.D1[m];
    }
  }
  // Padding after the last group: any valid thin segment.
  for (int l = 0; l < Lanes; ++l)
  {
    sa[numThin + l] = 0.0;
    sd[numThin + l] = 1.0 / 8.0;
  }
  double* w = t.A;      // reused: the series' results in sorted order
  double* alpha = t.D1; // (A and D1 were copied to sa, sd)
  for (int terms = 1; terms <= maxOrder; ++terms)
  {
    const int first = groupStart[terms], last = groupStart[terms + 1];
    if (first < last)
    {
      ThinWilliamsMaxBlocks(terms, sa + first, sd + first, (last - first + Lanes - 1) / Lanes,
        w + first, alpha + first);
    }
  }
}

/// The thin pieces' RGBA from their weights, as ThinWeights() and IntegrateSegment().
void SegmentBatch::WriteThin(RGBA* out)
{
  const ThinArrays t = this->ThinLanes(this->NumPieces);
  const int numThin = this->PerTerms[detail::MaxThinOrder + 1];
  const Piece* __restrict pieces = this->Pieces.data();
  for (int pos = 0; pos < numThin; ++pos)
  {
    const int m = this->Order[pos];
    const double w = t.A[pos], alpha = t.D1[pos];
    const double wf = std::max(0.0, w);
    const double wb = std::max(0.0, alpha - w);
    RGBA& o = this->DestOf(pieces[m].Dest, out);
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
  this->SplitOut.clear();
  return total;
}
}
