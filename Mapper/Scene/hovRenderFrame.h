/**
 * @class   hov::RenderFrame
 * @brief   One render of vtkHighOrderVolumeMapper, as every render mode reads
 *          it: what is drawn (camera, volume, renderer, size, opaque depth),
 *          the mapper's settings with every enum converted once
 *          (FrameSettings), the selected scalars and their cache key, where
 *          messages and progress go, and what the render produced (the
 *          image, statistics).
 *
 * Built once per render by the facade (vtkHighOrderVolumeMapper::Render or
 * RenderImage) and handed to the mode's backend (hovBackend.h). The checks
 * every mode makes are here, in one place: ValidateView() (a camera, a
 * volume and a positive size; hov::CheckView and a finite view-depth range;
 * the input brought up to date; the scalars selected), SetupRays() (the
 * pixel rays and their clipping) and UpdateTransferFunction() (a table from
 * the volume property, its messages once per rebuild). The rule they follow
 * (README, "Failures and messages: the rule"): an error where the frame
 * cannot be rendered, a warning where it is empty for a reason of the scene.
 *
 * Thread safety: one frame per render, on the rendering thread.
 * @sa hov::Backend, vtkHighOrderVolumeMapper
 */
#ifndef hovRenderFrame_h
#define hovRenderFrame_h

#include "hovFrameSettings.h" // FrameSettings, FrameStatistics, FrameMessages
#include "hovTileBatches.h"   // ProgressFunction

#include "vtkType.h" // vtkMTimeType

#include <algorithm> // std::max
#include <array>     // Content
#include <climits>   // INT_MAX
#include <string>    // messages
#include <vector>    // the image

class vtkCamera;
class vtkDataArray;
class vtkHighOrderTransferFunction;
class vtkRenderer;
class vtkUnstructuredGridBase;
class vtkUnstructuredGridVolumeMapper;
class vtkVisibilitySort;
class vtkVolume;

namespace hov
{
class ViewRays;

/// The scalars a frame renders (vtkAbstractMapper::GetScalars on the input).
struct ScalarSelection
{
  vtkDataArray* Array = nullptr;
  /// Where the array was found (GetScalars' cellFlag): 0 point data, 1 cell data, 2 field data.
  int Association = 0;
  /// Cell scalars (Association 1): one value per cell.
  bool CellScalars = false;
  /// The component rendered, or -1 for the magnitude.
  int Component = -1;
  /// VectorMode COMPONENT with VectorComponent outside the array's components
  /// (Component is then clamped into range).
  bool ComponentClamped = false;
};

/// What decides whether a prepared input can be reused: the input, the array,
/// their modification times, the component and the association.
struct InputKey
{
  vtkUnstructuredGridBase* Input = nullptr;
  vtkMTimeType InputTime = 0;
  vtkDataArray* Array = nullptr;
  vtkMTimeType ArrayTime = 0;
  int Component = -2;
  bool CellScalars = false;
  bool operator==(const InputKey& o) const
  {
    return this->Input == o.Input && this->InputTime == o.InputTime && this->Array == o.Array &&
      this->ArrayTime == o.ArrayTime && this->Component == o.Component &&
      this->CellScalars == o.CellScalars;
  }
  bool operator!=(const InputKey& o) const { return !(*this == o); }
};

class RenderFrame
{
public:
  // What is drawn (set by the facade).
  vtkCamera* Camera = nullptr;
  vtkVolume* Volume = nullptr;
  /// The renderer drawing the volume, or null (RenderImage: no window).
  vtkRenderer* Renderer = nullptr;
  /// The mapper: its input, scalar selection and clipping planes.
  vtkUnstructuredGridVolumeMapper* Mapper = nullptr;
  vtkVisibilitySort* VisibilitySort = nullptr;
  int Width = 0, Height = 0;
  double Aspect = 1.0;
  /// The viewport's origin in the window (window renders).
  int X0 = 0, Y0 = 0;
  /// Window depth of opaque geometry per pixel (1: nothing), or null.
  const float* Depth = nullptr;
  FrameSettings Settings;
  /// An interactive frame (hov::InteractionBudget, chosen by the facade from
  /// the allocated render time): one ray per Subsampling x Subsampling block
  /// of pixels (hovReducedImage.h), RAY_CAST at tolerance x10,
  /// OPENGL_PROJECTION in the approximate order. Still frames: false, 1.
  bool Interactive = false;
  int Subsampling = 1;
  FrameMessages* Messages = nullptr;
  /// Progress and abort between tile batches; empty without observers.
  ProgressFunction Progress;

