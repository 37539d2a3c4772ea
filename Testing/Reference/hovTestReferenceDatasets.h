/**
 * @file hovTestReferenceDatasets.h
 * @brief Loading and tessellating the bundled issue-4 datasets for the
 * TestDataset* tests: the dolfinx T-junction (quadratic tetrahedra, point
 * array "speed") and the CalculiX mixed-cell zoo (hexahedra, wedges,
 * pyramids, tetrahedra, point array "temperature"), and the transfer
 * functions whose opacity nodes are also colour nodes. Used by the tests and
 * by Testing/Benchmarks/Mixed (no test-driver dependency).
 */
#ifndef hovTestReferenceDatasets_h
#define hovTestReferenceDatasets_h

#include "vtkSmartPointer.h"

#include <map>
#include <string>

class vtkCamera;
class vtkUnstructuredGrid;
class vtkVolumeProperty;

namespace hovTestRef
{
/// <dataDir>/<file> with @p array as active point scalars (an empty grid if unreadable).
vtkSmartPointer<vtkUnstructuredGrid> LoadDataset(
  const std::string& dataDir, const std::string& file, const std::string& array);

/// Number of cells of each VTK cell type.
std::map<int, long long> CellTypeCounts(vtkUnstructuredGrid* grid);

/// "type:count ..." of CellTypeCounts.
std::string DescribeCellTypes(vtkUnstructuredGrid* grid);

/// Linear tetrahedra of the zoo by vtkDataSetTriangleFilter; @p seconds = its time.
vtkSmartPointer<vtkUnstructuredGrid> TetrahedralizeLinear(vtkUnstructuredGrid* grid, double& seconds);

/// Quadratic tets split 8-way (SubdivideQuadraticTetras, 1 level); @p seconds = its time.
vtkSmartPointer<vtkUnstructuredGrid> TessellateQuadratic(vtkUnstructuredGrid* grid, double& seconds);

/// New colour and opacity functions in @p property: five nodes over [lo, hi],
/// each opacity node also a colour node; unit distance @p unit.
void DatasetTF(vtkVolumeProperty* property, double lo, double hi, double unit);

/// The demo/test cameras of the two datasets.
void TJunctionCamera(vtkCamera* cam);
void ZooCamera(vtkCamera* cam);
}

#endif
