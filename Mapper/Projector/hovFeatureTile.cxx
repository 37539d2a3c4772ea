#include "hovFeatureTile.h"

#include "hovCellSetup.h"    // tetrahedra face planes
#include "hovTileGeometry.h"  // ClipRayFaces

#include "hovCompositing.h" // CompositeBehind
#include "hovPixelRange.h"  // row spans

#include <algorithm> // std::sort, std::min, std::max
#include <cmath>     // NaN
#include <limits>    // quiet NaN

namespace
{
using Ray = hov::ViewRays::Ray;
using Tetra = hov::CellSetup::Tetra;
using hov::BoxMargin;

/// Window-x span of the convex hull of the 4 projected vertices on the row at
/// height @p y (the span of the row's crossings with all 6 edges); false if
/// the row misses it.
bool HullRowSpan(const glm::dvec2* p, double y, double& xMin, double& xMax)
{
  xMin = 1e300;
  xMax = -1e300;
  for (int a = 0; a < 4; ++a)
  {
    if (p[a].y == y)
    {
      xMin = std::min(xMin, p[a].x);
      xMax = std::max(xMax, p[a].x);
    }
    for (int b = a + 1; b < 4; ++b)
    {
      if ((p[a].y - y) * (p[b].y - y) >= 0.0)
      {
        continue;
      }
      const double x = p[a].x + (p[b].x - p[a].x) * ((y - p[a].y) / (p[b].y - p[a].y));
      xMin = std::min(xMin, x);
      xMax = std::max(xMax, x);
    }
  }
  return xMin <= xMax;
}
}

void hov::FeatureTile::Init(const Frame& frame, int tileIndex)
{
  // As hov::ProjectorTile::Init: the same rays and ray ranges.
  this->InitPixels(*frame.Rays, frame.Depth, frame.Bins, tileIndex);
  this->LastExit.assign(
    static_cast<size_t>(this->W) * this->H, std::numeric_limits<double>::quiet_NaN());
}

template <typename Visit>
void hov::FeatureTile::ForIntervals(
  const Frame& frame, vtkIdType k, bool skipDone, Visit&& visit)
{
  const vtkIdType cell = (*frame.Order)[k];
  const vtkIdType numTets = static_cast<vtkIdType>(frame.Setup->GetTetras().size());
  const auto& box = frame.Boxes[k];
  if (cell >= numTets)
  {
    const hov::GeneralCellTile::TileRows rows{ this->X0, this->Y0, this->W, 0, this->H,
      this->Rays.data(), this->TMax.data() };
    const auto& hits = this->General.Collect(frame.General, static_cast<int>(cell - numTets), box,
      rows, skipDone ? this->Done.data() : nullptr);
    const auto& intervals = this->General.Intervals();
    for (const auto& hit : hits)
    {
      for (int m = hit.First; m < hit.First + hit.Count; ++m)
      {
        visit(static_cast<size_t>(hit.Pixel), intervals[m].T0, intervals[m].T1);
      }
    }
    return;
  }
  const Tetra& tet = frame.Setup->GetTetras()[cell];
  // The exact clip against the cell's canonical face planes: the arithmetic
  // of the fast path's ClipRay (hovTileGeometry.h), so shared faces give
  // bit-identical exit/entry times, and the same symbolic perturbation for
  // rays lying in a face.
  double nx[4], ny[4], nz[4], offset[4];
  frame.Setup->FacePlanes(tet, nx, ny, nz, offset);
  const int i0 = std::max(box[0], this->X0) - this->X0;
  const int i1 = std::min(box[1], this->X0 + this->W - 1) - this->X0;
  const int j0 = std::max(box[2], this->Y0) - this->Y0;
  const int j1 = std::min(box[3], this->Y0 + this->H - 1) - this->Y0;
  glm::dvec2 corners[4];
  bool projectable = true;
  for (int v = 0; v < 4; ++v)
  {
    corners[v] = frame.General.Window[tet.Points[v]];
    projectable = projectable && frame.General.Projectable[tet.Points[v]];
  }
  for (int j = j0; j <= j1; ++j)
  {
    int r0 = i0, r1 = i1;
    if (projectable)
    {
      // Only the pixel centres in the row's span of the projection (the
      // exact clip below decides; BoxMargin of slack against round-off).
      double xMin, xMax;
      if (!HullRowSpan(corners, this->Y0 + j + 0.5, xMin, xMax))
      {
        continue;
      }
      const hov::PixelRange span =
        hov::PixelCentresIn(xMin, xMax, this->X0 + r0, this->X0 + r1, BoxMargin);
      r0 = span.First - this->X0;
      r1 = span.Last - this->X0;
    }
    for (int i = r0; i <= r1; ++i)
    {
      const size_t p = static_cast<size_t>(j) * this->W + i;
      double tIn, tOut;
      if ((skipDone && this->Done[p]) ||
        !tile::ClipRayFaces(nx, ny, nz, offset, this->Rays[p], this->TMax[p], frame.PerturbX,
          frame.PerturbY, tIn, tOut))
      {
        continue;
      }
      visit(p, tIn, tOut);
    }
  }
}

