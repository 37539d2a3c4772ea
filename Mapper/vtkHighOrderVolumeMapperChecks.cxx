// vtkHighOrderVolumeMapper: the checks every render mode applies to a frame
// (issue 21): the view, the float image's range, and the message for an empty
// image. The rule they implement, for every entry point:
//  - RenderImage returns 0 (and reports an error; the image is zero) when it
//    cannot render: no input, no scalars, no property, an unusable camera
//    (hov::CheckView) or size; otherwise 1, also for an image that is empty
//    for a reason of the scene (the volume out of view, transparent, clipped
//    away), which is then reported by a warning.
//  - Render (a window) reports the same errors and warnings and draws nothing
//    where RenderImage returns 0.
//  - The float image never holds NaN or Inf: a pixel whose colour is not
//    finite, or beyond float's range, is drawn transparent and counted in one
//    warning per frame.
#include "vtkHighOrderVolumeMapper.h"

#include "hovViewCheck.h" // the view check

#include "vtkCamera.h"
#include "vtkPlaneCollection.h"
#include "vtkVolume.h"

#include <cfloat> // FLT_MAX
#include <cmath>  // std::isfinite, std::abs
#include <string> // messages

namespace
{
/// Zeroes the pixels (4 values each) with a value that float cannot hold;
/// returns how many.
template <typename T>
size_t ZeroOverflowingPixels(T* rgba, size_t pixels)
{
  size_t bad = 0;
  for (size_t p = 0; p < pixels; ++p)
  {
    T* v = rgba + 4 * p;
    bool ok = true;
    for (int c = 0; c < 4; ++c)
    {
      ok = ok && std::isfinite(v[c]) && std::abs(static_cast<double>(v[c])) <= FLT_MAX;
    }
    if (!ok)
    {
      v[0] = v[1] = v[2] = v[3] = T(0);
      ++bad;
    }
  }
  return bad;
}

/// True if the float image of these values is zero: a double value below
/// float's smallest denormal (e.g. a unit distance of 1e300) is published as 0.
template <typename T>
bool AllZero(const T* rgba, size_t pixels)
{
  for (size_t i = 0; i < 4 * pixels; ++i)
  {
    if (static_cast<float>(rgba[i]) != 0.0f)
    {
      return false;
    }
  }
  return true;
}
}

bool vtkHighOrderVolumeMapper::CheckFrameView(vtkCamera* camera, vtkVolume* volume, double aspect)
{
  const std::string why = hov::CheckView(camera, volume ? volume->GetMatrix() : nullptr, aspect);
  if (!why.empty())
  {
    vtkErrorMacro("Cannot render: " << why << ".");
    return false;
  }
  if (this->ViewDepthClipping &&
    !(std::isfinite(this->ViewDepthRange[0]) && std::isfinite(this->ViewDepthRange[1])))
  {
    vtkErrorMacro("Cannot render: the view-depth range [" << this->ViewDepthRange[0] << ", "
                                                         << this->ViewDepthRange[1]
                                                         << "] is not finite.");
    return false;
  }
  return true;
}

template <typename T>
void vtkHighOrderVolumeMapper::CheckFrameImage(T* rgba, size_t pixels, bool drawn)
{
  const size_t bad = ZeroOverflowingPixels(rgba, pixels);
  if (bad > 0)
  {
    vtkWarningMacro(<< bad << " of " << pixels << " pixels had a colour that is not finite or "
                    << "beyond float's range (EmissionScale " << this->EmissionScale
                    << ", the colours and the unit distance set the glow); they are drawn "
                    << "transparent.");
  }
  // An empty image needs a message: once until an image is not empty again
  // or a setting changes; an aborted frame or one with nothing to draw has had
  // its own.
  const bool empty = drawn && !this->LastRenderAborted && AllZero(rgba, pixels);
  if (empty && (!this->WarnedEmptyImage || this->WarnedEmptyTime != this->GetMTime()))
  {
    std::string why = "it lies outside the view or behind opaque geometry, or is transparent "
                      "there and crosses no isosurface";
    if (this->ViewDepthClipping && !(this->ViewDepthRange[0] < this->ViewDepthRange[1]))
    {
      why = "the view-depth range [" + std::to_string(this->ViewDepthRange[0]) + ", " +
        std::to_string(this->ViewDepthRange[1]) + "] is empty";
    }
    else if (this->ViewDepthClipping ||
      (this->ClippingPlanes && this->ClippingPlanes->GetNumberOfItems() > 0))
    {
      why += ", or the clipping planes / view-depth range leave nothing of it";
    }
    vtkWarningMacro("The image is empty: nothing of the volume's " << this->NumberOfRenderedCells
                                                                   << " rendered cells is "
                                                                      "visible ("
                                                                   << why << ").");
  }
  this->WarnedEmptyImage = empty;
  this->WarnedEmptyTime = this->GetMTime();
}

template void vtkHighOrderVolumeMapper::CheckFrameImage<double>(double*, size_t, bool);
template void vtkHighOrderVolumeMapper::CheckFrameImage<float>(float*, size_t, bool);

void vtkHighOrderVolumeMapper::WarnTransparent()
{
  vtkWarningMacro("The transfer function has no opacity anywhere (and the emission model needs "
                  "extinction to glow): the volume is invisible; nothing rendered.");
}
