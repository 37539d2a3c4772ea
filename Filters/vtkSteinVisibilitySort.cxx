// Exact visibility ordering (Stein et al., HIAC 6); see vtkSteinVisibilitySort.h.
#include "vtkSteinVisibilitySort.h"

#include "hovSteinGraph.h" // GraphSort, Topology
#include "hovSteinMerge.h" // SortBackToFront, Geometry, View

#include "vtkCamera.h"
#include "vtkDataSet.h"
#include "vtkIdList.h"
#include "vtkIdTypeArray.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"

#include <algorithm>
#include <chrono>

vtkStandardNewMacro(vtkSteinVisibilitySort);

struct vtkSteinVisibilitySort::Internals
{
  hovStein::Geometry Geometry;
  hovStein::View View;
  hovStein::Topology Topology;
  hovStein::GraphSort GraphSorter; ///< with its per-view buffers
  bool TopologyValid = false;
  std::vector<vtkIdType> Order; ///< back to front
  std::vector<vtkIdType> CycleCells;
  vtkNew<vtkIdTypeArray> Chunk;
  vtkNew<vtkIdTypeArray> Whole;
  vtkIdType Cursor = 0;
  // What the cached data were built from.
  vtkDataSet* GeometryInput = nullptr;
  vtkMTimeType GeometryInputTime = 0, GeometryModelTime = 0;
  bool GeometryValid = false;
  vtkCamera* SortCamera = nullptr;
  vtkMTimeType SortCameraTime = 0;
  int SortTiles[2] = { -1, -1 };
  int SortAlgorithm = -1;
  int SortCulling = -1;
  bool SortValid = false;
};

vtkSteinVisibilitySort::vtkSteinVisibilitySort()
  : Impl(new Internals)
{
}

vtkSteinVisibilitySort::~vtkSteinVisibilitySort() = default;

namespace
{
double Seconds(std::chrono::steady_clock::time_point t0)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}
}

