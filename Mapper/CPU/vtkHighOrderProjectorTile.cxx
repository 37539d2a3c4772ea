#include "vtkHighOrderProjectorTile.h"

#include "vtkHighOrderTileGeometry.h" // ray clipping, row spans

#include "vtkSMPTools.h" // parallel binning

#include <algorithm> // std::min, std::max
#include <cmath>     // std::ceil, std::floor

namespace
{
using Ray = vtkHighOrderViewRays::Ray;
using CellRecord = vtkHighOrderProjectorTile::CellRecord;
using namespace hovTileGeometry;

#ifdef HOV_CLIP_LANES
#if defined(__x86_64__) && !defined(__APPLE__)
#define HOV_SPAN_TARGET_CLONES __attribute__((target_clones("avx2", "default")))
#else
#define HOV_SPAN_TARGET_CLONES
#endif
/**
 * ClipPixelLanes() for the pixels [p, p + count) of a row (the tile's ray
 * arrays are padded for the last block of lanes). Compiled also for AVX2 (one
 * instruction per four-pixel operation), chosen at load time; the operations,
 * hence the results, are the same on every CPU.
 */
HOV_SPAN_TARGET_CLONES
void ClipSpan(const CellRecord& cell, const TileRays& rays, size_t p, int count, double* tIn,
  double* tOut, double* sIn, double* sOut, signed char* hit)
{
  for (int i = 0; i < count; i += PixelLanes)
  {
    ClipPixelLanes(cell, rays, p + i, tIn + i, tOut + i, sIn + i, sOut + i, hit + i);
  }
}
#endif

/// Distance, in cells of a tile's list, at which the per-cell data is
/// prefetched: cells come in visibility (or depth) order, scattered in memory,
/// and each one's few pixels take less time than a cache miss.
constexpr vtkIdType PrefetchDistance = 4;

/// Prefetch what ForCellSegments reads of ordered cell k.
inline void PrefetchCell(const vtkHighOrderProjectorTile::Frame& frame, vtkIdType k)
{
  const char* cell = reinterpret_cast<const char*>(&(*frame.Cells)[k]);
  for (size_t offset = 0; offset < sizeof(CellRecord); offset += 64)
  {
    __builtin_prefetch(cell + offset);
  }
}

/// Insertion sort: linear on the nearly sorted per-pixel lists.
template <typename T>
void InsertionSort(T* first, T* last)
{
  for (T* i = first + 1; i < last; ++i)
  {
    if (!(*i < *(i - 1)))
    {
      continue;
    }
    const T v = *i;
    T* j = i;
    do
    {
      *j = *(j - 1);
      --j;
    } while (j > first && v < *(j - 1));
    *j = v;
  }
}
}

void vtkHighOrderProjectorTile::Bins::Build(
  const std::vector<CellRecord>& cells, int width, int height, int tileSize)
{
  this->Size = tileSize;
  this->TilesX = (width + tileSize - 1) / tileSize;
  this->TilesY = (height + tileSize - 1) / tileSize;
  const int numTiles = this->TilesX * this->TilesY;
  auto forTiles = [&](const Box& b, auto&& f) {
    if (b[0] > b[1] || b[2] > b[3])
    {
      return;
    }
    for (int ty = b[2] / tileSize; ty <= b[3] / tileSize; ++ty)
    {
      for (int tx = b[0] / tileSize; tx <= b[1] / tileSize; ++tx)
      {
        f(ty * this->TilesX + tx);
      }
    }
  };
  // In parallel over a fixed number of cell chunks (the result does not
  // depend on the threads): count per chunk and tile, offsets per tile in
  // chunk order, then each chunk fills its slots; every tile's list stays in
  // cell order.
  const vtkIdType numCells = static_cast<vtkIdType>(cells.size());
  const vtkIdType chunk = (numCells + Chunks - 1) / Chunks;
  this->Fill.assign(static_cast<size_t>(Chunks) * numTiles, 0);
  vtkSMPTools::For(0, Chunks, 1, [&](vtkIdType c0, vtkIdType c1) {
    for (vtkIdType c = c0; c < c1; ++c)
    {
      vtkIdType* count = this->Fill.data() + c * numTiles;
      for (vtkIdType k = c * chunk; k < std::min(numCells, (c + 1) * chunk); ++k)
      {
        forTiles(cells[k].PixelBox, [&](int t) { ++count[t]; });
      }
    }
  });
  this->Start.assign(numTiles + 1, 0);
  vtkIdType next = 0;
  for (int t = 0; t < numTiles; ++t)
  {
    this->Start[t] = next;
    for (int c = 0; c < Chunks; ++c)
    {
      const vtkIdType n = this->Fill[static_cast<size_t>(c) * numTiles + t];
      this->Fill[static_cast<size_t>(c) * numTiles + t] = next; // becomes the write position
      next += n;
    }
  }
  this->Start[numTiles] = next;
  this->Cells.resize(next);
  vtkSMPTools::For(0, Chunks, 1, [&](vtkIdType c0, vtkIdType c1) {
    for (vtkIdType c = c0; c < c1; ++c)
    {
      vtkIdType* fill = this->Fill.data() + c * numTiles;
      for (vtkIdType k = c * chunk; k < std::min(numCells, (c + 1) * chunk); ++k)
      {
        forTiles(cells[k].PixelBox, [&](int t) { this->Cells[fill[t]++] = k; });
      }
    }
  });
}

