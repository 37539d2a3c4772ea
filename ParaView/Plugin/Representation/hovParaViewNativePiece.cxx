#include "hovParaViewNativePiece.h"

#include "vtkAppendFilter.h"                  // leaves appended, cells kept
#include "vtkCellData.h"                      // ghost cells
#include "vtkCompositeDataIterator.h"         // the selected leaves
#include "vtkCompositeDataSet.h"              // composite inputs
#include "vtkExtractBlockUsingDataAssembly.h" // the selected blocks
#include "vtkNew.h"                           // vtkNew
#include "vtkPartitionedDataSet.h"            // partitioned inputs
#include "vtkUnstructuredGrid.h"              // the piece

namespace
{
/// The unstructured-grid leaves of @p composite (may be null) appended into
/// @p piece, points unmerged; @p piece is left as it is if there are none.
void AppendLeaves(vtkCompositeDataSet* composite, vtkUnstructuredGrid* piece)
{
  vtkNew<vtkAppendFilter> append;
  append->MergePointsOff();
  if (composite)
  {
    vtkSmartPointer<vtkCompositeDataIterator> it;
    it.TakeReference(composite->NewIterator());
    for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
    {
      if (auto* leaf = vtkUnstructuredGrid::SafeDownCast(it->GetCurrentDataObject()))
      {
        append->AddInputData(leaf);
      }
    }
  }
  if (append->GetNumberOfInputConnections(0) > 0)
  {
    append->Update();
    piece->ShallowCopy(append->GetOutput());
  }
}
}

vtkSmartPointer<vtkUnstructuredGrid> hov::NativePiece(vtkDataObject* input,
  const std::vector<std::string>& selectors, const std::string& assembly, bool& selectedNothing)
{
  selectedNothing = false;
  auto piece = vtkSmartPointer<vtkUnstructuredGrid>::New();
  if (auto* grid = vtkUnstructuredGrid::SafeDownCast(input))
  {
    piece->ShallowCopy(grid);
  }
  else if (auto* partitioned = vtkPartitionedDataSet::SafeDownCast(input))
  {
    // (Also vtkMultiPieceDataSet.) One dataset in partitions, which
    // selectors do not address: every partition (as ParaView's extractor
    // does not take this type, its own volume draws nothing of it).
    AppendLeaves(partitioned, piece);
  }
  else if (auto* composite = vtkCompositeDataSet::SafeDownCast(input))
  {
    vtkNew<vtkExtractBlockUsingDataAssembly> extract;
    extract->SetInputData(composite);
    for (const std::string& selector : selectors)
    {
      extract->AddSelector(selector.c_str());
    }
    if (!assembly.empty())
    {
      extract->SetAssemblyName(assembly.c_str());
    }
    extract->Update();
    AppendLeaves(vtkCompositeDataSet::SafeDownCast(extract->GetOutputDataObject(0)), piece);
    selectedNothing = piece->GetNumberOfCells() == 0 && composite->GetNumberOfCells() > 0;
  }
  else if (auto* dataset = vtkDataSet::SafeDownCast(input))
  {
    vtkNew<vtkAppendFilter> append;
    append->AddInputData(dataset);
    append->Update();
    piece->ShallowCopy(append->GetOutput());
  }
  if (piece->GetCellData()->HasAnyGhostBitSet(
        vtkDataSetAttributes::DUPLICATECELL | vtkDataSetAttributes::HIDDENCELL))
  {
    // Ghost cells are drawn by the rank that owns them, as ParaView's
    // preprocessor removes them (else they would be composited twice).
    piece->RemoveGhostCells();
  }
  return piece;
}
