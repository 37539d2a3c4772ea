/**
 * @file    hovTileSkeleton.h
 * @brief   The one tile skeleton of the CPU cell projector (HIAC 5.1), shared
 *          by its plain path (hov::CellProjector, hov::ProjectorTile) and its
 *          feature path (hov::FeatureProjector, hov::FeatureTile): the
 *          settings and statistics of a frame, every point projected once,
 *          the cells' pixel boxes binned into square tiles in visibility
 *          order, the pixels of a tile (its rays, accumulated colour, witness
 *          and done flags) and the parallel tile loop with progress and abort.
 *
 * Threads: the tiles run in parallel (vtkSMPTools, hov::ForTileBatches), one
 * tile object per thread kept across tiles and frames (its buffers keep their
 * capacity; the result does not depend on which thread runs a tile); every
 * pixel belongs to one tile, whose cells come in the order given, so the image
 * is bit-identical for any number of threads.
 *
 * Thread safety: TileBins::Build and ProjectPoints run vtkSMPTools loops; a
 * TilePixels belongs to one thread.
 * @sa hov::CellProjector, hov::FeatureProjector, hovTileBatches.h
 */
#ifndef hovTileSkeleton_h
#define hovTileSkeleton_h

#include "hovTileBatches.h" // ProgressFunction, ForTileBatches, ClearTiles
#include "hovViewRays.h"    // Ray

#include "hovCompositing.h"   // RGBA
#include "hovRayIntegrator.h" // IntegrationSettings

#include "vtkSMPThreadLocal.h" // one tile per thread
#include "vtkType.h"           // vtkIdType

#include <glm/glm.hpp> // dvec2, dvec3

#include <algorithm> // std::min, std::max
#include <array>     // pixel boxes
#include <climits>   // INT_MAX
#include <vector>    // buffers

namespace hov
{
/// Settings of a CPU projector frame.
struct ProjectorSettings
{
  IntegrationSettings Integration;
  double TerminationTransmittance = 1e-9;
  int TileSize = 32;
  /// Largest memory of the per-frame cell records of the whole order
  /// (hov::CellRecords); beyond it each tile builds its own cells' records.
  size_t RecordBudget = size_t(256) << 20;
  /// Order each pixel's segments by entry distance instead of trusting the
  /// cell order (exact for any set of non-overlapping cells).
  bool PerPixelSort = false;
  /// Bin no tetrahedron or linear cell whose scalar range has no extinction
  /// (hov::CellRecords; only where each of its segments is exactly zero:
  /// Williams-Max emission).
  bool SkipTransparent = false;
  /// If set: called between tile batches with the fraction done; true aborts (hovTileBatches.h).
  ProgressFunction Progress;
};

/// What a CPU projector frame reports.
struct ProjectorStatistics
{
  vtkIdType WitnessViolations = 0; ///< pixels where the order was wrong
  vtkIdType Segments = 0;          ///< ray-cell segments integrated
  vtkIdType Pieces = 0;            ///< pieces integrated (>= Segments)
  vtkIdType Records = 0;           ///< cell records built (hov::CellRecords)
  vtkIdType TransparentCells = 0;  ///< cells skipped: no extinction over their range
  double ShadingErrorEstimate = 0.0; ///< worst estimate of a shaded quadrature segment
  bool Aborted = false;            ///< Progress returned true: unrendered tiles are zero
  /// Columns [x0, x1) and rows [y0, y1), {x0, x1, y0, y1}, outside of which
  /// every pixel of the image is zero (tiles without cells); all of it
  /// unless the projector says less.
  std::array<int, 4> Content = { 0, INT_MAX, 0, INT_MAX };
};

/// A cell's pixel box: i0, i1, j0, j1 inclusive; i0 > i1 means empty.
using CellBox = std::array<int, 4>;

/// Pixel centres inside a projection are those within this many pixels of it
/// (slack against round-off; the per-pixel ray test that follows is exact).
constexpr double BoxMargin = 1e-6;
/// Largest tile side (vtkHighOrderVolumeMapper clamps TileSize to it).
constexpr int MaxTileSize = 256;
/// Witness tolerance: a later cell may start this much (relative to the view
/// depth) in front of the farthest exit so far before the order counts as
/// wrong. Exits and entries through a shared face are bit-identical
/// (canonical planes), so this only absorbs round-off at edges and vertices.
constexpr double WitnessRelativeTolerance = 1e-9;

/// The tile side of @p settings (clamped to [4, MaxTileSize]).
inline int TileSizeOf(const ProjectorSettings& settings)
{
  return std::min(std::max(4, settings.TileSize), MaxTileSize);
}

/// Every point projected to window coordinates (pixel centres at
/// half-integers); Projectable: in front of the eye plane.
struct ProjectedPoints
{
  std::vector<glm::dvec2> Window;
  std::vector<unsigned char> Projectable;
  void Project(const ViewRays& rays, const std::vector<glm::dvec3>& points);
};

/// Cells binned into image tiles, each tile's list in the order given.
struct TileBins
{
  int Size = 32, TilesX = 0, TilesY = 0;
  std::vector<vtkIdType> Start; ///< per tile, into Cells
  std::vector<vtkIdType> Cells; ///< ordered-cell indices
  std::vector<vtkIdType> Fill;  ///< scratch: per chunk and tile
  static constexpr int Chunks = 16; ///< cell chunks binned in parallel
  /// Bin the cells whose pixel boxes are @p boxes (per ordered cell).
  void Build(const std::vector<CellBox>& boxes, int width, int height, int tileSize);
  int NumberOfTiles() const { return this->TilesX * this->TilesY; }
  /// The pixels of the tiles with cells, as ProjectorStatistics::Content
  /// (all zero if none) for an image of @p width x @p height.
  std::array<int, 4> ContentBox(int width, int height) const;
};

/// The pixels of one tile (tile-local pixel p = j W + i) and what is
/// accumulated in them; a tile renderer derives from it.
class TilePixels
{
public:
  /**
   * Size the tile @p tileIndex of @p bins and trace its rays
   * (hov::ViewRays::TracedPixelRay: OpenGL pixel centres, the opaque
   * @p depth of the frame or null, the clipping); nothing accumulated yet.
   */
  void InitPixels(const ViewRays& rays, const float* depth, const TileBins& bins, int tileIndex);