template <typename Visit>
void hov::FeatureTile::ForSplatPixels(const Frame& frame, vtkIdType k, Visit&& visit)
{
  const hov::FeatureProjector::Splat& splat = frame.Splats[frame.SplatOf[k]];
  for (int b = 0; b < 3; ++b)
  {
    for (int a = 0; a < 3; ++a)
    {
      const int i = splat.Footprint.X0 + a - this->X0, j = splat.Footprint.Y0 + b - this->Y0;
      if (i < 0 || i >= this->W || j < 0 || j >= this->H)
      {
        continue;
      }
      const size_t p = static_cast<size_t>(j) * this->W + i;
      const Ray& ray = this->Rays[p];
      const double t = glm::dot(splat.Center - ray.Origin, ray.Direction);
      if (t >= 0.0 && t <= this->TMax[p]) // inside the ray's range (clipping, depth)
      {
        visit(p, 3 * b + a, t);
      }
    }
  }
}

void hov::FeatureTile::Composite(const Frame& frame, size_t p, const hov::RGBA& c)
{
  hov::CompositeBehind(this->Accum[p], c);
  if (1.0 - this->Accum[p].A <= frame.Settings->TerminationTransmittance)
  {
    this->Done[p] = 1;
  }
}

void hov::FeatureTile::Segment(
  const Frame& frame, size_t p, vtkIdType k, double tIn, double tOut, Stats& st)
{
  if (this->Done[p])
  {
    return;
  }
  // A surface at the entry belongs to this segment unless one ended here
  // (shared faces: bit-identical; edges and vertices: within WitnessTol).
  const bool includeFront = !(std::abs(tIn - this->LastExit[p]) <= frame.WitnessTol);
  const hov::RGBA c = this->Integrator.Integrate(
    frame.Segment, (*frame.Order)[k], this->Rays[p], tIn, tOut, includeFront, st.Pieces);
  st.ShadingErrorEstimate =
    std::max(st.ShadingErrorEstimate, this->Integrator.GetShadingErrorEstimate());
  this->Witness(p, tIn, tOut, frame.WitnessTol);
  this->LastExit[p] = tOut;
  this->Composite(frame, p, c);
  ++st.Segments;
}

void hov::FeatureTile::SplatPixel(
  const Frame& frame, size_t p, vtkIdType k, int weight, Stats& st)
{
  if (this->Done[p])
  {
    return;
  }
  const auto& fp = frame.Splats[frame.SplatOf[k]].Footprint;
  this->Composite(frame, p, fp.Pixel[weight / 3][weight % 3]);
  ++st.Segments;
}

void hov::FeatureTile::Render(
  const Frame& frame, int tileIndex, std::vector<double>& rgba, Stats& st)
{
  this->Init(frame, tileIndex);
  this->Integrator.ResetShadingErrorEstimate();
  const vtkIdType* cells = frame.Bins.Cells.data() + frame.Bins.Start[tileIndex];
  const vtkIdType count = frame.Bins.Start[tileIndex + 1] - frame.Bins.Start[tileIndex];
  if (!frame.Settings->PerPixelSort)
  {
    for (vtkIdType c = 0; c < count; ++c)
    {
      const vtkIdType k = cells[c];
      if (frame.SplatOf[k] >= 0)
      {
        this->ForSplatPixels(frame, k, [&](size_t p, int w, double) { this->SplatPixel(frame, p, k, w, st); });
        continue;
      }
      this->ForIntervals(frame, k, true,
        [&](size_t p, double tIn, double tOut) { this->Segment(frame, p, k, tIn, tOut, st); });
    }
  }
  else
  {
    // Every interval and splat pixel becomes a fragment; each pixel's list
    // is sorted by entry (splats: the centroid's depth on that ray).
    this->Fragments.clear();
    for (vtkIdType c = 0; c < count; ++c)
    {
      const vtkIdType k = cells[c];
      if (frame.SplatOf[k] >= 0)
      {
        this->ForSplatPixels(frame, k, [&](size_t p, int w, double t) {
          this->Fragments.push_back(Fragment{ t, t, static_cast<int>(p), static_cast<int>(k), w });
        });
        continue;
      }
      this->ForIntervals(frame, k, false, [&](size_t p, double tIn, double tOut) {
        this->Fragments.push_back(Fragment{ tIn, tOut, static_cast<int>(p), static_cast<int>(k), -1 });
      });
    }
    std::sort(this->Fragments.begin(), this->Fragments.end(), [](const Fragment& a, const Fragment& b) {
      return a.Pixel != b.Pixel ? a.Pixel < b.Pixel : a < b;
    });
    for (const Fragment& f : this->Fragments)
    {
      if (f.Splat >= 0)
      {
        this->SplatPixel(frame, f.Pixel, f.Order, f.Splat, st);
      }
      else
      {
        this->Segment(frame, f.Pixel, f.Order, f.TIn, f.TOut, st);
      }
    }
  }
  this->WritePixels(rgba, frame.Rays->GetWidth(), st);
}
