#include "hovProjectorTile.h"

#include "hovProjectorTileLanes.h" // pixel lanes
#include "hovTileGeometry.h"        // ray clipping, row spans

#include "vtkSMPTools.h" // parallel binning

#include <algorithm> // std::min, std::max
#include <cmath>     // std::ceil, std::floor

namespace
{
using Ray = vtkHighOrderViewRays::Ray;
using CellRecord = vtkHighOrderProjectorTile::CellRecord;
using namespace hovTileGeometry;
}

void vtkHighOrderProjectorTile::Bins::Build(
  const std::vector<Box>& boxes, int width, int height, int tileSize)
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
  const vtkIdType numCells = static_cast<vtkIdType>(boxes.size());
  const vtkIdType chunk = (numCells + Chunks - 1) / Chunks;
  this->Fill.assign(static_cast<size_t>(Chunks) * numTiles, 0);
  vtkSMPTools::For(0, Chunks, 1, [&](vtkIdType c0, vtkIdType c1) {
    for (vtkIdType c = c0; c < c1; ++c)
    {
      vtkIdType* count = this->Fill.data() + c * numTiles;
      for (vtkIdType k = c * chunk; k < std::min(numCells, (c + 1) * chunk); ++k)
      {
        forTiles(boxes[k], [&](int t) { ++count[t]; });
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
        forTiles(boxes[k], [&](int t) { this->Cells[fill[t]++] = k; });
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
  this->DoneInRow.assign(this->H, 0);
  // The rays again as padded arrays per coordinate, for the pixel lanes.
  const size_t padded = n + PixelLanes;
  this->TMax.resize(padded, 0.0);
  this->LaneStore.resize(6 * padded); // the padding lanes keep any (defined) old values
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

void vtkHighOrderProjectorTile::ReserveQueue(int n)
{
  if (n + PixelLanes <= this->QueueCapacity)
  {
    return;
  }
  const int capacity = std::max(2 * this->QueueCapacity, n + PixelLanes + BatchSize);
  std::vector<double> store(5 * static_cast<size_t>(capacity));
  for (int f = 0; f < 5; ++f)
  {
    const double* from = this->QueueStore.data() + static_cast<size_t>(f) * this->QueueCapacity;
    std::copy(from, from + this->NumQueued, store.data() + static_cast<size_t>(f) * capacity);
  }
  this->QueueStore.swap(store);
  double* a = this->QueueStore.data();
  this->QTIn = a;
  this->QTOut = a + capacity;
  this->QSIn = a + 2 * static_cast<size_t>(capacity);
  this->QSOut = a + 3 * static_cast<size_t>(capacity);
  this->QLength = a + 4 * static_cast<size_t>(capacity);
  this->QPixel.resize(capacity);
  this->QInterval.resize(capacity);
  this->QueueCapacity = capacity;
}

void vtkHighOrderProjectorTile::QueueCellSegments(const Frame& frame, vtkIdType k)
{
  const CellRecord& cell = (*frame.Cells)[k];
  const Box& b = cell.PixelBox;
  const int j0 = std::max(b[2] - this->Y0, this->RowBegin);
  const int j1 = std::min(b[3] - this->Y0, this->RowEnd - 1);
  const ProjectedEdges edges(cell);
  // The rows' pixel ranges first (independent rows: their latencies overlap),
  // then all rows clipped in one call.
  int start[MaxTileSize], count[MaxTileSize];
  int rows = 0;
  if (cell.Projectable)
  {
    const int i0 = std::max(b[0], this->X0) - this->X0;
    const int i1 = std::min(b[1], this->X0 + this->W - 1) - this->X0;
    rows = RowRanges(edges, this->X0, this->Y0, this->W, i0, i1, j0, j1, start, count);
  }
  else
  {
    for (int j = j0; j <= j1; ++j)
    {
      int r0, r1;
      if (this->RowRange(cell, edges, j, r0, r1))
      {
        start[rows] = j * this->W + r0;
        count[rows++] = r1 - r0 + 1;
      }
    }
  }
  int total = 0, done = 0;
  for (int r = 0; r < rows; ++r)
  {
    total += count[r];
    done += this->DoneInRow[start[r] / this->W];
  }
  if (this->NumQueued + total + PixelLanes > this->QueueCapacity)
  {
    this->ReserveQueue(this->NumQueued + total);
  }
  const LaneOut lanes{ this->QTIn, this->QTOut, this->QSIn, this->QSOut, this->QLength,
    this->QPixel.data(), this->QInterval.data() };
  const int q = this->NumQueued;
  if (ClipRows(cell, this->LaneRays, start, count, rows, lanes, q) && done == 0)
  {
    this->NumQueued += total; // the common case: every pixel hit, none done
    return;
  }
  for (int r = 0, src = q; r < rows; src += count[r++])
  {
    this->CompactRow(frame, cell, start[r], count[r], src);
  }
}

void vtkHighOrderProjectorTile::CompactRow(
  const Frame& frame, const CellRecord& cell, size_t p0, int count, int src)
{
  int next = this->NumQueued; // <= src: rows are compacted in order
  for (int i = 0; i < count; ++i)
  {
    const size_t p = p0 + i;
    if (this->Done[p])
    {
      continue;
    }
    const Ray& ray = this->Rays[p];
    const int from = src + i;
    const int hit = LaneHit(cell, ray, this->QTIn[from], this->QTOut[from]);
    if (hit == 0)
    {
      continue;
    }
    if (hit > 0)
    {
      if (next != from)
      {
        this->QTIn[next] = this->QTIn[from];
        this->QTOut[next] = this->QTOut[from];
        this->QSIn[next] = this->QSIn[from];
        this->QSOut[next] = this->QSOut[from];
        this->QLength[next] = this->QLength[from];
        this->QPixel[next] = this->QPixel[from];
      }
      ++next;
      continue;
    }
    // Undecided (a ray parallel to a face): ClipRay()'s tie rules.
    double tIn, tOut;
    if (!ClipRay(cell, ray, this->TMax[p], frame.PerturbX, frame.PerturbY, tIn, tOut))
    {
      continue;
    }
    const double sAtOrigin = cell.RefScalar + glm::dot(cell.Gradient, ray.Origin - cell.RefPoint);
    const double slope = glm::dot(cell.Gradient, ray.Direction);
    this->QTIn[next] = tIn;
    this->QTOut[next] = tOut;
    this->QSIn[next] = sAtOrigin + tIn * slope;
    this->QSOut[next] = sAtOrigin + tOut * slope;
    this->QLength[next] = tOut - tIn;
    this->QPixel[next] = static_cast<int>(p);
    ++next;
  }
  this->NumQueued = next; // QInterval: the cell's throughout
}

void vtkHighOrderProjectorTile::Flush(const Frame& frame, vtkHighOrderCellProjector::Statistics& st)
{
  const int n = this->NumQueued;
  if (n == 0)
  {
    return;
  }
  if (this->Results.size() < static_cast<size_t>(n))
  {
    this->Results.resize(n); // grows only (a resize up would clear the new entries each time)
    this->Pieces.resize(n);
  }
  const hov::SegmentBatch::Arrays jobs{ this->QSIn, this->QSOut, this->QLength,
    this->QInterval.data() };
  this->Batch.Integrate(*frame.TF, frame.Settings->Integration, jobs, n, this->Results.data(),
    this->Pieces.data());
  // In queue order, skipping pixels that turned opaque meanwhile: exactly
  // what compositing one segment at a time does (Witness(), Composite()).
  // Everything through locals: byte stores (Done) may alias any member.
  vtkIdType segments = 0, pieces = 0;
  const int* pixel = this->QPixel.data();
  const double* tIn = this->QTIn;
  const double* tOut = this->QTOut;
  const hov::RGBA* results = this->Results.data();
  const int* piecesOf = this->Pieces.data();
  hov::RGBA* accum = this->Accum.data();
  double* maxExit = this->MaxExit.data();
  unsigned char* violated = this->Violated.data();
  unsigned char* done = this->Done.data();
  const double tol = frame.WitnessTol;
  const double termination = frame.Settings->TerminationTransmittance;
  for (int m = 0; m < n; ++m)
  {
    const int p = pixel[m];
    if (done[p])
    {
      continue;
    }
    if (tIn[m] < maxExit[p] - tol)
    {
      violated[p] = 1;
    }
    maxExit[p] = std::max(maxExit[p], tOut[m]);
    hov::CompositeBehind(accum[p], results[m]);
    if (1.0 - accum[p].A <= termination)
    {
      done[p] = 1;
      ++this->DoneInRow[p / this->W];
    }
    ++segments;
    pieces += piecesOf[m];
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
    this->QueueCellSegments(frame, k);
    if (this->NumQueued >= BatchSize)
    {
      this->Flush(frame, st);
    }
  }
  this->Flush(frame, st);
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
