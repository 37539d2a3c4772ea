// The per-pixel ordering of hov::ProjectorTile (Settings::PerPixelSort):
// every segment of a band of the tile's rows becomes a fragment; fragments are
// bucketed by pixel, sorted by entry and composited pixel by pixel. Kept apart
// from the cell-order loop (hov::ProjectorTile.cxx).
#include "hovProjectorTile.h"

#include "hovProjectorTileLanes.h" // pixel lanes
#include "hovTileGeometry.h"        // ray clipping, row spans

#include <algorithm> // std::min, std::max

namespace
{
using Ray = hov::ViewRays::Ray;
using CellRecord = hov::ProjectorTile::CellRecord;
using namespace hov::tile;

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

void hov::ProjectorTile::Queue(
  size_t p, double tIn, double tOut, double sIn, double sOut, int interval)
{
  if (this->NumQueued + 1 > this->QueueCapacity)
  {
    this->ReserveQueue(this->NumQueued + 1);
  }
  const int q = this->NumQueued++;
  this->QTIn[q] = tIn;
  this->QTOut[q] = tOut;
  this->QSIn[q] = sIn;
  this->QSOut[q] = sOut;
  this->QLength[q] = tOut - tIn;
  this->QPixel[q] = static_cast<int>(p);
  this->QInterval[q] = interval;
}

/// Visit every (pixel, segment) of ordered cell k in this tile.
template <typename Visit>
void hov::ProjectorTile::ForCellSegments(const Frame& frame, vtkIdType k, Visit&& visit)
{
  const CellRecord& cell = (*frame.Cells)[k];
  const Box& b = cell.PixelBox;
  const int j0 = std::max(b[2] - this->Y0, this->RowBegin);
  const int j1 = std::min(b[3] - this->Y0, this->RowEnd - 1);
  const ProjectedEdges edges(cell);
  constexpr int span = MaxTileSize + PixelLanes;
  double tIn[span], tOut[span], sIn[span], sOut[span], length[span];
  for (int j = j0; j <= j1; ++j)
  {
    int r0, r1;
    if (!this->RowRange(cell, edges, j, r0, r1))
    {
      continue;
    }
    const size_t p0 = static_cast<size_t>(j) * this->W + r0;
    const bool all =
      ClipSpan(cell, this->LaneRays, p0, r1 - r0 + 1, LaneOut{ tIn, tOut, sIn, sOut, length, nullptr, nullptr }, 0);
    for (int i = 0; i <= r1 - r0; ++i)
    {
      const size_t p = p0 + i;
      const int hit = all ? 1 : LaneHit(cell, this->Rays[p], tIn[i], tOut[i]);
      if (hit > 0)
      {
        visit(p, tIn[i], tOut[i], sIn[i], sOut[i]);
        continue;
      }
      const Ray& ray = this->Rays[p];
      double t0, t1;
      if (hit == 0 || !ClipRay(cell, ray, this->TMax[p], frame.PerturbX, frame.PerturbY, t0, t1))
      {
        continue;
      }
      const double sAtOrigin =
        cell.RefScalar + glm::dot(cell.Gradient, ray.Origin - cell.RefPoint);
      const double slope = glm::dot(cell.Gradient, ray.Direction);
      visit(p, t0, t1, sAtOrigin + t0 * slope, sAtOrigin + t1 * slope);
    }
  }
}

void hov::ProjectorTile::RenderPerPixel(const Frame& frame, const vtkIdType* cells,
  vtkIdType count, Statistics& st)
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

void hov::ProjectorTile::CollectFragments(
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
    this->ForCellSegments(frame, k,
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

void hov::ProjectorTile::CompositeFragments(
  const Frame& frame, Statistics& st)
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

