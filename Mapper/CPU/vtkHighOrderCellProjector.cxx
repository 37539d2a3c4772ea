#include "vtkHighOrderCellProjector.h"

#include "vtkHighOrderTetraSetup.h"
#include "vtkHighOrderViewRays.h"

#include "hovCompositing.h"      // CompositeBehind
#include "hovTransferFunction.h" // the table

#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"

#include <algorithm> // std::min, std::max, std::sort
#include <array>     // pixel boxes
#include <cmath>     // std::ceil, std::floor

namespace
{
// Witness tolerance: a later cell may start this much (relative to the view
// depth) in front of the farthest exit so far before the order counts as
// wrong. Exits and entries through a shared face are bit-identical (canonical
// planes), so this only absorbs round-off at edges and vertices.
constexpr double WitnessRelativeTolerance = 1e-9;

using Box = std::array<int, 4>; // i0, i1, j0, j1 inclusive; i0 > i1 means empty

/// A cell's projected vertices, stored per ordered cell so that the tile
/// loop reads one cache line instead of four scattered points.
struct CellScreen
{
  glm::dvec2 Vertex[4];
  bool Projectable; ///< every vertex in front of the eye plane
};
using Tetra = vtkHighOrderTetraSetup::Tetra;
using Ray = vtkHighOrderViewRays::Ray;

/// Pixel box of a tetrahedron: the pixel centres inside its projected
/// bounding box, widened by BoxMargin pixels against round-off in the
/// projection (the per-pixel ray test that follows is exact).
constexpr double BoxMargin = 1e-6;

Box PixelBox(const Tetra& tet, const std::vector<glm::dvec2>& window,
  const std::vector<unsigned char>& projectable, int width, int height)
{
  double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
  for (vtkIdType id : tet.Points)
  {
    if (!projectable[id])
    {
      return Box{ 0, width - 1, 0, height - 1 }; // crosses the eye plane
    }
    x0 = std::min(x0, window[id].x);
    x1 = std::max(x1, window[id].x);
    y0 = std::min(y0, window[id].y);
    y1 = std::max(y1, window[id].y);
  }
  const double lim = 1e9; // keep the int conversion defined for far-off cells
  Box b;
  b[0] = static_cast<int>(std::max(0.0, std::ceil(std::max(x0, -lim) - 0.5 - BoxMargin)));
  b[1] = static_cast<int>(std::min(width - 1.0, std::floor(std::min(x1, lim) - 0.5 + BoxMargin)));
  b[2] = static_cast<int>(std::max(0.0, std::ceil(std::max(y0, -lim) - 0.5 - BoxMargin)));
  b[3] = static_cast<int>(std::min(height - 1.0, std::floor(std::min(y1, lim) - 0.5 + BoxMargin)));
  return b;
}

/// Exact clip of a ray against the four face planes; false if it misses.
/// A ray parallel to a face and exactly in its plane (num == 0) is resolved
/// by the symbolic displacement e px + e^2 py of vtkHighOrderViewRays: inside
/// iff n.px < 0, or n.px == 0 and n.py < 0. The two cells sharing a face hold
/// opposite canonical normals, so exactly one of them takes such a ray.
inline bool ClipRay(const Tetra& tet, const Ray& ray, double tMax, const glm::dvec3& px,
  const glm::dvec3& py, double& tIn, double& tOut)
{
  tIn = 0.0;
  tOut = tMax;
  for (int k = 0; k < 4; ++k)
  {
    const double denom = glm::dot(tet.Normal[k], ray.Direction);
    const double num = tet.Offset[k] - glm::dot(tet.Normal[k], ray.Origin);
    if (denom > 0.0)
    {
      tOut = std::min(tOut, num / denom);
    }
    else if (denom < 0.0)
    {
      tIn = std::max(tIn, num / denom);
    }
    else if (num < 0.0)
    {
      return false;
    }
    else if (num == 0.0)
    {
      const double nx = glm::dot(tet.Normal[k], px);
      if (nx > 0.0 || (nx == 0.0 && glm::dot(tet.Normal[k], py) >= 0.0))
      {
        return false;
      }
    }
  }
  return tIn < tOut;
}

/// A ray-cell segment waiting for its turn (per-pixel ordering).
struct Fragment
{
  double TIn, TOut, SIn, SOut;
  int Pixel;
  int Order; ///< position in the tile's cell list: a deterministic tie-break
  bool operator<(const Fragment& o) const
  {
    return this->TIn != o.TIn ? this->TIn < o.TIn : this->Order < o.Order;
  }
};

/// Insertion sort: linear on the nearly sorted per-pixel lists.
void InsertionSort(Fragment* first, Fragment* last)
{
  for (Fragment* i = first + 1; i < last; ++i)
  {
    if (!(*i < *(i - 1)))
    {
      continue;
    }
    const Fragment v = *i;
    Fragment* j = i;
    do
    {
      *j = *(j - 1);
      --j;
    } while (j > first && v < *(j - 1));
    *j = v;
  }
}

/// Cells binned into image tiles, each tile's list in visibility order.
struct TileBins
{
  int Size, TilesX, TilesY;
  std::vector<Box> Boxes;           // per ordered cell
  std::vector<vtkIdType> Start;     // per tile, into Cells
  std::vector<vtkIdType> Cells;     // ordered-cell indices

