#include "hovCellProjector.h"

#include "hovProjectorTile.h" // the per-tile work
#include "hovTileBatches.h"   // progress and abort between tile batches
#include "hovCellSetup.h"
#include "hovViewRays.h"

#include "hovPixelRange.h"       // pixel boxes of far-off cells
#include "hovTransferFunction.h" // the table

#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"

#include <algorithm> // std::min, std::max, std::sort
#include <array>     // pixel boxes
#include <utility>   // pair
#include <cmath>     // std::ceil, std::floor

/// Per-frame arrays kept across frames.
struct vtkHighOrderCellProjector::Buffers
{
  std::vector<glm::dvec2> Window;
  std::vector<unsigned char> Projectable;
  std::vector<vtkHighOrderProjectorTile::CellRecord> Cells;
  std::vector<vtkHighOrderProjectorTile::Box> Boxes; ///< the records' pixel boxes, for binning
  std::vector<std::pair<float, vtkIdType>> DepthOrder; ///< per-pixel mode: (depth, tetra)
  std::vector<vtkIdType> Order;                        ///< per-pixel mode: tetras by depth
  std::vector<int> GeneralOf; ///< per ordered cell: general cell index, or -1
  vtkHighOrderProjectorTile::Bins TileBins;
  vtkSMPThreadLocal<vtkHighOrderProjectorTile> Tiles;
};

namespace
{
// Witness tolerance: a later cell may start this much (relative to the view
// depth) in front of the farthest exit so far before the order counts as
// wrong. Exits and entries through a shared face are bit-identical (canonical
// planes), so this only absorbs round-off at edges and vertices.
constexpr double WitnessRelativeTolerance = 1e-9;

using Box = vtkHighOrderProjectorTile::Box;
using CellRecord = vtkHighOrderProjectorTile::CellRecord;
using Tetra = vtkHighOrderTetraSetup::Tetra;

/// Pixel box of a tetrahedron: the pixel centres inside its projected
/// bounding box, widened by BoxMargin pixels against round-off in the
/// projection (the per-pixel ray test that follows is exact).
constexpr double BoxMargin = vtkHighOrderProjectorTile::BoxMargin;

/// Distance, in ordered cells, at which a tetrahedron is prefetched while the
/// cell records are built.
constexpr vtkIdType RecordPrefetch = 8;

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
  return hov::PixelBoxOf(x0, x1, y0, y1, width, height, BoxMargin);
}

/// Centroid of the corners of general cell @p g (per-pixel mode's depth key).
glm::dvec3 GeneralCentroid(const vtkHighOrderTetraSetup& setup, vtkIdType g)
{
  const vtkHighOrderGeneralCells& cells = setup.GetGeneralCells();
  const vtkHighOrderGeneralCells::Cell& cell = cells.GetCells()[g];
  const double* x = cells.GetNodes(cell);
  const int n = hov::CellCornerCount(cell.Shape);
  glm::dvec3 c(0.0);
  for (int v = 0; v < n; ++v)
  {
    c += glm::dvec3(x[3 * v], x[3 * v + 1], x[3 * v + 2]);
  }
  return c / static_cast<double>(n);
}

/// The record of general cell @p g: only its pixel box and projectability
/// are read by the tile loop (binning, band test); the rest is zero.
void GeneralRecord(const vtkHighOrderGeneralCellTile::FrameData& general, int g, int width,
  int height, CellRecord& cell)
{
  cell = CellRecord();
  bool projectable = true;
  cell.PixelBox = vtkHighOrderGeneralCellTile::PixelBox(general, g, width, height, projectable);
  cell.Projectable = projectable;
  cell.Interval = -2;
}
}