void vtkHighOrderProjectorTile::Init(const Frame& frame, int tileIndex)
{
  const vtkHighOrderViewRays& rays = *frame.Rays;
  const Bins& bins = *frame.TileBins;
  const int width = rays.GetWidth();
  this->X0 = (tileIndex % bins.TilesX) * bins.Size;
  this->Y0 = (tileIndex / bins.TilesX) * bins.Size;
  this->W = std::min(bins.Size, width - this->X0);
  this->H = std::min(bins.Size, rays.GetHeight() - this->Y0);
  const size_t n = static_cast<size_t>(this->W) * this->H;
  this->Rays.resize(n);
  this->TMax.resize(n);
  this->Accum.assign(n, hov::RGBA());
  this->MaxExit.assign(n, -1e300);
  this->Violated.assign(n, 0);
  this->Done.assign(n, 0);
  this->NumFragments = 0;
  this->RowBegin = 0;
  this->RowEnd = this->H;
  for (int j = 0; j < this->H; ++j)
  {
    for (int i = 0; i < this->W; ++i)
    {
      const int pi = this->X0 + i, pj = this->Y0 + j;
      const size_t p = static_cast<size_t>(j) * this->W + i;
      const double z = frame.Depth ? frame.Depth[static_cast<size_t>(pj) * width + pi] : 1.0;
      this->Rays[p] = rays.TracedPixelRay(pi, pj, z, this->TMax[p]);
    }
  }
#ifdef HOV_CLIP_LANES
  // The rays again as padded arrays per coordinate, for the pixel lanes.
  const size_t padded = n + PixelLanes;
  this->TMax.resize(padded, 0.0);
  this->LaneStore.assign(6 * padded, 0.0);
  double* a = this->LaneStore.data();
  for (size_t p = 0; p < n; ++p)
  {
    const Ray& ray = this->Rays[p];
    a[p] = ray.Origin.x;
    a[padded + p] = ray.Origin.y;
    a[2 * padded + p] = ray.Origin.z;
    a[3 * padded + p] = ray.Direction.x;
    a[4 * padded + p] = ray.Direction.y;
    a[5 * padded + p] = ray.Direction.z;
  }
  this->LaneRays = { a, a + padded, a + 2 * padded, a + 3 * padded, a + 4 * padded,
    a + 5 * padded, this->TMax.data() };
#endif
}

void vtkHighOrderProjectorTile::WriteTile(const hov::RGBA* accum, const unsigned char* violated,
  int x0, int y0, int w, int h, int width, std::vector<double>& rgba, vtkIdType& violations)
{
  for (int j = 0; j < h; ++j)
  {
    for (int i = 0; i < w; ++i)
    {
      const size_t p = static_cast<size_t>(j) * w + i;
      double* out = &rgba[4 * (static_cast<size_t>(y0 + j) * width + x0 + i)];
      out[0] = accum[p].R;
      out[1] = accum[p].G;
      out[2] = accum[p].B;
      out[3] = accum[p].A;
      violations += violated[p];
    }
  }
}

