/**
 * @file hovBreakpointWalk.h
 * @brief The one walk over the transfer-function intervals that a monotone
 * run of the scalar crosses (HIAC section 5.1: a ray segment split at every
 * breakpoint), shared by every segment path: the linear segment
 * (hovRayIntegrator.cxx), the batched segments (hovSegmentBatch.cxx), the
 * polynomial field (hovPolynomialSegment.cxx) and the two-field segment
 * (hovTwoFieldSegment.cxx).
 *
 * A run goes monotonically from sStart to sEnd. The walk starts in the table
 * interval holding sStart in walking direction (FindIntervalUpward(sStart)
 * going up, FindIntervalDownward(sStart) going down: a run starting exactly
 * on a node going down belongs to the interval below it) and moves one
 * interval at a time; CrossesNode() tells whether the current interval ends
 * at a node strictly before sEnd (the run crosses it: Node() is its value,
 * exactly), else the run ends in the current interval. Interval k spans
 * [X[k], X[k+1]]; -1 and n - 1 are the clamped outer regions.
 *
 * Where along the ray a node falls is the caller's business (a fraction of a
 * linear segment, a root of a polynomial field); ForEachLinearPiece() is the
 * linear case, with the exact piece ends and lengths of the scalar kernel.
 *
 * Thread safety: a walk is a value (one per run); the table is read only.
 * @sa hovTransferFunction.h, hovRayIntegrator.h
 */
#ifndef hovBreakpointWalk_h
#define hovBreakpointWalk_h

#include "hovTransferFunction.h" // the table walked

#include <cmath> // std::isfinite

namespace hov
{
class BreakpointWalk
{
public:
  BreakpointWalk() = default;
  /// A walk toward @p sEnd from interval @p k (the interval of the run's start in walking direction).
  BreakpointWalk(const TransferFunction& tf, int k, bool up, double sEnd)
    : X(tf.GetNodes().data())
    , N(tf.GetNumberOfNodes())
    , K(k)
    , Up(up)
    , SEnd(sEnd)
  {
  }
  /// The walk of the run from @p sStart to @p sEnd (up if sEnd > sStart), its interval searched.
  static BreakpointWalk Of(const TransferFunction& tf, double sStart, double sEnd)
  {
    const bool up = sEnd > sStart;
    return BreakpointWalk(
      tf, up ? tf.FindIntervalUpward(sStart) : tf.FindIntervalDownward(sStart), up, sEnd);
  }

  /// The current interval.
  int Interval() const { return this->K; }
  /// True if the current interval ends at a node strictly before the run's end.
  bool CrossesNode() const
  {
    return this->Up ? (this->K + 1 < this->N && this->X[this->K + 1] < this->SEnd)
                    : (this->K >= 0 && this->X[this->K] > this->SEnd);
  }
  /// The node where the current interval ends (if CrossesNode()).
  double Node() const { return this->X[this->NodeIndex()]; }
  /// Its index in the table.
  int NodeIndex() const { return this->Up ? this->K + 1 : this->K; }
  /// On to the next interval (across Node()).
  void Next() { this->K += this->Up ? 1 : -1; }

private:
  const double* X = nullptr;
  int N = 0;
  int K = -1;
  bool Up = true;
  double SEnd = 0.0;
};

/**
 * The linear pieces of a segment of length @p length on which the scalar goes
 * linearly from @p sFront to @p sBack (sFront != sBack, both finite), starting
 * in interval @p k: @p visit(interval, s0, s1, pieceLength) for each piece of
 * positive length, front to back, until it returns false. A node falls at the
 * fraction (s - sFront) / (sBack - sFront) of the segment (on halved values if
 * the difference overflows), so the piece ends are the node values exactly.
 */
template <typename Visit>
inline void ForEachLinearPiece(const TransferFunction& tf, int k, double sFront, double sBack,
  double length, Visit&& visit)
{
  const double ds = sBack - sFront;
  const double scale = std::isfinite(ds) ? 1.0 : 0.5;
  const double invDs = 1.0 / (scale * sBack - scale * sFront);
  BreakpointWalk walk(tf, k, ds > 0.0, sBack);
  double xPrev = 0.0; // fraction of the segment already visited
  double sPrev = sFront;
  while (true)
  {
    const bool last = !walk.CrossesNode();
    double sNext = sBack, xNext = 1.0;
    if (!last)
    {
      sNext = walk.Node();
      xNext = (scale * sNext - scale * sFront) * invDs;
    }
    const double pieceLength = length * (xNext - xPrev);
    if (pieceLength > 0.0 && !visit(walk.Interval(), sPrev, sNext, pieceLength))
    {
      return;
    }
    if (last)
    {
      return;
    }
    xPrev = xNext;
    sPrev = sNext;
    walk.Next();
  }
}
}

#endif
