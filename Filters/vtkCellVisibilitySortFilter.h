/**
 * @class   vtkCellVisibilitySortFilter
 * @brief   Reorders the cells of an unstructured grid into visibility order
 *          for a camera, with cycle and violation diagnostics.
 *
 * Input: a vtkUnstructuredGrid. Parameters: the vtkCamera (required), an
 * optional model transform (the vtkProp3D matrix the grid will be drawn
 * with; identity if unset), the Direction (BACK_TO_FRONT, the default, or
 * FRONT_TO_BACK) and the vtkVisibilitySort to use (default: a
 * vtkSteinVisibilitySort, exact for acyclic sets of convex cells, HIAC
 * section 6; set a vtkCellCenterDepthSort to compare with VTK's approximate
 * sort). SetNumberOfTiles() is forwarded to a vtkSteinVisibilitySort and
 * ignored by other sorts.
 *
 * Output: the same grid with its cells in visibility order. Points and point
 * data are shared with the input (shallow copies); cell data are reordered.
 * Two cell arrays are added:
 *  - "vtkOriginalCellIds" (vtkIdType): the input id of each output cell.
 *    The output position of input cell c is the index i with
 *    vtkOriginalCellIds[i] == c (scatter the array to invert it).
 *  - "SortRank" (vtkIdType): the position of each output cell in
 *    BACK-TO-FRONT order (0 = drawn first, the rearmost), whatever the
 *    Direction: it equals the output index for BACK_TO_FRONT and
 *    n-1-index for FRONT_TO_BACK, so "cell a is drawn before cell b
 *    back to front" reads SortRank[a] < SortRank[b] in either case.
 *
 * Field data of the output (one tuple each unless noted):
 *  - "NumberOfCycles": cycles the sort found (vtkSteinVisibilitySort only;
 *    -1 when the sort does not report cycles).
 *  - "CycleCellIds": input ids of the cells involved in cycles (n tuples).
 *  - "NumberOfUnorderedCells": cells the sort could not order exactly
 *    (vtkSteinVisibilitySort only; -1 otherwise).
 *  - "SortSeconds": wall time of InitTraversal() plus all GetNextCells().
 *  - "NumberOfViolations": interior faces ordered wrongly (see below; -1 when
 *    ComputeViolations is off).
 *  - "NumberOfCheckedFaces": interior faces the violation check examined.
 *
 * Violation check (works with any vtkVisibilitySort): every face shared by
 * exactly two cells (same corner points) is a piece of plane separating them.
 * If the eye (the camera position mapped into data coordinates by the inverse
 * model transform; for a parallel projection, the point at infinity against
 * the direction of projection) lies on one side of the face's plane, every
 * view ray crossing the face goes from the cell on the eye side into the
 * other one, so the cell on the far side must come first back to front. The
 * plane is the Newell plane of the face's corners; faces seen edge-on (the eye
 * within the face's maximum corner deviation plus 1e-9 of the eye distance
 * from the plane) and faces entirely behind the eye are skipped. It is exact
 * for conforming meshes and cheap (O(n log n)), but does not see order errors
 * between cells that do not share a face (non-convex meshes, disconnected
 * pieces, sliding interfaces): those need a ray-casting check. Face corners of
 * tetrahedra, voxels, hexahedra, wedges, pyramids and the quadratic
 * tetrahedron, hexahedron, wedge and pyramid are used; faces of other cell
 * types are not checked.
 *
 * The camera's, the model transform's and the sort's modification times are
 * part of this filter's MTime, so moving the camera re-executes the filter.
 * Errors: no camera, or a sort returning ids out of range (reported; missing
 * cells are appended, duplicates dropped, so the output keeps every cell once).
 *
 * Thread safety: one execution at a time per filter (the sort is shared).
 *
 * @sa vtkSteinVisibilitySort vtkCellCenterDepthSort vtkVisibilitySort
 * vtkHighOrderVolumeMapper
 */

#ifndef vtkCellVisibilitySortFilter_h
#define vtkCellVisibilitySortFilter_h

#include "vtkRenderingHighOrderVolumeModule.h" // for export macro
#include "vtkUnstructuredGridAlgorithm.h"

class vtkCamera;
class vtkIdTypeArray;
class vtkMatrix4x4;
class vtkVisibilitySort;