  void Build(const std::vector<Box>& boxes, int width, int height, int tileSize)
  {
    this->Size = tileSize;
    this->TilesX = (width + tileSize - 1) / tileSize;
    this->TilesY = (height + tileSize - 1) / tileSize;
    const int numTiles = this->TilesX * this->TilesY;
    this->Start.assign(numTiles + 1, 0);
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
    for (const Box& b : boxes)
    {
      forTiles(b, [&](int t) { ++this->Start[t + 1]; });
    }
    for (int t = 0; t < numTiles; ++t)
    {
      this->Start[t + 1] += this->Start[t];
    }
    this->Cells.resize(this->Start[numTiles]);
    std::vector<vtkIdType> fill(this->Start.begin(), this->Start.end() - 1);
    for (size_t k = 0; k < boxes.size(); ++k)
    {
      forTiles(boxes[k], [&](int t) { this->Cells[fill[t]++] = static_cast<vtkIdType>(k); });
    }
  }
};

/// One tile's pixels: rays, accumulated colour, witness state.
struct Tile
{
  int X0 = 0, Y0 = 0, W = 0, H = 0;
  std::vector<Ray> Rays;
  std::vector<double> TMax;
  std::vector<hov::RGBA> Accum;
  std::vector<double> MaxExit;
  std::vector<unsigned char> Violated;
  std::vector<unsigned char> Done;
  std::vector<Fragment> Fragments; ///< in cell order
  std::vector<Fragment> ByPixel;   ///< bucketed by pixel, then sorted by entry
  std::vector<int> PixelStart;
  std::vector<int> Fill;
  std::vector<vtkIdType> CellOrder;

  void Init(int tileIndex, const TileBins& bins, const vtkHighOrderViewRays& rays, const float* depth)
  {
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
    this->Fragments.clear();
    for (int j = 0; j < this->H; ++j)
    {
      for (int i = 0; i < this->W; ++i)
      {
        const int pi = this->X0 + i, pj = this->Y0 + j;
        const size_t p = static_cast<size_t>(j) * this->W + i;
        this->Rays[p] = rays.PixelRay(pi, pj);
        double tMax = this->Rays[p].TFar;
        const double z = depth ? depth[static_cast<size_t>(pj) * width + pi] : 1.0;
        if (z < 1.0)
        {
          tMax = std::min(tMax, rays.DepthToT(pi, pj, this->Rays[p], z));
        }
        this->TMax[p] = tMax;
      }
    }
  }

  /// Tile-local pixel range covered by box b.
  void Clamp(const Box& b, int& i0, int& i1, int& j0, int& j1) const
  {
    i0 = std::max(b[0], this->X0) - this->X0;
    i1 = std::min(b[1], this->X0 + this->W - 1) - this->X0;
    j0 = std::max(b[2], this->Y0) - this->Y0;
    j1 = std::min(b[3], this->Y0 + this->H - 1) - this->Y0;
  }

