/**
 * @class   hov::CellScene
 * @brief   The scene set-up the cell-projection modes share (CPU_ACCURATE and
 *          OPENGL_PROJECTION): the validated cells (hov::CellSetup), the
 *          front-to-back cell order and the transfer-function table, each
 *          rebuilt only when what it depends on changed.
 *
 * Prepare(): the input and volume property must exist and the scalars must
 * have been selected (errors otherwise); the cells are rebuilt when the input,
 * the array, their modification times, the component or the association
 * change (hov::InputKey), and every problem of the cells is reported once per
 * rebuild (unsupported types, NaN/Inf, degenerate, inverted and curved cells).
 *
 * PrepareOrder(): with CellOrdering VISIBILITY_SORT (or when the caller needs
 * the visibility order), the vtkVisibilitySort's back-to-front order of the
 * rendered cells, reversed; kept while the cells, the camera, the volume
 * matrix and the sort are unchanged (the same order for the same view, which
 * also keeps ties deterministic). A vtkSteinVisibilitySort that reports a
 * cycle is warned about once per input, and OrderHasCycles() tells the CPU
 * projector to composite per pixel. With PER_PIXEL_SORT any order will do:
 * the rendered cells in their own order.
 *
 * Thread safety: rendering thread only.
 * @sa hov::CellSetup, hov::RenderFrame, vtkSteinVisibilitySort
 */
#ifndef hovCellScene_h
#define hovCellScene_h

#include "hovCellSetup.h"                 // the cells
#include "hovRenderFrame.h"               // RenderFrame, InputKey
#include "vtkHighOrderTransferFunction.h" // the table

#include "vtkNew.h" // the table object

#include <vector> // the order

class vtkCamera;

namespace hov
{
class CellScene
{
public:
  /**
   * The cells of @p frame's input (see the class doc); their counts go to the
   * frame's statistics. False (an error reported) if they cannot be rendered.
   */
  bool Prepare(RenderFrame& frame);

  /**
   * The front-to-back order for @p frame's view (see the class doc); with
   * @p needVisibilitySort the vtkVisibilitySort's even with PER_PIXEL_SORT
   * (cell projection has no per-pixel sort). False if there is no sort (an
   * error reported).
   */
  bool PrepareOrder(const RenderFrame& frame, bool needVisibilitySort);

  const CellSetup& GetCells() const { return this->Cells; }
  const std::vector<vtkIdType>& GetFrontToBack() const { return this->FrontToBack; }
  /// The Stein sort found a cycle in the current order: composite per pixel.
  bool OrderHasCycles() const { return this->HasCycles; }
  /// The transfer-function table of these modes (vtkHighOrderVolumeMapper::GetTransferFunction).
  vtkHighOrderTransferFunction* GetTransferFunction() { return this->TransferFunction; }

private:
  /// Warnings about the cells of a new build.
  void ReportCells(const RenderFrame& frame) const;

  CellSetup Cells;
  InputKey CellsKey;
  bool CellsValid = false;
  unsigned long CellsGeneration = 0;

  std::vector<vtkIdType> FrontToBack;
  vtkCamera* OrderCamera = nullptr;
  vtkMTimeType OrderCameraTime = 0;
  vtkMTimeType OrderMatrixTime = 0;
  vtkMTimeType OrderSortTime = 0;
  unsigned long OrderGeneration = ~0ul;
  bool HasCycles = false;
  unsigned long CycleWarningGeneration = ~0ul;

  vtkNew<vtkHighOrderTransferFunction> TransferFunction;
};
}

#endif