void vtkHighOrderProjectorTile::WriteEmptyTile(
  const Frame& frame, int tileIndex, std::vector<double>& rgba)
{
  const Bins& bins = *frame.TileBins;
  const int width = frame.Rays->GetWidth();
  const int x0 = (tileIndex % bins.TilesX) * bins.Size;
  const int y0 = (tileIndex / bins.TilesX) * bins.Size;
  const int w = std::min(bins.Size, width - x0);
  const int h = std::min(bins.Size, frame.Rays->GetHeight() - y0);
  for (int j = 0; j < h; ++j)
  {
    double* row = &rgba[4 * (static_cast<size_t>(y0 + j) * width + x0)];
    std::fill(row, row + 4 * static_cast<size_t>(w), 0.0);
  }
}

void vtkHighOrderProjectorTile::Write(
  std::vector<double>& rgba, int width, vtkHighOrderCellProjector::Statistics& st) const
{
  WriteTile(this->Accum.data(), this->Violated.data(), this->X0, this->Y0, this->W, this->H, width,
    rgba, st.WitnessViolations);
}

/// Visit every (pixel, segment) of ordered cell k in this tile.
template <typename Visit>
void vtkHighOrderProjectorTile::ForCellSegments(
  const Frame& frame, vtkIdType k, bool skipDone, Visit&& visit)
{
  const CellRecord& cell = (*frame.Cells)[k];
  const Box& b = cell.PixelBox;
  const int i0 = std::max(b[0], this->X0) - this->X0;
  const int i1 = std::min(b[1], this->X0 + this->W - 1) - this->X0;
  const int j0 = std::max(b[2] - this->Y0, this->RowBegin);
  const int j1 = std::min(b[3] - this->Y0, this->RowEnd - 1);
  const ProjectedEdges edges(cell);
  for (int j = j0; j <= j1; ++j)
  {
    int r0 = i0, r1 = i1;
    if (cell.Projectable)
    {
      // Only the pixel centres inside the projection (BoxMargin of slack).
      double xMin, xMax;
      if (!RowSpan(edges, this->Y0 + j + 0.5, xMin, xMax))
      {
        continue;
      }
      r0 = std::max(r0, CeilToInt(xMin - 0.5 - BoxMargin) - this->X0);
      r1 = std::min(r1, FloorToInt(xMax - 0.5 + BoxMargin) - this->X0);
    }
#ifdef HOV_CLIP_LANES
    double spanIn[MaxTileSize + PixelLanes], spanOut[MaxTileSize + PixelLanes];
    double spanSIn[MaxTileSize + PixelLanes], spanSOut[MaxTileSize + PixelLanes];
    signed char spanHit[MaxTileSize + PixelLanes];
    const size_t rowStart = static_cast<size_t>(j) * this->W;
    if (r1 >= r0)
    {
      ClipSpan(cell, this->LaneRays, rowStart + r0, r1 - r0 + 1, spanIn, spanOut, spanSIn,
        spanSOut, spanHit);
    }
#endif
    for (int i = r0; i <= r1; ++i)
    {
      const size_t p = static_cast<size_t>(j) * this->W + i;
      if (skipDone && this->Done[p])
      {
        continue;
      }
      const Ray& ray = this->Rays[p];
      double tIn, tOut;
#ifdef HOV_CLIP_LANES
      const int hit = spanHit[i - r0];
      if (hit > 0)
      {
        visit(p, spanIn[i - r0], spanOut[i - r0], spanSIn[i - r0], spanSOut[i - r0]);
        continue;
      }
      if (hit == 0 ||
        !ClipRay(cell, ray, this->TMax[p], frame.PerturbX, frame.PerturbY, tIn, tOut))
#else
      if (!ClipRay(cell, ray, this->TMax[p], frame.PerturbX, frame.PerturbY, tIn, tOut))
#endif
      {
        continue;
      }
      const double sAtOrigin =
        cell.RefScalar + glm::dot(cell.Gradient, ray.Origin - cell.RefPoint);
      const double slope = glm::dot(cell.Gradient, ray.Direction);
      visit(p, tIn, tOut, sAtOrigin + tIn * slope, sAtOrigin + tOut * slope);
    }
  }
}

