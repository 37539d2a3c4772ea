#include "hovImageCheck.h"

#include "hovRenderFrame.h" // settings, statistics, messages

#include <cfloat>  // FLT_MAX
#include <cmath>   // std::isfinite, std::abs
#include <sstream> // messages
#include <string>  // messages

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

/// Why an image of @p frame is empty.
std::string WhyEmpty(const hov::FrameSettings& s)
{
  std::string why = "it lies outside the view or behind opaque geometry, or is transparent "
                    "there and crosses no isosurface";
  if (s.ViewDepthClipping && !(s.ViewDepthRange[0] < s.ViewDepthRange[1]))
  {
    why = "the view-depth range [" + std::to_string(s.ViewDepthRange[0]) + ", " +
      std::to_string(s.ViewDepthRange[1]) + "] is empty";
  }
  else if (s.ViewDepthClipping || s.HasClippingPlanes)
  {
    why += ", or the clipping planes / view-depth range leave nothing of it";
  }
  return why;
}
}

template <typename T>
void hov::ImageCheck::Check(
  T* rgba, size_t pixels, const RenderFrame& frame, vtkMTimeType settingsTime)
{
  const size_t bad = ZeroOverflowingPixels(rgba, pixels);
  if (bad > 0)
  {
    std::ostringstream text;
    text << bad << " of " << pixels << " pixels had a colour that is not finite or beyond "
         << "float's range (EmissionScale " << frame.Settings.EmissionScale
         << ", the colours and the unit distance set the glow); they are drawn transparent.";
    frame.Warning(text.str());
  }
  const bool empty = frame.Drawn && !frame.Stats.Aborted && AllZero(rgba, pixels);
  if (empty && (!this->WarnedEmptyImage || this->WarnedTime != settingsTime))
  {
    std::ostringstream text;
    text << "The image is empty: nothing of the volume's " << frame.Stats.RenderedCells
         << " rendered cells is visible (" << WhyEmpty(frame.Settings) << ").";
    frame.Warning(text.str());
  }
  this->WarnedEmptyImage = empty;
  this->WarnedTime = settingsTime;
}

template void hov::ImageCheck::Check<double>(double*, size_t, const hov::RenderFrame&, vtkMTimeType);
template void hov::ImageCheck::Check<float>(float*, size_t, const hov::RenderFrame&, vtkMTimeType);
