/**
 * @file hovBreakpointThinning.h
 * @brief Which mergeable breakpoints a shaded segment keeps (hovShadedSegment.h,
 * "Mergeable breakpoints"): the one rule of IntegrateShadedSegment and of
 * ShadedBreakpoints, which applies it before locating the crossings.
 * Internal to the kernels (namespace hov::detail).
 */
#ifndef hovBreakpointThinning_h
#define hovBreakpointThinning_h

#include <algorithm> // std::max

namespace hov
{
namespace detail
{
/**
 * Which mergeable breakpoints are kept: with @p count breakpoints,
 * @p mergeable of them mergeable, and at most @p maxPieces pieces, rank r (in
 * t order) of the M mergeable ones is kept iff
 * floor((r + 1) B / M) > floor(r B / M), B of them in all. The one rule of
 * IntegrateShadedSegment and of ShadedBreakpoints (which applies it before
 * locating the crossings).
 */
class Thinning
{
public:
  Thinning(long long count, long long mergeable, long long maxPieces)
    : M(mergeable)
    , Thin(mergeable > 0 && count + 1 > maxPieces)
  {
    this->B = this->Thin ? std::max(0LL, maxPieces - 1 - (count - mergeable)) : mergeable;
  }
  /// True if the mergeable breakpoint of rank @p r is kept.
  bool Keeps(long long r) const
  {
    return !this->Thin || (r + 1) * this->B / this->M != r * this->B / this->M;
  }

private:
  long long M;
  bool Thin;
  long long B = 0;
};
}
}

#endif
