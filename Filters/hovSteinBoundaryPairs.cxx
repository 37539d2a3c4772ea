// Boundary face pairs of vtkSteinVisibilitySort's ADJACENCY_GRAPH (see hovSteinBoundaryPairs.h).
#include "hovSteinBoundaryPairs.h"

#include "hovSteinFacePairs.h" // FillFaceData, ClassifyFacePair
#include "hovSteinPairEdges.h" // PairEdges
#include "hovSteinPairGrid.h"  // FaceData, PairGrid
#include "hovSteinSheets.h"    // BoundaryAdjacency, SheetCover

#include "vtkSMPTools.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <type_traits>

namespace hovStein
{
namespace
{
inline bool Disjoint(const float* a, const float* b)
{
  return a[1] <= b[0] || b[1] <= a[0] || a[3] <= b[2] || b[3] <= a[2];
}

/// The tiles a face's extents cover: ix0, ix1, iy0, iy1 (inclusive).
using TileRange = std::array<int, 4>;

static_assert(6 * static_cast<double>(MaxIndexedCells) < 4294967296.0, "face indices fit");
static_assert(std::is_same<CellIndex, std::int32_t>::value, "TileRecord::Cell holds a CellIndex");

/// Tile lists (CSR) of the EXIT ([0]) and ENTRY ([1]) faces as records, in
/// increasing face order within each tile.
struct TileLists
{
  std::vector<vtkIdType> Start[2]; ///< per tile + 1
  FillBuffer<TileRecord> Records[2];
};

/// Bands of tile rows for BinFaces: band b holds the tiles [Start(b), Start(b + 1)).
struct TileBands
{
  const PairGrid& Grid;
  int Count;
  vtkIdType Start(vtkIdType b) const { return b * this->Grid.NY / this->Count * this->Grid.NX; }
  /// Calls fn(face, roles, tile) for the tiles of band @p b, face by face.
  template <class Fn>
  void ForTiles(vtkIdType b, const std::vector<ViewFace>& faces,
    const FillBuffer<TileRange>& ranges, Fn&& fn) const
  {
    const int y0 = static_cast<int>(this->Start(b) / this->Grid.NX);
    const int y1 = static_cast<int>(this->Start(b + 1) / this->Grid.NX);
    const vtkIdType nf = static_cast<vtkIdType>(faces.size());
    for (vtkIdType i = 0; i < nf; ++i)
    {
      const TileRange& r = ranges[i];
      const int roles = faces[i].Roles & 3;
      for (int iy = std::max(r[2], y0); roles && iy <= std::min(r[3], y1 - 1); ++iy)
      {
        for (int ix = r[0]; ix <= r[1]; ++ix)
        {
          fn(i, roles, static_cast<vtkIdType>(iy) * this->Grid.NX + ix);
        }
      }
    }
  }
};

/**
 * Bins the faces into the tiles they cover as records (@p make(i, k, record)
 * fills face i's EXIT (k = 0) or ENTRY (k = 1) record but its Tiles), in
 * parallel over bands of tile rows: each band scans all faces and keeps its
 * own rows, so the lists come out in face order whatever the number of bands
 * and threads; each face's records are made once per band, from its data read
 * in order (not gathered per tile).
 */
template <class MakeRecord>
void BinFaces(const PairGrid& grid, const std::vector<ViewFace>& faces,
  const FillBuffer<TileRange>& ranges, TileLists& lists, MakeRecord&& make)
{
  const vtkIdType nt = static_cast<vtkIdType>(grid.NX) * grid.NY;
  // Enough bands to balance the threads (each scans all faces).
  const int threads = vtkSMPTools::GetEstimatedNumberOfThreads();
  const TileBands bands{ grid, threads > 1 ? std::min(grid.NY, 2 * threads) : 1 };
  for (int k = 0; k < 2; ++k)
  {
    lists.Start[k].assign(nt + 1, 0);
  }
  vtkIdType* count[2] = { lists.Start[0].data() + 1, lists.Start[1].data() + 1 };
  vtkSMPTools::For(0, bands.Count, 1, [&](vtkIdType b0, vtkIdType b1) {
    for (vtkIdType b = b0; b < b1; ++b)
    {
      bands.ForTiles(b, faces, ranges, [&](vtkIdType, int roles, vtkIdType tile) {
        count[0][tile] += roles & 1;
        count[1][tile] += roles >> 1;
      });
    }
  });
  for (int k = 0; k < 2; ++k)
  {
    std::vector<vtkIdType>& start = lists.Start[k];
    for (vtkIdType i = 0; i < nt; ++i)
    {
      start[i + 1] += start[i];
    }
    Refill(lists.Records[k], start[nt]);
  }
  vtkSMPTools::For(0, bands.Count, 1, [&](vtkIdType b0, vtkIdType b1) {
    std::vector<vtkIdType> cursor[2];
    TileRecord proto[2];
    for (vtkIdType b = b0; b < b1; ++b)
    {
      const vtkIdType first = bands.Start(b), last = bands.Start(b + 1);
      for (int k = 0; k < 2; ++k)
      {
        cursor[k].assign(lists.Start[k].begin() + first, lists.Start[k].begin() + last);
      }
      vtkIdType made = -1; // the face whose records proto holds
      bands.ForTiles(b, faces, ranges, [&](vtkIdType i, int roles, vtkIdType tile) {
        if (i != made)
        {
          for (int k = 0; k < 2; ++k)
          {
            if (roles & (1 << k))
            {
              make(i, k, proto[k]);
              for (int q = 0; q < 4; ++q)
              {
                proto[k].Tiles[q] = static_cast<std::int16_t>(ranges[i][q]);
              }
            }
          }
          made = i;
        }
        for (int k = 0; k < 2; ++k)
        {
          if (roles & (1 << k))
          {
            lists.Records[k][cursor[k][tile - first]++] = proto[k];
          }
        }
      });
    }
  });
}

}

/// The per-view buffers (kept between views).
struct BoundaryPairs::Buffers
{
  FillBuffer<FaceData> Data;
  FillBuffer<TileRange> Ranges;
  TileLists Lists;
  std::vector<CellPairs> BlockPairs;
  std::vector<CellRange> BlockRange; ///< of the blocks' first cells
  std::vector<vtkIdType> BlockCount, BlockDropped, BlockKept;
  PairEdges Edges; ///< the blocks' cell pairs made unique and decided
  /// Where the faces overlap deeply, per tile: the largest Depth - Far of its
  /// ENTRY records, rounded up (a record's Depth is at most its Far plus that).
  FillBuffer<double> Thick;
  SheetCover Sheets;
};

namespace
{
/**
 * The cell pairs (ENTRY cell, 2 EXIT cell + 1 if @p certify and the face
 * pair proves the edge) of the face pairs that pass the tests of the file doc
 * and are not dropped by @p sheets (if not null), per tile
 * the EXIT records against the ENTRY records, in parallel over fixed blocks of
 * tiles; appended in tile order. Each face pair is counted (and if dropped,
 * logged to @p log if not null) in the tile of the lower-left corner of the
 * intersection of the extents. Without sheets it is also found there; with
 * sheets, in the first tile of that intersection (in row order) that has no
 * covering sheet between the faces, if any. Where @p depthSorted (each
 * tile's ENTRY records by decreasing Far, b.Thick set), the scan of an EXIT
 * face stops once the remaining ENTRY faces lie in front of it, and with
 * sheets and no log it starts after the ENTRY faces separated from it in the
 * tile: the pairs of that tile that are dropped are then not met, nor
 * counted, and those kept are counted where they are found (the number kept,
 * counted less dropped, does not depend on the skipping).
 */
void FindCellPairs(const Geometry& g, const PairGrid& grid, const SheetCover* sheets,
  bool depthSorted, bool certify, const std::vector<ViewFace>& faces,
  std::vector<BoundaryPairs::FacePair>* log, BoundaryPairs::Buffers& b, PairStats& stats)
{
  const vtkIdType nt = static_cast<vtkIdType>(grid.NX) * grid.NY;
  const vtkIdType numBlocks = std::min<vtkIdType>(nt, 256);
  b.BlockPairs.resize(numBlocks);
  b.BlockRange.resize(numBlocks);
  b.BlockCount.resize(numBlocks);
  b.BlockDropped.resize(numBlocks);
  b.BlockKept.resize(numBlocks);
  std::vector<std::vector<BoundaryPairs::FacePair>> logs(log ? numBlocks : 0);
  const vtkIdType* exitStart = b.Lists.Start[0].data();
  const vtkIdType* entryStart = b.Lists.Start[1].data();
  const bool skip = sheets && depthSorted && !log;
  vtkSMPTools::For(0, numBlocks, 1, [&](vtkIdType b0, vtkIdType b1) {
    for (vtkIdType blk = b0; blk < b1; ++blk)
    {
      CellPairs found; // local (no shared cache lines), with the block's old capacity
      found.swap(b.BlockPairs[blk]);
      found.clear();
      vtkIdType count = 0, dropped = 0, kept = 0;
      // The face pair tests of the EXIT face F against the batch's ENTRY faces.
      constexpr int BatchSize = 16;
      const TileRecord* batch[BatchSize];
      int numBatch = 0;
      auto testBatch = [&](const TileRecord& F) {
        const FaceData& DF = b.Data[F.Face];
        for (int k = 0; k < numBatch; ++k)
        {
          const TileRecord* G = batch[k];
          const int kind = ClassifyFacePair(g, DF, F.Far, b.Data[G->Face], G->Far, certify);
          if (kind != NoCandidate)
          {
            // The ENTRY cell first (the edges' source: they come out
            // bucketed by it), the EXIT cell times 2, plus 1 if the edge
            // needs no test (no overflow: see the static_assert in hovSteinPairEdges.cxx).
            found.emplace_back(G->Cell, 2 * vtkIdType(F.Cell) + (kind == ProvedEdge));
          }
        }
        numBatch = 0;
      };
      for (vtkIdType tile = blk * nt / numBlocks; tile < (blk + 1) * nt / numBlocks; ++tile)
      {
        const int ix = static_cast<int>(tile % grid.NX), iy = static_cast<int>(tile / grid.NX);
        const TileRecord* first = b.Lists.Records[1].data() + entryStart[tile];
        const TileRecord* last = b.Lists.Records[1].data() + entryStart[tile + 1];
        const double thick = depthSorted ? b.Thick[tile] : 0;
        for (vtkIdType i = exitStart[tile]; i < exitStart[tile + 1]; ++i)
        {
          const TileRecord& F = b.Lists.Records[0][i];
          if (i + 2 < exitStart[tile + 1])
          {
            Prefetch(b.Data.data() + b.Lists.Records[0][i + 2].Face);
          }
          // An ENTRY face G with G.Far > nearest has a covering sheet between
          // it and F in this tile.
          const double nearest = sheets ? sheets->NearestRear(tile, F.Far) : VTK_DOUBLE_MAX;
          const TileRecord* G = first;
          if (skip && nearest < VTK_DOUBLE_MAX)
          {
            G = std::partition_point(
              first, last, [nearest](const TileRecord& r) { return r.Far > nearest; });
          }
          for (; G != last; ++G)
          {
            if (G->Depth < F.Depth)
            {
              // Every ENTRY face after G has Depth <= G->Far + thick.
              if (depthSorted && G->Far + thick + 1e-12 * (std::abs(G->Far) + thick) < F.Depth)
              {
                break;
              }
              continue;
            }
            if (G->Cell == F.Cell || Disjoint(F.Box, G->Box))
            {
              continue;
            }
            // The tiles of the intersection of the extents (both faces are in each).
            const int x0 = std::max(F.Tiles[0], G->Tiles[0]);
            const int y0 = std::max(F.Tiles[2], G->Tiles[2]);
            const bool owner = x0 == ix && y0 == iy;
            if (!sheets && !owner)
            {
              continue;
            }
            count += owner;
            if (sheets)
            {
              const int x1 = std::min(F.Tiles[1], G->Tiles[1]);
              const int y1 = std::min(F.Tiles[3], G->Tiles[3]);
              if (G->Far > nearest) // separated in this tile
              {
                if (owner &&
                  ((x0 == x1 && y0 == y1) || sheets->Separates(x0, x1, y0, y1, F.Far, G->Far)))
                {
                  ++dropped; // never consecutive along a ray (hovSteinSheets.h)
                  if (log)
                  {
                    const ViewFace &f = faces[F.Face], &h = faces[G->Face];
                    logs[blk].push_back({ f.Cell, f.Face, h.Cell, h.Face });
                  }
                }
                continue;
              }
              if (!owner)
              {
                if (!sheets->SeparatesBefore(x0, x1, y0, y1, ix, iy, F.Far, G->Far))
                {
                  continue; // found in an earlier tile
                }
                count += skip; // the lower-left tile, separated, skipped it
              }
            }
            ++kept; // found here, once
            // Tested in batches: the face data of a batch's ENTRY faces,
            // scattered through memory, are fetched meanwhile.
            Prefetch(b.Data.data() + G->Face);
            batch[numBatch++] = G;
            if (numBatch == BatchSize)
            {
              testBatch(F);
            }
          }
          testBatch(F);
        }
      }
      vtkIdType lo = VTK_ID_MAX, hi = -1; // the range of first cells
      for (const auto& p : found)
      {
        lo = std::min(lo, p.first);
        hi = std::max(hi, p.first);
      }
      b.BlockRange[blk] = { lo, hi };
      b.BlockPairs[blk].swap(found);
      b.BlockCount[blk] = count;
      b.BlockDropped[blk] = dropped;
      b.BlockKept[blk] = kept;
    }
  });
  for (vtkIdType blk = 0; blk < numBlocks; ++blk)
  {
    stats.FacePairs += b.BlockCount[blk];
    stats.DroppedFacePairs += b.BlockDropped[blk];
    stats.KeptFacePairs += b.BlockKept[blk];
  }
  for (const auto& blockLog : logs)
  {
    log->insert(log->end(), blockLog.begin(), blockLog.end());
  }
}

/**
 * Whether the faces overlap deeply enough for covering sheets to pay: the
 * (EXIT, ENTRY) face pairs sharing a tile, a bound on the candidate pairs,
 * exceed 40 per face. Measured: the bracket 20, blocks of vtkRTAnalyticSource
 * tetrahedra 18-19 (culling dropped under 1% of their face pairs, for ~2 ms
 * of set-up per view); the 0.5M heatsink 130 (culling dropped 75%).
 */
bool DeepOverlap(const PairGrid& grid, const TileLists& lists, vtkIdType numFaces)
{
  double pairs = 0;
  for (vtkIdType tile = 0; tile < grid.NumberOfTiles(); ++tile)
  {
    pairs += static_cast<double>(lists.Start[0][tile + 1] - lists.Start[0][tile]) *
      static_cast<double>(lists.Start[1][tile + 1] - lists.Start[1][tile]);
  }
  return pairs > 40.0 * static_cast<double>(numFaces);
}

}

BoundaryPairs::BoundaryPairs()
  : B(new Buffers)
{
}

BoundaryPairs::~BoundaryPairs() = default;

void BoundaryPairs::ReleaseBuffers()
{
  this->B.reset(new Buffers);
}

void BoundaryPairs::Edges(const Geometry& g, const Topology& t, const View& v,
  const std::vector<ViewFace>& faces, FillBuffer<vtkIdType>& offsets,
  FillBuffer<vtkIdType>& targets, PairStats& stats)
{
  if (this->DroppedLog)
  {
    this->DroppedLog->clear(); // this view's, even when it has none
  }
  const vtkIdType nf = static_cast<vtkIdType>(faces.size());
  if (nf < 2)
  {
    offsets.assign(g.NumberOfCells + 1, 0);
    targets.clear();
    return;
  }
  Buffers& b = *this->B;
  Refill(b.Data, nf); // every record is filled
  vtkSMPTools::For(0, nf, 4096, [&](vtkIdType begin, vtkIdType end) {
    for (vtkIdType i = begin; i < end; ++i)
    {
      FillFaceData(g, v, faces[i], b.Data[i]);
    }
  });
  const PairGrid grid = MakePairGrid(v, b.Data);
  Refill(b.Ranges, nf);
  vtkSMPTools::For(0, nf, 4096, [&](vtkIdType begin, vtkIdType end) {
    for (vtkIdType i = begin; i < end; ++i)
    {
      const float* box = b.Data[i].Box;
      b.Ranges[i] = { grid.IX(box[0]), grid.IX(box[1]), grid.IY(box[2]), grid.IY(box[3]) };
    }
  });
  // The EXIT and ENTRY faces as contiguous records in tile order (the search
  // streams through them and rejects almost every candidate on them).
  const double diagonal = g.Diagonal;
  BinFaces(grid, faces, b.Ranges, b.Lists, [&](vtkIdType i, int k, TileRecord& r) {
    const FaceData& d = b.Data[i];
    std::copy(d.Box, d.Box + 4, r.Box);
    r.Depth = k == 1 ? d.Rear : DepthBefore(d.Front, diagonal);
    r.Far = k == 1 ? DepthBefore(d.Front, diagonal) : DepthAfter(d.Rear, diagonal);
    r.Cell = static_cast<CellIndex>(faces[i].Cell);
    r.Face = static_cast<std::uint32_t>(i);
  });
  // Where the faces overlap deeply: the covering sheets, then each tile's
  // ENTRY records by decreasing Far.
  const bool deep = DeepOverlap(grid, b.Lists, nf);
  const SheetCover* sheets = nullptr;
  if (this->SheetCulling == CullAlways || (this->SheetCulling == CullWhereDeep && deep))
  {
    if (!this->Adjacency)
    {
      this->Adjacency.reset(new BoundaryAdjacency);
    }
    BoundaryAdjacency& adjacency = *this->Adjacency;
    if (adjacency.Generation != t.Generation || adjacency.Across.size() != 4 * t.Boundary.size())
    {
      adjacency.Build(g, t); // once per topology: kept by ReleaseBuffers()
    }
    // (From the ENTRY records still in face order within each tile.)
    b.Sheets.Build(g, t, v, adjacency, faces, b.Data, grid, b.Lists.Start[1].data(),
      b.Lists.Records[1].data());
    stats.Sheets = b.Sheets.GetStats();
    sheets = &b.Sheets;
  }
  // Each tile's ENTRY records by decreasing Far (their front depth), so that
  // the search can skip those behind a covering sheet and stop once the rest
  // lie in front of an EXIT face (the pairs found do not depend on the order:
  // they are sorted and made unique afterwards).
  const vtkIdType* entryStart = b.Lists.Start[1].data();
  Refill(b.Thick, deep ? grid.NumberOfTiles() : 0); // every tile is set below
  vtkSMPTools::For(0, deep ? grid.NumberOfTiles() : 0, 256, [&](vtkIdType begin, vtkIdType end) {
    for (vtkIdType tile = begin; tile < end; ++tile)
    {
      const auto records = b.Lists.Records[1].begin();
      std::sort(records + entryStart[tile], records + entryStart[tile + 1],
        [](const TileRecord& x, const TileRecord& y) {
          return x.Far > y.Far || (x.Far == y.Far && x.Face < y.Face);
        });
      double thick = 0;
      for (vtkIdType i = entryStart[tile]; i < entryStart[tile + 1]; ++i)
      {
        thick = std::max(thick, b.Lists.Records[1][i].Depth - b.Lists.Records[1][i].Far);
      }
      b.Thick[tile] = thick * (1 + 1e-12);
    }
  });
  FindCellPairs(g, grid, sheets, deep, this->CertifiedEdges, faces, this->DroppedLog, b, stats);
  b.Edges.Collect(b.BlockPairs, b.BlockRange);
  stats.Tests += b.Edges.Decide(g, v, offsets, targets);
}
}
