#include "hovProjectorTile.h"

#include "hovCellRecords.h"         // per-tile records
#include "hovProjectorTileLanes.h" // pixel lanes
#include "hovTileGeometry.h"        // ray clipping, row spans

#include <algorithm> // std::min, std::max
#include <cmath>     // std::ceil, std::floor

namespace
{
using Ray = hov::ViewRays::Ray;
using CellRecord = hov::ProjectorTile::CellRecord;
using namespace hov::tile;
}

void hov::ProjectorTile::Init(const Frame& frame, int tileIndex)
{
  this->InitPixels(*frame.Rays, frame.Depth, *frame.Bins, tileIndex);
  const size_t n = static_cast<size_t>(this->W) * this->H;
  this->NumFragments = 0;
  this->RowBegin = 0;
  this->RowEnd = this->H;
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

void hov::ProjectorTile::ReserveQueue(int n)
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

void hov::ProjectorTile::QueueCellSegments(const Frame& frame, vtkIdType k)
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

void hov::ProjectorTile::CompactRow(
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

void hov::ProjectorTile::Flush(const Frame& frame, Statistics& st)
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
  // In queue order, skipping pixels that turned opaque meanwhile.
  const CompositeTarget target{ this->Accum.data(), this->MaxExit.data(), this->Violated.data(),
    this->Done.data(), this->DoneInRow.data(), this->W, frame.WitnessTol,
    frame.Settings->TerminationTransmittance };
  vtkIdType pieces = 0;
  const vtkIdType segments = CompositeQueue(this->QPixel.data(), this->QTIn, this->QTOut,
    this->Results.data(), this->Pieces.data(), n, target, pieces);
  st.Segments += segments;
  st.Pieces += pieces;
  this->NumQueued = 0;
}

void hov::ProjectorTile::RenderInCellOrder(const Frame& frame, const vtkIdType* cells,
  vtkIdType count, Statistics& st)
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

void hov::ProjectorTile::Render(const Frame& frame, int tileIndex, std::vector<double>& rgba,
  Statistics& stats)
{
  const TileBins& bins = *frame.Bins;
  const vtkIdType* cells = bins.Cells.data() + bins.Start[tileIndex];
  const vtkIdType count = bins.Start[tileIndex + 1] - bins.Start[tileIndex];
  if (count == 0)
  {
    // No cell: the tile stays transparent (most tiles around a model); no rays.
    WriteEmptyTile(bins, frame.Rays->GetWidth(), frame.Rays->GetHeight(), tileIndex, rgba);
    return;
  }
  if (!frame.Cells)
  {
    // No records for the whole order (over the memory budget): this tile's
    // cells' records, bit for bit what CellRecords::Build makes, indexed in
    // the tile's order (which keeps the cell order and its ties).
    const CellRecords& records = *frame.Records;
    const bool general = frame.General != nullptr;
    this->LocalRecords.resize(count);
    this->LocalCells.resize(count);
    this->LocalGeneralOf.resize(general ? count : 0);
    constexpr vtkIdType cellAhead = 16, pointsAhead = 8;
    for (vtkIdType c = 0; c < count; ++c)
    {
      if (c + cellAhead < count)
      {
        records.PrefetchCell(cells[c + cellAhead]);
      }
      if (c + pointsAhead < count)
      {
        records.PrefetchPoints(cells[c + pointsAhead]);
      }
      records.Make(cells[c], this->LocalRecords[c]);
      this->LocalCells[c] = c;
      if (general)
      {
        this->LocalGeneralOf[c] = records.GetGeneralOf()[cells[c]];
      }
    }
    stats.Records += count;
    Frame local = frame;
    local.Cells = &this->LocalRecords;
    GeneralCellTile::FrameData localGeneral;
    if (general)
    {
      localGeneral = *frame.General;
      localGeneral.GeneralOf = &this->LocalGeneralOf;
      local.General = &localGeneral;
    }
    this->RenderCells(local, tileIndex, this->LocalCells.data(), count, rgba, stats);
    return;
  }
  this->RenderCells(frame, tileIndex, cells, count, rgba, stats);
}

void hov::ProjectorTile::ReleaseLocalRecords()
{
  std::vector<CellRecord>().swap(this->LocalRecords);
  std::vector<vtkIdType>().swap(this->LocalCells);
  std::vector<int>().swap(this->LocalGeneralOf);
}

void hov::ProjectorTile::RenderCells(const Frame& frame, int tileIndex, const vtkIdType* cells,
  vtkIdType count, std::vector<double>& rgba, Statistics& stats)
{
  this->Init(frame, tileIndex);
  if (frame.Settings->PerPixelSort)
  {
    this->RenderPerPixel(frame, cells, count, stats);
  }
  else
  {
    this->RenderInCellOrder(frame, cells, count, stats);
  }
  this->WritePixels(rgba, frame.Rays->GetWidth(), stats);
}
