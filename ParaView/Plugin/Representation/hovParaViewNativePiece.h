// The grid "Accurate Volume" hands ParaView's view: the input's cells as stored.
#ifndef hovParaViewNativePiece_h
#define hovParaViewNativePiece_h

#include "vtkSmartPointer.h" // the piece

#include <string> // selectors
#include <vector> // selectors

class vtkDataObject;
class vtkUnstructuredGrid;

namespace hov
{
/**
 * The unstructured grid of @p input with its cells as stored (ParaView's own
 * volume preprocessor always tetrahedralises):
 *  - a vtkUnstructuredGrid: shallow-copied;
 *  - a vtkPartitionedDataSet (or vtkMultiPieceDataSet): every partition's
 *    unstructured grid appended (selectors do not address partitions);
 *  - another composite dataset: the blocks @p selectors select in @p assembly
 *    (empty: the extractor's default, the hierarchy), as ParaView's "Blocks"
 *    property selects them for its volume, their unstructured grids appended
 *    with their points unmerged; @p selectedNothing is set when the input
 *    has cells and the selection none;
 *  - another vtkUnstructuredGridBase (vtkDataSet): copied cell by cell, types unchanged;
 *  - anything else, or null: an empty grid.
 * Ghost cells are removed (their owner draws them), as ParaView's
 * preprocessor removes them.
 */
vtkSmartPointer<vtkUnstructuredGrid> NativePiece(vtkDataObject* input,
  const std::vector<std::string>& selectors, const std::string& assembly, bool& selectedNothing);
}

#endif