  /// Witness update of pixel p for a segment [tIn, tOut] composited next.
  void Witness(size_t p, double tIn, double tOut, double tolerance)
  {
    if (tIn < this->MaxExit[p] - tolerance)
    {
      this->Violated[p] = 1;
    }
    this->MaxExit[p] = std::max(this->MaxExit[p], tOut);
  }

  /// The tile's accumulated pixels into @p rgba (image width @p width), the
  /// witness flags into @p stats.
  void WritePixels(std::vector<double>& rgba, int width, ProjectorStatistics& stats) const;

  /// Write tile @p tileIndex transparent (no cell overlaps it; no rays traced).
  static void WriteEmptyTile(
    const TileBins& bins, int width, int height, int tileIndex, std::vector<double>& rgba);

protected:
  int X0 = 0, Y0 = 0, W = 0, H = 0;
  std::vector<ViewRays::Ray> Rays;
  std::vector<double> TMax;
  std::vector<RGBA> Accum;
  std::vector<double> MaxExit;
  std::vector<unsigned char> Violated;
  std::vector<unsigned char> Done;
};

/**
 * The tile loop of a frame: every tile of @p bins rendered by
 * @p tiles.Local().Render(frame, tile, rgba, stats) in parallel (in batches
 * with progress reports if @p progress is set), the tiles an abort left out
 * zeroed, the tiles' statistics summed.
 */
template <typename Tile, typename Frame>
ProjectorStatistics RunTiles(const TileBins& bins, int width, int height,
  const ProgressFunction& progress, vtkSMPThreadLocal<Tile>& tiles, const Frame& frame,
  std::vector<double>& rgba)
{
  const int numTiles = bins.NumberOfTiles();
  std::vector<ProjectorStatistics> tileStats(numTiles);
  const int tilesDone = ForTileBatches(numTiles, progress,
    [&](vtkIdType t) { tiles.Local().Render(frame, static_cast<int>(t), rgba, tileStats[t]); });
  ProjectorStatistics stats;
  stats.Aborted = tilesDone < numTiles;
  ClearTiles(tilesDone, numTiles, bins.TilesX, bins.Size, width, height, rgba);
  for (const ProjectorStatistics& st : tileStats)
  {
    stats.WitnessViolations += st.WitnessViolations;
    stats.Segments += st.Segments;
    stats.Pieces += st.Pieces;
    stats.Records += st.Records;
    stats.ShadingErrorEstimate = std::max(stats.ShadingErrorEstimate, st.ShadingErrorEstimate);
  }
  return stats;
}
}

#endif
