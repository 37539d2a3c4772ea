/**
 * @class   vtkSteinVisibilitySort
 * @brief   Exact visibility ordering of convex cells (Stein et al., corrected and
 *          multitiled as in HIAC section 6).
 *
 * Orders the cells of a vtkDataSet back to front (or front to back) for a
 * vtkCamera, perspective or parallel, and the model transform of the prop,
 * such that whenever a view ray meets two cells, the cell nearer the eye comes
 * later in back-to-front order. The ordering is exact for any acyclic set of
 * non-intersecting convex cells: meshes may be non-convex, have holes, be
 * disconnected, or have non-conforming (sliding) interfaces.
 *
 * Two algorithms (SetAlgorithm()); both use the same exact Obstructs(P, Q)
 * test (below) and give exact orders for acyclic sets of non-intersecting
 * convex cells.
 *
 * ADJACENCY_GRAPH (the default, because it is 10-100x faster at the same
 * exactness): a visibility DAG built from the mesh's face adjacency.
 * 1. View-independent (cached): faces are matched by their sorted corner point
 *    ids. A face shared by exactly two cells lying on opposite sides of it is
 *    INTERIOR; all other faces (mesh boundary, sliding interfaces, hanging
 *    nodes, duplicated points) are BOUNDARY faces.
 * 2. Per view, each interior face gives an edge: the cell on the far side of
 *    its plane from the eye comes first (exact Orient3d of the eye; parallel
 *    projection: Orient3dDirection); the eye on the plane gives no edge.
 *    Non-planar (Newell) faces with the eye near their slab are undecided and
 *    their two cells are handled like boundary cells.
 * 3. A boundary face whose plane has the eye strictly inside is an EXIT face
 *    (a view ray can leave the mesh there), strictly outside an ENTRY face
 *    (undecided faces are both). For every EXIT face F of a cell a and ENTRY
 *    face G of a cell b != a such that the screen extents of F and G overlap,
 *    G reaches behind F's front depth, and (for exact face planes) G has a
 *    corner on the closed outer side of F's plane and F one of G's plane,
 *    Obstructs(a, b) (once per cell pair) adds the edge b -> a
 *    (hovSteinBoundaryPairs.h).
 * 4. Kahn's topological sort (FIFO; initial sources back to front by rearmost
 *    depth). If it stalls, the rest's strongly connected components (iterative
 *    Tarjan) are output in topological order, each back to front by rearmost
 *    depth, and every nontrivial component counts as one cycle.
 * Why it is exact: let a view ray meet P in front of Q (in their interiors).
 * Rays near it meet them in the same order; take one that avoids all cell
 * edges and walk along it from P's point to Q's. Each step leaves a cell
 * through a face. Through an interior face from A into B: the ray moves away
 * from the eye, so the eye is on A's side and B -> A is an edge. Otherwise it
 * leaves A through a boundary face F whose plane has the eye inside (an EXIT
 * face) and, after a gap or a non-matching interface, enters the
 * next cell B through a boundary face G whose plane has the eye outside (an
 * ENTRY face). The ray crosses F at x and G at y farther along, so the screen
 * extents of F and G both contain the image of x, G reaches behind x (behind
 * F's front), y is on the closed outer side of F's plane (so is a corner of
 * G, G lying in the convex hull of its corners; y is on the plane when F and
 * G are coplanar) and x on the closed outer side of G's plane (the eye's
 * side, as the ray crosses G's plane only at y); the pair (F, G) is
 * found, the ray meets A in front of B, so Obstructs(A, B) holds and B -> A
 * is an edge. The walk gives a path Q -> ... -> P: Q precedes P in every
 * topological order. Cells hidden behind the near plane are not on the walk
 * (it stays in front of P's point); unsupported cells act as empty space (their
 * neighbours have boundary faces there).
 * Measured (hovBenchSort, 2 cores, loaded machine; re-sort after a 5 degree
 * rotation, vtkCellCenterDepthSort = CCD in the same process; RT = tetrahedra
 * of vtkRTAnalyticSource): RT 13.7k cells 0.0023 s (2.4x CCD), bracket 56k
 * (a quarter on the boundary) 0.024 s (4.0x; 9.7k Obstructs tests), RT 197k
 * 0.032 s (1.7x), 625k 0.086 s (1.2x), 976k 0.11 s (1.0x), with a
 * view-independent set-up of 0.26 s at 976k. MULTITILED_MERGE took 0.27 s at
 * 13.7k and 1.15 s on the bracket (190-280x CCD), about 20 s at 976k.
 * Since then the per-view work of ADJACENCY_GRAPH runs in parallel with
 * persistent buffers and filtered face planes (same orders): interleaved with
 * the previous version on the same loaded machine (load 5-7), the bracket
 * re-sort takes 0.5-0.65x its time (medians of 50 re-sorts), RT 197k-976k
 * about 0.5x; first sorts about the same (0.8-1.05x).
 *
 * MULTITILED_MERGE (HIAC 6, 6.1, 6.2 as published):
 * 1. Rough sort by each cell's rearmost depth (the Global Sorting List).
 * 2. The view plane is cut into tiles (n^(1/6) x n^(1/6) by default,
 *    SetNumberOfTiles()); each tile keeps a list of its cells sorted by rearmost
 *    depth (Tile Sorting Lists).
 * 3. The head P of the global list is output once Obstructs(P, Q) is false for
 *    every Q in P's tiles whose rearmost depth lies behind P's front; each Q
 *    records the last P it was tested against, so a pair is tested once, and the
 *    scan of a tile list stops at the first Q entirely in front of P. A Q that P
 *    obstructs is moved to the head of the global list and tagged.
 * Obstructs(P, Q) tries, cheapest first: disjoint screen x and y extents;
 * P behind a back face of Q; Q in front of a front face of P (face planes are
 * Newell planes with their maximum vertex deviation, so slightly non-planar
 * quadrilateral faces are handled); then ProjectsBehind, which compares depths
 * at crossings of projected edges and, when no edges cross, applies the
 * convex-hull containment correction of HIAC 6.1. Orientation tests use
 * filtered exact predicates (hovGeometricPredicates), so shared faces, coplanar
 * faces and edges crossing at vertices are decided exactly.
 *
 * Perspective views may have the eye inside the mesh's bounding box: cells are
 * ordered by the part of them in front of a near plane at a tiny distance from
 * the eye (nothing nearer can be drawn); cells entirely behind it are invisible
 * and are output first in back-to-front order.
 *
 * Cells: tetrahedron, voxel, hexahedron, wedge, pyramid, and the quadratic
 * tetrahedron, hexahedron, wedge and pyramid with straight edges (ordered by
 * their corner vertices). Other cell types, and cells with NaN/Inf
 * coordinates, cannot be ordered exactly: they are reported once with a
 * warning, counted in GetNumberOfUnorderedCells(), and output first
 * (back to front by rearmost depth).
 *
 * Cycles (MULTITILED_MERGE): if a cell already moved to the head must move again,
 * the visibility relation has a cycle. The sort then outputs the current head
 * anyway (so every cell is output exactly once and the sort always terminates:
 * each cell is moved at most once), counts the cycle and records the cells
 * involved (GetCycleCells()). Images of cells in a cycle may be wrong where
 * they overlap; the mapper's z-buffer witness counts those pixels.
 *
 * Re-sorting after a camera change reuses the view-independent data (cell
 * corners, faces, world-space face planes and, for ADJACENCY_GRAPH, the face
 * adjacency), rebuilt only when the input or the model transform changes.
 * Faces match by point ids: meshes whose neighbouring cells use duplicated
 * points are still ordered exactly, only more slowly (every face is a
 * boundary face). ADJACENCY_GRAPH indexes cells and faces in 32 bits: at most
 * 700 million cells (an error beyond; MULTITILED_MERGE has no such limit).
 *
 * Thread safety: one sort per object at a time; the set-up, the face
 * matching and, per view, the face directions and edges, the boundary face
 * roles, pair search and Obstructs tests of ADJACENCY_GRAPH run in parallel
 * with vtkSMPTools over fixed blocks (results independent of the thread
 * count and backend: TestSteinSortThreads); the merge and the topological
 * sort are sequential. The per-view buffers are kept between sorts.
 *
 * @sa vtkVisibilitySort vtkCellCenterDepthSort vtkCellVisibilitySortFilter
 * vtkHighOrderVolumeMapper
 */

