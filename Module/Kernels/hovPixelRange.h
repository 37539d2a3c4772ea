/**
 * @file    hovPixelRange.h
 * @brief   The pixel centres covered by a window-coordinate interval, as ints,
 *          for any double input (huge, infinite or NaN included).
 *
 * Pixel i of an image of @c size pixels has its centre at window coordinate
 * i + 0.5. The centres inside [lo - margin, hi + margin] are
 * i = ceil(lo - 0.5 - margin) .. floor(hi - 0.5 + margin), clamped to
 * [0, size - 1]. Both ends are clamped in double before the conversion to int:
 * a projected coordinate can be far beyond INT_MAX (a camera view angle near
 * 0 magnifies the scene by ~1e10) and converting such a double to int is
 * undefined behaviour. An empty range comes back as first > last; a NaN end
 * gives an empty range.
 */
#ifndef hovPixelRange_h
#define hovPixelRange_h

#include <array> // pixel boxes
#include <cmath> // std::ceil, std::floor, std::isnan

namespace hov
{

/// First and last pixel (inclusive) of a range; empty when First > Last.
struct PixelRange
{
  int First = 0;
  int Last = -1;
  bool Empty() const { return this->First > this->Last; }
};

/// Pixel centres i in [lower, upper] (e.g. a tile's columns) with
/// lo - margin <= i + 0.5 <= hi + margin. Empty if lower > upper.
inline PixelRange PixelCentresIn(double lo, double hi, int lower, int upper, double margin)
{
  PixelRange r{ lower, lower - 1 };
  const double first = std::ceil(lo - 0.5 - margin);
  const double last = std::floor(hi - 0.5 + margin);
  if (std::isnan(first) || std::isnan(last) || lower > upper)
  {
    return r;
  }
  // Clamped in double (to [lower, upper + 1] and [lower - 1, upper]) before
  // the conversion, which is then always defined.
  r.First = first <= lower ? lower : (first > upper ? upper + 1 : static_cast<int>(first));
  r.Last = last >= upper ? upper : (last < lower ? lower - 1 : static_cast<int>(last));
  return r;
}

/// Pixel centres i in [0, size - 1] with lo - margin <= i + 0.5 <= hi + margin.
inline PixelRange PixelCentresIn(double lo, double hi, int size, double margin)
{
  return PixelCentresIn(lo, hi, 0, size - 1, margin);
}

/// The pixel box {i0, i1, j0, j1} (inclusive; empty when i0 > i1 or j0 > j1)
/// of the window-coordinate box [x0, x1] x [y0, y1] widened by @p margin.
template <typename Box = std::array<int, 4>>
inline Box PixelBoxOf(double x0, double x1, double y0, double y1, int width, int height,
  double margin)
{
  const PixelRange x = PixelCentresIn(x0, x1, width, margin);
  const PixelRange y = PixelCentresIn(y0, y1, height, margin);
  return Box{ x.First, x.Last, y.First, y.Last };
}

} // namespace hov

#endif