void vtkSteinVisibilitySort::InitTraversal()
{
  Internals& im = *this->Impl;
  im.Cursor = 0;
  if (!this->Input)
  {
    vtkErrorMacro("No input data set to sort.");
    im.Order.clear();
    im.SortValid = false;
    return;
  }
  if (!this->Camera)
  {
    vtkErrorMacro("No camera: cannot sort the cells of " << this->Input->GetClassName() << ".");
    im.Order.clear();
    im.SortValid = false;
    return;
  }
  const auto t0 = std::chrono::steady_clock::now();
  const bool rebuild = !im.GeometryValid || im.GeometryInput != this->Input ||
    im.GeometryInputTime != this->Input->GetMTime() ||
    im.GeometryModelTime != this->ModelTransform->GetMTime() ||
    im.Geometry.SharedCellsMoved(this->Input);
  this->LastSetupSeconds = 0;
  if (rebuild)
  {
    im.Geometry.Build(this->Input, this->ModelTransform);
    im.GeometryInput = this->Input;
    im.GeometryInputTime = this->Input->GetMTime();
    im.GeometryModelTime = this->ModelTransform->GetMTime();
    im.GeometryValid = true;
    im.TopologyValid = false;
    im.SortValid = false;
  }
  bool built = rebuild;
  if (this->Algorithm == ADJACENCY_GRAPH && !im.TopologyValid)
  {
    if (im.Geometry.NumberOfCells > hovStein::MaxIndexedCells)
    {
      vtkErrorMacro("ADJACENCY_GRAPH orders at most " << hovStein::MaxIndexedCells
                                                      << " cells (32-bit adjacency); this input has "
                                                      << im.Geometry.NumberOfCells
                                                      << ": use MULTITILED_MERGE.");
      im.Order.clear();
      im.SortValid = false;
      return;
    }
    built = true;
    im.Topology.Build(im.Geometry);
    im.TopologyValid = true;
    im.SortValid = false;
  }
  if (built)
  {
    this->LastSetupSeconds = Seconds(t0);
  }
  if (im.SortValid && im.SortCamera == this->Camera &&
    im.SortCameraTime == this->Camera->GetMTime() && im.SortTiles[0] == this->NumberOfTilesX &&
    im.SortTiles[1] == this->NumberOfTilesY &&
    im.SortAlgorithm == this->Algorithm &&
    (this->Algorithm != ADJACENCY_GRAPH || im.SortCulling == this->BoundaryPairCulling))
  {
    this->LastSortSeconds = Seconds(t0);
    return; // nothing changed: hand out the same order again
  }
  // The adjacency graph needs the cells' depth ranges and extents only for a
  // few cells (View::DepthRange); the merge needs them all.
  im.View.Setup(im.Geometry, this->Camera, this->Algorithm != ADJACENCY_GRAPH);
  if (this->Algorithm == ADJACENCY_GRAPH)
  {
    this->SortGraph();
  }
  else
  {
    this->SortMerge();
  }
  if (im.Geometry.NumberOfCells > this->ViewBufferCellLimit)
  {
    // The order is all that outlives the sort: the per-view buffers (190 MB
    // for 2M tetrahedra) are freed before the frame allocates its own.
    im.View = hovStein::View();
    im.GraphSorter.ReleaseBuffers();
  }
  if (static_cast<vtkIdType>(im.Order.size()) != im.Geometry.NumberOfCells)
  {
    vtkErrorMacro("Internal error: " << im.Order.size() << " cells ordered out of "
                                     << im.Geometry.NumberOfCells << ".");
  }
  this->NumberOfUnorderedCells = im.Geometry.NumberOfBadCells;
  if (im.Geometry.NumberOfBadCells > 0)
  {
    vtkWarningMacro(<< im.Geometry.NumberOfBadCells
                    << " cells cannot be ordered exactly (unsupported type, invalid point ids "
                       "or non-finite coordinates; first: cell "
                    << im.Geometry.FirstBadCell << "); they are output first.");
  }
  im.SortCamera = this->Camera;
  im.SortCameraTime = this->Camera->GetMTime();
  im.SortTiles[0] = this->NumberOfTilesX;
  im.SortTiles[1] = this->NumberOfTilesY;
  im.SortAlgorithm = this->Algorithm;
  im.SortCulling = this->BoundaryPairCulling;
  im.SortValid = true;
  this->LastSortTime.Modified();
  this->LastSortSeconds = Seconds(t0);
}

void vtkSteinVisibilitySort::SortMerge()
{
  Internals& im = *this->Impl;
  hovStein::MergeStats stats;
  hovStein::SortBackToFront(im.Geometry, im.View, this->NumberOfTilesX, this->NumberOfTilesY,
    im.Order, stats);
  this->NumberOfCycles = stats.Cycles;
  this->NumberOfObstructsTests = stats.Tests;
  this->NumberOfMoves = stats.Moves;
  this->NumberOfGraphEdges = 0;
  this->NumberOfBoundaryCells = 0;
  this->NumberOfBoundaryFacePairs = this->NumberOfDroppedFacePairs = 0;
  im.CycleCells = stats.CycleCells;
  this->UsedTiles[0] = stats.TilesX;
  this->UsedTiles[1] = stats.TilesY;
}

