/**
 * @file hovSteinPairEdges.h
 * @brief The last steps of the Stein sort's boundary pair search
 *        (hovSteinBoundaryPairs.h): its cell pairs made unique, decided, and
 *        written as the edges' adjacency.
 *
 * The search finds cell pairs (b, 2 a + certain): b the cell of the ENTRY
 * face, a that of the EXIT face, certain 1 if a face pair proves the edge
 * b -> a (InFrontOnScreen). They are bucketed by b (a counting sort over the
 * range of b), each bucket's entries sorted and made unique on its own, in
 * parallel (an entry is certain if any of its repeats is); the uncertain
 * ones are tested with Obstructs(a, b) in parallel, the hulls of the tested
 * cells computed once first; each bucket keeps its edges in place, which
 * are then copied out as the CSR of the Digraph's extra edges (each cell's
 * targets in increasing order). Results do not depend on the thread count.
 */
#ifndef hovSteinPairEdges_h
#define hovSteinPairEdges_h

#include "hovSteinBuffers.h" // FillBuffer
#include "hovSteinHulls.h"   // HullCache
#include "hovSteinView.h"    // Geometry, View

#include <cstdint> // std::uint8_t, std::uint32_t
#include <utility> // std::pair
#include <vector>  // storage

namespace hovStein
{
/// Cell pairs (b, 2 a + certain), in the order the search found them.
using CellPairs = std::vector<std::pair<vtkIdType, vtkIdType>>;
/// The least and greatest first cell of a block of CellPairs (least > greatest if empty).
using CellRange = std::pair<vtkIdType, vtkIdType>;

/// De-duplication and decision of the search's cell pairs, with its buffers (kept between views).
class PairEdges
{
public:
  /// Buckets the pairs of @p blocks (in block order) by first cell; @p ranges: each block's.
  void Collect(const std::vector<CellPairs>& blocks, const std::vector<CellRange>& ranges);
  /**
   * Decides the collected pairs for the view @p v: the edges b -> a as a CSR
   * over all cells of @p g (@p offsets per cell + 1, @p targets). Returns the
   * number of Obstructs() tests.
   */
  vtkIdType Decide(const Geometry& g, const View& v, FillBuffer<vtkIdType>& offsets,
    FillBuffer<vtkIdType>& targets);

private:
  /// The first entry of bucket @p i (first cell Lo + i) in Second.
  vtkIdType* Bucket(vtkIdType i) { return this->Second.data() + (i == 0 ? 0 : this->End[i - 1]); }
  /// The buckets are over the first cells [Lo, Lo + Kept.size()).
  vtkIdType Lo = 0;
  /// Bucket i's entries (second cells) are Second[End[i - 1] (0 for i = 0), End[i]).
  FillBuffer<vtkIdType> End, Second;
  FillBuffer<std::uint32_t> Kept; ///< per bucket: distinct second cells, then edges
  FillBuffer<std::uint8_t> Used;  ///< per cell: tested
  std::vector<vtkIdType> Cells;   ///< the tested cells
  HullCache Hulls;
};
}

#endif