  void Write(std::vector<double>& rgba, int width, vtkHighOrderCellProjector::Statistics& st) const
  {
    for (int j = 0; j < this->H; ++j)
    {
      for (int i = 0; i < this->W; ++i)
      {
        const size_t p = static_cast<size_t>(j) * this->W + i;
        double* out = &rgba[4 * (static_cast<size_t>(this->Y0 + j) * width + this->X0 + i)];
        out[0] = this->Accum[p].R;
        out[1] = this->Accum[p].G;
        out[2] = this->Accum[p].B;
        out[3] = this->Accum[p].A;
        st.WitnessViolations += this->Violated[p];
      }
    }
  }
};

/// Everything a tile worker reads.
struct Frame
{
  const std::vector<Tetra>& Tets;
  const std::vector<vtkIdType>& Order;
  const TileBins& Bins;
  const hov::TransferFunction& TF;
  const vtkHighOrderCellProjector::Settings& Settings;
  double WitnessTol;
  glm::dvec3 PerturbX, PerturbY;
  const std::vector<CellScreen>& Screen;           ///< per ordered cell: projected vertices
  const std::vector<float>& DepthKey;              ///< per ordered cell: centroid depth
  const std::vector<int>& CellInterval; ///< per ordered cell: its transfer-function interval, or -2

  /// Witness, integral and compositing of one segment at tile pixel p.
  void Integrate(Tile& tile, size_t p, double tIn, double tOut, double sIn, double sOut,
    int interval, vtkHighOrderCellProjector::Statistics& st) const
  {
    if (tIn < tile.MaxExit[p] - this->WitnessTol)
    {
      tile.Violated[p] = 1;
    }
    tile.MaxExit[p] = std::max(tile.MaxExit[p], tOut);
    int pieces = 1;
    const hov::RGBA seg = interval >= -1
      ? hov::IntegrateLinearScalarInInterval(
          this->TF, interval, sIn, sOut, tOut - tIn, this->Settings.Integration)
      : hov::IntegrateLinearScalar(this->TF, sIn, sOut, tOut - tIn, this->Settings.Integration, &pieces);
    hov::CompositeBehind(tile.Accum[p], seg);
    ++st.Segments;
    st.Pieces += pieces;
    if (1.0 - tile.Accum[p].A <= this->Settings.TerminationTransmittance)
    {
      tile.Done[p] = 1;
    }
  }

  /// Visit every (pixel, segment) of the tile's cells in visibility order.
  /**
   * Window-x range of the projected cell on the row at height y: the
   * projection is the convex hull of the projected vertices, and a line meets
   * a convex hull of points in the span of its crossings with all segments
   * between them (the six projected edges). False if the row misses it.
   */
  static bool RowSpan(const CellScreen& cell, double y, double& xMin, double& xMax)
  {
    xMin = 1e300;
    xMax = -1e300;
    for (int a = 0; a < 4; ++a)
    {
      const glm::dvec2& p = cell.Vertex[a];
      for (int b = a + 1; b < 4; ++b)
      {
        const glm::dvec2& q = cell.Vertex[b];
        if ((p.y - y) * (q.y - y) > 0.0)
        {
          continue; // the edge is entirely above or below the row
        }
        if (p.y == q.y)
        {
          xMin = std::min(xMin, std::min(p.x, q.x));
          xMax = std::max(xMax, std::max(p.x, q.x));
          continue;
        }
        const double x = p.x + (q.x - p.x) * ((y - p.y) / (q.y - p.y));
        xMin = std::min(xMin, x);
        xMax = std::max(xMax, x);
      }
    }
    return xMin <= xMax;
  }

