/**
 * @class   hov::CellRecords
 * @brief   The per-frame records of the CPU projector's ordered cells
 *          (hov::ProjectorTile::CellRecord: face planes and field, projected
 *          vertices, pixel box, transfer-function interval): what the tile
 *          loop reads of a cell, in processing order.
 *
 * Build() computes every ordered cell's pixel box (for binning) and, while
 * the records of all cells fit in the budget, every record too, in one
 * parallel pass (IsWhole()): each record is then built once per frame and
 * the tiles read them in order. Beyond the budget (meshes of about a million
 * cells and more with the default 256 MiB: a 2M-tetrahedron frame's records
 * take 551 MB), no record is kept: each tile builds the records of its own
 * cells with Make() into a buffer the size of its cell list (a cell
 * overlapping several tiles is built by each of them; 1.5-2.3 tiles a cell at
 * 2M tetrahedra). Both give the same records bit for bit, so the image does
 * not depend on the budget.
 *
 * Thread safety: Build() runs vtkSMPTools loops; Make() and the getters are
 * const and may run on any thread.
 * @sa hov::CellProjector, hov::ProjectorTile
 */
#ifndef hovCellRecords_h
#define hovCellRecords_h

#include "hovGeneralCellTile.h" // FrameData
#include "hovProjectorTile.h"   // CellRecord

#include "vtkType.h" // vtkIdType

#include <cstddef> // size_t
#include <vector>  // records, boxes

namespace hov
{
class CellSetup;
class TransferFunction;

class CellRecords
{
public:
  using CellRecord = ProjectorTile::CellRecord;

  /**
   * The pixel boxes (and general-cell indices) of the cells @p order (rendered
   * cell ids of @p setup) for a @p width x @p height image with the projected
   * points @p points, and their records if they take at most @p budgetBytes.
   * @p general's GeneralOf is pointed at this object's general-cell indices.
   * The arguments must outlive the frame (Make() reads them).
   *
   * With @p skipTransparent, a tetrahedron or a linear general cell (voxel,
   * hexahedron, wedge, pyramid) whose scalar range lies where @p tf has no
   * extinction (TransferFunction::ZeroExtinctionOver; their shape functions
   * are >= 0, so the exact field stays within the node values) gets an empty
   * box: it is binned nowhere and none of its segments, each exactly zero
   * under Williams-Max emission, is computed. Returns the number of such
   * cells.
   */
  vtkIdType Build(const CellSetup& setup, const std::vector<vtkIdType>& order,
    const ProjectedPoints& points, const TransferFunction& tf, int width, int height,
    GeneralCellTile::FrameData& general, size_t budgetBytes, bool skipTransparent = false);

  /// True if every record was built (GetRecords(); but those of skipped,
  /// transparent cells, which no tile reads); false: tiles use Make().
  bool IsWhole() const { return this->Whole; }
  /// The records of the ordered cells (IsWhole() only; empty otherwise).
  const std::vector<CellRecord>& GetRecords() const { return this->Records; }
  /// The pixel boxes of the ordered cells.
  const std::vector<CellBox>& GetBoxes() const { return this->Boxes; }
  /// Per ordered cell: its general cell index, or -1 (empty without general cells).
  const std::vector<int>& GetGeneralOf() const { return this->GeneralOf; }
  /**
   * The frame is done: forgets Build()'s arguments (Make() may no longer be
   * called) and, unless every record was built (kept for the next frame, as
   * the boxes), frees the boxes and general-cell indices.
   */
  void EndFrame();
  /// The record of ordered cell @p k, as Build() would have made it (for a
  /// cell that Build() did not skip: only those are binned).
  void Make(vtkIdType k, CellRecord& record) const;
  /// Make() reads scattered memory: fetch ordered cell @p k's cell, then (a
  /// few cells later, once the cell has arrived) its points.
  void PrefetchCell(vtkIdType k) const;
  void PrefetchPoints(vtkIdType k) const;

  /// The pixel box of the tetrahedron with points @p ids (in front of the eye
  /// or the whole image), widened by BoxMargin.
  static CellBox TetraBox(const vtkIdType ids[4], const ProjectedPoints& points, int width,
    int height);

private:
  const CellSetup* Setup = nullptr;
  const std::vector<vtkIdType>* Order = nullptr;
  const ProjectedPoints* Points = nullptr;
  const TransferFunction* TF = nullptr;
  const GeneralCellTile::FrameData* General = nullptr;
  int Width = 0, Height = 0;
  bool Whole = true;
  std::vector<CellRecord> Records;
  std::vector<CellBox> Boxes;
  std::vector<int> GeneralOf;
};
}

#endif
