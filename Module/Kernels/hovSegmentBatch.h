/**
 * @file hovSegmentBatch.h
 * @brief Many independent ray segments integrated at once: the same results,
 * bit for bit, as hov::IntegrateLinearScalar() per segment, at a fraction of
 * the cost.
 *
 * Why: the thin-segment series of hovSegmentIntegral (the common case for fine
 * meshes) is a chain of dependent multiply-adds; one segment at a time the CPU
 * waits on each step's latency. Segments of different pixels are independent,
 * so SegmentBatch evaluates them side by side: thin Williams-Max segments are
 * grouped by their number of series terms (hov::detail::ThinTerms, the count
 * the scalar kernel uses) and evaluated four at a time, lane by lane with
 * exactly the scalar kernel's operations in the scalar kernel's order, so the
 * result does not change in any bit (no fused multiply-add is introduced: the
 * module targets baseline x86-64 and the extra AVX2 clone does not enable FMA;
 * note that GCC contracts a*b+c even under -std=c++17 wherever FMA is enabled,
 * e.g. with -march=native). Every other
 * segment (several transfer-function intervals, thick, opaque, Wilhelms-Van
 * Gelder emission or the approximate method) goes through the scalar kernels.
 *
 * Thread safety: one SegmentBatch per thread (it owns scratch buffers, reused
 * from call to call so that rendering allocates nothing per frame).
 * @sa hovRayIntegrator.h, hovSegmentIntegral.h, hovThinSeries.h
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
  /// (from IntervalOfRange() over the cell, >= -1), or -2 if unknown.
  int Interval = -2;
};

class HOV_EXPORT SegmentBatch
{
public:
  /**
   * out[i] = the premultiplied RGBA of jobs[i]: IntegrateLinearScalarInInterval()
   * if jobs[i].Interval >= -1, else IntegrateLinearScalar(). Returns the number
   * of linear pieces integrated (1 per segment with a known interval);
   * @p pieces, if given, receives that number per segment.
   */
  long long Integrate(const TransferFunction& tf, const IntegrationSettings& settings,
    const SegmentJob* jobs, int count, RGBA* out, int* pieces = nullptr);

private:
  /// A thin Williams-Max segment waiting for its block.
  struct ThinItem
  {
    SegmentEnd Front, Back; ///< transfer function at both ends (evaluated in place)
    double A, D1;           ///< front depth rate tauFront L and total depth D(1)
    int Index;              ///< into out
    int Terms;              ///< series terms (as the scalar kernel)
  };
  std::vector<ThinItem> Items;
  std::vector<int> Order; ///< Items grouped by Terms
  std::vector<double> SortedA, SortedD1; ///< their A and D1 in that order
  std::vector<double> W, Alpha;          ///< the series' results in that order
};
}

#endif