inline void vtkHighOrderProjectorTile::Queue(
  size_t p, double tIn, double tOut, double sIn, double sOut, int interval)
{
  // Field by field into preallocated slots (no temporary: building a struct
  // on the stack and copying it stalled on store forwarding).
  if (this->NumQueued == static_cast<int>(this->Jobs.size()))
  {
    this->Jobs.resize(2 * this->Jobs.size() + BatchSize);
    this->Pending.resize(this->Jobs.size());
  }
  hov::SegmentJob& job = this->Jobs[this->NumQueued];
  job.SFront = sIn;
  job.SBack = sOut;
  job.Length = tOut - tIn;
  job.Interval = interval;
  PendingSegment& seg = this->Pending[this->NumQueued];
  seg.TIn = tIn;
  seg.TOut = tOut;
  seg.Pixel = static_cast<int>(p);
  ++this->NumQueued;
}

void vtkHighOrderProjectorTile::Flush(const Frame& frame, vtkHighOrderCellProjector::Statistics& st)
{
  const int n = this->NumQueued;
  if (n == 0)
  {
    return;
  }
  this->Results.resize(n);
  this->Pieces.resize(n);
  this->Batch.Integrate(*frame.TF, frame.Settings->Integration, this->Jobs.data(), n,
    this->Results.data(), this->Pieces.data());
  // In queue order, skipping pixels that turned opaque meanwhile: exactly
  // what compositing one segment at a time does.
  // (Counted in locals: the byte stores to Done may alias the statistics.)
  vtkIdType segments = 0, pieces = 0;
  for (int m = 0; m < n; ++m)
  {
    const PendingSegment& seg = this->Pending[m];
    if (this->Done[seg.Pixel])
    {
      continue;
    }
    this->Witness(frame, seg.Pixel, seg.TIn, seg.TOut);
    this->Composite(frame, seg.Pixel, this->Results[m]);
    ++segments;
    pieces += this->Pieces[m];
  }
  st.Segments += segments;
  st.Pieces += pieces;
  this->NumQueued = 0;
}

void vtkHighOrderProjectorTile::RenderInCellOrder(const Frame& frame, const vtkIdType* cells,
  vtkIdType count, vtkHighOrderCellProjector::Statistics& st)
{
  this->NumQueued = 0;
  for (vtkIdType c = 0; c < count; ++c)
  {
    if (c + PrefetchDistance < count)
    {
      PrefetchCell(frame, cells[c + PrefetchDistance]);
    }
    const vtkIdType k = cells[c];
    if (IsGeneral(frame, k))
    {
      this->Flush(frame, st); // the tetra segments queued so far come first
      this->RenderGeneralCell(frame, k, st);
      continue;
    }
    const int interval = (*frame.Cells)[k].Interval;
    this->ForCellSegments(frame, k, true,
      [&](size_t p, double tIn, double tOut, double sIn, double sOut) {
        this->Queue(p, tIn, tOut, sIn, sOut, interval);
      });
    if (this->NumQueued >= BatchSize)
    {
      this->Flush(frame, st);
    }
  }
  this->Flush(frame, st);
}

void vtkHighOrderProjectorTile::RenderPerPixel(const Frame& frame, const vtkIdType* cells,
  vtkIdType count, vtkHighOrderCellProjector::Statistics& st)
{
  // Band by band (about BandPixels pixels: whole rows of the tile), so that a band's fragments stay
  // in the cache while they are bucketed and sorted.
  this->NumQueued = 0;
  const int rows = std::max(1, BandPixels / std::max(this->W, 1));
  for (int band = 0; band < this->H; band += rows)
  {
    this->RowBegin = band;
    this->RowEnd = std::min(band + rows, this->H);
    this->CollectFragments(frame, cells, count);
    this->CompositeFragments(frame, st);
  }
  this->Flush(frame, st);
  this->RowBegin = 0;
  this->RowEnd = this->H;
}

