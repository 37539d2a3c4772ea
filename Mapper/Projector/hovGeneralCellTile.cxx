#include "hovGeneralCellTile.h"

#include "hovGeneralCells.h"  // the cells
#include "hovTileSkeleton.h" // BoxMargin, shared with the tetrahedra

#include "hovPixelRange.h"  // pixel boxes and row spans
#include "hovPolynomial.h" // constant pieces

#include <algorithm> // std::min, std::max
#include <cmath>     // std::ceil, std::floor

namespace
{
constexpr double BoxMargin = hov::BoxMargin;

/// Terms of a restricted field whose largest value on a piece is below this
/// times the cell's largest |scalar| are rounding noise (the restriction's own
/// bound is 32 eps sum |s_i|) and are dropped.
constexpr double NegligibleRelative = 8.0 * 2.220446049250313e-16;

/// Window-x span of the convex hull of @p n projected corners on the row at
/// height @p y (a row meets a hull of points in the span of its crossings
/// with all segments between them); false if the row misses it.
bool HullRowSpan(const glm::dvec2* corners, int n, double y, double& xMin, double& xMax)
{
  xMin = 1e300;
  xMax = -1e300;
  for (int a = 0; a < n; ++a)
  {
    const glm::dvec2& p = corners[a];
    if (p.y == y)
    {
      xMin = std::min(xMin, p.x);
      xMax = std::max(xMax, p.x);
    }
    for (int b = a + 1; b < n; ++b)
    {
      const glm::dvec2& q = corners[b];
      if ((p.y - y) * (q.y - y) >= 0.0)
      {
        continue; // both on one side (ends on the row are taken above)
      }
      const double x = p.x + (q.x - p.x) * ((y - p.y) / (q.y - p.y));
      xMin = std::min(xMin, x);
      xMax = std::max(xMax, x);
    }
  }
  return xMin <= xMax;
}
}

std::array<int, 4> hov::GeneralCellTile::PixelBox(
  const FrameData& frame, int g, int width, int height, bool& projectable)
{
  const hov::GeneralCells::Cell& cell = frame.Cells->GetCells()[g];
  const int corners = hov::CellCornerCount(cell.Shape);
  double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
  projectable = true;
  for (int v = 0; v < corners; ++v)
  {
    const std::int64_t id = cell.CornerIds[v];
    if (!frame.Projectable[id])
    {
      projectable = false;
      return { 0, width - 1, 0, height - 1 }; // crosses the eye plane
    }
    x0 = std::min(x0, frame.Window[id].x);
    x1 = std::max(x1, frame.Window[id].x);
    y0 = std::min(y0, frame.Window[id].y);
    y1 = std::max(y1, frame.Window[id].y);
  }
  return hov::PixelBoxOf(x0, x1, y0, y1, width, height, BoxMargin);
}

hov::RayPerturbation hov::GeneralCellTile::PerturbationOf(const hov::ViewRays& rays)
{
  hov::RayPerturbation p;
  for (int k = 0; k < 3; ++k)
  {
    p.X[k] = rays.GetPerturbX()[k];
    p.Y[k] = rays.GetPerturbY()[k];
  }
  return p;
}