void vtkSteinVisibilitySort::SortGraph()
{
  Internals& im = *this->Impl;
  hovStein::GraphStats stats;
  static_assert(static_cast<int>(CULLING_OFF) == hovStein::BoundaryPairs::CullNever &&
      static_cast<int>(CULLING_AUTO) == hovStein::BoundaryPairs::CullWhereDeep &&
      static_cast<int>(CULLING_ON) == hovStein::BoundaryPairs::CullAlways,
    "the public culling modes are the pair search's");
  im.GraphSorter.SetSheetCulling(this->BoundaryPairCulling);
  im.GraphSorter.Sort(im.Geometry, im.Topology, im.View, im.Order, stats);
  this->NumberOfCycles = stats.Cycles;
  this->NumberOfObstructsTests = stats.Tests;
  this->NumberOfMoves = 0;
  this->NumberOfGraphEdges = stats.FaceEdges + stats.ObstructEdges;
  this->NumberOfBoundaryCells = im.Topology.NumberOfBoundaryCells;
  this->NumberOfBoundaryFacePairs = stats.FacePairs;
  this->NumberOfDroppedFacePairs = stats.DroppedFacePairs;
  im.CycleCells = stats.CycleCells;
  this->UsedTiles[0] = this->UsedTiles[1] = 0;
}

vtkIdTypeArray* vtkSteinVisibilitySort::GetNextCells()
{
  Internals& im = *this->Impl;
  const vtkIdType n = static_cast<vtkIdType>(im.Order.size());
  if (im.Cursor >= n)
  {
    return nullptr;
  }
  const vtkIdType m = std::min<vtkIdType>(this->MaxCellsReturned, n - im.Cursor);
  im.Chunk->SetNumberOfTuples(m);
  vtkIdType* out = im.Chunk->GetPointer(0);
  for (vtkIdType i = 0; i < m; ++i, ++im.Cursor)
  {
    out[i] = this->Direction == FRONT_TO_BACK ? im.Order[n - 1 - im.Cursor] : im.Order[im.Cursor];
  }
  return im.Chunk;
}

vtkIdTypeArray* vtkSteinVisibilitySort::GetOrder()
{
  Internals& im = *this->Impl;
  const vtkIdType cursor = im.Cursor;
  this->InitTraversal();
  im.Cursor = std::min<vtkIdType>(cursor, static_cast<vtkIdType>(im.Order.size()));
  const vtkIdType n = static_cast<vtkIdType>(im.Order.size());
  im.Whole->SetNumberOfTuples(n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    im.Whole->SetValue(i, this->Direction == FRONT_TO_BACK ? im.Order[n - 1 - i] : im.Order[i]);
  }
  return im.Whole;
}

void vtkSteinVisibilitySort::GetCycleCells(vtkIdList* ids)
{
  ids->Reset();
  for (vtkIdType c : this->Impl->CycleCells)
  {
    ids->InsertNextId(c);
  }
}

void vtkSteinVisibilitySort::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Algorithm: "
     << (this->Algorithm == ADJACENCY_GRAPH ? "ADJACENCY_GRAPH" : "MULTITILED_MERGE") << "\n";
  os << indent << "ViewBufferCellLimit: " << this->ViewBufferCellLimit << "\n";
  os << indent << "BoundaryPairCulling: " << this->BoundaryPairCulling << "\n";
  os << indent << "NumberOfGraphEdges: " << this->NumberOfGraphEdges << "\n";
  os << indent << "NumberOfBoundaryCells: " << this->NumberOfBoundaryCells << "\n";
  os << indent << "NumberOfBoundaryFacePairs: " << this->NumberOfBoundaryFacePairs
     << " (dropped " << this->NumberOfDroppedFacePairs << ")\n";
  os << indent << "NumberOfTiles: " << this->NumberOfTilesX << " x " << this->NumberOfTilesY
     << " (used " << this->UsedTiles[0] << " x " << this->UsedTiles[1] << ")\n";
  os << indent << "NumberOfCycles: " << this->NumberOfCycles << "\n";
  os << indent << "NumberOfUnorderedCells: " << this->NumberOfUnorderedCells << "\n";
  os << indent << "NumberOfObstructsTests: " << this->NumberOfObstructsTests << "\n";
  os << indent << "NumberOfMoves: " << this->NumberOfMoves << "\n";
  os << indent << "LastSortSeconds: " << this->LastSortSeconds << "\n";
  os << indent << "LastSetupSeconds: " << this->LastSetupSeconds << "\n";
}
