/**
 * @class   hov::ProjectorTile
 * @brief   One image tile of hov::CellProjector: scan conversion of the
 *          tile's cells, exact ray clipping, batched segment integrals and
 *          front-to-back compositing.
 *
 * The projector bins its cells (in visibility order) into square tiles; a
 * tile is rendered by one thread with this object, which keeps its buffers
 * from tile to tile (nothing is allocated per tile once they have grown).
 *
 * Visibility order (RenderInCellOrder): cell by cell, the segments of the
 * cell's covered, not yet opaque pixels are gathered, integrated together by
 * hov::SegmentBatch (independent pixels: the batch hides the latency of the
 * series) and composited behind what each pixel holds. A pixel receives its
 * segments in exactly the cell order, as when integrating one at a time.
 * Per cell (QueueCellSegments): the pixel range of each of its rows, four
 * rows per vector (RowRanges), then all its rows clipped in one call
 * (ClipRows: four or two pixels per vector, the results written straight
 * into the queue's arrays, hovProjectorTileLanes.h); a row is only
 * revisited pixel by pixel if some pixel missed, was undecided (a ray in a
 * face's plane) or is already opaque. Tiles that no cell overlaps are
 * written transparent without tracing their rays.
 *
 * Per-pixel order (RenderPerPixel; the projector then orders the cells by
 * centroid depth, so fragments arrive nearly sorted): every segment of the
 * tile becomes a fragment; fragments are bucketed by pixel, sorted by entry distance,
 * integrated in one batch and composited pixel by pixel in that order,
 * stopping where the pixel becomes opaque.
 *
 * General cells (hexahedra, wedges, ..., quadratic cells: Frame::General,
 * hov::GeneralCellTile, in hovProjectorTileGeneral.cxx) take
 * their turn in the same order: in cell order the queued tetra segments are
 * flushed, then each covered pixel composites the cell's intervals (first
 * entry and last exit for the witness); per pixel, every interval is a
 * fragment sorted with the others.
 *
 * Both give bit for bit the image of integrating and compositing one segment
 * at a time (SegmentBatch is bit-identical to the scalar kernels), for any
 * number of threads.
 *
 * Thread safety: one object per thread; Frame is shared read-only.
 * @sa hov::CellProjector, hovSegmentBatch.h
 */
#ifndef hovProjectorTile_h
#define hovProjectorTile_h

#include "hovGeneralCellTile.h" // non-tetrahedral cells
#include "hovTileSkeleton.h"    // TilePixels, TileBins, settings, statistics

#include "hovSegmentBatch.h" // batched integrals

#include <vector> // buffers

namespace hov::tile
{
struct ProjectedEdges;
}

namespace hov
{
class CellRecords;

class ProjectorTile : public TilePixels
{
public:
  using Box = CellBox;
  using Statistics = ProjectorStatistics;

  /**
   * Everything the tile loop reads of a cell, per ordered cell (built each
   * frame by hov::CellRecords in one parallel pass, or by each tile for its
   * own cells beyond the memory budget): the tile loop then reads a few
   * consecutive cache lines per cell instead of a scattered tetrahedron, four
   * scattered points and several per-cell arrays.
   */
  struct CellRecord
  {
    double NX[4], NY[4], NZ[4], Offset[4]; ///< face k: (NX,NY,NZ)[k] . x <= Offset[k]
    glm::dvec3 Gradient;                   ///< as hov::CellSetup::Tetra
    glm::dvec3 RefPoint;
    double RefScalar;
    glm::dvec2 Vertex[4]; ///< projected vertices (window coordinates)
    Box PixelBox;         ///< pixel centres of the projected bounding box
    int Interval; ///< transfer-function interval of the whole cell, or a search hint (hov::SegmentJob)
    bool Projectable;     ///< every vertex in front of the eye plane
  };

  /// The rays of a tile as arrays per coordinate (padded: a block of pixel
  /// lanes may read past any pixel), for the lanes of hovTileGeometry.h.
  struct TileRays
  {
    const double *OX, *OY, *OZ, *DX, *DY, *DZ, *TMax;
  };

  /// Everything the tiles of one frame read.
  struct Frame
  {
    const TileBins* Bins;
    /// Per ordered cell; null: each tile builds its cells' records from Records.
    const std::vector<CellRecord>* Cells;
    const CellRecords* Records = nullptr;
    const hov::TransferFunction* TF;
    const ProjectorSettings* Settings;
    const hov::ViewRays* Rays;
    const float* Depth;
    double WitnessTol;
    glm::dvec3 PerturbX, PerturbY;
    /// The general cells, or null if there are none (tetrahedra only).
    const hov::GeneralCellTile::FrameData* General = nullptr;
  };

  /// Render tile @p tileIndex of @p frame and write it into @p rgba.
  void Render(const Frame& frame, int tileIndex, std::vector<double>& rgba,
    Statistics& stats);

