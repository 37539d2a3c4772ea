/**
 * @file hovSegmentBatch.h
 * @brief Many independent ray segments integrated at once: the same results,
 * bit for bit, as hov::IntegrateLinearScalar() per segment, at a fraction of
 * the cost.
 *
 * Why: the thin-segment series of hovSegmentIntegral (the common case for fine
 * meshes) is a chain of dependent multiply-adds; one segment at a time the CPU
 * waits on each step's latency. Segments of different pixels are independent,
 * so SegmentBatch evaluates them side by side, four at a time, lane by lane
 * with exactly the scalar kernel's operations in the scalar kernel's order, so
 * the result does not change in any bit. Four consecutive thin segments of one
 * interior interval (the common case: neighbouring pixels of one cell) are
 * finished in registers, transfer function to RGBA, with the largest number of
 * series terms among them (hov::detail::ThinTerms, the count the scalar kernel
 * uses) and each lane's extra terms replaced by exact zeros, which leaves every
 * lane's bits unchanged; the other thin segments are grouped by their number of
 * terms and evaluated four at a time. The series' Horner steps are fused
 * multiply-adds where the CPU has them, in both kernels alike
 * (hov::detail::FusedSeries); no other multiply-add is contracted (the kernels
 * are compiled with -ffp-contract=off: GCC contracts a*b+c even under
 * -std=c++17 wherever FMA is enabled, as in the FMA clone).
 *
 * The transfer function is evaluated four segments at a time where four
 * consecutive segments lie in one interior interval (the segments of one
 * cell, as the CPU tiles queue them), with Evaluate()'s operations per lane;
 * one segment at a time otherwise.
 *
 * A segment whose scalar crosses transfer-function nodes is split into its
 * linear pieces exactly as IntegrateLinearScalar() walks them (same piece
 * ends, same lengths); the pieces join the batch like any segment and are
 * composited afterwards in order, stopping where the segment turns opaque, as
 * the scalar walk does. Thick and opaque pieces go through the scalar kernel
 * (IntegrateSegment); Wilhelms-Van Gelder emission and the approximate method
 * use the scalar kernels throughout.
 *
 * Thread safety: one SegmentBatch per thread (it owns scratch buffers, reused
 * from call to call so that rendering allocates nothing per frame).
 * @sa hovRayIntegrator.h, hovSegmentIntegral.h, hovThinSeries.h, hovSegmentBatchLanes.h
 */
#ifndef hovSegmentBatch_h
#define hovSegmentBatch_h

#include "hovCompositing.h"
#include "hovConfig.h"
#include "hovRayIntegrator.h" // IntegrationSettings
#include "hovSegmentIntegral.h" // SegmentEnd

#include <vector> // scratch

namespace hov
{
class TransferFunction;

/// One segment: the scalar goes linearly from SFront (eye side) to SBack.
struct SegmentJob
{
  double SFront = 0.0;
  double SBack = 0.0;
  double Length = 0.0; ///< world length
  /// The transfer-function interval holding the segment's whole scalar range
  /// (from IntervalOfRange() over the cell, >= -1), or -2 if unknown, or
  /// -3 - h if unknown but near interval h (e.g. the interval of the cell's
  /// smallest scalar: where the search for the segment's interval starts).
  int Interval = -2;
};

class HOV_EXPORT SegmentBatch
{
public:
  /// Segments as arrays (what a renderer fills lane by lane): segment i is
  /// { SFront[i], SBack[i], Length[i], Interval[i] } as in SegmentJob.
  struct Arrays
  {
    const double* SFront;
    const double* SBack;
    const double* Length;
    const int* Interval;
  };

  /**
   * out[i] = the premultiplied RGBA of segment i: IntegrateLinearScalarInInterval()
   * if its Interval >= -1, else IntegrateLinearScalar(). Returns the number
   * of linear pieces integrated (1 per segment with a known interval);
   * @p pieces, if given, receives that number per segment.
   */
  long long Integrate(const TransferFunction& tf, const IntegrationSettings& settings,
    const Arrays& jobs, int count, RGBA* out, int* pieces = nullptr);

  /// The same for segments given as structures.
  long long Integrate(const TransferFunction& tf, const IntegrationSettings& settings,
    const SegmentJob* jobs, int count, RGBA* out, int* pieces = nullptr);

  /// The pieces as lanes for the thin series (index = lane: segment i, then
  /// the pieces of split segments): depths, colours at both ends, number of
  /// terms; the thin lanes left for the sorted series, in increasing order
  /// (Pending[0, *NumPending): the lane kernels finish most blocks of four
  /// themselves); and those sorted by number of terms (index = position in
  /// Order).
  struct ThinArrays
  {
    double *A, *D1, *FrontR, *FrontG, *FrontB, *BackR, *BackG, *BackB, *SortedA, *SortedD1;
    int* Terms;
    int* Pending;
    int* NumPending;
  };

private:
  /// A piece of a segment that crosses transfer-function nodes.
  struct Piece
  {
    double S0, S1, Length;
    int Interval;
  };
  /// A segment split into Count pieces (SplitOut[First, First + Count)).
  struct Split
  {
    int Job, First, Count;
  };
  static constexpr int ThinFields = 10;
  static constexpr int Skip = -1000000; ///< Resolved: nothing to evaluate

  long long IntegrateScalar(const TransferFunction& tf, const IntegrationSettings& settings,
    const Arrays& jobs, int count, RGBA* out, int* pieces);
  long long ResolveIntervals(
    const TransferFunction& tf, const Arrays& jobs, int count, RGBA* out, int* pieces);
  void SplitSegment(const TransferFunction& tf, int job, int k, double sFront, double sBack,
    double length);
  ThinArrays ThinLanes(int n);
  void EvaluateLanes(const TransferFunction& tf, const IntegrationSettings& settings,
    const Arrays& jobs, int count, RGBA* out);
  void ThinSeries(int n);
  void WriteThin(int count, RGBA* out);
  long long CompositeSplits(RGBA* out, int* pieces);
  void AddPiece(const Piece& piece)
  {
    if (this->NumPieces == static_cast<int>(this->Pieces.size()))
    {
      this->Pieces.resize(2 * this->Pieces.size() + 64); // grows only: none in steady state
    }
    this->Pieces[this->NumPieces++] = piece;
  }

  std::vector<int> Resolved; ///< per segment: its interval, or Skip
  std::vector<int> SplitStart; ///< per segment to split: the interval it starts in
  std::vector<int> Left;       ///< the segments whose interval is still to be found
  std::vector<Piece> Pieces;
  int NumPieces = 0;
  std::vector<Split> Splits;
  std::vector<RGBA> SplitOut;    ///< per piece: its RGBA
  std::vector<double> ThinStore; ///< the ThinArrays' doubles, one array after the other
  std::vector<int> ThinTerms;    ///< their Terms
  std::vector<int> Pending;      ///< ThinArrays::Pending
  int NumPending = 0;
  int GroupStart[24] = {};       ///< first position in Order per number of terms
  std::vector<int> Order;        ///< thin lanes grouped by number of terms
  std::vector<double> JobS, JobL;        ///< SegmentJob input as arrays
  std::vector<int> JobK;
};
}

#endif
