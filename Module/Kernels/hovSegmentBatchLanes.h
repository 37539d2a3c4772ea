/**
 * @file hovSegmentBatchLanes.h
 * @brief Internal to hov::SegmentBatch: its lane kernels (the thin series of
 * four segments at a time, the transfer function at four segments of one
 * interval at a time) and the one-segment evaluation they fall back to, each
 * with exactly the scalar kernels' operations (see hovSegmentBatch.h).
 *
 * Not part of the public API (namespace hov::detail).
 */
#ifndef hovSegmentBatchLanes_h
#define hovSegmentBatchLanes_h

#include "hovSegmentBatch.h"     // Arrays, ThinArrays
#include "hovThinSeries.h"       // thin-series branch threshold and term counts
#include "hovTransferFunction.h" // Evaluate

#include <algorithm> // std::max, std::min
#include <cmath>     // std::isfinite

#if defined(__GNUC__)
#define HOV_LANES_HIDDEN __attribute__((visibility("hidden")))
#else
#define HOV_LANES_HIDDEN
#endif

// Which build of hovSegmentBatchLanes.cxx this is. The module's is "cloned":
// one copy per instruction set, picked for the CPU at load time. The kernel
// tests also build the file as one variant at a time (HOV_LANES_ONLY: 1 =
// baseline x86-64, 2 = FMA3, see the .cxx) to run the variants this CPU would
// not pick (TestLaneVariants.cxx). Each build's functions live in a namespace
// of their own, so one test program can hold them all.
#if !defined(HOV_LANES_ONLY)
#define HOV_LANES_NAMESPACE cloned
#elif HOV_LANES_ONLY == 1
#define HOV_LANES_NAMESPACE baseline
#elif HOV_LANES_ONLY == 2
#define HOV_LANES_NAMESPACE fma3
#else
#error "HOV_LANES_ONLY: 1 (baseline) or 2 (FMA3)"
#endif

namespace hov
{
namespace detail
{
/// Segments evaluated side by side (one V4 of the lane kernels).
constexpr int Lanes = 4;

inline namespace HOV_LANES_NAMESPACE
{

/**
 * IntegrateLinearScalarInInterval() -> IntegrateSegment() ->
 * ExactSegmentWeights() for one piece (valid: length > 0, finite ends),
 * taking the thin branch aside for the lanes: a thin piece's depths, colours
 * and number of terms go to lane @p m of @p t (appended to its Pending lanes),
 * any other piece is integrated here by the scalar kernel into @p dest.
 */
inline __attribute__((always_inline)) void EvaluatePiece(const TransferFunction& tf, int k,
  double s0, double s1, double length, const ThinTermByExponent& thinTerms,
  const SegmentBatch::ThinArrays& t, int m, RGBA& dest)
{
  SegmentEnd f, b;
  tf.Evaluate(k, s0, false, f);
  tf.Evaluate(k, s1, false, b);
  const double depthFront = std::max(f.Tau, 0.0) * length;
  const double depthBack = std::max(b.Tau, 0.0) * length;
  const double a = std::min(depthFront, DepthCap);
  const double c = std::min(depthBack, DepthCap);
  const double d1 = 0.5 * (a + c);
  if (!std::isfinite(depthFront) || !std::isfinite(depthBack) || !(d1 > 0.0) ||
    d1 > ThinDepth)
  {
    // Copies: the ends above stay in registers (their address would escape).
    const SegmentEnd front = f, back = b;
    dest = IntegrateSegment(length, front, back, EmissionModel::WilliamsMax, SegmentMethod::Exact);
    return;
  }
  t.A[m] = a;
  t.D1[m] = d1;
  t.Terms[m] = thinTerms(d1);
  t.Pending[(*t.NumPending)++] = m;
  t.FrontR[m] = f.Color[0];
  t.FrontG[m] = f.Color[1];
  t.FrontB[m] = f.Color[2];
  t.BackR[m] = b.Color[0];
  t.BackG[m] = b.Color[1];
  t.BackB[m] = b.Color[2];
}


/**
 * The thin series (w = WFront before clamping, and alpha) of @p blocks
 * consecutive blocks of Lanes segments (depth rates @p a, total depths
 * @p d1), all with @p terms terms, exactly as the scalar kernel.
 */
HOV_LANES_HIDDEN void ThinWilliamsMaxBlocks(
  int terms, const double* a, const double* d1, int blocks, double* w, double* alpha);

/// Transfer functions of at most this many nodes are counted by CountIntervals().
constexpr int MaxCountedNodes = 16;
/// CountIntervals()' mark of a segment that crosses a node.
constexpr int NeedsSplit = -2000000;

/**
 * The segments' intervals into @p resolved: each segment's known one
 * (Interval >= -1) as it is; for every block of Lanes segments from a
 * multiple of Lanes that are all of unknown interval (< -1) and valid
 * (length > 0, finite ends), with a function of 1 <= @p n <= MaxCountedNodes nodes
 * @p x, the interval each starts in, by counting nodes (see the definition):
 * the same as the search from any start (FindIntervalUpward / Downward) with
 * the same one-piece test. A counted segment that crosses a node is marked
 * NeedsSplit, its start interval in @p splitStart. The indices of those and
 * of all segments still of unknown interval go to @p left, in increasing
 * order; returns how many.
 */
HOV_LANES_HIDDEN int CountIntervals(const double* x, int n, const SegmentBatch::Arrays& jobs,
  int count, int* resolved, int* splitStart, int* left);

/**
 * EvaluatePiece() for the resolved segments (lane i for segment i;
 * resolved[i] == @p skip: none). Four consecutive valid thin segments of one
 * interior interval are finished in registers, their RGBA written to @p out;
 * any other thin segment goes to the lanes of @p t and its Pending list (the
 * sorted series finishes it), a thick or opaque one to the scalar kernel.
 */
HOV_LANES_HIDDEN void EvaluateSegments(const TransferFunction& tf, const int* resolved, int skip,
  const SegmentBatch::Arrays& jobs, int count, const SegmentBatch::ThinArrays& t, RGBA* out);
}
}
}

#endif