#ifndef vtkSteinVisibilitySort_h
#define vtkSteinVisibilitySort_h

#include "vtkRenderingHighOrderVolumeModule.h" // for export macro
#include "vtkVisibilitySort.h"

#include <memory> // for std::unique_ptr

class vtkIdList;
class vtkIdTypeArray;

class VTKRENDERINGHIGHORDERVOLUME_EXPORT vtkSteinVisibilitySort : public vtkVisibilitySort
{
public:
  static vtkSteinVisibilitySort* New();
  vtkTypeMacro(vtkSteinVisibilitySort, vtkVisibilitySort);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * vtkVisibilitySort interface: InitTraversal() sorts (when the input, the
   * camera, the model transform or the settings changed since the last sort)
   * and GetNextCells() hands out the order in chunks of MaxCellsReturned.
   */
  void InitTraversal() override;
  vtkIdTypeArray* GetNextCells() override;
  ///@}

  /// The ordering algorithms (see the class doc).
  enum Algorithms
  {
    ADJACENCY_GRAPH = 0, ///< default: face adjacency DAG + Obstructs() on boundary cells
    MULTITILED_MERGE = 1 ///< HIAC 6.2 as published
  };

  ///@{
  /**
   * The ordering algorithm (default ADJACENCY_GRAPH). Both are exact for
   * acyclic sets of non-intersecting convex cells.
   */
  vtkSetClampMacro(Algorithm, int, ADJACENCY_GRAPH, MULTITILED_MERGE);
  vtkGetMacro(Algorithm, int);
  void SetAlgorithmToAdjacencyGraph() { this->SetAlgorithm(ADJACENCY_GRAPH); }
  void SetAlgorithmToMultitiledMerge() { this->SetAlgorithm(MULTITILED_MERGE); }
  ///@}

