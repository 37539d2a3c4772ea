#include "hovParaViewNativePiece.h"

#include "vtkAppendFilter.h"                  // leaves appended, cells kept
#include "vtkCompositeDataIterator.h"         // the selected leaves
#include "vtkCompositeDataSet.h"              // composite inputs
#include "vtkExtractBlockUsingDataAssembly.h" // the selected blocks
#include "vtkNew.h"                           // vtkNew
#include "vtkUnstructuredGrid.h"              // the piece

vtkSmartPointer<vtkUnstructuredGrid> hov::NativePiece(vtkDataObject* input,
  const std::vector<std::string>& selectors, const std::string& assembly, bool& selectedNothing)
{
  selectedNothing = false;
  auto piece = vtkSmartPointer<vtkUnstructuredGrid>::New();
  if (auto* grid = vtkUnstructuredGrid::SafeDownCast(input))
  {
    piece->ShallowCopy(grid);
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
    vtkNew<vtkAppendFilter> append;
    append->MergePointsOff();
    if (auto* selected = vtkCompositeDataSet::SafeDownCast(extract->GetOutputDataObject(0)))
    {
      vtkSmartPointer<vtkCompositeDataIterator> it;
      it.TakeReference(selected->NewIterator());
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
    selectedNothing = piece->GetNumberOfCells() == 0 && composite->GetNumberOfCells() > 0;
  }
  else if (auto* dataset = vtkDataSet::SafeDownCast(input))
  {
    vtkNew<vtkAppendFilter> append;
    append->AddInputData(dataset);
    append->Update();
    piece->ShallowCopy(append->GetOutput());
  }
  return piece;
}
