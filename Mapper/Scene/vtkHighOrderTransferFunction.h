/**
 * @class   vtkHighOrderTransferFunction
 * @brief   Converts a vtkVolumeProperty into the module's exact transfer-function table.
 *
 * Reads the colour (RGB or grey) and scalar-opacity functions of one component
 * of a vtkVolumeProperty, exactly as VTK evaluates them, and builds a
 * hov::TransferFunction (Module/Kernels/hovTransferFunction.h): a table whose
 * nodes are the union of all colour and opacity nodes, with colour and
 * extinction linear between nodes.
 *
 * - Linear segments (midpoint 0.5, sharpness 0, RGB colour space, linear
 *   scale) are copied node for node: exact.
 * - Any other segment (midpoint/sharpness, HSV/Lab/Diverging/Step colour
 *   spaces, log10 scale) is sampled adaptively through VTK's own GetColor /
 *   GetValue until linear interpolation is within SamplingTolerance
 *   (default 1e-6, absolute, values in [0,1]) at the checked points.
 * - Clamping off: values outside the node range are 0 (opacity) or black /
 *   the below/above-range colours (colour), as VTK evaluates them; this becomes
 *   a jump at the end nodes.
 * - Gradient opacity and shading are not part of this emission-absorption
 *   model; the mapper warns when they are enabled.
 *
 * The table is rebuilt only when the property, its functions or a setting
 * changes.
 *
 * Thread safety: Update() is not thread safe; GetTable() is read-only.
 * @sa vtkHighOrderVolumeMapper, hov::TransferFunction
 */
#ifndef vtkHighOrderTransferFunction_h
#define vtkHighOrderTransferFunction_h

#include "vtkObject.h"
#include "vtkRenderingHighOrderVolumeModule.h" // For export macro

#include <memory> // For std::unique_ptr
#include <string> // For messages
#include <vector> // For messages

class vtkVolumeProperty;
namespace hov
{
class TransferFunction;
}

class VTKRENDERINGHIGHORDERVOLUME_EXPORT vtkHighOrderTransferFunction : public vtkObject
{
public:
  static vtkHighOrderTransferFunction* New();
  vtkTypeMacro(vtkHighOrderTransferFunction, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Settings of the table (see hov::TransferFunctionSpec): opacity semantics
   * (0 GPU-compatible, 1 VTK-unstructured, 2 raw extinction), relative
   * tolerance of the GPU-compatible linearisation, Wilhelms-Van Gelder
   * emission scale, and the component of the property to read.
   */
  vtkSetClampMacro(OpacitySemantics, int, 0, 2);
  vtkGetMacro(OpacitySemantics, int);
  vtkSetClampMacro(GPUTolerance, double, 1e-14, 0.5);
  vtkGetMacro(GPUTolerance, double);
  vtkSetMacro(EmissionScale, double);
  vtkGetMacro(EmissionScale, double);
  /// Most nodes the GPU-compatible refinement may add (a warning says when
  /// the tolerance was not reached within them).
  vtkSetClampMacro(RefinementBudget, int, 0, 1000000);
  vtkGetMacro(RefinementBudget, int);
  vtkSetClampMacro(Component, int, 0, 3);
  vtkGetMacro(Component, int);
  vtkSetClampMacro(SamplingTolerance, double, 1e-12, 0.1);
  vtkGetMacro(SamplingTolerance, double);
  ///@}

  /**
   * Rebuild the table from @p property if it or a setting changed since the
   * last call. Returns false if there is no property.
   */
  bool Update(vtkVolumeProperty* property);

  /// Number of times the table was rebuilt (Update() skips unchanged inputs).
  vtkGetMacro(BuildCount, int);

  /// Number of table nodes and node @p i as (s, r, g, b, tau); for inspection.
  int GetNumberOfNodes();
  void GetNode(int i, double node[5]);
  /// Number of nodes added by the GPU-compatible refinement.
  int GetNumberOfRefinementNodes();
  /// Problems found by the last rebuild (one line each).
  int GetNumberOfMessages() { return static_cast<int>(this->Messages.size()); }
  const char* GetMessage(int i);

#ifndef __VTK_WRAP__
  const hov::TransferFunction& GetTable() const { return *this->Table; }
  /**
   * GPU-compatible semantics only (else GetTable()): the table of the same
   * colour and opacity nodes, plus the coarse refinement nodes of
   * SlabTolerance, whose "extinction" is the opacity a(s) itself (clamped to
   * [0, 1], linear between nodes), for the OpenGL projection's exact
   * per-fragment extinction (hov::GPUAverageExtinction).
   */
  const hov::TransferFunction& GetLinearOpacityTable() const
  {
    return this->OpacitySemantics == 0 ? *this->LinearOpacityTable : *this->Table;
  }
  /// The raw opacity and colour the blend modes read (hov::BlendModeTableSpec).
  const hov::TransferFunction& GetBlendTable() const { return *this->BlendTable; }
  /// The unit distance of the last build (vtkVolumeProperty's, per component).
  double GetUnitDistance() const { return this->UnitDistance; }
#endif
  ///@{
  /**
   * GPU-compatible semantics: the linear-opacity table also has the nodes of
   * a coarse refinement of -ln(1 - a) (relative chord error at most this;
   * default 0.1), so that the OpenGL projection's slabs, over which vertex
   * colours are interpolated, follow the curvature of the extinction.
   */
  vtkSetClampMacro(SlabTolerance, double, 1e-6, 1.0);
  vtkGetMacro(SlabTolerance, double);
  ///@}

protected:
  vtkHighOrderTransferFunction();
  ~vtkHighOrderTransferFunction() override;

  int OpacitySemantics = 0;
  double GPUTolerance = 1e-4;
  int RefinementBudget = 1000000;
  double EmissionScale = 1.0;
  int Component = 0;
  double SamplingTolerance = 1e-6;
  double SlabTolerance = 0.1;
  int BuildCount = 0;

private:
  vtkHighOrderTransferFunction(const vtkHighOrderTransferFunction&) = delete;
  void operator=(const vtkHighOrderTransferFunction&) = delete;

  std::unique_ptr<hov::TransferFunction> Table;
  std::unique_ptr<hov::TransferFunction> LinearOpacityTable;
  std::unique_ptr<hov::TransferFunction> BlendTable;
  double UnitDistance = 1.0;
  std::vector<std::string> Messages;
  vtkVolumeProperty* LastProperty = nullptr;
  vtkMTimeType LastPropertyTime = 0;
  vtkMTimeType LastBuildSettingsTime = 0;
};

#endif
