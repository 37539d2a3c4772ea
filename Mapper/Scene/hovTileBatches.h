/**
 * @file   hovTileBatches.h
 * @brief  Tile loop of the CPU projectors with progress reports and abort.
 *
 * hov::ForTileBatches runs the tiles [0, numTiles) through
 * vtkSMPTools::For. Without a progress callback it is one parallel loop.
 * With one, the tiles run in about ProgressBatches consecutive batches (each
 * a parallel loop; a batch that takes longer than ProgressBatchSeconds makes
 * the next ones smaller, so that a long frame answers an abort within about
 * that time) and the callback is called on the calling thread after each
 * batch with the fraction of tiles done (ending at exactly 1), and once with 0
 * before the first (an abort requested during the set-up); if it returns true
 * the remaining batches are skipped. Every pixel belongs to one
 * tile and a tile's result does not depend on when or where it runs, so the
 * image of a completed render is bit-identical with or without batches.
 * hov::ClearTiles zeroes the pixels of the tiles that did not run.
 *
 * Thread safety: the callback is only called from the calling thread.
 * @sa hov::CellProjector, hov::FeatureProjector
 */
#ifndef hovTileBatches_h
#define hovTileBatches_h

#include "vtkSMPTools.h"

#include <algorithm>  // std::min
#include <chrono>     // batch times
#include <functional> // std::function
#include <vector>     // the image

namespace hov
{
/// Progress callback: fraction of tiles done in (0, 1]; return true to abort.
using ProgressFunction = std::function<bool(double)>;

/// Number of batches the tiles are split into when progress is reported.
constexpr int ProgressBatches = 128;

/// Longest wall time of a batch between two progress reports (seconds).
constexpr double ProgressBatchSeconds = 0.04;

/**
 * Run @p tileFunction(t) for every tile t (in parallel, see the file doc).
 * Returns the number of tiles run: numTiles unless @p progress aborted.
 */
template <typename TileFunction>
int ForTileBatches(
  int numTiles, const ProgressFunction& progress, TileFunction&& tileFunction)
{
  int batch = progress ? std::max(1, (numTiles + ProgressBatches - 1) / ProgressBatches)
                       : std::max(1, numTiles);
  int done = 0;
  if (progress && progress(0.0))
  {
    return 0; // aborted during the set-up before the tiles
  }
  while (done < numTiles)
  {
    const auto start = std::chrono::steady_clock::now();
    const int end = std::min(numTiles, done + batch);
    vtkSMPTools::For(done, end, 1, [&](vtkIdType t0, vtkIdType t1) {
      for (vtkIdType t = t0; t < t1; ++t)
      {
        tileFunction(t);
      }
    });
    done = end;
    const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (progress && seconds > ProgressBatchSeconds)
    {
      batch = std::max(1, static_cast<int>(batch * ProgressBatchSeconds / seconds));
    }
    if (progress && progress(static_cast<double>(done) / numTiles) && done < numTiles)
    {
      break;
    }
  }
  return done;
}

/// Zero the RGBA pixels of tiles [firstTile, numTiles) (tiles of @p tileSize, @p tilesX per row).
inline void ClearTiles(int firstTile, int numTiles, int tilesX, int tileSize,
  int width, int height, std::vector<double>& rgba)
{
  for (int t = firstTile; t < numTiles; ++t)
  {
    const int x0 = (t % tilesX) * tileSize, y0 = (t / tilesX) * tileSize;
    const int x1 = std::min(width, x0 + tileSize), y1 = std::min(height, y0 + tileSize);
    for (int y = y0; y < y1; ++y)
    {
      std::fill(rgba.begin() + (static_cast<size_t>(y) * width + x0) * 4,
        rgba.begin() + (static_cast<size_t>(y) * width + x1) * 4, 0.0);
    }
  }
}

}

#endif
