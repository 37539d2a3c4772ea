/**
 * @class   vtkHighOrderVolumeMapper
 * @brief   Accurate volume rendering of unstructured finite-element grids.
 *
 * A vtkUnstructuredGridVolumeMapper that reads the same vtkVolumeProperty as
 * VTK's volume mappers. Render mode implemented so far: the accurate CPU path
 * (HIAC, Williams, Max & Stein 1998, sections 4-6): cells in visibility
 * order (by default from the exact vtkSteinVisibilitySort, or from any
 * vtkVisibilitySort, or per pixel), exact ray entry/exit per OpenGL pixel
 * centre, the scalar split at every transfer-function breakpoint (colour and
 * opacity nodes alike), the exact emission-absorption integral per piece,
 * premultiplied compositing in double precision.
 *
 * Cell types: linear tetrahedra (VTK_TETRA, the fast path: face planes, the
 * closed-form integral with libcerf's erfcx/Dawson, exact) and, in the same
 * visibility order, voxels, hexahedra, wedges, pyramids, quadratic
 * tetrahedra, quadratic (20-node) and triquadratic hexahedra, quadratic
 * wedges and pyramids (types 11-14, 24-27, 29; "general cells"). For a
 * general cell each pixel ray gets its exact inside intervals (planar faces,
 * or bilinear patches for non-planar quadrilaterals; a shared face gives
 * bit-identical exit/entry times, also next to a linear tetrahedron, and a
 * ray lying exactly in a shared planar face goes to exactly one of the two
 * cells by the tetrahedra's symbolic perturbation rule, so no cracks and no
 * double counting), the
 * cell's own interpolant restricted to each interval as polynomial pieces
 * (exact for affine cells: degree 1 to 6 in the ray parameter; Chebyshev
 * with a 1e-10 relative bound otherwise, e.g. pyramids and distorted
 * hexahedra), each piece integrated with exact optical depth and
 * Gauss-Kronrod colour (error estimate <= 1e-9 per channel; degree <= 1 uses
 * the tetrahedra's closed form), pieces composited front to back. Measured:
 * affine general cells with a linear field match the same field on
 * tetrahedra to 3e-14; constant-field blocks of every type, including a
 * non-planar shared face, match the analytic chord to 4e-15
 * (TestMixedAffine, TestMixedChord). The APPROXIMATE integration method
 * applies to tetrahedra only (general cells are always integrated as above).
 *
 * Geometry policy: cells are straight-edged, taken from their corners. A
 * quadratic cell whose mid-edge/face nodes are off the straight-edged
 * positions is rendered straight-edged with its quadratic field in its
 * reference coordinates, and the mapper warns once per input with the count
 * and the largest node deviation relative to the cell size (deviations up to
 * 1e-6 are ignored). Curved geometry needs a ray caster.
 *
 * Clipping, per pixel on the ray, in both paths and both orderings: the
 * clipping planes of vtkAbstractMapper (SetClippingPlanes/AddClippingPlane,
 * world coordinates, the half-space the normal points into is kept, as in
 * vtkGPUVolumeRayCastMapper) and the view-depth slab (HIAC z-clipping:
 * SetViewDepthClipping, SetViewDepthRange). Each ray's parameter range
 * becomes [tMin, tMax]: the near plane (or the clip planes' entry) to the
 * far plane, the opaque depth or the clip planes' exit.
 *
 * Features (HIAC 5.1-5.3; all off by default; see their setters):
 * embedded isosurfaces (AddIsosurface: any number, Phong-shaded with the
 * renderer's lights when the property's Shade is on, edge-on opacity, curved
 * inside quadratic and trilinear cells, drawn once on shared faces), three
 * fields (SetColorArrayName, SetIsosurfaceArrayName: colour and isosurfaces
 * from other point arrays than the extinction), subpixel splatting of
 * cells smaller than a pixel (SetSplatting, SetSplatPixelThreshold).
 * When one is active every cell goes through hov::FeatureProjector
 * (same cells, order, rays and clipping; always the EXACT integration);
 * otherwise the image and speed are those of the plain path, bit for bit.
 * Measured: TestIsoSphere (a sphere isosurface in quadratic cells: shaded
 * intensity vs the analytic normal 2.4e-15; flat facets of 16^3 linear cubes
 * 0.13), TestIsoNested, TestIsoSharedFaces (closed forms, 5e-16),
 * TestFieldsTwoArrays (two linear fields vs a long double reference, 9e-16),
 * TestSplatCube (196608 splatted tetrahedra vs 6 exact ones: image integrals
 * within 7e-4, blur up to 0.012 per pixel).
 *
 * Opacity semantics (SetOpacitySemantics):
 *  - GPU_COMPATIBLE (default): extinction -ln(1 - a(s))/u, the limit
 *    vtkGPUVolumeRayCastMapper converges to; linearised between refined
 *    breakpoints with relative tolerance GPUOpacityTolerance; image error
 *    <= 2 GPUOpacityTolerance (colours in [0,1]).
 *  - VTK_UNSTRUCTURED: extinction a(s)/u, what VTK's unstructured mappers use. Exact.
 *  - RAW_EXTINCTION: the opacity function gives extinction per unit length. Exact.
 * Emission (SetEmissionModel): WILLIAMS_MAX (default; emission = colour x
 * extinction, as VTK does) or WILHELMS_VAN_GELDER (emission independent of
 * extinction: the colour function gives glow per unit distance u, times
 * EmissionScale: a non-absorbing layer of thickness u glows with
 * EmissionScale x colour).
 *
 * Lengths are measured in dataset coordinates (like vtkGPUVolumeRayCastMapper
 * and the Bunyk ray caster). The float image (premultiplied RGBA, one pixel
 * per viewport pixel, row 0 at the bottom) is available after every render
 * from GetFloatImage(); on screen it is blended over what is drawn, and rays
 * stop at the depth of opaque geometry rendered before the volume.
 *
 * Bad input never crashes and never produces NaN pixels: missing,
 * non-numeric or too short scalar arrays are an error (nothing drawn); cells
 * of unsupported types (polyhedra, Lagrange/Bezier cells, 2D cells, ...: "not
 * yet supported by the CPU projection path"), NaN/Inf points or scalars,
 * broken connectivity and degenerate cells (zero volume; for general cells
 * also tangled ones, whose Jacobian changes sign) are skipped with one
 * warning (giving the counts) each time the input or the scalar selection
 * changes; inverted cells are rendered and reported the same way.
 *
 * Thread safety: rendering uses vtkSMPTools internally; the float image is
 * bit-identical for any number of threads.
 * @sa vtkHighOrderTransferFunction, vtkSteinVisibilitySort, vtkCellVisibilitySortFilter,
 * vtkUnstructuredGridVolumeRayCastMapper,
 * vtkProjectedTetrahedraMapper
 */
