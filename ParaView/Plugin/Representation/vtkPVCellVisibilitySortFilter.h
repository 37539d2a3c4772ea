/**
 * @class   vtkPVCellVisibilitySortFilter
 * @brief   vtkCellVisibilitySortFilter with its camera given as values (ParaView filter).
 *
 * ParaView's "Cell Visibility Sort" filter: the module's
 * vtkCellVisibilitySortFilter (cells reordered into visibility order, the
 * arrays vtkOriginalCellIds and SortRank, the field data NumberOfCycles,
 * CycleCellIds, NumberOfUnorderedCells, SortSeconds, NumberOfViolations,
 * NumberOfCheckedFaces) whose camera is set through plain properties
 * (position, focal point, view up, view angle, parallel projection and scale:
 * a ParaView filter has no access to a view's vtkCamera) and whose sort is
 * chosen by number: the exact vtkSteinVisibilitySort with either algorithm, or
 * VTK's approximate vtkCellCenterDepthSort for comparison.
 *
 * In an MPI run each rank sorts its own piece for the same camera.
 * @sa vtkCellVisibilitySortFilter, vtkSteinVisibilitySort
 */
#ifndef vtkPVCellVisibilitySortFilter_h
#define vtkPVCellVisibilitySortFilter_h

#include "vtkCellVisibilitySortFilter.h"
#include "vtkParaViewHighOrderVolumeModule.h" // For export macro

#include "vtkNew.h" // For the camera

class VTKPARAVIEWHIGHORDERVOLUME_EXPORT vtkPVCellVisibilitySortFilter
  : public vtkCellVisibilitySortFilter
{
public:
  static vtkPVCellVisibilitySortFilter* New();
  vtkTypeMacro(vtkPVCellVisibilitySortFilter, vtkCellVisibilitySortFilter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The camera the cells are sorted for (world coordinates, degrees).
  void SetCameraPosition(double x, double y, double z);
  void SetCameraFocalPoint(double x, double y, double z);
  void SetCameraViewUp(double x, double y, double z);
  void SetCameraViewAngle(double degrees);
  void SetCameraParallelProjection(int parallel);
  void SetCameraParallelScale(double scale);
  ///@}

  enum SortAlgorithmType
  {
    STEIN_ADJACENCY_GRAPH = 0, ///< exact (default)
    STEIN_MULTITILED_MERGE = 1, ///< exact, HIAC 6.2 as published (slower)
    CELL_CENTER_DEPTH = 2       ///< VTK's vtkCellCenterDepthSort (approximate)
  };
  ///@{
  /// Which sort orders the cells.
  void SetSortAlgorithm(int algorithm);
  int GetSortAlgorithm() const { return this->SortAlgorithm; }
  ///@}

protected:
  vtkPVCellVisibilitySortFilter();
  ~vtkPVCellVisibilitySortFilter() override;

private:
  vtkPVCellVisibilitySortFilter(const vtkPVCellVisibilitySortFilter&) = delete;
  void operator=(const vtkPVCellVisibilitySortFilter&) = delete;

  vtkNew<vtkCamera> SortCamera;
  int SortAlgorithm = -1;
};

#endif
