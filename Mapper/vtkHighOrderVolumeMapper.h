/**
 * @class   vtkHighOrderVolumeMapper
 * @brief   Accurate volume rendering of unstructured finite-element grids.
 *
 * A vtkUnstructuredGridVolumeMapper that reads the same vtkVolumeProperty as
 * VTK's volume mappers and evaluates the emission-absorption integral along
 * every pixel's ray in closed form (double precision, every transfer-function
 * breakpoint kept). Render modes (SetRenderMode; README, "Choosing a render
 * mode"):
 *  - CPU_ACCURATE (default): HIAC cell projection (Williams, Max & Stein,
 *    IEEE TVCG 1998, sections 4-6) in the exact visibility order of
 *    vtkSteinVisibilitySort, linear and quadratic cells. Mapper/Projector.
 *  - OPENGL_PROJECTION: HIAC section 7 regions drawn with OpenGL into a float
 *    target (not faster than CPU_ACCURATE on a software OpenGL).
 *    Mapper/Regions, Mapper/OpenGL. RenderImage() gives the CPU_ACCURATE image.
 *  - RAY_CAST: one ray per pixel through curved Lagrange and Bezier cells of
 *    any order (ElVis, Nelson et al., IEEE TVCG 2012, with rigorous
 *    enclosures), to a stated per-pixel tolerance. Mapper/RayCast.
 *
 * Opacity semantics: GPU_COMPATIBLE (default, vtkGPUVolumeRayCastMapper's
 * limit), VTK_UNSTRUCTURED (VTK's unstructured mappers), RAW_EXTINCTION.
 * Emission: WILLIAMS_MAX (as VTK) or WILHELMS_VAN_GELDER. Shading, gradient
 * opacity and blend modes as VTK's GPU mapper defines them (README: what each
 * mode honours; anything else warns once). Interaction follows the volume's
 * allocated render time in every mode. The image is float premultiplied RGBA
 * (GetFloatImage(), row 0 at the bottom), blended over what is drawn, rays
 * stopping at opaque geometry drawn before the volume.
 *
 * Render() and RenderImage() build one frame (hov::RenderFrame), hand it to
 * the render mode's backend (hov::Backend, SelectBackend()), publish the
 * image and, in a window, display it. Bad input never crashes and never
 * produces NaN pixels (README, "Failures and messages: the rule"). Measured
 * accuracy, speed and test names: README.
 *
 * Thread safety: rendering uses vtkSMPTools internally; the float image is
 * bit-identical for any number of threads.
 * @sa vtkHighOrderTransferFunction, vtkSteinVisibilitySort, vtkCellVisibilitySortFilter,
 * vtkProjectedTetrahedraMapper, vtkUnstructuredGridVolumeRayCastMapper
 */
#ifndef vtkHighOrderVolumeMapper_h
#define vtkHighOrderVolumeMapper_h

#include "vtkRenderingHighOrderVolumeModule.h" // For export macro
#include "vtkUnstructuredGridVolumeMapper.h"

#include <memory> // For std::unique_ptr
#include <vector> // For Isosurfaces

class vtkCamera;
class vtkDoubleArray;
class vtkHighOrderTransferFunction;
class vtkImageData;
class vtkVisibilitySort;
namespace hov
{
class Backend;
class RenderFrame;
}