class VTKRENDERINGHIGHORDERVOLUME_EXPORT vtkCellVisibilitySortFilter
  : public vtkUnstructuredGridAlgorithm
{
public:
  static vtkCellVisibilitySortFilter* New();
  vtkTypeMacro(vtkCellVisibilitySortFilter, vtkUnstructuredGridAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The camera the order is computed for (required).
  virtual void SetCamera(vtkCamera* camera);
  vtkGetObjectMacro(Camera, vtkCamera);
  ///@}

  ///@{
  /// The model transform (data to world) the grid is drawn with; nullptr = identity.
  virtual void SetModelTransform(vtkMatrix4x4* matrix);
  vtkGetObjectMacro(ModelTransform, vtkMatrix4x4);
  ///@}

  enum DirectionType
  {
    BACK_TO_FRONT = 0,
    FRONT_TO_BACK = 1
  };
  ///@{
  /// Order of the output cells (default BACK_TO_FRONT).
  vtkSetClampMacro(Direction, int, BACK_TO_FRONT, FRONT_TO_BACK);
  vtkGetMacro(Direction, int);
  void SetDirectionToBackToFront() { this->SetDirection(BACK_TO_FRONT); }
  void SetDirectionToFrontToBack() { this->SetDirection(FRONT_TO_BACK); }
  ///@}

  ///@{
  /// Tiles of vtkSteinVisibilitySort (0 = its default n^(1/6)); ignored by other sorts.
  vtkSetClampMacro(NumberOfTilesX, int, 0, 4096);
  vtkGetMacro(NumberOfTilesX, int);
  vtkSetClampMacro(NumberOfTilesY, int, 0, 4096);
  vtkGetMacro(NumberOfTilesY, int);
  void SetNumberOfTiles(int nx, int ny)
  {
    this->SetNumberOfTilesX(nx);
    this->SetNumberOfTilesY(ny);
  }
  ///@}

  ///@{
  /// The sort (default a vtkSteinVisibilitySort). nullptr restores the default.
  virtual void SetVisibilitySort(vtkVisibilitySort* sort);
  vtkGetObjectMacro(VisibilitySort, vtkVisibilitySort);
  ///@}

  ///@{
  /// Run the interior-face violation check (default on).
  vtkSetMacro(ComputeViolations, bool);
  vtkGetMacro(ComputeViolations, bool);
  vtkBooleanMacro(ComputeViolations, bool);
  ///@}

  ///@{
  /// Diagnostics of the last execution (also in the output's field data).
  vtkGetMacro(NumberOfCycles, vtkIdType);
  vtkGetMacro(NumberOfUnorderedCells, vtkIdType);
  vtkGetMacro(NumberOfViolations, vtkIdType);
  vtkGetMacro(NumberOfCheckedFaces, vtkIdType);
  vtkGetMacro(SortSeconds, double);
  ///@}

  /// Includes the camera's, the model transform's and the sort's MTime.
  vtkMTimeType GetMTime() override;

protected:
  vtkCellVisibilitySortFilter();
  ~vtkCellVisibilitySortFilter() override;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  vtkCamera* Camera = nullptr;
  vtkMatrix4x4* ModelTransform = nullptr;
  vtkVisibilitySort* VisibilitySort = nullptr;
  int Direction = BACK_TO_FRONT;
  int NumberOfTilesX = 0;
  int NumberOfTilesY = 0;
  bool ComputeViolations = true;

  vtkIdType NumberOfCycles = 0;
  vtkIdType NumberOfUnorderedCells = 0;
  vtkIdType NumberOfViolations = 0;
  vtkIdType NumberOfCheckedFaces = 0;
  double SortSeconds = 0.0;

private:
  vtkCellVisibilitySortFilter(const vtkCellVisibilitySortFilter&) = delete;
  void operator=(const vtkCellVisibilitySortFilter&) = delete;

  bool RunSort(vtkUnstructuredGrid* input, vtkIdTypeArray* backToFront);
  void CheckFaces(vtkUnstructuredGrid* input, vtkIdTypeArray* backToFront);

  // The sort's MTime after this filter configured it (changes made by the
  // filter itself must not make it re-execute).
  vtkMTimeType SortConfiguredTime = 0;
};

#endif