#ifndef vtkHighOrderVolumeMapper_h
#define vtkHighOrderVolumeMapper_h

#include "vtkRenderingHighOrderVolumeModule.h" // For export macro
#include "vtkUnstructuredGridVolumeMapper.h"

#include <memory> // For std::unique_ptr
#include <vector> // For Isosurfaces

class vtkCamera;
class vtkDataArray;
class vtkDoubleArray;
namespace hov
{
class CellSetup;
class FeatureSetup;
struct ProjectionState;
struct RayCastState;
}
class vtkHighOrderTransferFunction;
class vtkImageData;
class vtkVisibilitySort;
class vtkVolumeProperty;

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
  /// Relative tolerance of the linearised GPU-compatible extinction (default 1e-4).
  /// Clamped to [1e-8, 0.1] (with a warning: below 1e-8 the image error bound is
  /// beyond float's resolution); NaN/Inf is refused with an error (the value stays).
  /// RAY_CAST linearises with max(GPUOpacityTolerance, RayCastTolerance / 10).
  virtual void SetGPUOpacityTolerance(double value);
  vtkGetMacro(GPUOpacityTolerance, double);
  ///@}

  enum EmissionModelType
  {
    WILLIAMS_MAX = 0,
    WILHELMS_VAN_GELDER = 1
  };
  ///@{
  /// Glow energy model (HIAC section 5) and the Wilhelms-Van Gelder scale.
  vtkSetClampMacro(EmissionModel, int, WILLIAMS_MAX, WILHELMS_VAN_GELDER);
  vtkGetMacro(EmissionModel, int);
  void SetEmissionModelToWilliamsMax() { this->SetEmissionModel(WILLIAMS_MAX); }
  void SetEmissionModelToWilhelmsVanGelder() { this->SetEmissionModel(WILHELMS_VAN_GELDER); }
  /// Glow multiplier of WILHELMS_VAN_GELDER. Clamped to [0, 1e6] with a
  /// warning (larger values only overflow the image); NaN/Inf is refused with
  /// an error (the value stays).
  virtual void SetEmissionScale(double value);
  vtkGetMacro(EmissionScale, double);
  ///@}

  enum IntegrationMethodType
  {
    EXACT = 0,
    APPROXIMATE = 1
  };
  ///@{
  /// EXACT: closed-form integral; APPROXIMATE: HIAC's fast method (exact opacity, averaged colour).
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
  /**
   * Multi-component arrays: render the magnitude (default) or one component.
   * With COMPONENT and vtkVolumeProperty::IndependentComponents on, the
   * property's functions of that component are used; otherwise component 0's.
   */
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
   * VISIBILITY_SORT (default, HIAC): cells are composited in the order of
   * the vtkVisibilitySort set with SetVisibilitySort(), by default a
   * vtkSteinVisibilitySort (exact for any acyclic set of non-intersecting
   * convex cells, HIAC section 6): the z-buffer witness then reads 0 (a
   * general cell counts with its first entry and last exit). If the
   * Stein sort reports a cycle for a frame, the mapper warns (once per input)
   * and composites that frame with PER_PIXEL_SORT, which is exact anyway.
   * With another sort (e.g. VTK's approximate vtkCellCenterDepthSort) the
   * order is exact only where that sort is, and the witness counts the pixels
   * where it was not.
   * PER_PIXEL_SORT: each pixel's ray segments are sorted by entry distance;
   * exact for any set of non-overlapping cells, convex or not, with no global
   * sort (the witness then counts pixels where cells overlap). CPU paths
   * only: OPENGL_PROJECTION with EXACT_ORDER always uses the VisibilitySort.
   */
  vtkSetClampMacro(CellOrdering, int, VISIBILITY_SORT, PER_PIXEL_SORT);
  vtkGetMacro(CellOrdering, int);
  void SetCellOrderingToVisibilitySort() { this->SetCellOrdering(VISIBILITY_SORT); }
  void SetCellOrderingToPerPixelSort() { this->SetCellOrdering(PER_PIXEL_SORT); }
  ///@}

  ///@{
  /**
   * Visibility sort used with CellOrdering VISIBILITY_SORT (default: a
   * vtkSteinVisibilitySort, exact; vtkCellCenterDepthSort is VTK's
   * approximate alternative). It is given the valid cells only (tetrahedra
   * and general cells with their own types).
   */
  void SetVisibilitySort(vtkVisibilitySort* sort);
  vtkGetObjectMacro(VisibilitySort, vtkVisibilitySort);
  ///@}

  ///@{
  /**
   * A pixel stops compositing once its transmittance is at most this value
   * (the error this causes is at most the value). Default 1e-9; 0 disables.
   */
  /// Clamped to [0.0, 0.1] (with a warning); NaN/Inf is refused with an error (the value stays).
  virtual void SetTerminationTransmittance(double value);
  vtkGetMacro(TerminationTransmittance, double);
  ///@}

  ///@{
  /**
   * Side in pixels of the square image tiles the CPU path distributes over
   * threads (default 16: a tile's segment list then stays in the L2 cache).
   * A performance knob only: the image does not depend on it.
   */
  vtkSetClampMacro(TileSize, int, 4, 256);
  vtkGetMacro(TileSize, int);
  ///@}

  ///@{
  /// Clip rays at the depth of opaque geometry already drawn (default on).
  vtkSetMacro(UseDepthBuffer, bool);
  vtkGetMacro(UseDepthBuffer, bool);
  vtkBooleanMacro(UseDepthBuffer, bool);
  ///@}

  ///@{
  /**
   * View-depth clipping (HIAC z-clipping; off by default): only the part of
   * the volume whose view depth lies in ViewDepthRange [near, far] is
   * rendered, i.e. the slab between two planes parallel to the screen. View
   * depth is the distance from the camera position along the direction of
   * projection, in world units (the units of vtkCamera::SetClippingRange),
   * for perspective and parallel projections alike. Applied per pixel on the
   * ray, like the clipping planes (SetClippingPlanes/AddClippingPlane, world
   * coordinates; the half-space the plane normal points into is kept, as in
   * VTK's mappers).
   */
  vtkSetMacro(ViewDepthClipping, bool);
  vtkGetMacro(ViewDepthClipping, bool);
  vtkBooleanMacro(ViewDepthClipping, bool);
  vtkSetVector2Macro(ViewDepthRange, double);
  vtkGetVector2Macro(ViewDepthRange, double);
  ///@}

  ///@{
  /**
   * Isosurfaces (HIAC 5.1-5.2; any number): surfaces of the isosurface field
   * (the main scalars, or IsosurfaceArrayName) at @p value, colour
   * (@p r, @p g, @p b) and opacity @p opacity at normal incidence, embedded in
   * the volume integral of every ray segment and composited in depth order
   * (surfaces at the same depth in the order they were added). Normal from
   * the field gradient per pixel (constant in a linear tetrahedron; from the
   * shape-function derivatives and the inverse Jacobian at the hit in
   * quadratic and trilinear cells: curved, smooth surfaces). Shading: when
   * the vtkVolumeProperty's Shade (component 0) is on, Blinn-Phong with its
   * Ambient/Diffuse/Specular/SpecularPower and the renderer's switched-on
   * lights (RenderImage: a white headlight); when Shade is off the surfaces
   * are unshaded (their colour as given). Either way a surface is more
   * opaque seen edge-on: 1 - (1 - opacity)^(1/|cos|) (HIAC 5.2, capped at
   * 100x the optical depth). A surface lying exactly on a face shared by two
   * cells is drawn once. AddIsosurface returns the surface's index.
   */
  int AddIsosurface(double value, double r, double g, double b, double opacity);
  void RemoveAllIsosurfaces();
  int GetNumberOfIsosurfaces();
  /// Value of surface @p i (0 if out of range).
  double GetIsosurfaceValue(int i);
  ///@}

  ///@{
  /**
   * Three fields (HIAC 5): optional point arrays for the colour (the
   * property's colour function applied to it, while the opacity function
   * stays on the main scalars, which set the extinction) and for the
   * isosurfaces. Empty or null name (default): the main scalars. Component
   * k >= 0 of a multi-component array, or -1 (default) the magnitude.
   * Missing, non-numeric or too short arrays are errors (nothing drawn).
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
   * Subpixel splatting (HIAC 5.3; off by default): cells (any type) whose
   * projected bounding box is smaller than SplatPixelThreshold pixels^2
   * (default 2) and at most 3 pixels wide and high are splatted: their
   * volume times the extinction and colour at their centroid, divided by the
   * cross-section of a pixel's ray bundle there (perspective shrinkage),
   * spread over 3 x 3 pixels by the biquadratic B-spline kernel
   * (hov::SplatCellContribution), composited in the cell's visibility turn
   * (per-pixel ordering: at the centroid's depth along each pixel's ray).
   * Surfaces inside a splatted cell are not drawn. Bit-identical for any
   * number of threads.
   */
  vtkSetMacro(Splatting, bool);
  vtkGetMacro(Splatting, bool);
  vtkBooleanMacro(Splatting, bool);
  /// Clamped to [0.0, 1e6] (with a warning); NaN/Inf is refused with an error (the value stays).
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
   * CPU_ACCURATE (default): the exact CPU path described above.
   * OPENGL_PROJECTION: HIAC section 7's hardware polyhedron projection, for
   * interaction: every cell (linear tetrahedra; hexahedra, wedges, pyramids
   * and voxels whole when no transfer-function node lies inside their scalar
   * range, else split into tetrahedra of their corners) and each of its
   * transfer-function slabs (HIAC Fig. 3; all three opacity semantics; GPU-
   * compatible with the exact mean extinction of each fragment's segment from
   * the linear opacity, hov::GPUAverageExtinction, and slabs at the property's
   * nodes plus a coarse refinement) is divided into the homogeneous
   * regions of its projection, drawn with per-vertex segment length L, average
   * extinction and colour by ProjectionColorMethod, opacity per fragment from a
   * float texture of 1 - exp(-L tau_avg), premultiplied blending into a
   * GL_RGBA32F target in the order ProjectionOrder gives, composited over the
   * scene; fragments behind opaque geometry are dropped (whole fragments: a
   * cell cut by an opaque surface is not shortened). The float image is in
   * GetFloatImage() after every render (not GetDoubleImage()). Not applied in
   * this mode: isosurfaces, separate colour/isosurface fields, splatting,
   * clipping planes, view-depth clipping (a warning names them once);
   * RenderImage() always uses the CPU path. See
   * hov::ProjectionRegions for the exact construction and accuracy.
   * RAY_CAST (issue 6; Mapper/vtkHighOrderVolumeMapperRayCast.cxx): one ray
   * per pixel through curved Lagrange cells (hov::CurvedRayCaster: BVH,
   * curved-face entry/exit, E/PS/S segment categorization with rigorous
   * enclosures, breakpoints located, adaptive quadrature to
   * RayCastTolerance per channel). Cells: Lagrange tetrahedra, hexahedra,
   * wedges (71-73, curved, HigherOrderDegrees or node counts) and linear and
   * quadratic tetrahedra, hexahedra, voxels, wedges, pyramids (10-14,
   * 24-27, 29, 32), and Bezier tetrahedra, hexahedra, wedges (78-80, not
   * rational), converted exactly to Lagrange cells (hov::RayCastCells);
   * other types (Lagrange/Bezier pyramids 74/81, 2D cells), NaN/Inf nodes and inverted or
   * degenerate cells are skipped with one warning giving the counts. Point
   * scalars only. The float image is in GetFloatImage(), the per-pixel error
   * estimate in GetRayCastErrorImage(); RenderImage() uses this mode too.
   * Opacity semantics, emission model, clipping planes, view-depth clipping
   * and the opaque depth apply; isosurfaces, separate fields and splatting
   * do not (a warning names them once).
   * Interaction: in Render(), when the render window's DesiredUpdateRate is
   * at least RayCastInteractiveUpdateRate (default 1 frame/s:
   * vtkRenderWindowInteractor sets its InteractiveUpdateRate, 15, while the
   * camera moves and its StillUpdateRate, 0.0001, when it stops), the frame
   * is cheaper: rays on a coarser grid (an f x f block of pixels per ray:
   * every f-th pixel centre in x and y of a reduced viewport, each ray
   * stopping at the nearest opaque depth of its block) replicated to its
   * block, and the tolerance loosened 10x (at most 0.05). The factor f is
   * RayCastInteractiveSubsampling, or by default chosen so that the frame fits
   * the window's time budget 1/DesiredUpdateRate at the cost per ray of the
   * previous RAY_CAST frame (2 <= f <= 16; 2 before any frame). The still
   * frame is at full accuracy. GetLastRenderWasInteractive() tells which one
   * was drawn, GetLastRayCastSubsampling() its f (1 for a still frame).
   */
  vtkSetClampMacro(RenderMode, int, CPU_ACCURATE, RAY_CAST);
  vtkGetMacro(RenderMode, int);
  void SetRenderModeToCPUAccurate() { this->SetRenderMode(CPU_ACCURATE); }
  void SetRenderModeToOpenGLProjection() { this->SetRenderMode(OPENGL_PROJECTION); }
  void SetRenderModeToRayCast() { this->SetRenderMode(RAY_CAST); }
  ///@}

  ///@{
  /**
   * RAY_CAST: absolute error target per colour channel of each pixel's
   * premultiplied RGBA (ElVis's "pixel-exact" 0.001 by default), handed to
   * the segment quadrature (CurvedSegmentSettings::Quadrature.Tolerance).
   */
  /// Clamped to [1e-12, 0.1] (with a warning); NaN/Inf is refused with an error (the value stays).
  virtual void SetRayCastTolerance(double value);
  vtkGetMacro(RayCastTolerance, double);
  ///@}

  ///@{
  /// RAY_CAST interaction threshold in frames per second (see RenderMode).
  /// Clamped to [0.0, 1e6] (with a warning); NaN/Inf is refused with an error (the value stays).
  virtual void SetRayCastInteractiveUpdateRate(double value);
  vtkGetMacro(RayCastInteractiveUpdateRate, double);
  /// Whether the last RAY_CAST frame was the cheaper interactive one.
  vtkGetMacro(LastRenderWasInteractive, bool);
  /// RAY_CAST interactive frames: pixels per ray in x and y (0, the default:
  /// from the time budget; see RenderMode). Clamped to [0, 64].
  vtkSetClampMacro(RayCastInteractiveSubsampling, int, 0, 64);
  vtkGetMacro(RayCastInteractiveSubsampling, int);
  /// The pixels per ray in x and y of the last RAY_CAST frame.
  vtkGetMacro(LastRayCastSubsampling, int);
  ///@}

  /**
   * RAY_CAST: per-pixel error estimate of the last image (array "Error", one
   * float per pixel, the layout of GetFloatImage(); the sum over the ray's
   * segments of each segment's largest channel error estimate). Empty after
   * the other modes.
   */
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
  /**
   * How OPENGL_PROJECTION mode turns a fragment's optical depth d = L tau_avg
   * into opacity (methods M1-M3; M0 interpolates the vertex opacity). The
   * texture (HIAC section 7, hovProjectionColor.h) is bilinear on a 512^2 float
   * grid, within 1.2e-5 of 1 - exp(-d); the analytic lookup is the shader's
   * float exp (about 1e-7) and skips the texture fetch, which on llvmpipe is
   * about a fifth of the frame on large meshes (hovBenchProjection --lookup).
   * The default is therefore the analytic lookup: more accurate and 6-15% faster
   * on llvmpipe (and no slower on a GPU, where exp is one instruction); the
   * texture is HIAC's route for hardware without fragment arithmetic and is
   * kept, tested to the same 2/255 acceptance (TestProjectionAnalytic).
   */
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
   * @p height pixels without any OpenGL (the projection aspect is
   * width/height). Returns 1 on success (also for an empty or invisible
   * volume: the image is then zero), 0 on error. The result is in GetFloatImage().
   */
  int RenderImage(vtkCamera* camera, vtkVolume* volume, int width, int height);

  /// The last image: float premultiplied RGBA (array "RGBA"), row 0 at the bottom.
  vtkImageData* GetFloatImage();

  /**
   * The last image in the double precision it is computed in (4 components,
   * width x height tuples, the layout of GetFloatImage()), copied into
   * @p rgba: for accuracy checks finer than float resolution.
   */
  void GetDoubleImage(vtkDoubleArray* rgba);

  ///@{
  /// Diagnostics of the last render.
  vtkGetMacro(WitnessViolations, vtkIdType);
  vtkGetMacro(NumberOfRenderedCells, vtkIdType);
  vtkGetMacro(NumberOfSkippedCells, vtkIdType);
  vtkGetMacro(NumberOfSegments, vtkIdType);
  vtkGetMacro(NumberOfPieces, vtkIdType);
  /// RAY_CAST: rays traced (pixels with a non-empty view interval; of the
  /// reduced grid in an interactive frame). NumberOfSegments then counts the
  /// cell intervals integrated, NumberOfPieces those plus the breakpoints
  /// located in them (the smooth pieces).
  vtkGetMacro(NumberOfRays, vtkIdType);
  /// Wall-clock seconds of the last image computation (sort + integration).
  vtkGetMacro(LastImageTime, double);
  ///@}

  ///@{
  /**
   * Progress and abort (the CPU modes, CPU_ACCURATE and RAY_CAST, where rows
   * of rays play the part of tiles): during the tile loop the mapper
   * fires vtkCommand::ProgressEvent (UpdateProgress, from the rendering
   * thread, between batches of about 1/32 of the tiles; 0 at the start,
   * non-decreasing, 1 when all tiles are done). An observer may call
   * SetAbortExecute(1); when a renderer draws the volume, the render window's
   * AbortRender is also polled (vtkRenderWindow::CheckAbortStatus). Then the
   * remaining tiles are skipped and left zero (never NaN) and
   * GetLastRenderAborted() is true. AbortExecute is reset at the start of
   * every image. The tiles run in batches only when the mapper has a
   * ProgressEvent observer or the render window an AbortCheckEvent observer
   * (otherwise one parallel loop, as before); a render that is not aborted
   * gives a bit-identical image either way.
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
  double RayCastTolerance = 1e-3;
  double RayCastInteractiveUpdateRate = 1.0;
  bool LastRenderWasInteractive = false;
  int RayCastInteractiveSubsampling = 0;
  int LastRayCastSubsampling = 1;
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
  int TileSize = 16;
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
  vtkIdType NumberOfPieces = 0;
  vtkIdType NumberOfRays = 0;
  double LastImageTime = 0.0;
  bool LastRenderAborted = false;

private:
  vtkHighOrderVolumeMapper(const vtkHighOrderVolumeMapper&) = delete;
  void operator=(const vtkHighOrderVolumeMapper&) = delete;

  int ComputeImage(vtkCamera* camera, vtkVolume* volume, int width, int height, double aspect,
    const float* depth);
  bool ValidateInputs(vtkCamera* camera, vtkVolume* volume, int width, int height, double aspect);
  // Frame checks shared by every mode (vtkHighOrderVolumeMapperChecks.cxx).
  /// False (an error reported) if the camera/volume give no usable view.
  bool CheckFrameView(vtkCamera* camera, vtkVolume* volume, double aspect);
  /// Zeroes non-finite/overflowing pixels (one warning) and warns once when a
  /// drawn image (@p drawn: cells were rendered) is empty.
  template <typename T>
  void CheckFrameImage(T* rgba, size_t pixels, bool drawn);
  void WarnTransparent();
  bool WarnedEmptyImage = false;
  vtkMTimeType WarnedEmptyTime = 0;
  bool PrepareCells(vtkVolume* volume);
  /// False if the volume is invisible (no extinction and no WVG glow);
  /// @p rebuilt (if given): whether the table was rebuilt now.
  bool PrepareTransferFunction(vtkVolumeProperty* property, bool* rebuilt = nullptr);
  /// The front-to-back cell order: the VisibilitySort's, or any order with
  /// PER_PIXEL_SORT unless @p needVisibilitySort (cell projection has no
  /// per-pixel sort).
  bool PrepareOrder(vtkCamera* camera, vtkVolume* volume, bool needVisibilitySort = false);
  /// impl.RGBA into the float image, after CheckFrameImage (@p drawn: see there).
  void PublishImage(int width, int height, bool drawn);
  /// Progress callback of the CPU tile loop: true to abort.
  bool ReportTileProgress(double done);
  /// Feature set-up of a frame: -1 error (reported), 0 no feature active, 1 active.
  int PrepareFeatures(vtkCamera* camera, vtkVolume* volume);

  // OPENGL_PROJECTION mode (Mapper/OpenGL/vtkHighOrderVolumeMapperProjection.cxx).
  void RenderProjection(vtkRenderer* ren, vtkVolume* vol);
  /// Cells, transfer function and (exact order) front-to-back order of a
  /// projection frame; false if nothing is to be drawn (errors reported).
  bool PrepareProjectionFrame(vtkCamera* camera, vtkVolume* volume, double aspect, bool exactOrder,
    const hov::CellSetup** setup, const std::vector<vtkIdType>** frontToBack,
    vtkHighOrderTransferFunction** tf);
  /// One warning when the table's colours exceed float's range (the GL path).
  void CheckProjectionColorRange(vtkHighOrderTransferFunction* tf);
  std::unique_ptr<hov::ProjectionState> ProjectionImpl;

  // RAY_CAST mode (Mapper/vtkHighOrderVolumeMapperRayCast.cxx): fills @p rgba
  // (4 doubles per pixel); returns 1 on success, 0 on error (reported);
  // @p drawn: whether visible cells were traced.
  int ComputeRayCastImage(vtkCamera* camera, vtkVolume* volume, int width, int height,
    double aspect, const float* depth, std::vector<double>& rgba, bool& drawn);
  std::unique_ptr<hov::RayCastState> RayCastImpl;

  struct Internals;
  std::unique_ptr<Internals> Impl;
  // Isosurfaces, fields, splatting (vtkHighOrderVolumeMapperFeatures.cxx).
  std::unique_ptr<hov::FeatureSetup> FeatureImpl;
  vtkRenderer* FrameRenderer = nullptr; ///< the renderer of the frame being drawn, if any
};

#endif
