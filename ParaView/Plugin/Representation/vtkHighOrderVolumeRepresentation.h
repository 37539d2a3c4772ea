/**
 * @class   vtkHighOrderVolumeRepresentation
 * @brief   ParaView's "Accurate Volume" representation of unstructured grids.
 *
 * A vtkUnstructuredGridVolumeRepresentation whose volume mapper is the
 * module's vtkHighOrderVolumeMapper (through vtkPVHighOrderVolumeMapper), so
 * it takes ParaView's colour map, opacity function, unit distance, position and
 * orientation exactly like ParaView's own "Volume" representation, and adds
 * the mapper's settings (render mode, opacity semantics, emission model,
 * integration method, cell ordering, ray-cast tolerance, isosurfaces,
 * separate colour and isosurface arrays) and its diagnostics.
 *
 * Native cells: ParaView's volume representation runs every input through
 * vtkVolumeRepresentationPreprocessor, which always tetrahedralises
 * (vtkDataSetTriangleFilter). This representation hands the view the input
 * grid itself instead (composite inputs: the unstructured grids of the
 * blocks selected by ParaView's "Blocks" property appended, cells unchanged), so linear, quadratic, mixed and Lagrange cells reach the
 * mapper as stored, also after ParaView's kd-tree redistribution on many
 * ranks (whole cells move; boundary cells are uniquely assigned).
 *
 * Parallel rendering: the representation asks for ordered compositing; each
 * rank renders its piece in exact order into its layer (premultiplied RGBA
 * over transparent black, viewport and projection from the renderer and
 * camera IceT prepares) and IceT composites the layers in the kd-tree's
 * visibility order.
 *
 * Colour map: the mapper integrates the colour function as a function of
 * the scalar, every node a breakpoint. ParaView's colour maps are
 * discretized by default (256 steps) and its default one interpolates in a
 * non-linear (Diverging) colour space; as ParaView's GPU volume mapper does,
 * the volume uses the continuous colour function (Discretize is not applied
 * to the volume), and non-linear colour spaces are linearised to
 * ColorSamplingTolerance (default 1e-4 per channel, 0.03/255; the module's own
 * default is 1e-6; the OpenGL projection, accurate to about 1/255, uses at
 * least 1e-3). The 256 steps would be 256 jumps, and with 1e-6 the
 * default map becomes 1262 nodes (3473 discretized) instead of 144: every
 * node splits every ray segment and, in the OpenGL projection, every cell.
 *
 * ParaView's "Use Separate Opacity Array" maps onto the mapper's fields:
 * extinction from the opacity array (through the opacity function), colour
 * from the colouring array (through the colour map).
 *
 * @sa vtkHighOrderVolumeMapper, vtkPVHighOrderVolumeMapper,
 * vtkUnstructuredGridVolumeRepresentation
 */
#ifndef vtkHighOrderVolumeRepresentation_h
#define vtkHighOrderVolumeRepresentation_h

#include "vtkParaViewHighOrderVolumeModule.h" // For export macro
#include "vtkUnstructuredGridVolumeRepresentation.h"

#include "vtkNew.h"          // For vtkNew
#include "vtkSmartPointer.h" // For the native piece
#include "vtkWeakPointer.h"  // For the colour map copied

#include <string> // For SeparateColorArray, the block selectors
#include <vector> // For the block selectors

class vtkColorTransferFunction;
class vtkDataSet;
class vtkPVHighOrderVolumeMapper;
class vtkUnstructuredGrid;

