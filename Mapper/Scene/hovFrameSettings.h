/**
 * @file    hovFrameSettings.h
 * @brief   The settings of vtkHighOrderVolumeMapper for one frame, as the
 *          render modes read them (every enum a hov enum, converted once by
 *          the facade: vtkHighOrderVolumeMapper.cxx, FrameSettingsOf, with a
 *          static_assert per value), the statistics a frame reports back, and
 *          the interface messages go through.
 *
 * Thread safety: plain values; one per frame.
 * @sa hov::RenderFrame
 */
#ifndef hovFrameSettings_h
#define hovFrameSettings_h

#include "hovBlendModes.h"       // BlendMode
#include "hovProjectionColor.h"  // ProjectionColorMethod
#include "hovSegmentIntegral.h"  // EmissionModel, SegmentMethod
#include "hovShading.h"          // ShadingLight, ShadingMaterial
#include "hovTransferFunction.h" // OpacitySemantics, OpacityNode
#include "hovVolumeShading.h"    // AmbientTerm

#include "vtkType.h" // vtkIdType

#include <string> // array names
#include <vector> // isosurfaces

namespace hov
{
/// vtkHighOrderVolumeMapper::RenderModeType.
enum class RenderMode
{
  CPUAccurate = 0,
  OpenGLProjection = 1,
  RayCast = 2
};

/// vtkHighOrderVolumeMapper::CellOrderingType.
enum class CellOrdering
{
  VisibilitySort = 0,
  PerPixelSort = 1
};

/// vtkHighOrderVolumeMapper::VectorModeType.
enum class VectorMode
{
  Magnitude = 0,
  Component = 1
};

/// vtkHighOrderVolumeMapper::ProjectionOrderType.
enum class ProjectionOrder
{
  Exact = 0,
  Approximate = 1
};

/// vtkHighOrderVolumeMapper::ProjectionOpacityLookupType.
enum class OpacityLookup
{
  Texture = 0,
  Analytic = 1
};

/// The volume's own shading and gradient opacity (vtkVolumeProperty, component
/// 0, COMPOSITE blending only; read by hov::ReadVolumeShading).
struct ShadingFrameSettings
{
  bool Shade = false;       ///< Shade(0) on and COMPOSITE blending
  ShadingMaterial Material; ///< Ambient/Diffuse/Specular/SpecularPower, two-sided lighting
  AmbientTerm Ambient = AmbientTerm::MaterialColor;
  double AmbientLight[3] = { 0.0, 0.0, 0.0 }; ///< sum of I La (AmbientTerm::LightAmbient)
  std::vector<ShadingLight> Lights;           ///< world coordinates
  bool GradientOpacity = false;               ///< a gradient-opacity function applies
  std::vector<OpacityNode> GradientOpacityNodes;
  bool Active() const { return this->Shade || this->GradientOpacity; }
};

/// The mapper's settings (see vtkHighOrderVolumeMapper.h for their meaning).
struct FrameSettings
{
  RenderMode Mode = RenderMode::CPUAccurate;
  OpacitySemantics Semantics = OpacitySemantics::GPUCompatible;
  double GPUOpacityTolerance = 1e-4;
  EmissionModel Emission = EmissionModel::WilliamsMax;
  double EmissionScale = 1.0;
  SegmentMethod Integration = SegmentMethod::Exact;
  CellOrdering Ordering = CellOrdering::VisibilitySort;
  VectorMode Vectors = VectorMode::Magnitude;
  int VectorComponent = 0;
  double TerminationTransmittance = 1e-9;
  int TileSize = 32;
  int CellRecordMemory = 256; ///< MiB (vtkHighOrderVolumeMapper::SetCellRecordMemory)
  bool SkipTransparentCells = true;
  bool UseDepthBuffer = true;
  bool ViewDepthClipping = false;
  double ViewDepthRange[2] = { 0.0, 1.0 };
  bool HasClippingPlanes = false;
  /// Blend mode (hovBlendModes.h); unsupported public values arrive as Composite.
  BlendMode Blend = BlendMode::Composite;
  double AverageRange[2] = { -VTKFloatMax, VTKFloatMax };

  // RAY_CAST
  double RayCastTolerance = 1e-3;

  // OPENGL_PROJECTION
  ProjectionColorMethod ColorMethod = ProjectionColorMethod::ExactColor;
  ProjectionOrder Order = ProjectionOrder::Exact;
  OpacityLookup Lookup = OpacityLookup::Analytic;

  // Features (HIAC 5.1-5.3; the CPU_ACCURATE mode)
  std::vector<double> Isosurfaces; ///< value, r, g, b, opacity per surface
  std::string ColorArray;          ///< empty: colour from the main scalars
  int ColorComponent = -1;
  std::string IsosurfaceArray; ///< empty: isosurfaces of the main scalars
  int IsosurfaceComponent = -1;
  bool Splatting = false;
  double SplatPixelThreshold = 2.0;

  ShadingFrameSettings Shading;

  int NumberOfIsosurfaces() const { return static_cast<int>(this->Isosurfaces.size() / 5); }
};

/// What a frame reports back (the mapper's diagnostics of the last render).
struct FrameStatistics
{
  vtkIdType WitnessViolations = 0;
  vtkIdType RenderedCells = 0;
  vtkIdType SkippedCells = 0;
  vtkIdType Segments = 0;
  vtkIdType Pieces = 0;
  vtkIdType Rays = 0;
  vtkIdType SplattedCells = 0;
  vtkIdType CellRecords = 0;
  vtkIdType TransparentCells = 0;
  bool Aborted = false;
  /// Set by the mode they belong to only (-1 / 0: not reported by this frame).
  vtkIdType ProjectedTriangles = -1;
  vtkIdType ProjectedSlabs = -1;
  /// Worst error estimate of a shaded segment integrated by quadrature (0: none).
  double ShadingErrorEstimate = 0.0;
  /// Seconds of the frame that do not depend on its number of pixels (the
  /// cells, the order; hov::InteractionBudget).
  double FixedSeconds = 0.0;
};

/// Where a frame's messages go: the mapper's vtkWarningMacro / vtkErrorMacro.
class FrameMessages
{
public:
  virtual ~FrameMessages() = default;
  virtual void Warning(const std::string& text) = 0;
  virtual void Error(const std::string& text) = 0;
};
}

#endif
