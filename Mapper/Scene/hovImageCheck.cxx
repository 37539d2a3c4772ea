#include "hovImageCheck.h"

#include "hovRenderFrame.h" // settings, statistics, messages

#include "vtkSMPTools.h" // the parallel pass

#include <algorithm> // std::min
#include <atomic>    // the blocks' counts
#include <cfloat>    // FLT_MAX
#include <cmath>     // std::isfinite, std::abs
#include <sstream>   // messages
#include <string>    // messages

namespace
{
/// Pixels per block of the parallel pass (a block's values stay in cache).
constexpr size_t BlockPixels = 16384;

/**
 * One pass over the pixels [b, e) (4 values each): zeroes a pixel with a
 * value that float cannot hold (NaN, Inf, beyond FLT_MAX) and counts it,
 * writes the values as float into @p out if it is not null, and tells
 * whether any value is non-zero as a float (a double below float's smallest
 * denormal, e.g. from a unit distance of 1e300, is published as 0).
 */
template <typename T>
void CheckPixels(T* rgba, size_t b, size_t e, float* out, size_t& bad, bool& nonZero)
{
  for (size_t p = b; p < e; ++p)
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
    for (int c = 0; c < 4; ++c)
    {
      const float f = static_cast<float>(v[c]);
      nonZero = nonZero || f != 0.0f;
      if (out)
      {
        out[4 * p + c] = f;
      }
    }
  }
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
  T* rgba, size_t pixels, const RenderFrame& frame, vtkMTimeType settingsTime, float* out)
{
  // Blocks in parallel: a 1024x1024 image is 32 MB of doubles, a serial pass
  // over it several milliseconds of every frame.
  std::atomic<size_t> badPixels{ 0 };
  std::atomic<bool> anyNonZero{ false };
  const vtkIdType blocks = static_cast<vtkIdType>((pixels + BlockPixels - 1) / BlockPixels);
  vtkSMPTools::For(0, blocks, 1, [&](vtkIdType b0, vtkIdType b1) {
    size_t bad = 0;
    bool nonZero = false;
    CheckPixels(rgba, static_cast<size_t>(b0) * BlockPixels,
      std::min(pixels, static_cast<size_t>(b1) * BlockPixels), out, bad, nonZero);
    badPixels += bad;
    if (nonZero)
    {
      anyNonZero = true;
    }
  });
  const size_t bad = badPixels;
  if (bad > 0)
  {
    std::ostringstream text;
    text << bad << " of " << pixels << " pixels had a colour that is not finite or beyond "
         << "float's range (EmissionScale " << frame.Settings.EmissionScale
         << ", the colours and the unit distance set the glow); they are drawn transparent.";
    frame.Warning(text.str());
  }
  // An image emptied by the overflow has had its warning: not "empty" too
  // (with the reasons of an image that shows nothing of the volume).
  const bool empty = frame.Drawn && !frame.Stats.Aborted && !anyNonZero && bad == 0;
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

template void hov::ImageCheck::Check<double>(
  double*, size_t, const hov::RenderFrame&, vtkMTimeType, float*);
template void hov::ImageCheck::Check<float>(
  float*, size_t, const hov::RenderFrame&, vtkMTimeType, float*);