vtkHighOrderCellProjector::Statistics vtkHighOrderCellProjector::Render(
  const vtkHighOrderTetraSetup& setup, const std::vector<vtkIdType>& frontToBack,
  const vtkHighOrderViewRays& rays, const hov::TransferFunction& tf, const Settings& settings,
  const float* depth, std::vector<double>& rgba) const
{
  Statistics stats;
  const int width = rays.GetWidth(), height = rays.GetHeight();
  if (width <= 0 || height <= 0 || frontToBack.empty() || tf.GetNumberOfNodes() == 0)
  {
    rgba.assign(static_cast<size_t>(std::max(width, 0)) * std::max(height, 0) * 4, 0.0);
    return stats;
  }
  // The tiles cover the image and write every pixel: no need to clear it.
  rgba.resize(static_cast<size_t>(width) * height * 4);
  const auto& tets = setup.GetTetras();
  const auto& points = setup.GetPoints();
  const vtkIdType numTets = static_cast<vtkIdType>(tets.size());
  const bool hasGeneral = !setup.GetGeneralCells().GetCells().empty();

  // Per-frame arrays live across frames: no allocation, no page faults.
  if (!this->Scratch)
  {
    this->Scratch = std::make_shared<Buffers>();
  }
  Buffers& buf = *this->Scratch;

  // Project every point once.
  std::vector<glm::dvec2>& window = buf.Window;
  std::vector<unsigned char>& projectable = buf.Projectable;
  window.resize(points.size());
  projectable.resize(points.size());
  vtkSMPTools::For(0, static_cast<vtkIdType>(points.size()), [&](vtkIdType b, vtkIdType e) {
    for (vtkIdType i = b; i < e; ++i)
    {
      double x = 0.0, y = 0.0;
      projectable[i] = rays.Project(points[i], x, y);
      window[i] = glm::dvec2(x, y);
    }
  });
  // Per-pixel mode: any cell order gives the same image, since each pixel
  // sorts its own segments; cells by centroid depth along the central ray
  // make each pixel's list arrive nearly sorted (cheap insertion sort), and
  // sorting them once here keeps every tile's list in depth order and in
  // memory order at the same time.
  const std::vector<vtkIdType>* order = &frontToBack;
  if (settings.PerPixelSort)
  {
    const vtkHighOrderViewRays::Ray centre = rays.PixelRay(width / 2, height / 2);
    buf.DepthOrder.resize(frontToBack.size());
    vtkSMPTools::For(0, static_cast<vtkIdType>(frontToBack.size()), [&](vtkIdType b, vtkIdType e) {
      for (vtkIdType k = b; k < e; ++k)
      {
        const vtkIdType id = frontToBack[k];
        const glm::dvec3 c = id < numTets ? 0.25 * (points[tets[id].Points[0]] +
                                                     points[tets[id].Points[1]] +
                                                     points[tets[id].Points[2]] +
                                                     points[tets[id].Points[3]])
                                          : GeneralCentroid(setup, id - numTets);
        buf.DepthOrder[k] = { static_cast<float>(glm::dot(c - centre.Origin, centre.Direction)),
          frontToBack[k] };
      }
    });
    vtkSMPTools::Sort(buf.DepthOrder.begin(), buf.DepthOrder.end()); // (depth, id): deterministic
    buf.Order.resize(buf.DepthOrder.size());
    for (size_t k = 0; k < buf.Order.size(); ++k)
    {
      buf.Order[k] = buf.DepthOrder[k].second;
    }
    order = &buf.Order;
  }
  // Per cell, in that order and in one pass, its record for the tile loop:
  // face planes and field, projected vertices, pixel box, and the
  // transfer-function interval holding its whole scalar range (most cells of
  // a fine mesh: their segments skip the search).
  const size_t numCells = order->size();
  std::vector<CellRecord>& records = buf.Cells;
  records.resize(numCells);
  buf.Boxes.resize(numCells);
  // The general cells' frame data (their records only carry the pixel box).
  vtkHighOrderGeneralCellTile::FrameData general;
  general.Cells = &setup.GetGeneralCells();
  general.GeneralOf = &buf.GeneralOf;
  general.Window = window.data();
  general.Perturbation = vtkHighOrderGeneralCellTile::PerturbationOf(rays);
  general.Projectable = projectable.data();
  general.TF = &tf;
  general.Segment.Emission = settings.Integration.Emission;
  buf.GeneralOf.resize(hasGeneral ? numCells : 0);
  vtkSMPTools::For(0, static_cast<vtkIdType>(numCells), [&](vtkIdType b, vtkIdType e) {
    for (vtkIdType k = b; k < e; ++k)
    {
      if (hasGeneral)
      {
        buf.GeneralOf[k] = (*order)[k] < numTets ? -1 : static_cast<int>((*order)[k] - numTets);
        if (buf.GeneralOf[k] >= 0)
        {
          GeneralRecord(general, buf.GeneralOf[k], width, height, records[k]);
          buf.Boxes[k] = records[k].PixelBox;
          continue;
        }
      }
      // The order scatters the tetrahedra in memory: fetch a few ahead.
      if (k + RecordPrefetch < e && (*order)[k + RecordPrefetch] < numTets)
      {
        const char* ahead = reinterpret_cast<const char*>(&tets[(*order)[k + RecordPrefetch]]);
        for (size_t offset = 0; offset < sizeof(Tetra); offset += 64)
        {
          __builtin_prefetch(ahead + offset);
        }
      }
      const Tetra& tet = tets[(*order)[k]];
      CellRecord& cell = records[k];
      for (int f = 0; f < 4; ++f)
      {
        cell.NX[f] = tet.Normal[f].x;
        cell.NY[f] = tet.Normal[f].y;
        cell.NZ[f] = tet.Normal[f].z;
        cell.Offset[f] = tet.Offset[f];
      }
      cell.Gradient = tet.Gradient;
      cell.RefPoint = tet.RefPoint;
      cell.RefScalar = tet.RefScalar;
      cell.PixelBox = PixelBox(tet, window, projectable, width, height);
      cell.Projectable = true;
      for (int v = 0; v < 4; ++v)
      {
        cell.Vertex[v] = window[tet.Points[v]];
        cell.Projectable = cell.Projectable && projectable[tet.Points[v]];
      }
      cell.Interval = hov::IntervalOfRange(tf, tet.ScalarMin, tet.ScalarMax);
      if (cell.Interval == -2)
      {
        // Across nodes: a hint for the search of each segment's interval.
        cell.Interval = -3 - tf.FindIntervalUpward(tet.ScalarMin);
      }
      buf.Boxes[k] = cell.PixelBox;
    }
  });
  vtkHighOrderProjectorTile::Bins& bins = buf.TileBins;
  bins.Build(buf.Boxes, width, height, std::min(std::max(4, settings.TileSize), vtkHighOrderProjectorTile::MaxTileSize));

  // Tiles in parallel; every pixel is composited by one thread in a fixed order.
  const int numTiles = bins.TilesX * bins.TilesY;
  vtkHighOrderProjectorTile::Frame frame;
  frame.TileBins = &bins;
  frame.Cells = &records;
  frame.TF = &tf;
  frame.Settings = &settings;
  frame.Rays = &rays;
  frame.Depth = depth;
  frame.WitnessTol = WitnessRelativeTolerance * rays.GetDepthScale();
  frame.PerturbX = rays.GetPerturbX();
  frame.PerturbY = rays.GetPerturbY();
  frame.General = hasGeneral ? &general : nullptr;
  std::vector<Statistics> tileStats(numTiles);
  // One tile object per thread, kept across tiles and frames so that its
  // buffers keep their capacity (the result does not depend on which thread
  // runs a tile).
  vtkSMPThreadLocal<vtkHighOrderProjectorTile>& tiles = buf.Tiles;
  const int tilesDone = vtkHighOrderForTileBatches(numTiles, settings.Progress,
    [&](vtkIdType t) { tiles.Local().Render(frame, static_cast<int>(t), rgba, tileStats[t]); });
  stats.Aborted = tilesDone < numTiles;
  vtkHighOrderClearTiles(tilesDone, numTiles, bins.TilesX, bins.Size, width, height, rgba);
  for (const Statistics& st : tileStats)
  {
    stats.WitnessViolations += st.WitnessViolations;
    stats.Segments += st.Segments;
    stats.Pieces += st.Pieces;
  }
  return stats;
}