  ///@{
  /**
   * Tiles of the multitiled merge (HIAC 6.2; MULTITILED_MERGE only). 0 (default) means
   * ceil(n^(1/6)) in each direction for n cells.
   */
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
  /**
   * Largest input (in cells, default 1,000,000) whose per-view buffers are
   * kept from one sort to the next. Above it they are freed once a sort is
   * done and only the order and the view-independent data (adjacency, face
   * planes) stay, so that a renderer's frame does not add its memory to
   * theirs (190 MB for 2M tetrahedra); each sort then allocates them again,
   * which made re-sorts of a 0.5M-cell heatsink about 20% slower. 0: always
   * freed. The order does not depend on it.
   */
  vtkSetClampMacro(ViewBufferCellLimit, vtkIdType, 0, VTK_ID_MAX);
  vtkGetMacro(ViewBufferCellLimit, vtkIdType);
  ///@}

  enum BoundaryPairCullingModes
  {
    CULLING_OFF = 0,  ///< test every candidate boundary face pair
    CULLING_AUTO = 1, ///< default: cull where the boundary faces overlap deeply
    CULLING_ON = 2    ///< always cull
  };

  ///@{
  /**
   * ADJACENCY_GRAPH: skip the Obstructs() test of boundary face pairs that
   * can never be consecutive along a view ray, because a covering sheet of
   * front-facing boundary faces lies strictly between them on every ray
   * through both (hovSteinSheets.h). The order is exact in every mode.
   * CULLING_AUTO (default) builds the sheets (a few milliseconds per view on
   * 50k cells) only where the EXIT and ENTRY faces overlap deeply (more than
   * 40 face pairs sharing a pair-search tile per face: finned or stacked
   * parts, not single solids); on a 0.5M-cell heatsink it halves the
   * re-sort. CULLING_OFF tests every candidate (for comparison).
   */
  vtkSetClampMacro(BoundaryPairCulling, int, CULLING_OFF, CULLING_ON);
  vtkGetMacro(BoundaryPairCulling, int);
  void SetBoundaryPairCullingToOff() { this->SetBoundaryPairCulling(CULLING_OFF); }
  void SetBoundaryPairCullingToAuto() { this->SetBoundaryPairCulling(CULLING_AUTO); }
  void SetBoundaryPairCullingToOn() { this->SetBoundaryPairCulling(CULLING_ON); }
  ///@}

