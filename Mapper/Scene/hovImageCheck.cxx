#include "hovImageCheck.h"

#include "hovRenderFrame.h" // settings, statistics, messages

#include "vtkSMPTools.h" // the parallel pass

#include <algorithm> // std::min
#include <array>     // the blocks' boxes
#include <atomic>    // the blocks' counts
#include <cfloat>    // FLT_MAX
#include <cmath>     // std::abs
#include <sstream>   // messages
#include <string>    // messages
#include <vector>    // the blocks' boxes

namespace
{
/// Pixels per block of the parallel pass (a block's values stay in cache).
constexpr size_t BlockPixels = 16384;

/// Pixels per chunk of CheckRow (its values stay in L1 between its loops).
constexpr int ChunkPixels = 64;

/// Whether any of the @p n floats is non-zero (branch free: vectorized).
inline bool AnyNonZero(const float* f, size_t n)
{
  unsigned any = 0;
  for (size_t i = 0; i < n; ++i)
  {
    any |= static_cast<unsigned>(f[i] != 0.0f);
  }
  return any != 0;
}

/**
 * One row of @p n pixels (4 values each) at @p rgba: zeroes a pixel with a
 * value that float cannot hold (NaN, Inf, beyond FLT_MAX) and counts it in
 * @p bad, writes the values as float into @p out (or a chunk-sized scratch
 * if it is null) and widens [x0, x1) to the row's non-zero pixels as float
 * (a double below float's smallest denormal, e.g. from a unit distance of
 * 1e300, is published as 0). Chunk by chunk, branch free (the compiler
 * vectorizes the loops): a chunk's values are tested first, and only a
 * chunk with a bad value is looked at pixel by pixel.
 */
template <typename T>
void CheckRow(T* rgba, int n, float* out, size_t& bad, int& x0, int& x1)
{
  float scratch[4 * ChunkPixels];
  for (int c0 = 0; c0 < n; c0 += ChunkPixels)
  {
    const int c1 = std::min(n, c0 + ChunkPixels);
    const size_t v0 = 4 * static_cast<size_t>(c0), v1 = 4 * static_cast<size_t>(c1);
    unsigned ok = 1;
    for (size_t i = v0; i < v1; ++i)
    {
      // False for NaN too.
      ok &= static_cast<unsigned>(std::abs(static_cast<double>(rgba[i])) <= FLT_MAX);
    }
    if (!ok)
    {
      for (size_t i = v0; i < v1; i += 4)
      {
        T* v = rgba + i;
        bool fine = true;
        for (int c = 0; c < 4; ++c)
        {
          fine = fine && std::abs(static_cast<double>(v[c])) <= FLT_MAX;
        }
        if (!fine)
        {
          v[0] = v[1] = v[2] = v[3] = T(0);
          ++bad;
        }
      }
    }
    float* f = out ? out + v0 : scratch;
    for (size_t i = v0; i < v1; ++i)
    {
      f[i - v0] = static_cast<float>(rgba[i]);
    }
    if (!AnyNonZero(f, v1 - v0))
    {
      continue;
    }
    // The chunk's first and last non-zero pixels, if they widen the range.
    int first = c0, last = c1 - 1;
    while (!AnyNonZero(f + 4 * (first - c0), 4))
    {
      ++first;
    }
    while (!AnyNonZero(f + 4 * (last - c0), 4))
    {
      --last;
    }
    x0 = std::min(x0, first);
    x1 = std::max(x1, last + 1);
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
  // Blocks of rows in parallel: a 1024x1024 image is 32 MB of doubles, a
  // serial pass over it several milliseconds of every frame. Each block
  // keeps its box of non-zero pixels; they are merged after the pass.
  const bool rows = frame.Width > 0 && pixels == static_cast<size_t>(frame.Width) * frame.Height;
  const int width = rows ? frame.Width : static_cast<int>(std::min<size_t>(pixels, BlockPixels));
  const size_t height = width > 0 ? (pixels + width - 1) / width : 0;
  const size_t blockRows = std::max<size_t>(1, BlockPixels / std::max(width, 1));
  const vtkIdType blocks = static_cast<vtkIdType>((height + blockRows - 1) / blockRows);
  std::vector<std::array<int, 4>> boxes(blocks, std::array<int, 4>{ width, 0, 0, 0 });
  std::atomic<size_t> badPixels{ 0 };
  // Outside the backend's content box every value is zero: only written
  // (as float zero), not read (a 1024x1024 frame of a mesh that covers a
  // fifth of it: 3.4 -> 2.4 ms).
  int content[4] = { 0, width, 0, static_cast<int>(height) };
  if (rows)
  {
    content[0] = std::min(std::max(frame.Content[0], 0), width);
    content[1] = std::min(std::max(frame.Content[1], content[0]), width);
    content[2] = std::min(std::max(frame.Content[2], 0), frame.Height);
    content[3] = std::min(std::max(frame.Content[3], content[2]), frame.Height);
  }
  vtkSMPTools::For(0, blocks, 1, [&](vtkIdType b0, vtkIdType b1) {
    size_t bad = 0;
    for (vtkIdType b = b0; b < b1; ++b)
    {
      std::array<int, 4>& box = boxes[b];
      const size_t y0 = b * blockRows, y1 = std::min(height, y0 + blockRows);
      for (size_t y = y0; y < y1; ++y)
      {
        const size_t p = y * width;
        const int n = static_cast<int>(std::min<size_t>(width, pixels - p));
        // This row's part of the content box: [c0, c1).
        const bool inside = static_cast<int>(y) >= content[2] && static_cast<int>(y) < content[3];
        const int c0 = inside ? std::min(content[0], n) : n;
        const int c1 = inside ? std::min(content[1], n) : n;
        if (out)
        {
          std::fill(out + 4 * p, out + 4 * (p + c0), 0.0f);
          std::fill(out + 4 * (p + c1), out + 4 * (p + n), 0.0f);
        }
        int x0 = width, x1 = 0;
        if (c0 < c1)
        {
          CheckRow(rgba + 4 * (p + c0), c1 - c0, out ? out + 4 * (p + c0) : nullptr, bad, x0, x1);
          x0 += c0;
          x1 += c0;
        }
        if (x0 < x1)
        {
          box[0] = std::min(box[0], x0);
          box[1] = std::max(box[1], x1);
          box[2] = box[3] > box[2] ? box[2] : static_cast<int>(y);
          box[3] = static_cast<int>(y) + 1;
        }
      }
    }
    badPixels += bad;
  });
  int box[4] = { width, 0, 0, 0 }; // x0, x1, y0, y1 (half-open)
  for (const std::array<int, 4>& b : boxes)
  {
    if (b[0] < b[1])
    {
      box[0] = std::min(box[0], b[0]);
      box[1] = std::max(box[1], b[1]);
      box[2] = box[3] > box[2] ? std::min(box[2], b[2]) : b[2];
      box[3] = std::max(box[3], b[3]);
    }
  }
  const bool anyNonZero = box[0] < box[1];
  if (!anyNonZero)
  {
    box[0] = box[1] = box[2] = box[3] = 0;
  }
  else if (!rows)
  {
    // Not the frame's rows (never so today): the whole frame, to be safe.
    box[0] = box[2] = 0;
    box[1] = std::max(frame.Width, 0);
    box[3] = std::max(frame.Height, 0);
  }
  std::copy(box, box + 4, this->NonZeroBox);
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
  // Nothing to draw (no cell rendered, an invisible transfer function): the
  // backend said why when it found it; said again once a setting changes.
  const bool notDrawn = !frame.Drawn && !frame.Stats.Aborted && !frame.NotDrawnReason.empty();
  if (notDrawn && !frame.NotDrawnWarned &&
    (this->WarnedNotDrawn != frame.NotDrawnReason || this->WarnedTime != settingsTime))
  {
    frame.Warning(frame.NotDrawnReason);
  }
  this->WarnedNotDrawn = notDrawn ? frame.NotDrawnReason : std::string();
  this->WarnedTime = settingsTime;
}

template void hov::ImageCheck::Check<double>(
  double*, size_t, const hov::RenderFrame&, vtkMTimeType, float*);
template void hov::ImageCheck::Check<float>(
  float*, size_t, const hov::RenderFrame&, vtkMTimeType, float*);