  // Set by ValidateView() (SelectInput()).
  vtkUnstructuredGridBase* Input = nullptr;
  ScalarSelection Scalars;

  // What the backend produced.
  /// The image in double precision (4 per pixel, premultiplied, row 0 at the
  /// bottom), or left empty by a backend that writes the float image itself.
  std::vector<double> RGBA;
  /// Columns [x0, x1) and rows [y0, y1), {x0, x1, y0, y1}, outside of which
  /// every value of RGBA is zero (the backend's promise; by default the
  /// whole image, no promise).
  std::array<int, 4> Content = { 0, INT_MAX, 0, INT_MAX };
  /// Whether visible cells were drawn (an empty image then needs a warning).
  bool Drawn = false;
  FrameStatistics Stats;
  /// Why a valid frame drew nothing (no cell this mode renders, an invisible
  /// transfer function; empty otherwise), and whether the backend said so this
  /// frame (hov::ImageCheck says it again once a setting changes).
  mutable std::string NotDrawnReason;
  mutable bool NotDrawnWarned = false;
  /// Whether the input's cells were read (and reported) this frame.
  mutable bool InputReported = false;

  void Warning(const std::string& text) const { this->Messages->Warning(text); }
  void Error(const std::string& text) const { this->Messages->Error(text); }

  /**
   * The checks of every mode, in order: a camera, a volume and a positive
   * size; a usable view (hov::CheckView) and a finite view-depth range; the
   * input updated; then the scalars selected (no message: a mode reports
   * missing input or scalars in its own words). False with an error reported
   * if the frame cannot be rendered.
   */
  bool ValidateView();

  /// The input updated and its scalars selected (Input, Scalars; part of
  /// ValidateView, no message).
  void SelectInput();

  /// The cache key of the selected input and scalars (after SelectInput()).
  InputKey Key() const;

  /**
   * @p rays for a @p width x @p height grid of pixels (the frame's aspect),
   * with the mapper's clipping planes and view-depth slab. False (an error
   * reported) if the matrices are singular.
   */
  bool SetupRays(ViewRays& rays, int width, int height) const;

  /**
   * Bring @p tf up to date with the volume property and the frame's settings
   * (its GPU-compatible linearisation at @p gpuTolerance), reporting the
   * table's messages when it was rebuilt (@p rebuilt). Returns whether the
   * volume can be visible: the table has extinction, or the emission model
   * glows without it.
   */
  bool UpdateTransferFunction(vtkHighOrderTransferFunction* tf, double gpuTolerance, bool& rebuilt) const;

  /// A transfer function transparent everywhere: the frame's NotDrawnReason,
  /// said now if @p warn (the table was rebuilt).
  void NoVisibleVolume(bool warn) const;

  /// No cell of the input is rendered in this mode: the frame's
  /// NotDrawnReason (the cells' own warnings came when the input was read).
  void NoRenderedCell(vtkIdType cells) const;

  /// Most pixels an image may have: 16384 x 16384 (a CPU frame holds about
  /// 50 bytes per pixel: RGBA in double and float, tiles, error image).
  static constexpr size_t MaxImagePixels = size_t(1) << 28;

  /// Width x Height, or 0 if either is not positive or the product exceeds
  /// MaxImagePixels (ValidateView() reports both): the pixels a frame allocates.
  size_t ImagePixels() const
  {
    if (this->Width <= 0 || this->Height <= 0)
    {
      return 0;
    }
    const size_t n = static_cast<size_t>(this->Width) * static_cast<size_t>(this->Height);
    return n <= MaxImagePixels ? n : 0;
  }

  /// The zero image of the frame's size (empty for a size ImagePixels() refuses).
  void ClearImage() { this->RGBA.assign(this->ImagePixels() * 4, 0.0); }
};
}

#endif
