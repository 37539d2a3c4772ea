#include "hovSegmentBatch.h"

#include "hovBreakpointWalk.h"    // ForEachLinearPiece
#include "hovSegmentBatchLanes.h" // lane kernels, EvaluatePiece
#include "hovThinSeries.h"         // term counts
#include "hovTransferFunction.h"   // interval search

#include <algorithm> // std::max, std::min, std::fill
#include <cmath>     // std::isfinite

namespace hov
{
using detail::EvaluatePiece;
using detail::EvaluateSegments;
using detail::ThinWilliamsMaxBlocks;
using detail::Lanes;

namespace
{
/**
 * TransferFunction::FindIntervalUpward(@p s) (@p up) or FindIntervalDownward(@p s)
 * for a finite @p s, walking from the hint of @p interval (<= -3: interval
 * -3 - interval is near s) if there is one: the largest k with X[k] <= s (or
 * -1) does not depend on where the walk starts.
 */
inline int FindInterval(const TransferFunction& tf, double s, bool up, int interval)
{
  if (interval > -3)
  {
    return up ? tf.FindIntervalUpward(s) : tf.FindIntervalDownward(s);
  }
  const std::vector<double>& x = tf.GetNodes();
  const int n = static_cast<int>(x.size());
  int k = std::min(-3 - interval, n - 1);
  while (k >= 0 && x[k] > s)
  {
    --k;
  }
  while (k + 1 < n && x[k + 1] <= s)
  {
    ++k;
  }
  while (!up && k >= 0 && x[k] >= s)
  {
    --k; // FindIntervalDownward: the largest k with X[k] < s
  }
  return k;
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
 * (SplitSegment()) and invalid ones of unknown interval
 * (IntegrateLinearScalar()'s early return) written as zero here, both marked
 * Skip (invalid segments of known interval: EvaluateSegments()). Returns the
 * pieces of the unsplit segments (split ones are counted when composited).
 */
long long SegmentBatch::ResolveIntervals(
  const TransferFunction& tf, const Arrays& jobs, int count, RGBA* out, int* pieces)
{
  this->NumPieces = 0;
  this->Splits.clear();
  this->SplitOut.clear();
  // Known intervals as they are (EvaluateSegments() checks those segments);
  // blocks of four unknown ones counted (CountIntervals(): the interval, or
  // NeedsSplit and where the split starts); the others searched here.
  if (this->Resolved.size() < static_cast<size_t>(count))
  {
    this->Resolved.resize(count); // grows only: none in steady state
    this->SplitStart.resize(count);
    this->Left.resize(count);
  }
  int* __restrict resolved = this->Resolved.data();
  if (pieces)
  {
    std::fill(pieces, pieces + count, 1);
  }
  const std::vector<double>& nodes = tf.GetNodes();
  const int n = static_cast<int>(nodes.size());
  long long total = count;
  const int* left = this->Left.data();
  const int numLeft = detail::CountIntervals(
    nodes.data(), n, jobs, count, resolved, this->SplitStart.data(), this->Left.data());
  for (int j = 0; j < numLeft; ++j)
  {
    const int i = left[j];
    if (resolved[i] == detail::NeedsSplit && jobs.Interval[i] != detail::NeedsSplit)
    {
      // (A hint equal to the mark, from a table of about two million nodes,
      // takes the search below.)
      resolved[i] = Skip;
      this->SplitSegment(
        tf, i, this->SplitStart[i], jobs.SFront[i], jobs.SBack[i], jobs.Length[i]);
      --total; // counted when composited
      continue;
    }
    const double sFront = jobs.SFront[i], sBack = jobs.SBack[i], length = jobs.Length[i];
    resolved[i] = Skip;
    if (!(length > 0.0) || !std::isfinite(sFront) || !std::isfinite(sBack) || n == 0)
    {
      out[i] = RGBA(); // IntegrateLinearScalar(): nothing, no piece
      --total;
      if (pieces)
      {
        pieces[i] = 0;
      }
      continue;
    }
    // OnePieceInterval(), inline; the walk starts from the same interval.
    const bool up = sBack - sFront >= 0.0;
    const int k = FindInterval(tf, sFront, up, jobs.Interval[i]);
    if (up ? (k + 1 >= n || nodes[k + 1] >= sBack) : (k < 0 || nodes[k] <= sBack))
    {
      resolved[i] = k;
      continue;
    }
    this->SplitSegment(tf, i, k, sFront, sBack, length);
    --total; // counted when composited
  }
  return total;
}

/// IntegrateLinearScalar()'s pieces of a segment crossing nodes (starting in
/// interval @p k): the same piece ends and lengths (ForEachLinearPiece).
void SegmentBatch::SplitSegment(const TransferFunction& tf, int job, int k, double sFront,
  double sBack, double length)
{
  Split split{ job, static_cast<int>(this->SplitOut.size()), 0 };
  ForEachLinearPiece(tf, k, sFront, sBack, length,
    [&](int interval, double s0, double s1, double pieceLength) {
      this->AddPiece(Piece{ s0, s1, pieceLength, interval }); // its result: SplitOut[piece]
      this->SplitOut.emplace_back();
      ++split.Count;
      return true;
    });
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
    this->Pending.resize(stride);
  }
  double* f = this->ThinStore.data();
  return ThinArrays{ f, f + stride, f + 2 * stride, f + 3 * stride, f + 4 * stride,
    f + 5 * stride, f + 6 * stride, f + 7 * stride, f + 8 * stride, f + 9 * stride,
    this->ThinTerms.data(), this->Pending.data(), &this->NumPending };
}

/// EvaluateSegments() (lane i for segment i), then EvaluatePiece() for the
/// pieces of split ones (lane count + m for piece m).
void SegmentBatch::EvaluateLanes(const TransferFunction& tf,
  const IntegrationSettings& settings, const Arrays& jobs, int count, RGBA* out)
{
  (void)settings; // Williams-Max, exact (see Integrate())
  const ThinArrays t = this->ThinLanes(count + this->NumPieces);
  const detail::ThinTermByExponent& thinTerms = detail::ThinTerms();
  this->NumPending = 0;
  EvaluateSegments(tf, this->Resolved.data(), Skip, jobs, count, t, out);
  const Piece* __restrict pieces = this->Pieces.data();
  for (int m = 0; m < this->NumPieces; ++m)
  {
    EvaluatePiece(tf, pieces[m].Interval, pieces[m].S0, pieces[m].S1, pieces[m].Length, thinTerms,
      t, count + m, this->SplitOut[m]);
  }
}

/**
 * The pending thin lanes (ThinArrays::Pending, of the @p n pieces) grouped by
 * number of terms (counting sort, stable), their depths contiguous, then each
 * group Lanes at a time (lanes are independent: the grouping does not change
 * any result). The weights W and alpha, in that order, overwrite A and D1
 * (copied before).
 */
void SegmentBatch::ThinSeries(int n)
{
  constexpr int maxOrder = detail::MaxThinOrder;
  const ThinArrays t = this->ThinLanes(n);
  const int* __restrict pending = t.Pending;
  const int numPending = this->NumPending;
  // Counts per number of terms, in two interleaved tables (no chain of
  // increments of one counter through memory).
  int counts[2][maxOrder + 2] = {};
  for (int i = 0; i < numPending; ++i)
  {
    ++counts[i & 1][t.Terms[pending[i]]];
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
  for (int i = 0; i < numPending; ++i)
  {
    const int m = pending[i];
    const int pos = next[t.Terms[m]]++;
    order[pos] = m;
    sa[pos] = t.A[m];
    sd[pos] = t.D1[m];
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