class VTKPARAVIEWHIGHORDERVOLUME_EXPORT vtkHighOrderVolumeRepresentation
  : public vtkUnstructuredGridVolumeRepresentation
{
public:
  static vtkHighOrderVolumeRepresentation* New();
  vtkTypeMacro(vtkHighOrderVolumeRepresentation, vtkUnstructuredGridVolumeRepresentation);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// Forwarded to the mapper (see vtkHighOrderVolumeMapper for the meaning of each).
  void SetRenderMode(int mode);
  void SetBlendMode(int mode);
  void SetOpacitySemantics(int semantics);
  void SetGPUOpacityTolerance(double tolerance);
  void SetEmissionModel(int model);
  void SetEmissionScale(double scale);
  void SetIntegrationMethod(int method);
  void SetCellOrdering(int ordering);
  void SetTerminationTransmittance(double value);
  void SetRayCastTolerance(double tolerance);
  void SetProjectionColorMethod(int method);
  void SetProjectionOrder(int order);
  void SetUseDepthBuffer(int use);
  void SetSkipTransparentCells(int skip);
  ///@}

  ///@{
  /// Isosurfaces: value, colour (r, g, b) and opacity of each (HIAC 5.1-5.2).
  void AddIsosurface(double value, double r, double g, double b, double opacity);
  void RemoveAllIsosurfaces();
  ///@}

  ///@{
  /**
   * Separate fields (HIAC 5): the colour map applied to another point array
   * than the one the opacity function sees, and isosurfaces of a third.
   * An empty name or "None" selects the colouring array. Component -1: magnitude.
   */
  void SetSeparateColorArray(const char* name);
  void SetSeparateColorArrayComponent(int component);
  void SetIsosurfaceArray(const char* name);
  void SetIsosurfaceArrayComponent(int component);
  ///@}

  ///@{
  /**
   * ParaView's block selection of composite inputs ("Blocks", the Assembly):
   * the selected blocks' unstructured grids are rendered, as ParaView's
   * "Volume" does (these hide the superclass's, whose preprocessor is not
   * used here; they also forward to it).
   */
  void SetActiveAssembly(const char* name);
  void AddBlockSelector(const char* selector);
  void RemoveAllBlockSelectors();
  ///@}

  /// The colour map (ParaView's LookupTable); the volume uses its continuous form (see above).
  void SetColor(vtkColorTransferFunction* lut);

  /// Linearisation tolerance of colour functions in non-linear colour spaces (default 1e-4).
  void SetColorSamplingTolerance(double tolerance);

  /// Write the float image (.vti) after every frame; empty: never (see vtkPVHighOrderVolumeMapper).
  void SetFloatImageFileName(const char* name);

  ///@{
  /// Diagnostics of the last frame on this rank (information properties).
  vtkIdType GetWitnessViolations();
  vtkIdType GetNumberOfRenderedCells();
  vtkIdType GetNumberOfSkippedCells();
  vtkIdType GetNumberOfTransparentCells();
  double GetLastImageTime();
  double GetLastFrameTime();
  double GetRayCastErrorEstimate();
  vtkIdType GetNumberOfRenderCalls();
  /// RAY_CAST: pixels per ray in x and y of the last frame (1: a still frame at full accuracy).
  int GetLastRayCastSubsampling();
  /// Cells in this rank's piece and their distinct VTK cell types (as delivered to the mapper).
  vtkIdType GetNumberOfPieceCells();
  int GetNumberOfPieceCellTypes();
  ///@}

  /// The mapper (for inspection and tests).
  vtkPVHighOrderVolumeMapper* GetHighOrderMapper();

  int ProcessViewRequest(vtkInformationRequestKey* request_type, vtkInformation* inInfo,
    vtkInformation* outInfo) override;

protected:
  vtkHighOrderVolumeRepresentation();
  ~vtkHighOrderVolumeRepresentation() override;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  void UpdateMapperParameters() override;

private:
  vtkHighOrderVolumeRepresentation(const vtkHighOrderVolumeRepresentation&) = delete;
  void operator=(const vtkHighOrderVolumeRepresentation&) = delete;

  /// The volume property's colour function: @p lut, or its continuous copy.
  void UpdateColorFunction();
  /// The mapper's colour sampling tolerance: ColorSamplingTolerance, at least 1e-3 in OPENGL_PROJECTION.
  void ApplyColorSamplingTolerance();
  /// The LOD surface mapper coloured like ParaView's surfaces: @p arrayName through the colour map.
  void UpdateLODMapper(const char* arrayName, int association);
  /// Warn once per piece about an empty piece (MPI) or a missing colouring array.
  void ReportPiece(vtkDataSet* piece);
  /// The colouring array's name ("" for none).
  std::string CurrentArrayName();

  vtkNew<vtkPVHighOrderVolumeMapper> Mapper;
  vtkSmartPointer<vtkColorTransferFunction> ColorMap; ///< as ParaView set it
  vtkNew<vtkColorTransferFunction> ContinuousColorMap;
  /// The map ContinuousColorMap was copied from, and its MTime then (ParaView
  /// keeps one map per array: a switch back to an older map must copy again).
  vtkWeakPointer<vtkColorTransferFunction> ContinuousColorMapSource;
  vtkMTimeType ContinuousColorMapTime = 0;
  vtkSmartPointer<vtkUnstructuredGrid> NativePiece;
  std::string SeparateColorArray;
  std::string Assembly; ///< empty: the extractor's default (the hierarchy)
  std::vector<std::string> BlockSelectors;
  int SeparateColorArrayComponent = -1;
  double ColorSamplingTolerance = 1e-4;
  /// The piece delivered for the frame being prepared (REQUEST_RENDER), or null.
  vtkDataSet* RenderedPiece = nullptr;
  bool WarnedMapScalars = false;
  bool WarnedMultiComponents = false;
  /// The block selection last warned as selecting nothing (assembly and selectors).
  std::string WarnedSelection;
  bool WarnedCellColorArray = false;
  vtkMTimeType ReportedPieceTime = 0;
  std::string ReportedArray = "(none reported)";
};

#endif