  /// Frees the buffers of the per-tile records (see Frame::Cells).
  void ReleaseLocalRecords();

private:
  /// Render() with the records of the tile's cells @p cells (@p count) in frame.Cells.
  void RenderCells(const Frame& frame, int tileIndex, const vtkIdType* cells, vtkIdType count,
    std::vector<double>& rgba, Statistics& stats);
  void Init(const Frame& frame, int tileIndex);
  void RenderInCellOrder(const Frame& frame, const vtkIdType* cells, vtkIdType count,
    Statistics& st);
  void RenderPerPixel(const Frame& frame, const vtkIdType* cells, vtkIdType count,
    Statistics& st);
  void CollectFragments(const Frame& frame, const vtkIdType* cells, vtkIdType count);
  void CompositeFragments(const Frame& frame, Statistics& st);
  /// Rows [r0, r1] of the tile's pixels (tile coordinates) where ordered
  /// cell @p cell may cover pixel centres on tile row @p j; false if none.
  bool RowRange(const CellRecord& cell, const tile::ProjectedEdges& edges, int j, int& r0, int& r1) const;
  /// Visit the segments of ordered cell k in rows [RowBegin, RowEnd) of the tile.
  template <typename Visit>
  void ForCellSegments(const Frame& frame, vtkIdType k, Visit&& visit);
  /// Cell order: queue the segments of ordered cell k at the tile's
  /// unfinished pixels (clipped straight into the queue's arrays).
  void QueueCellSegments(const Frame& frame, vtkIdType k);
  /// QueueCellSegments() for a cell where some lane did not simply hit or
  /// some pixel is done: the row of pixels [p0, p0 + count) clipped at queue
  /// position @p src is appended to the queue, keeping the hits in order and
  /// resolving undecided rays.
  void CompactRow(const Frame& frame, const CellRecord& cell, size_t p0, int count, int src);
  /// Make room for @p n queued segments (plus a block of padding lanes).
  void ReserveQueue(int n);
  /// Queue a segment of pixel p for the next Flush() (per-pixel order).
  void Queue(size_t p, double tIn, double tOut, double sIn, double sOut, int interval);
  /// Integrate the queued segments together, then composite them in queue order.
  void Flush(const Frame& frame, Statistics& st);
  /// Composite a segment's RGBA behind pixel p; marks it done when opaque.
  void Composite(const Frame& frame, size_t p, const hov::RGBA& seg);
  /// True if ordered cell k is a general cell.
  static bool IsGeneral(const Frame& frame, vtkIdType k)
  {
    return frame.General && (*frame.General->GeneralOf)[k] >= 0;
  }
  /// Cell order: composite general cell k into every covered, unfinished pixel.
  void RenderGeneralCell(const Frame& frame, vtkIdType k, Statistics& st);
  /// Per-pixel order: one fragment per ray interval of general cell k.
  void CollectGeneralFragments(const Frame& frame, vtkIdType k);
  /// Per-pixel order: integrate and composite a general cell's interval at pixel p.
  void CompositeGeneralInterval(const Frame& frame, size_t p, double tIn, double tOut,
    vtkIdType k, Statistics& st);
  /// The tile's rows [RowBegin, RowEnd) for the general-cell scan conversion.
  hov::GeneralCellTile::TileRows Rows() const
  {
    return { this->X0, this->Y0, this->W, this->RowBegin, this->RowEnd, this->Rays.data(),
      this->TMax.data() };
  }

  /// A ray-cell segment waiting for its turn (per-pixel ordering).
  struct Fragment
  {
    double TIn, TOut, SIn, SOut;
    int Pixel;
    int Order; ///< ordered-cell index: a deterministic tie-break
    bool operator<(const Fragment& o) const
    {
      return this->TIn != o.TIn ? this->TIn < o.TIn : this->Order < o.Order;
    }
  };

  int RowBegin = 0, RowEnd = 0; ///< rows ForCellSegments visits
  /// Per-pixel mode: pixels per band of rows (a band's fragments, some
  /// thousands, stay in the L1/L2 cache while they are bucketed and sorted).
  static constexpr int BandPixels = 64;
  std::vector<double> LaneStore;   ///< the rays per coordinate (hovProjectorTileLanes.h)
  TileRays LaneRays{};
  std::vector<Fragment> Fragments; ///< in cell order (NumFragments used)
  int NumFragments = 0;
  std::vector<Fragment> ByPixel;   ///< bucketed by pixel, then sorted by entry
  std::vector<int> PixelStart;
  std::vector<int> Fill;
  std::vector<int> DoneInRow;      ///< per tile row: pixels done
  /// Segments queued per Flush(): enough for full four-lane blocks of every
  /// term count, few enough to stay in the L1/L2 cache.
  static constexpr int BatchSize = 256;
  /// The queued segments, one array per field (the pixel lanes write them
  /// directly); QueueCapacity entries each, NumQueued used.
  std::vector<double> QueueStore;
  double *QTIn = nullptr, *QTOut = nullptr, *QSIn = nullptr, *QSOut = nullptr, *QLength = nullptr;
  std::vector<int> QPixel, QInterval;
  int QueueCapacity = 0;
  int NumQueued = 0;
  std::vector<hov::RGBA> Results;
  std::vector<int> Pieces;
  hov::SegmentBatch Batch;
  hov::GeneralCellTile General; ///< scratch of the general-cell path
  /// Per-tile records (Frame::Cells null): the tile's cells' records, their
  /// indices 0 .. n-1 and their general-cell indices.
  std::vector<CellRecord> LocalRecords;
  std::vector<vtkIdType> LocalCells;
  std::vector<int> LocalGeneralOf;
};
}

#endif
