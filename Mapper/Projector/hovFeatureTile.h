/**
 * @class   hov::FeatureTile
 * @brief   One image tile of hov::FeatureProjector: exact ray
 *          intervals of the tile's cells, hov::FeatureSegment per
 *          interval, splats, front-to-back compositing in cell order or per
 *          pixel.
 *
 * Linear tetrahedra are clipped against the same canonical face planes as
 * the fast path (hov::CellSetup; the arithmetic of its ClipRay, so
 * exit and entry through a shared face are bit-identical); general cells
 * through hov::GeneralCellTile::Collect. Per pixel the tile keeps the
 * exit of the last composited segment: a segment starting exactly there
 * does not own a surface at its front (hov::FeatureProjector).
 *
 * Thread safety: one object per thread; the frame is read-only.
 * @sa hov::FeatureProjector
 */
#ifndef hovFeatureTile_h
#define hovFeatureTile_h

#include "hovFeatureProjector.h" // Frame
#include "hovFeatureSegment.h"   // per-interval integral
#include "hovGeneralCellTile.h"  // general-cell intervals

#include <vector> // buffers

namespace hov
{
class FeatureTile : public TilePixels
{
public:
  using Frame = hov::FeatureProjector::Frame;
  using Stats = ProjectorStatistics;

  /// Render tile @p tileIndex of @p frame into @p rgba.
  void Render(const Frame& frame, int tileIndex, std::vector<double>& rgba, Stats& stats);

private:
  /// A ray interval (or splat, Splat >= 0) waiting for its turn.
  struct Fragment
  {
    double TIn, TOut;
    int Pixel;
    int Order; ///< ordered cell: deterministic tie-break
    int Splat; ///< -1, or the footprint weight index 3 j + i
    bool operator<(const Fragment& o) const
    {
      return this->TIn != o.TIn ? this->TIn < o.TIn : this->Order < o.Order;
    }
  };

  void Init(const Frame& frame, int tileIndex);
  /// Visit every interval (pixel, tIn, tOut) of ordered cell k in the tile.
  template <typename Visit>
  void ForIntervals(const Frame& frame, vtkIdType k, bool skipDone, Visit&& visit);
  /// Visit every pixel of splat k's footprint in the tile: (pixel, weight index, t).
  template <typename Visit>
  void ForSplatPixels(const Frame& frame, vtkIdType k, Visit&& visit);
  void Segment(const Frame& frame, size_t p, vtkIdType k, double tIn, double tOut, Stats& st);
  void SplatPixel(const Frame& frame, size_t p, vtkIdType k, int weight, Stats& st);
  void Composite(const Frame& frame, size_t p, const hov::RGBA& c);

  std::vector<double> LastExit; ///< exit of the last composited segment (NaN: none)
  std::vector<Fragment> Fragments;
  hov::GeneralCellTile General;
  hov::FeatureSegment Integrator;
};
}

#endif