class VTKRENDERINGHIGHORDERVOLUME_EXPORT vtkHighOrderVolumeMapper
  : public vtkUnstructuredGridVolumeMapper
{
public:
  static vtkHighOrderVolumeMapper* New();
  vtkTypeMacro(vtkHighOrderVolumeMapper, vtkUnstructuredGridVolumeMapper);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum OpacitySemanticsType
  {
    GPU_COMPATIBLE = 0,
    VTK_UNSTRUCTURED = 1,
    RAW_EXTINCTION = 2
  };
  ///@{
  /// How the scalar-opacity function becomes extinction (see class doc).
  vtkSetClampMacro(OpacitySemantics, int, GPU_COMPATIBLE, RAW_EXTINCTION);
  vtkGetMacro(OpacitySemantics, int);
  void SetOpacitySemanticsToGPUCompatible() { this->SetOpacitySemantics(GPU_COMPATIBLE); }
  void SetOpacitySemanticsToVTKUnstructured() { this->SetOpacitySemantics(VTK_UNSTRUCTURED); }
  void SetOpacitySemanticsToRawExtinction() { this->SetOpacitySemantics(RAW_EXTINCTION); }
  ///@}

  ///@{
  /// Relative tolerance of the linearised GPU-compatible extinction (default 1e-4;
  /// image error <= 2x this). Clamped to [1e-8, 0.1] with a warning; NaN/Inf is
  /// refused with an error (the value stays). RAY_CAST linearises with
  /// max(GPUOpacityTolerance, RayCastTolerance / 10).
  virtual void SetGPUOpacityTolerance(double value);
  vtkGetMacro(GPUOpacityTolerance, double);
  ///@}

  enum EmissionModelType
  {
    WILLIAMS_MAX = 0,
    WILHELMS_VAN_GELDER = 1
  };
  ///@{
  /// Glow energy model (HIAC section 5) and the Wilhelms-Van Gelder scale
  /// (clamped to [0, 1e6] with a warning; NaN/Inf refused with an error).
  vtkSetClampMacro(EmissionModel, int, WILLIAMS_MAX, WILHELMS_VAN_GELDER);
  vtkGetMacro(EmissionModel, int);
  void SetEmissionModelToWilliamsMax() { this->SetEmissionModel(WILLIAMS_MAX); }
  void SetEmissionModelToWilhelmsVanGelder() { this->SetEmissionModel(WILHELMS_VAN_GELDER); }
  virtual void SetEmissionScale(double value);
  vtkGetMacro(EmissionScale, double);
  ///@}

  enum IntegrationMethodType
  {
    EXACT = 0,
    APPROXIMATE = 1
  };
  ///@{
  /// EXACT: closed-form integral; APPROXIMATE: HIAC's fast method (exact
  /// opacity, averaged colour; linear tetrahedra only).
  vtkSetClampMacro(IntegrationMethod, int, EXACT, APPROXIMATE);
  vtkGetMacro(IntegrationMethod, int);
  void SetIntegrationMethodToExact() { this->SetIntegrationMethod(EXACT); }
  void SetIntegrationMethodToApproximate() { this->SetIntegrationMethod(APPROXIMATE); }
  ///@}

  enum VectorModeType
  {
    MAGNITUDE = 0,
    COMPONENT = 1
  };
  ///@{
  /// Multi-component arrays: the magnitude (default) or one component (with
  /// vtkVolumeProperty::IndependentComponents on, that component's functions).
  vtkSetClampMacro(VectorMode, int, MAGNITUDE, COMPONENT);
  vtkGetMacro(VectorMode, int);
  vtkSetMacro(VectorComponent, int);
  vtkGetMacro(VectorComponent, int);
  ///@}

  enum CellOrderingType
  {
    VISIBILITY_SORT = 0,
    PER_PIXEL_SORT = 1
  };
  ///@{
  /**
   * VISIBILITY_SORT (default, HIAC): cells composited in the order of the
   * VisibilitySort (exact with the default vtkSteinVisibilitySort; a frame
   * whose order has a cycle is composited per pixel, with one warning per
   * input). PER_PIXEL_SORT: each pixel sorts its own segments (exact for any
   * non-overlapping mesh). The CPU modes; OPENGL_PROJECTION with EXACT_ORDER
   * always uses the VisibilitySort.
   */
  vtkSetClampMacro(CellOrdering, int, VISIBILITY_SORT, PER_PIXEL_SORT);
  vtkGetMacro(CellOrdering, int);
  void SetCellOrderingToVisibilitySort() { this->SetCellOrdering(VISIBILITY_SORT); }
  void SetCellOrderingToPerPixelSort() { this->SetCellOrdering(PER_PIXEL_SORT); }
  ///@}

  ///@{
  /// The visibility sort of VISIBILITY_SORT (default: a vtkSteinVisibilitySort;
  /// vtkCellCenterDepthSort is VTK's approximate one). It is given the valid cells only.
  void SetVisibilitySort(vtkVisibilitySort* sort);
  vtkGetObjectMacro(VisibilitySort, vtkVisibilitySort);
  ///@}

  ///@{
  /// A pixel (a ray, in RAY_CAST) stops compositing once its transmittance is
  /// at most this value (the error it causes is at most the value). Default
  /// 1e-9; 0 disables. Clamped to [0, 0.1] with a warning; NaN/Inf refused with an error.
  virtual void SetTerminationTransmittance(double value);
  vtkGetMacro(TerminationTransmittance, double);
  ///@}

  ///@{
  /// Side in pixels of the square tiles the CPU path distributes over threads
  /// (default 32). A performance knob only: the image does not depend on it.
  vtkSetClampMacro(TileSize, int, 4, 256);
  vtkGetMacro(TileSize, int);
  ///@}

  ///@{
  /// Memory in MiB (default 256) the CPU path may spend on per-frame records
  /// of all its cells (272 bytes a tetrahedron). Beyond it (about a million
  /// cells) each tile builds the records of its own cells instead, and the
  /// mesh-sized per-frame arrays are freed after each frame: a 2M-tetrahedron
  /// frame then peaks about 600 MB lower and takes about 10% longer. A
  /// memory/time knob only: the image does not depend on it.
  vtkSetClampMacro(CellRecordMemory, int, 0, 1 << 20);
  vtkGetMacro(CellRecordMemory, int);
  ///@}

  ///@{
  /// CPU_ACCURATE with composite blending and Williams-Max emission, on the
  /// plain volume path (not with isosurfaces, a separate colour or isosurface
  /// array, splatting, volume shading or gradient opacity) (default on): skip each
  /// tetrahedron or linear cell (voxel, hexahedron, wedge, pyramid) whose
  /// scalar range lies where the transfer function has no extinction. Its
  /// segments would each add exactly zero (shape functions >= 0: the field
  /// stays within the node values), so the image is the same, at none of
  /// their cost, but where integrating them rounds a scalar past a node
  /// (README, "Transparent cells"). Quadratic cells are never skipped. The
  /// witness (GetWitnessViolations) then checks the order of the other cells.
  /// RAY_CAST with composite blending (unshaded rays under either emission
  /// model; with volume shading or gradient opacity under Williams-Max only,
  /// since under Wilhelms-Van Gelder the specular term glows without colour
  /// or extinction): a ray computes no interval (no
  /// face search, no inversion) in a cell, curved or not, whose rigorous
  /// field hull (Bernstein, not the node values) is invisible: no extinction
  /// there and, under Wilhelms-Van Gelder, no colour. Such a segment is
  /// exactly zero; the image changes only within the per-pixel tolerance, as
  /// the field error budget is then spread over the visible segments (except
  /// where a ray lies in a face shared with a visible cell and the field
  /// jumps there: README, "Transparent cells").
  /// Off: every cell is integrated (for timing or checks).
  /// GetNumberOfTransparentCells(): the cells skipped by the last render
  /// (RAY_CAST: the cells flagged, met by a ray or not).
  vtkSetMacro(SkipTransparentCells, bool);
  vtkGetMacro(SkipTransparentCells, bool);
  vtkBooleanMacro(SkipTransparentCells, bool);
  vtkGetMacro(NumberOfTransparentCells, vtkIdType);
  ///@}

  ///@{
  /// Clip rays at the depth of opaque geometry already drawn (default on).
  vtkSetMacro(UseDepthBuffer, bool);
  vtkGetMacro(UseDepthBuffer, bool);
  vtkBooleanMacro(UseDepthBuffer, bool);
  ///@}

  ///@{
  /**
   * View-depth clipping (HIAC z-clipping; off by default): only the slab of
   * view depths [near, far] (distance from the camera position along the
   * direction of projection, world units) is rendered, per pixel on the ray,
   * like the clipping planes (SetClippingPlanes/AddClippingPlane, world
   * coordinates, the half-space the normal points into kept). CPU modes.
   */
  vtkSetMacro(ViewDepthClipping, bool);
  vtkGetMacro(ViewDepthClipping, bool);
  vtkBooleanMacro(ViewDepthClipping, bool);
  vtkSetVector2Macro(ViewDepthRange, double);
  vtkGetVector2Macro(ViewDepthRange, double);
  ///@}

  ///@{
  /**
   * Isosurfaces (HIAC 5.1-5.2, CPU_ACCURATE; any number): surfaces of the
   * isosurface field at @p value, colour (@p r, @p g, @p b), opacity
   * @p opacity at normal incidence (1 - (1 - opacity)^(1/|cos|) edge-on),
   * embedded in the volume integral and composited in depth order; shaded
   * (Blinn-Phong, the renderer's lights; RenderImage: a white headlight) when
   * the property's Shade is on, unshaded otherwise. AddIsosurface returns the
   * surface's index.
   */
  int AddIsosurface(double value, double r, double g, double b, double opacity);
  void RemoveAllIsosurfaces();
  int GetNumberOfIsosurfaces();
  /// Value of surface @p i (0 if out of range).
  double GetIsosurfaceValue(int i);
  ///@}

  ///@{
  /**
   * Three fields (HIAC 5, CPU_ACCURATE): point arrays for the colour (the
   * colour function applied to it; the opacity function stays on the main
   * scalars) and for the isosurfaces. Empty name (default): the main scalars.
   * Component k >= 0, or -1 (default) the magnitude. Missing, non-numeric or
   * too short arrays are errors (nothing drawn).
   */
  vtkSetStringMacro(ColorArrayName);
  vtkGetStringMacro(ColorArrayName);
  vtkSetMacro(ColorArrayComponent, int);
  vtkGetMacro(ColorArrayComponent, int);
  vtkSetStringMacro(IsosurfaceArrayName);
  vtkGetStringMacro(IsosurfaceArrayName);
  vtkSetMacro(IsosurfaceArrayComponent, int);
  vtkGetMacro(IsosurfaceArrayComponent, int);
  ///@}

  ///@{
  /**
   * Subpixel splatting (HIAC 5.3, CPU_ACCURATE; off by default): cells whose
   * projected bounding box is smaller than SplatPixelThreshold pixels^2
   * (default 2; clamped to [0, 1e6] with a warning) and at most 3 pixels wide
   * and high are splatted over 3 x 3 pixels (hov::SplatCellContribution) in
   * their visibility turn. Surfaces inside a splatted cell are not drawn.
   */
  vtkSetMacro(Splatting, bool);
  vtkGetMacro(Splatting, bool);
  vtkBooleanMacro(Splatting, bool);
  virtual void SetSplatPixelThreshold(double value);
  vtkGetMacro(SplatPixelThreshold, double);
  /// Cells splatted in the last render.
  vtkGetMacro(NumberOfSplattedCells, vtkIdType);
  ///@}

  enum RenderModeType
  {
    CPU_ACCURATE = 0,
    OPENGL_PROJECTION = 1,
    RAY_CAST = 2
  };
  ///@{
  /**
   * The render mode (see the class doc and the README). Not applied in
   * OPENGL_PROJECTION: isosurfaces, separate fields, splatting, clipping
   * planes and view-depth clipping; in RAY_CAST: isosurfaces, separate fields
   * and splatting (one warning names them). Which mode for what, measured:
   * README, "Choosing a render mode".
   */
  vtkSetClampMacro(RenderMode, int, CPU_ACCURATE, RAY_CAST);
  vtkGetMacro(RenderMode, int);
  void SetRenderModeToCPUAccurate() { this->SetRenderMode(CPU_ACCURATE); }
  void SetRenderModeToOpenGLProjection() { this->SetRenderMode(OPENGL_PROJECTION); }
  void SetRenderModeToRayCast() { this->SetRenderMode(RAY_CAST); }
  ///@}

  enum BlendModeType
  {
    MINIMUM_INTENSITY_BLEND = 2, ///< vtkVolumeMapper's value
    AVERAGE_INTENSITY_BLEND = 3  ///< vtkVolumeMapper's value
  };
  ///@{
  /**
   * Blend modes (README, "Blend modes"): COMPOSITE_BLEND (default),
   * MAXIMUM_INTENSITY_BLEND, MINIMUM_INTENSITY_BLEND, AVERAGE_INTENSITY_BLEND
   * as vtkGPUVolumeRayCastMapper defines them, exact per ray in every mode
   * (OPENGL_PROJECTION computes their image with the CPU kernels). Other
   * values warn once and render as composite; isosurfaces, separate fields
   * and splatting are not applied with them. AverageIPScalarRange: as
   * vtkVolumeMapper's (default [VTK_FLOAT_MIN, VTK_FLOAT_MAX]).
   */
  void SetBlendModeToMinimumIntensity() { this->SetBlendMode(MINIMUM_INTENSITY_BLEND); }
  void SetBlendModeToAverageIntensity() { this->SetBlendMode(AVERAGE_INTENSITY_BLEND); }
  vtkSetVector2Macro(AverageIPScalarRange, double);
  vtkGetVectorMacro(AverageIPScalarRange, double, 2);
  ///@}

  ///@{
  /// RAY_CAST: absolute error target per colour channel of each pixel (ElVis's
  /// "pixel-exact" 0.001 by default). Clamped to [1e-12, 0.1] with a warning;
  /// NaN/Inf refused with an error.
  virtual void SetRayCastTolerance(double value);
  vtkGetMacro(RayCastTolerance, double);
  ///@}

  ///@{
  /**
   * Interaction, as VTK's volume mappers do it (README, "Interaction"): a
   * window frame is given the volume's GetAllocatedRenderTime(). With
   * AutoAdjustImageSampleDistance on (default), a frame whose estimated exact
   * cost (measured per mode) exceeds it is an interactive frame: one exact ray
   * per f x f block of pixels, f from the budget (2..16) or
   * InteractiveSubsampling if > 0 (clamped to [0, 64]); RAY_CAST at
   * tolerance x10 (by the CPU path's exact rays when every cell is linear and
   * no CPU-only feature is set), OPENGL_PROJECTION in the approximate order
   * (or by the CPU path when its regions alone exceed the budget). Frames that fit
   * (the still frame) are exact. A still frame estimated above
   * ProgressiveTime seconds (default 0.5; 0 off; clamped to [0, 1e6]) right
   * after an interactive frame, in a window with an initialized interactor,
   * is progressive: coarse at once, then refined on the interactor's timer,
   * its exact level abortable. Still frames not preceded by interaction are
   * exact at once.
   */
  vtkSetMacro(AutoAdjustImageSampleDistance, bool);
  vtkGetMacro(AutoAdjustImageSampleDistance, bool);
  vtkBooleanMacro(AutoAdjustImageSampleDistance, bool);
  vtkSetClampMacro(InteractiveSubsampling, int, 0, 64);
  vtkGetMacro(InteractiveSubsampling, int);
  virtual void SetProgressiveTime(double value);
  vtkGetMacro(ProgressiveTime, double);
  /// Whether the last frame was interactive, and its pixels per ray (> 1 also
  /// for a progressive level).
  vtkGetMacro(LastRenderWasInteractive, bool);
  vtkGetMacro(LastSubsampling, int);
  /// The render mode whose path drew the last frame: the RenderMode, except
  /// for reduced frames drawn by CPU_ACCURATE's path (OPENGL_PROJECTION when
  /// its regions alone exceed the budget; RAY_CAST on linear cells).
  vtkGetMacro(LastDrawingMode, int);
  ///@}

  ///@{
  /// Deprecated RAY_CAST names: Set/GetRayCastInteractiveSubsampling are
  /// InteractiveSubsampling, GetLastRayCastSubsampling is GetLastSubsampling;
  /// RayCastInteractiveUpdateRate is kept (range checked) but no longer read:
  /// the allocated render time decides.
  void SetRayCastInteractiveSubsampling(int f) { this->SetInteractiveSubsampling(f); }
  int GetRayCastInteractiveSubsampling() { return this->InteractiveSubsampling; }
  int GetLastRayCastSubsampling() { return this->LastSubsampling; }
  virtual void SetRayCastInteractiveUpdateRate(double value);
  vtkGetMacro(RayCastInteractiveUpdateRate, double);
  ///@}

  /// RAY_CAST: per-pixel error estimate of the last image (array "Error", one
  /// float per pixel, the layout of GetFloatImage()).
  vtkImageData* GetRayCastErrorImage();

  enum ProjectionColorMethodType
  {
    INTERPOLATED_OPACITY = 0, ///< M0: vertex opacity interpolated, average colour, no texture
    AVERAGE_COLOR = 1,        ///< M1: average chromaticity
    TABLE_COLOR = 2,          ///< M2: table-based eq. 8
    EXACT_COLOR = 3           ///< M3: exact eq. 8 per region vertex (default)
  };
  ///@{
  /// Colour per region vertex in OPENGL_PROJECTION mode (HIAC 7; hovProjectionColor.h).
  vtkSetClampMacro(ProjectionColorMethod, int, INTERPOLATED_OPACITY, EXACT_COLOR);
  vtkGetMacro(ProjectionColorMethod, int);
  ///@}

  enum ProjectionOrderType
  {
    EXACT_ORDER = 0,      ///< the VisibilitySort (default: vtkSteinVisibilitySort)
    APPROXIMATE_ORDER = 1 ///< centroid distance from the eye (fast, for interaction)
  };
  enum ProjectionOpacityLookupType
  {
    OPACITY_TEXTURE = 0, ///< HIAC's float texture of M(u, v) = 1 - exp(-u v)
    OPACITY_ANALYTIC = 1 ///< 1 - exp(-L tau_avg) in the fragment shader (default)
  };
  ///@{
  /// How OPENGL_PROJECTION turns a fragment's optical depth into opacity
  /// (methods M1-M3): the shader's exp (default: more accurate, and faster on
  /// llvmpipe) or HIAC's texture (within 1.2e-5).
  vtkSetClampMacro(ProjectionOpacityLookup, int, OPACITY_TEXTURE, OPACITY_ANALYTIC);
  vtkGetMacro(ProjectionOpacityLookup, int);
  void SetProjectionOpacityLookupToTexture() { this->SetProjectionOpacityLookup(OPACITY_TEXTURE); }
  void SetProjectionOpacityLookupToAnalytic()
  {
    this->SetProjectionOpacityLookup(OPACITY_ANALYTIC);
  }
  ///@}

  ///@{
  /// Cell order of OPENGL_PROJECTION mode.
  vtkSetClampMacro(ProjectionOrder, int, EXACT_ORDER, APPROXIMATE_ORDER);
  vtkGetMacro(ProjectionOrder, int);
  ///@}

  ///@{
  /// OPENGL_PROJECTION diagnostics of the last render.
  vtkGetMacro(NumberOfProjectedTriangles, vtkIdType);
  vtkGetMacro(NumberOfProjectedSlabs, vtkIdType);
  ///@}

  /**
   * Compute the float image for @p camera and @p volume at @p width x
   * @p height pixels without any window (aspect width/height). Returns 1 on
   * success (also for an empty or invisible volume: the image is then zero
   * and a warning says why), 0 on error. The result is in GetFloatImage().
   */
  int RenderImage(vtkCamera* camera, vtkVolume* volume, int width, int height);

  /**
   * The last image: float premultiplied RGBA (array "RGBA"), row 0 at the
   * bottom. The same vtkImageData every frame; its array is rewritten in
   * place by the next frame of the same size unless something else holds a
   * reference to it (then the next frame publishes a new array and the held
   * one keeps its values): to keep a frame, hold its array or DeepCopy it.
   */
  vtkImageData* GetFloatImage();

  /// The last CPU image in the double precision it is computed in (4
  /// components, the layout of GetFloatImage()), copied into @p rgba.
  void GetDoubleImage(vtkDoubleArray* rgba);

  ///@{
  /// Diagnostics of the last render. NumberOfRays: the pixel rays (fewer in an
  /// interactive frame; RAY_CAST: those traced). RAY_CAST:
  /// NumberOfSegments cell intervals, NumberOfPieces those plus the
  /// breakpoints located in them. NumberOfCellRecords (CPU_ACCURATE's
  /// composite path): the cell records built, one per cell while they fit in
  /// CellRecordMemory, else one per tile a cell overlaps. LastImageTime:
  /// wall-clock seconds of the image.
  vtkGetMacro(WitnessViolations, vtkIdType);
  vtkGetMacro(NumberOfRenderedCells, vtkIdType);
  vtkGetMacro(NumberOfSkippedCells, vtkIdType);
  vtkGetMacro(NumberOfSegments, vtkIdType);
  vtkGetMacro(NumberOfPieces, vtkIdType);
  vtkGetMacro(NumberOfCellRecords, vtkIdType);
  vtkGetMacro(NumberOfRays, vtkIdType);
  vtkGetMacro(LastImageTime, double);
  /// Worst error estimate of a shaded segment integrated by quadrature (README,
  /// "Shading and gradient opacity"); 0 if every one had a closed form.
  vtkGetMacro(ShadingErrorEstimate, double);
  ///@}

  ///@{
  /**
   * Progress and abort (CPU_ACCURATE and RAY_CAST): with a ProgressEvent
   * observer on the mapper (or an AbortCheckEvent observer on the window)
   * the tiles run in batches of about 1/32, with UpdateProgress between them
   * (0 at the start, 1 at the end); SetAbortExecute(1) (or the window's
   * AbortRender) skips the remaining tiles, left zero, and
   * GetLastRenderAborted() is true. An image not aborted is bit-identical
   * with or without observers.
   */
  vtkGetMacro(LastRenderAborted, bool);
  ///@}

  /// The transfer-function table in use (for inspection).
  vtkHighOrderTransferFunction* GetTransferFunction();

  void Render(vtkRenderer* ren, vtkVolume* vol) override;
  void ReleaseGraphicsResources(vtkWindow* win) override;

protected:
  vtkHighOrderVolumeMapper();
  ~vtkHighOrderVolumeMapper() override;

  int RenderMode = CPU_ACCURATE;
  double AverageIPScalarRange[2] = { VTK_FLOAT_MIN, VTK_FLOAT_MAX };
  double RayCastTolerance = 1e-3;
  double RayCastInteractiveUpdateRate = 1.0;
  bool AutoAdjustImageSampleDistance = true;
  int InteractiveSubsampling = 0;
  double ProgressiveTime = 0.5;
  bool LastRenderWasInteractive = false;
  int LastSubsampling = 1;
  int LastDrawingMode = CPU_ACCURATE;
  int ProjectionColorMethod = EXACT_COLOR;
  int ProjectionOrder = EXACT_ORDER;
  int ProjectionOpacityLookup = OPACITY_ANALYTIC;
  vtkIdType NumberOfProjectedTriangles = 0;
  vtkIdType NumberOfProjectedSlabs = 0;
  int OpacitySemantics = GPU_COMPATIBLE;
  int CellOrdering = VISIBILITY_SORT;
  double GPUOpacityTolerance = 1e-4;
  int EmissionModel = WILLIAMS_MAX;
  double EmissionScale = 1.0;
  int IntegrationMethod = EXACT;
  int VectorMode = MAGNITUDE;
  int VectorComponent = 0;
  double TerminationTransmittance = 1e-9;
  bool UseDepthBuffer = true;
  bool ViewDepthClipping = false;
  double ViewDepthRange[2] = { 0.0, 1.0 };
  int TileSize = 32;
  int CellRecordMemory = 256;
  bool SkipTransparentCells = true;
  vtkVisibilitySort* VisibilitySort = nullptr;
  std::vector<double> Isosurfaces; ///< value, r, g, b, opacity per surface
  char* ColorArrayName = nullptr;
  int ColorArrayComponent = -1;
  char* IsosurfaceArrayName = nullptr;
  int IsosurfaceArrayComponent = -1;
  bool Splatting = false;
  double SplatPixelThreshold = 2.0;
  vtkIdType NumberOfSplattedCells = 0;

  vtkIdType WitnessViolations = 0;
  vtkIdType NumberOfRenderedCells = 0;
  vtkIdType NumberOfSkippedCells = 0;
  vtkIdType NumberOfSegments = 0;
  vtkIdType NumberOfCellRecords = 0;
  vtkIdType NumberOfTransparentCells = 0;
  vtkIdType NumberOfPieces = 0;
  vtkIdType NumberOfRays = 0;
  double LastImageTime = 0.0;
  double ShadingErrorEstimate = 0.0;
  bool LastRenderAborted = false;

private:
  vtkHighOrderVolumeMapper(const vtkHighOrderVolumeMapper&) = delete;
  void operator=(const vtkHighOrderVolumeMapper&) = delete;

  /// The backend of the render mode: the one place the mode is chosen.
  /// @p window: a window render (RenderImage has none).
  hov::Backend& SelectBackend(bool window);
  /// A frame of this mapper's settings for @p camera and @p volume.
  void InitFrame(hov::RenderFrame& frame, vtkCamera* camera, vtkVolume* volume, int width,
    int height, double aspect, vtkRenderer* renderer);
  /// The CPU image of @p frame by @p backend, published; returns its status.
  int ComputeImage(hov::RenderFrame& frame, hov::Backend& backend);
  /// The frame's statistics and checked image into this mapper.
  void Publish(hov::RenderFrame& frame, float* windowPixels);
  /// The level of detail of a window frame (hov::InteractionBudget,
  /// hov::ProgressiveStill) into @p frame.
  void ChooseLevel(hov::RenderFrame& frame, vtkRenderer* ren, vtkVolume* vol);
  /// After a window frame of @p seconds: its cost measured, the progressive
  /// refinement advanced; true if the image was replaced by the last level.
  bool FinishLevel(hov::RenderFrame& frame, double seconds);
  /// Progress callback of the CPU tile loops: true to abort.
  bool ReportTileProgress(vtkRenderer* renderer, double done);

  struct Internals;
  std::unique_ptr<Internals> Impl;
};

#endif
