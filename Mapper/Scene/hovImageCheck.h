/**
 * @class   hov::ImageCheck
 * @brief   The checks every render mode applies to the float image it
 *          produced (issue 21; README, "Failures and messages: the rule").
 *
 * - The image never holds NaN or Inf: a pixel whose colour is not finite or
 *   beyond float's range is drawn transparent and counted in one warning per
 *   frame.
 * - The box of its non-zero pixels is kept (GetNonZeroBox()): only that
 *   part is drawn (hov::ImageDisplay), the rest of the image being zero.
 * - An empty image comes with a warning saying why, once until an image is
 *   not empty again or a setting changes (not when the overflow above is what
 *   emptied it: that has its own warning); a frame that was aborted has had its
 *   own message, and one that had nothing to draw (RenderFrame::Drawn false)
 *   had its reason (RenderFrame::NotDrawnReason) said by the backend when it
 *   found it, and here again once a setting changes.
 *
 * Thread safety: rendering thread only (it keeps the warned state between frames).
 * @sa hov::RenderFrame, vtkHighOrderVolumeMapper
 */
#ifndef hovImageCheck_h
#define hovImageCheck_h

#include "vtkType.h" // vtkMTimeType

#include <cstddef> // size_t
#include <string>  // the reason warned

namespace hov
{
class RenderFrame;

class ImageCheck
{
public:
  /**
   * Check @p pixels RGBA values of @p rgba (4 per pixel) of @p frame (see the
   * class doc); @p settingsTime is the mapper's modification time (a changed
   * setting warns about an empty image again). If @p out is not null, the
   * checked values are also written there as float (4 per pixel), in the same
   * parallel pass. @p pixels is the frame's Width x Height. Values outside
   * the frame's Content box are the backend's promised zeros: not read nor
   * checked, written as float zeros.
   */
  template <typename T>
  void Check(T* rgba, size_t pixels, const RenderFrame& frame, vtkMTimeType settingsTime,
    float* out = nullptr);

  /**
   * The smallest box holding every pixel of the last checked image that is
   * not zero as float: columns [x0, x1), rows [y0, y1), as {x0, x1, y0, y1};
   * all 0 for an image that is zero everywhere.
   */
  const int* GetNonZeroBox() const { return this->NonZeroBox; }

private:
  int NonZeroBox[4] = { 0, 0, 0, 0 };
  bool WarnedEmptyImage = false;
  std::string WarnedNotDrawn; ///< the last frame's RenderFrame::NotDrawnReason
  vtkMTimeType WarnedTime = 0;
};
}

#endif
