/**
 * @class   hov::RayCastBackend
 * @brief   The RAY_CAST render mode (issue 6): one ray per pixel through the
 *          cells as they are stored, curved Lagrange cells included
 *          (hov::RayCast, the adapter of hov::CurvedRayCaster).
 *
 * Per frame: the input converted and the caster built when the input or the
 * scalars change (hov::InputKey; skipped cells reported once per input); its
 * own transfer-function table, linearised at max(GPUOpacityTolerance,
 * RayCastTolerance / 10) (the table's error within a fifth of the per-pixel
 * tolerance: a finer table only adds breakpoints to locate); interactive
 * frames (RenderFrame::Interactive, chosen by the facade from the allocated
 * render time: hov::InteractionBudget) trace one ray per f x f block of
 * pixels at tolerance x10; rays stop at TerminationTransmittance. With
 * SkipTransparentCells, composite rays (shaded ones only under Williams-Max)
 * compute no interval in a cell whose rigorous field hull is invisible under
 * the table (they would add exactly zero). Output: the frame's image and the
 * per-pixel error estimate (GetErrorImage()).
 *
 * Thread safety: rendering thread only (the caster runs vtkSMPTools).
 * @sa hov::RayCast, hov::Backend, vtkHighOrderVolumeMapper (RenderMode)
 */
#ifndef hovRayCastBackend_h
#define hovRayCastBackend_h

#include "hovBackend.h" // the interface

#include "hovRayCast.h"                   // the caster adapter
#include "hovRayCastShading.h"            // shading, gradient opacity
#include "hovRenderFrame.h"               // InputKey
#include "vtkHighOrderTransferFunction.h" // its table

#include "vtkImageData.h" // the error image
#include "vtkNew.h"       // owned objects

#include <vector> // buffers

namespace hov
{
class RayCastBackend : public Backend
{
public:
  int Render(RenderFrame& frame, vtkImageData* floatImage) override;

  /// The per-pixel error estimate of the last frame (array "Error").
  vtkImageData* GetErrorImage() { return this->ErrorImage; }

  /// Whether the caster is built for the input of @p key and renders every
  /// one of its cells (none skipped: no inverted, degenerate or unsupported
  /// cell), so that another exact path may draw the same picture.
  bool RendersEveryCell(const InputKey& key) const
  {
    return this->Valid && key == this->Key && this->Skipped == 0;
  }

private:
  /// Everything but the error image's publication: 1 success, 0 error.
  int Trace(RenderFrame& frame);
  /// The caster for the frame's input (rebuilt when its key changes).
  void PrepareCaster(const RenderFrame& frame, vtkUnstructuredGrid* grid);

  RayCast Caster;
  RayCastShading Shading;
  bool Valid = false;
  InputKey Key;
  vtkIdType Skipped = -1; ///< cells of the input the caster leaves out
  bool FeatureWarned = false;
  vtkNew<vtkHighOrderTransferFunction> TransferFunction;
  /// Per caster cell: invisible over its whole field hull under the table
  /// (hov::RayCast::MarkInvisibleCells), valid for InvisibleEmission until the
  /// table or the caster is rebuilt.
  std::vector<unsigned char> Invisible;
  long long InvisibleCount = 0;
  bool InvisibleValid = false;
  EmissionModel InvisibleEmission = EmissionModel::WilliamsMax;
  vtkNew<vtkImageData> ErrorImage;
  std::vector<float> RGBA, Error, Depth;
};
}

#endif