  /**
   * The whole order of the last sort (cell ids of the input, in the current
   * Direction). Sorts first if needed. The array is owned by this object.
   */
  vtkIdTypeArray* GetOrder();

  ///@{
  /**
   * Diagnostics of the last sort.
   * - NumberOfCycles: cycles found (each broken by outputting the head).
   * - GetCycleCells(): ids of the cells involved in cycles (each id once).
   * - NumberOfUnorderedCells: unsupported or invalid cells output first.
   * - NumberOfObstructsTests: pairs tested with Obstructs() (full tests,
   *   not counting pairs skipped by depth or by last-comparison marks, nor,
   *   in the adjacency graph, those whose edge one boundary face pair proves).
   * - NumberOfMoves: cells moved to the head of the global list (merge).
   * - NumberOfGraphEdges: edges of the visibility DAG (adjacency graph),
   *   NumberOfBoundaryCells: cells with a boundary face (adjacency graph).
   * - NumberOfBoundaryFacePairs: candidate (EXIT, ENTRY) boundary face pairs
   *   the search met (adjacency graph), NumberOfDroppedFacePairs: those of
   *   them dropped by BoundaryPairCulling (before the plane tests). Where the
   *   culling runs on deeply overlapping faces, the search skips, per EXIT
   *   face and tile, the ENTRY faces behind its nearest covering sheet: those
   *   pairs are neither met nor counted (every pair it would drop is among
   *   them, so NumberOfDroppedFacePairs is then 0). The difference, the pairs
   *   kept for the screen and plane tests, does not depend on that.
   * - LastSortSeconds / LastSetupSeconds: wall time of the last sort and of
   *   the view-independent set-up it needed (0 when it was reused).
   */
  vtkGetMacro(NumberOfCycles, vtkIdType);
  void GetCycleCells(vtkIdList* ids);
  vtkGetMacro(NumberOfUnorderedCells, vtkIdType);
  vtkGetMacro(NumberOfObstructsTests, vtkIdType);
  vtkGetMacro(NumberOfMoves, vtkIdType);
  vtkGetMacro(NumberOfGraphEdges, vtkIdType);
  vtkGetMacro(NumberOfBoundaryCells, vtkIdType);
  vtkGetMacro(NumberOfBoundaryFacePairs, vtkIdType);
  vtkGetMacro(NumberOfDroppedFacePairs, vtkIdType);
  vtkGetMacro(LastSortSeconds, double);
  vtkGetMacro(LastSetupSeconds, double);
  ///@}

  /**
   * Tiles used by the last sort (the default or the settings, halved in both
   * directions while the tiles or their lists' entries would number more than
   * 16 per cell, at least 2^20 and at most 2^31 - 1 in all).
   */
  vtkGetVector2Macro(UsedTiles, int);

protected:
  vtkSteinVisibilitySort();
  ~vtkSteinVisibilitySort() override;

  int Algorithm = ADJACENCY_GRAPH;
  int NumberOfTilesX = 0;
  int NumberOfTilesY = 0;
  vtkIdType ViewBufferCellLimit = 1000000;
  int BoundaryPairCulling = CULLING_AUTO;
  vtkIdType NumberOfCycles = 0;
  vtkIdType NumberOfUnorderedCells = 0;
  vtkIdType NumberOfObstructsTests = 0;
  vtkIdType NumberOfMoves = 0;
  vtkIdType NumberOfGraphEdges = 0;
  vtkIdType NumberOfBoundaryCells = 0;
  vtkIdType NumberOfBoundaryFacePairs = 0;
  vtkIdType NumberOfDroppedFacePairs = 0;
  double LastSortSeconds = 0.0;
  double LastSetupSeconds = 0.0;
  int UsedTiles[2] = { 0, 0 };

private:
  vtkSteinVisibilitySort(const vtkSteinVisibilitySort&) = delete;
  void operator=(const vtkSteinVisibilitySort&) = delete;

  void SortMerge();
  void SortGraph();

  struct Internals;
  std::unique_ptr<Internals> Impl;
};

#endif
