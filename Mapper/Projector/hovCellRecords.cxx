#include "hovCellRecords.h"

#include "hovCellSetup.h"    // the cells
#include "hovGeneralCells.h" // their shapes and node ranges

#include "hovPixelRange.h"       // pixel boxes of far-off cells
#include "hovRayIntegrator.h"    // IntervalOfRange
#include "hovTransferFunction.h" // the table

#include "vtkSMPTools.h" // the per-frame pass

#include <algorithm> // std::min, std::max
#include <atomic>    // the count of transparent cells

namespace
{
using Tetra = hov::CellSetup::Tetra;
using CellRecord = hov::CellRecords::CellRecord;

/// Distance, in ordered cells, at which a tetrahedron is prefetched while the
/// cell records are built.
constexpr vtkIdType RecordPrefetch = 8;

/// The record of general cell @p g: only its pixel box and projectability
/// are read by the tile loop (binning, band test); the rest is zero.
void GeneralRecord(const hov::GeneralCellTile::FrameData& general, int g, int width,
  int height, CellRecord& cell)
{
  cell = CellRecord();
  bool projectable = true;
  cell.PixelBox = hov::GeneralCellTile::PixelBox(general, g, width, height, projectable);
  cell.Projectable = projectable;
  cell.Interval = -2;
}

/**
 * True if general cell @p g is linear (voxel, hexahedron, wedge, pyramid:
 * shape functions >= 0 in the cell, so the field stays within its node
 * values) and @p tf has no extinction over that range. A quadratic cell's
 * field can leave its node range: never skipped.
 */
bool TransparentGeneral(
  const hov::GeneralCellTile::FrameData& general, int g, const hov::TransferFunction& tf)
{
  const hov::GeneralCells::Cell& cell = general.Cells->GetCells()[g];
  const bool linear = cell.Shape == hov::CellShape::Voxel ||
    cell.Shape == hov::CellShape::Hexahedron || cell.Shape == hov::CellShape::Wedge ||
    cell.Shape == hov::CellShape::Pyramid;
  return linear && tf.ZeroExtinctionOver(cell.ScalarMin, cell.ScalarMax);
}

/// The record of tetrahedron @p tet with pixel box @p box (see
/// hov::ProjectorTile::CellRecord).
void TetraRecord(const hov::CellSetup& setup, const Tetra& tet, const hov::CellBox& box,
  const hov::ProjectedPoints& points, const hov::TransferFunction& tf, CellRecord& cell)
{
  setup.FacePlanes(tet, cell.NX, cell.NY, cell.NZ, cell.Offset);
  cell.Gradient = tet.Gradient;
  cell.RefPoint = setup.RefPoint(tet);
  cell.RefScalar = tet.RefScalar;
  cell.PixelBox = box;
  cell.Projectable = true;
  for (int v = 0; v < 4; ++v)
  {
    cell.Vertex[v] = points.Window[tet.Points[v]];
    cell.Projectable = cell.Projectable && points.Projectable[tet.Points[v]];
  }
  cell.Interval = hov::IntervalOfRange(tf, tet.ScalarMin, tet.ScalarMax);
  if (cell.Interval == -2)
  {
    // Across nodes: a hint for the search of each segment's interval.
    cell.Interval = -3 - tf.FindIntervalUpward(tet.ScalarMin);
  }
}
}

hov::CellBox hov::CellRecords::TetraBox(
  const vtkIdType ids[4], const ProjectedPoints& points, int width, int height)
{
  // The pixel centres inside the projected bounding box, widened by
  // BoxMargin pixels against round-off in the projection (the per-pixel ray
  // test that follows is exact).
  double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
  for (int v = 0; v < 4; ++v)
  {
    const vtkIdType id = ids[v];
    if (!points.Projectable[id])
    {
      return CellBox{ 0, width - 1, 0, height - 1 }; // crosses the eye plane
    }
    x0 = std::min(x0, points.Window[id].x);
    x1 = std::max(x1, points.Window[id].x);
    y0 = std::min(y0, points.Window[id].y);
    y1 = std::max(y1, points.Window[id].y);
  }
  return hov::PixelBoxOf(x0, x1, y0, y1, width, height, hov::BoxMargin);
}