void vtkHighOrderProjectorTile::CollectFragments(
  const Frame& frame, const vtkIdType* cells, vtkIdType count)
{
  // The projector ordered the cells by depth: fragments arrive nearly sorted.
  this->NumFragments = 0;
  const std::vector<CellRecord>& records = *frame.Cells;
  const int y0 = this->Y0 + this->RowBegin, y1 = this->Y0 + this->RowEnd - 1;
  for (vtkIdType c = 0; c < count; ++c)
  {
    const vtkIdType k = cells[c];
    if (c + PrefetchDistance < count)
    {
      PrefetchCell(frame, cells[c + PrefetchDistance]);
    }
    if (records[k].PixelBox[3] < y0 || records[k].PixelBox[2] > y1)
    {
      continue; // not in this band
    }
    if (IsGeneral(frame, k))
    {
      this->CollectGeneralFragments(frame, k);
      continue;
    }
    this->ForCellSegments(frame, k, false,
      [&](size_t p, double tIn, double tOut, double sIn, double sOut) {
        if (this->NumFragments == static_cast<int>(this->Fragments.size()))
        {
          this->Fragments.resize(2 * this->Fragments.size() + 1024);
        }
        Fragment& f = this->Fragments[this->NumFragments++];
        f.TIn = tIn;
        f.TOut = tOut;
        f.SIn = sIn;
        f.SOut = sOut;
        f.Pixel = static_cast<int>(p);
        f.Order = static_cast<int>(k);
      });
  }
}

void vtkHighOrderProjectorTile::CompositeFragments(
  const Frame& frame, vtkHighOrderCellProjector::Statistics& st)
{
  // Counting sort of the band's fragments by pixel (stable).
  const int first = this->RowBegin * this->W;
  const int n = (this->RowEnd - this->RowBegin) * this->W;
  this->PixelStart.assign(n + 1, 0);
  const Fragment* fragments = this->Fragments.data();
  for (int m = 0; m < this->NumFragments; ++m)
  {
    ++this->PixelStart[fragments[m].Pixel - first + 1];
  }
  for (int p = 0; p < n; ++p)
  {
    this->PixelStart[p + 1] += this->PixelStart[p];
  }
  if (this->ByPixel.size() < static_cast<size_t>(this->NumFragments))
  {
    this->ByPixel.resize(this->Fragments.size());
  }
  this->Fill.assign(this->PixelStart.begin(), this->PixelStart.end() - 1);
  for (int m = 0; m < this->NumFragments; ++m)
  {
    this->ByPixel[this->Fill[fragments[m].Pixel - first]++] = fragments[m];
  }
  // Each pixel's list by entry; the segments of consecutive pixels are
  // integrated together and composited pixel by pixel in that order.
  const std::vector<CellRecord>& records = *frame.Cells;
  for (int p = 0; p < n; ++p)
  {
    Fragment* begin = this->ByPixel.data() + this->PixelStart[p];
    Fragment* end = this->ByPixel.data() + this->PixelStart[p + 1];
    InsertionSort(begin, end);
    for (const Fragment* f = begin; f != end; ++f)
    {
      if (IsGeneral(frame, f->Order))
      {
        this->Flush(frame, st); // keep the pixel's order
        this->CompositeGeneralInterval(frame, first + p, f->TIn, f->TOut, f->Order, st);
        continue;
      }
      this->Queue(first + p, f->TIn, f->TOut, f->SIn, f->SOut, records[f->Order].Interval);
    }
    if (this->NumQueued >= BatchSize)
    {
      this->Flush(frame, st);
    }
  }
}

void vtkHighOrderProjectorTile::Render(const Frame& frame, int tileIndex, std::vector<double>& rgba,
  vtkHighOrderCellProjector::Statistics& stats)
{
  const Bins& bins = *frame.TileBins;
  const vtkIdType* cells = bins.Cells.data() + bins.Start[tileIndex];
  const vtkIdType count = bins.Start[tileIndex + 1] - bins.Start[tileIndex];
  if (count == 0)
  {
    // No cell: the tile stays transparent (most tiles around a model); no rays.
    WriteEmptyTile(frame, tileIndex, rgba);
    return;
  }
  this->Init(frame, tileIndex);
  if (frame.Settings->PerPixelSort)
  {
    this->RenderPerPixel(frame, cells, count, stats);
  }
  else
  {
    this->RenderInCellOrder(frame, cells, count, stats);
  }
  this->Write(rgba, frame.Rays->GetWidth(), stats);
}