  /// Visit every (pixel, segment) of the tile's cells in visibility order.
  template <typename Visit>
  void ForSegments(Tile& tile, const vtkIdType* cells, vtkIdType count, bool skipDone, Visit&& visit) const
  {
    for (vtkIdType c = 0; c < count; ++c)
    {
      const vtkIdType k = cells[c];
      const Tetra& tet = this->Tets[this->Order[k]];
      const CellScreen& screen = this->Screen[k];
      int i0, i1, j0, j1;
      tile.Clamp(this->Bins.Boxes[k], i0, i1, j0, j1);
      for (int j = j0; j <= j1; ++j)
      {
        int r0 = i0, r1 = i1;
        double xMin, xMax;
        if (screen.Projectable)
        {
          // Only the pixel centres inside the projection (BoxMargin of slack).
          if (!RowSpan(screen, tile.Y0 + j + 0.5, xMin, xMax))
          {
            continue;
          }
          r0 = std::max(r0, static_cast<int>(std::ceil(xMin - 0.5 - BoxMargin)) - tile.X0);
          r1 = std::min(r1, static_cast<int>(std::floor(xMax - 0.5 + BoxMargin)) - tile.X0);
        }
        for (int i = r0; i <= r1; ++i)
        {
          const size_t p = static_cast<size_t>(j) * tile.W + i;
          double tIn, tOut;
          if ((skipDone && tile.Done[p]) ||
            !ClipRay(tet, tile.Rays[p], tile.TMax[p], this->PerturbX, this->PerturbY, tIn, tOut))
          {
            continue;
          }
          const Ray& ray = tile.Rays[p];
          const double sAtOrigin = tet.RefScalar + glm::dot(tet.Gradient, ray.Origin - tet.RefPoint);
          const double slope = glm::dot(tet.Gradient, ray.Direction);
          visit(p, k, tIn, tOut, sAtOrigin + tIn * slope, sAtOrigin + tOut * slope);
        }
      }
    }
  }

  void RenderTile(Tile& tile, int tileIndex, vtkHighOrderCellProjector::Statistics& st) const
  {
    const vtkIdType* cells = this->Bins.Cells.data() + this->Bins.Start[tileIndex];
    const vtkIdType count = this->Bins.Start[tileIndex + 1] - this->Bins.Start[tileIndex];
    if (!this->Settings.PerPixelSort)
    {
      this->ForSegments(tile, cells, count, true,
        [&](size_t p, vtkIdType k, double tIn, double tOut, double sIn, double sOut) {
          this->Integrate(tile, p, tIn, tOut, sIn, sOut, this->CellInterval[k], st);
        });
      return;
    }
    // Cells by centroid depth first: each pixel's fragments then arrive nearly
    // in order and the insertion sort below has little to do. (Any order
    // gives the same image; this one only makes sorting cheap.)
    tile.CellOrder.assign(cells, cells + count);
    const std::vector<float>& key = this->DepthKey;
    std::sort(tile.CellOrder.begin(), tile.CellOrder.end(),
      [&key](vtkIdType p, vtkIdType q) { return key[p] != key[q] ? key[p] < key[q] : p < q; });
    this->ForSegments(tile, tile.CellOrder.data(), count, false,
      [&](size_t p, vtkIdType k, double tIn, double tOut, double sIn, double sOut) {
        tile.Fragments.push_back(
          Fragment{ tIn, tOut, sIn, sOut, static_cast<int>(p), static_cast<int>(k) });
      });
    // Counting sort by pixel (stable), then each pixel's list by entry.
    const size_t n = tile.Accum.size();
    tile.PixelStart.assign(n + 1, 0);
    for (const Fragment& f : tile.Fragments)
    {
      ++tile.PixelStart[f.Pixel + 1];
    }
    for (size_t p = 0; p < n; ++p)
    {
      tile.PixelStart[p + 1] += tile.PixelStart[p];
    }
    tile.ByPixel.resize(tile.Fragments.size());
    {
      std::vector<int>& fill = tile.Fill;
      fill.assign(tile.PixelStart.begin(), tile.PixelStart.end() - 1);
      for (const Fragment& f : tile.Fragments)
      {
        tile.ByPixel[fill[f.Pixel]++] = f;
      }
    }
    for (size_t p = 0; p < n; ++p)
    {
      Fragment* first = tile.ByPixel.data() + tile.PixelStart[p];
      Fragment* last = tile.ByPixel.data() + tile.PixelStart[p + 1];
      InsertionSort(first, last);
      for (const Fragment* f = first; f != last && !tile.Done[p]; ++f)
      {
        this->Integrate(tile, p, f->TIn, f->TOut, f->SIn, f->SOut, this->CellInterval[f->Order], st);
      }
    }
  }
};
}