const std::vector<hov::GeneralCellTile::Hit>& hov::GeneralCellTile::Collect(
  const FrameData& frame, int g, const std::array<int, 4>& box, const TileRows& rows,
  const unsigned char* skip)
{
  this->Hits.clear();
  this->IntervalList.clear();
  const hov::GeneralCells& cells = *frame.Cells;
  const hov::GeneralCells::Cell& cell = cells.GetCells()[g];
  const double* nodes = cells.GetNodes(cell);
  const int corners = hov::CellCornerCount(cell.Shape);
  glm::dvec2 projected[8];
  bool projectable = true;
  for (int v = 0; v < corners; ++v)
  {
    projected[v] = frame.Window[cell.CornerIds[v]];
    projectable = projectable && frame.Projectable[cell.CornerIds[v]];
  }
  const int i0 = std::max(box[0], rows.X0) - rows.X0;
  const int i1 = std::min(box[1], rows.X0 + rows.W - 1) - rows.X0;
  const int j0 = std::max(box[2] - rows.Y0, rows.RowBegin);
  const int j1 = std::min(box[3] - rows.Y0, rows.RowEnd - 1);
  hov::RayCellInterval found[hov::MaxRayCellIntervals];
  for (int j = j0; j <= j1; ++j)
  {
    int r0 = i0, r1 = i1;
    if (projectable)
    {
      double xMin, xMax;
      if (!HullRowSpan(projected, corners, rows.Y0 + j + 0.5, xMin, xMax))
      {
        continue;
      }
      const hov::PixelRange span =
        hov::PixelCentresIn(xMin, xMax, rows.X0 + r0, rows.X0 + r1, BoxMargin);
      r0 = span.First - rows.X0;
      r1 = span.Last - rows.X0;
    }
    for (int i = r0; i <= r1; ++i)
    {
      const int p = j * rows.W + i;
      if ((skip && skip[p]) || !(rows.TMax[p] > 0.0))
      {
        continue; // finished, or nothing left of the ray after clipping
      }
      const hov::ViewRays::Ray& ray = rows.Rays[p];
      const double origin[3] = { ray.Origin.x, ray.Origin.y, ray.Origin.z };
      const double direction[3] = { ray.Direction.x, ray.Direction.y, ray.Direction.z };
      const int n = hov::RayCellIntervals(cell.Shape, nodes, cell.CornerIds, origin, direction, 0.0,
        rows.TMax[p], found, cell.PlanarFaces, frame.Perturbation);
      if (n <= 0)
      {
        continue;
      }
      this->Hits.push_back(Hit{ p, static_cast<int>(this->IntervalList.size()), n });
      this->IntervalList.insert(this->IntervalList.end(), found, found + n);
    }
  }
  return this->Hits;
}

const std::vector<hov::RestrictedPiece>& hov::GeneralCellTile::Restrict(const FrameData& frame,
  int g, const hov::ViewRays::Ray& ray, double t0, double t1)
{
  const hov::GeneralCells& cells = *frame.Cells;
  const hov::GeneralCells::Cell& cell = cells.GetCells()[g];
  if (cell.ScalarMin == cell.ScalarMax)
  {
    // A constant field (cell scalars): one exact constant piece.
    this->Pieces.assign(1, hov::RestrictedPiece());
    this->Pieces[0].T0 = t0;
    this->Pieces[0].T1 = t1;
    this->Pieces[0].S.C[0] = cell.ScalarMin;
    return this->Pieces;
  }
  const double origin[3] = { ray.Origin.x, ray.Origin.y, ray.Origin.z };
  const double direction[3] = { ray.Direction.x, ray.Direction.y, ray.Direction.z };
  if (cell.Affine)
  {
    this->Pieces.resize(1);
    hov::GeneralCells::RestrictAffine(
      cell, cells.GetNodes(cell), origin, direction, t0, t1, this->Pieces[0]);
  }
  else
  {
    hov::RestrictCellScalar(cell.Shape, cells.GetNodes(cell), cells.GetScalars(cell), origin,
      direction, t0, t1, frame.Restriction, this->Pieces);
  }
  const double tol =
    NegligibleRelative * std::max(std::abs(cell.ScalarMin), std::abs(cell.ScalarMax));
  for (hov::RestrictedPiece& piece : this->Pieces)
  {
    hov::TrimNegligibleTerms(piece.S, piece.T1 - piece.T0, tol);
  }
  return this->Pieces;
}

hov::RGBA hov::GeneralCellTile::Integrate(const FrameData& frame, int g,
  const hov::ViewRays::Ray& ray, double t0, double t1, vtkIdType& pieces)
{
  const hov::GeneralCells::Cell& cell = frame.Cells->GetCells()[g];
  hov::RGBA sum;
  if (cell.ScalarMin == cell.ScalarMax)
  {
    // A constant field (cell scalars): one exact constant piece.
    hov::Polynomial s;
    s.C[0] = cell.ScalarMin;
    const hov::PolynomialSegmentResult r =
      hov::IntegratePolynomialScalar(*frame.TF, s, t1 - t0, frame.Segment);
    pieces += r.Pieces;
    return r.Color;
  }
  for (const hov::RestrictedPiece& piece : this->Restrict(frame, g, ray, t0, t1))
  {
    const hov::PolynomialSegmentResult r =
      hov::IntegratePolynomialScalar(*frame.TF, piece.S, piece.T1 - piece.T0, frame.Segment);
    pieces += r.Pieces;
    hov::CompositeBehind(sum, r.Color);
    if (sum.A >= 1.0)
    {
      break; // nothing behind is visible
    }
  }
  return sum;
}
