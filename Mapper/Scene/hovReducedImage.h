/**
 * @file   hovReducedImage.h
 * @brief  Interactive frames at reduced resolution: one ray per f x f block
 *         of pixels (the image of a grid of ceil(W/f) x ceil(H/f) pixel rays
 *         over the same viewport), the nearest opaque depth of each block,
 *         and the reduced image replicated onto every pixel of its block.
 *
 * Full pixel i of n belongs to reduced pixel floor((i + 1/2) m / n) of m, the
 * texel hov::ImageDisplay's blit fetches for it, so the CPU image and the
 * window agree pixel for pixel. With f = 1 nothing is reduced.
 *
 * Thread safety: plain functions.
 * @sa hov::InteractionBudget, vtkHighOrderVolumeMapper (interaction)
 */
#ifndef hovReducedImage_h
#define hovReducedImage_h

#include <algorithm> // std::min
#include <vector>    // buffers

namespace hov
{
/// Pixels of a side of @p n pixels at @p f pixels per ray.
inline int ReducedSize(int n, int f)
{
  return f > 1 ? (n + f - 1) / f : n;
}

/// Reduced pixel (of @p m) of full pixel @p i (of @p n).
inline int ReducedPixel(int i, int n, int m)
{
  return std::min(static_cast<int>((2LL * i + 1) * m / (2LL * n)), m - 1);
}

/// The nearest opaque depth of each reduced pixel's block into @p out.
inline void ReduceDepth(
  const float* depth, int width, int height, int rw, int rh, std::vector<float>& out)
{
  out.assign(static_cast<size_t>(rw) * rh, 1.0f);
  for (int j = 0; j < height; ++j)
  {
    const size_t row = static_cast<size_t>(ReducedPixel(j, height, rh)) * rw;
    for (int i = 0; i < width; ++i)
    {
      float& d = out[row + ReducedPixel(i, width, rw)];
      d = std::min(d, depth[static_cast<size_t>(j) * width + i]);
    }
  }
}

/// The reduced image @p in (@p c values per pixel) onto every pixel of @p out.
template <typename In, typename Out>
void ExpandImage(const In* in, int rw, int rh, int c, Out* out, int width, int height)
{
  for (int j = 0; j < height; ++j)
  {
    const size_t row = static_cast<size_t>(ReducedPixel(j, height, rh)) * rw;
    for (int i = 0; i < width; ++i)
    {
      const In* q = in + (row + ReducedPixel(i, width, rw)) * c;
      Out* p = out + (static_cast<size_t>(j) * width + i) * c;
      for (int k = 0; k < c; ++k)
      {
        p[k] = static_cast<Out>(q[k]);
      }
    }
  }
}
}

#endif