vtkHighOrderCellProjector::Statistics vtkHighOrderCellProjector::Render(
  const vtkHighOrderTetraSetup& setup, const std::vector<vtkIdType>& frontToBack,
  const vtkHighOrderViewRays& rays, const hov::TransferFunction& tf, const Settings& settings,
  const float* depth, std::vector<double>& rgba) const
{
  Statistics stats;
  const int width = rays.GetWidth(), height = rays.GetHeight();
  rgba.assign(static_cast<size_t>(width) * height * 4, 0.0);
  if (width <= 0 || height <= 0 || frontToBack.empty() || tf.GetNumberOfNodes() == 0)
  {
    return stats;
  }
  const auto& tets = setup.GetTetras();
  const auto& points = setup.GetPoints();

  // Project every point once, then box every cell (in visibility order).
  std::vector<glm::dvec2> window(points.size());
  std::vector<unsigned char> projectable(points.size());
  vtkSMPTools::For(0, static_cast<vtkIdType>(points.size()), [&](vtkIdType b, vtkIdType e) {
    for (vtkIdType i = b; i < e; ++i)
    {
      double x = 0.0, y = 0.0;
      projectable[i] = rays.Project(points[i], x, y);
      window[i] = glm::dvec2(x, y);
    }
  });
  // Per cell, in one pass: its pixel box; the transfer-function interval
  // holding its whole scalar range (most cells of a fine mesh: their segments
  // skip the search); its centroid depth along the central ray, to presort
  // cells in per-pixel mode.
  const size_t numCells = frontToBack.size();
  TileBins bins;
  bins.Boxes.resize(numCells);
  std::vector<int> cellInterval(numCells);
  std::vector<CellScreen> screen(numCells);
  std::vector<float> depthKey(settings.PerPixelSort ? numCells : 0);
  const vtkHighOrderViewRays::Ray centre = rays.PixelRay(width / 2, height / 2);
  vtkSMPTools::For(0, static_cast<vtkIdType>(numCells), [&](vtkIdType b, vtkIdType e) {
    for (vtkIdType k = b; k < e; ++k)
    {
      const Tetra& tet = tets[frontToBack[k]];
      bins.Boxes[k] = PixelBox(tet, window, projectable, width, height);
      CellScreen& cs = screen[k];
      cs.Projectable = true;
      for (int v = 0; v < 4; ++v)
      {
        cs.Vertex[v] = window[tet.Points[v]];
        cs.Projectable = cs.Projectable && projectable[tet.Points[v]];
      }
      cellInterval[k] = hov::IntervalOfRange(tf, tet.ScalarMin, tet.ScalarMax);
      if (settings.PerPixelSort)
      {
        const glm::dvec3 c = 0.25 * (points[tet.Points[0]] + points[tet.Points[1]] +
                                points[tet.Points[2]] + points[tet.Points[3]]);
        depthKey[k] = static_cast<float>(glm::dot(c - centre.Origin, centre.Direction));
      }
    }
  });
  bins.Build(bins.Boxes, width, height, std::max(4, settings.TileSize));

  // Tiles in parallel; every pixel is composited by one thread in a fixed order.
  const int numTiles = bins.TilesX * bins.TilesY;
  const Frame frame{ tets, frontToBack, bins, tf, settings,
    WitnessRelativeTolerance * rays.GetDepthScale(), rays.GetPerturbX(), rays.GetPerturbY(), screen,
    depthKey, cellInterval };
  std::vector<Statistics> tileStats(numTiles);
  // One Tile per thread, reused from tile to tile so that its buffers keep
  // their capacity (the result does not depend on which thread runs a tile).
  vtkSMPThreadLocal<Tile> tiles;
  vtkSMPTools::For(0, numTiles, 1, [&](vtkIdType tBegin, vtkIdType tEnd) {
    Tile& tile = tiles.Local();
    for (vtkIdType t = tBegin; t < tEnd; ++t)
    {
      tile.Init(static_cast<int>(t), bins, rays, depth);
      frame.RenderTile(tile, static_cast<int>(t), tileStats[t]);
      tile.Write(rgba, width, tileStats[t]);
    }
  });
  for (const Statistics& st : tileStats)
  {
    stats.WitnessViolations += st.WitnessViolations;
    stats.Segments += st.Segments;
    stats.Pieces += st.Pieces;
  }
  return stats;
}
