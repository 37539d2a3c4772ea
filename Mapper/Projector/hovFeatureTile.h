/**
 * @class   vtkHighOrderFeatureTile
 * @brief   One image tile of vtkHighOrderFeatureProjector: exact ray
 *          intervals of the tile's cells, vtkHighOrderFeatureSegment per
 *          interval, splats, front-to-back compositing in cell order or per
 *          pixel.
 *
 * Linear tetrahedra are clipped against the same canonical face planes as
 * the fast path (vtkHighOrderTetraSetup; the arithmetic of its ClipRay, so
 * exit and entry through a shared face are bit-identical); general cells
 * through vtkHighOrderGeneralCellTile::Collect. Per pixel the tile keeps the
 * exit of the last composited segment: a segment starting exactly there
 * does not own a surface at its front (vtkHighOrderFeatureProjector).
 *
 * Thread safety: one object per thread; the frame is read-only.
 * @sa vtkHighOrderFeatureProjector
 */
#ifndef vtkHighOrderFeatureTile_h
#define vtkHighOrderFeatureTile_h

#include "hovFeatureProjector.h" // Frame
#include "hovFeatureSegment.h"   // per-interval integral
#include "hovGeneralCellTile.h"  // general-cell intervals

#include <vector> // buffers

class vtkHighOrderFeatureTile
{
public:
  using Frame = vtkHighOrderFeatureProjector::Frame;
  using Stats = vtkHighOrderCellProjector::Statistics;

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

  int X0 = 0, Y0 = 0, W = 0, H = 0;
  std::vector<vtkHighOrderViewRays::Ray> Rays;
  std::vector<double> TMax;
  std::vector<hov::RGBA> Accum;
  std::vector<double> LastExit; ///< exit of the last composited segment (NaN: none)
  std::vector<double> MaxExit;
  std::vector<unsigned char> Violated;
  std::vector<unsigned char> Done;
  std::vector<Fragment> Fragments;
  vtkHighOrderGeneralCellTile General;
  vtkHighOrderFeatureSegment Integrator;
};

#endif