vtkIdType hov::CellRecords::Build(const CellSetup& setup, const std::vector<vtkIdType>& order,
  const ProjectedPoints& points, const TransferFunction& tf, int width, int height,
  GeneralCellTile::FrameData& general, size_t budgetBytes, bool skipTransparent)
{
  this->Setup = &setup;
  this->Order = &order;
  this->Points = &points;
  this->TF = &tf;
  this->General = &general;
  this->Width = width;
  this->Height = height;
  const auto& tets = setup.GetTetras();
  const vtkIdType numTets = static_cast<vtkIdType>(tets.size());
  const bool hasGeneral = !setup.GetGeneralCells().GetCells().empty();
  const size_t numCells = order.size();
  this->Whole = numCells <= budgetBytes / sizeof(CellRecord);
  if (this->Whole)
  {
    this->Records.resize(numCells);
  }
  else
  {
    std::vector<CellRecord>().swap(this->Records); // give the memory back
  }
  this->Boxes.resize(numCells);
  this->GeneralOf.resize(hasGeneral ? numCells : 0);
  general.GeneralOf = &this->GeneralOf;
  // Per cell, in that order and in one pass, its pixel box and (whole) its
  // record: most cells of a fine mesh get the transfer-function interval
  // holding their whole scalar range (their segments skip the search).
  // A table without a node of zero extinction has no transparent cell.
  skipTransparent = skipTransparent && tf.HasZeroExtinctionNode();
  std::atomic<vtkIdType> transparent(0);
  vtkSMPTools::For(0, static_cast<vtkIdType>(numCells), [&](vtkIdType b, vtkIdType e) {
    CellRecord scratch;
    vtkIdType skipped = 0;
    for (vtkIdType k = b; k < e; ++k)
    {
      CellRecord& cell = this->Whole ? this->Records[k] : scratch;
      if (hasGeneral)
      {
        this->GeneralOf[k] = order[k] < numTets ? -1 : static_cast<int>(order[k] - numTets);
        if (this->GeneralOf[k] >= 0)
        {
          if (skipTransparent && TransparentGeneral(general, this->GeneralOf[k], tf))
          {
            this->Boxes[k] = CellBox{ 0, -1, 0, -1 }; // in no tile
            ++skipped;
            continue;
          }
          GeneralRecord(general, this->GeneralOf[k], width, height, cell);
          this->Boxes[k] = cell.PixelBox;
          continue;
        }
      }
      // The order scatters the tetrahedra in memory: fetch a few ahead.
      if (k + RecordPrefetch < e)
      {
        this->PrefetchCell(k + RecordPrefetch);
      }
      const Tetra& tet = tets[order[k]];
      if (skipTransparent && tf.ZeroExtinctionOver(tet.ScalarMin, tet.ScalarMax))
      {
        this->Boxes[k] = CellBox{ 0, -1, 0, -1 }; // in no tile
        ++skipped;
        continue;
      }
      this->Boxes[k] = TetraBox(tet.Points, points, width, height);
      if (this->Whole)
      {
        TetraRecord(setup, tet, this->Boxes[k], points, tf, cell);
      }
    }
    transparent += skipped;
  });
  return transparent;
}

void hov::CellRecords::EndFrame()
{
  this->Setup = nullptr;
  this->Order = nullptr;
  this->Points = nullptr;
  this->TF = nullptr;
  this->General = nullptr;
  if (!this->Whole)
  {
    std::vector<CellBox>().swap(this->Boxes);
    std::vector<int>().swap(this->GeneralOf);
  }
}

void hov::CellRecords::PrefetchCell(vtkIdType k) const
{
  const vtkIdType id = (*this->Order)[k];
  const auto& tets = this->Setup->GetTetras();
  if (id < static_cast<vtkIdType>(tets.size()))
  {
    const char* cell = reinterpret_cast<const char*>(&tets[id]);
    for (size_t offset = 0; offset < sizeof(Tetra); offset += 64)
    {
      __builtin_prefetch(cell + offset);
    }
  }
}

void hov::CellRecords::PrefetchPoints(vtkIdType k) const
{
  const vtkIdType id = (*this->Order)[k];
  const auto& tets = this->Setup->GetTetras();
  if (id < static_cast<vtkIdType>(tets.size()))
  {
    for (vtkIdType p : tets[id].Points)
    {
      __builtin_prefetch(&this->Setup->GetPoints()[p]);
      __builtin_prefetch(&this->Points->Window[p]);
      __builtin_prefetch(&this->Points->Projectable[p]);
    }
  }
}

void hov::CellRecords::Make(vtkIdType k, CellRecord& record) const
{
  const vtkIdType id = (*this->Order)[k];
  const auto& tets = this->Setup->GetTetras();
  if (id >= static_cast<vtkIdType>(tets.size()))
  {
    GeneralRecord(*this->General, this->GeneralOf[k], this->Width, this->Height, record);
    return;
  }
  TetraRecord(*this->Setup, tets[id], this->Boxes[k], *this->Points, *this->TF, record);
}
