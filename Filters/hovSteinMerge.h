/**
 * @file hovSteinMerge.h
 * @brief Rough sort and multitiled merge of vtkSteinVisibilitySort (HIAC 6.2).
 *
 * 1. Cells not ordered exactly (bad cells, cells hidden behind the near plane)
 *    come first, back to front by rearmost depth.
 * 2. The others form the Global Sorting List (GSL), back to front by rearmost
 *    depth (float key rounded towards the back; ties by cell id). A stable LSD
 *    radix sort is used.
 * 3. The screen region is cut into tiles; each tile's list (TSL) holds the
 *    cells whose extents reach it, in GSL order, as an intrusive doubly linked
 *    list in a flat array (entries carry the rear key and the extents, so the
 *    scan is sequential in memory).
 * 4. Merge (steps 5-8): the head P is output once no Q in its tiles, with rear
 *    behind P's front, is obstructed by P. Last-comparison marks skip pairs
 *    already tested; the scan of a tile stops at the first Q entirely in front
 *    of P. An obstructed Q is pushed on the head stack (moved to the head of
 *    the GSL). A Q already on the stack closes a cycle: it is counted, its
 *    cells (the stack from Q to P) are recorded, and P is output. Each cell
 *    enters the stack once, so the merge always terminates and outputs every
 *    cell exactly once.
 *
 * Thread safety: sequential; not re-entrant.
 */
#ifndef hovSteinMerge_h
#define hovSteinMerge_h

#include "hovSteinView.h" // Geometry, View

namespace hovStein
{
struct MergeStats
{
  vtkIdType Tests = 0, Moves = 0, Cycles = 0;
  std::vector<vtkIdType> CycleCells; ///< each id once
  int TilesX = 0, TilesY = 0;        ///< tiles used
};

/// Back-to-front order of all cells of @p g for the view @p v (tiles <= 0: default).
void SortBackToFront(const Geometry& g, const View& v, int tilesX, int tilesY,
  std::vector<vtkIdType>& order, MergeStats& stats);

/// Stable sort of @p ids by @p keys descending (LSD radix on the float bits).
void RadixSortDescending(std::vector<vtkIdType>& ids, const std::vector<float>& keys);
}

#endif
