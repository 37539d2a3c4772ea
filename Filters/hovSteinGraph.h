/**
 * @file hovSteinGraph.h
 * @brief The ADJACENCY_GRAPH algorithm of vtkSteinVisibilitySort: a per-view
 *        visibility DAG from face adjacency plus Obstructs() on boundary cells,
 *        then a topological sort (see vtkSteinVisibilitySort.h for why it is exact).
 *
 * Per view (cells hidden behind the near plane or unsupported take no part;
 * they are output first, back to front by rearmost depth):
 * 1. Interior faces (hovSteinTopology): the exact side of the eye (Orient3d of
 *    the eye against the face triangle; parallel projection: Orient3dDirection
 *    with the direction towards the eye; the triangle's point ids kept per
 *    face, Topology::TripleA) gives the edge far cell -> near cell;
 *    the eye on the plane gives no edge. Non-planar (Newell) faces decide only
 *    when the eye is clearly off the face (margin below); otherwise the face is
 *    UNDECIDED and its two cells take part in step 2 in both roles. In
 *    parallel over faces, then over cells (each cell's outgoing edges and
 *    in-degree, from the view-independent per-cell face lists).
 * 2. Boundary faces (hovSteinBoundaryPairs): EXIT faces (the eye strictly
 *    on the inner side of the plane: a view ray can leave the mesh there) are
 *    paired with ENTRY faces (the eye strictly outside) of other cells whose
 *    screen extents overlap, that reach behind the exit face's front and are
 *    not separated from it by either face's plane; undecided Newell or
 *    degenerate faces count in both roles. For each surviving cell pair
 *    (a, b), Obstructs(a, b) adds the edge b -> a. The roles, the face pairs and
 *    the Obstructs() tests run in parallel over fixed blocks; pairs are
 *    de-duplicated and decided in a fixed order, so the result does not depend
 *    on the number of threads.
 * 3. Kahn's algorithm on the DAG, FIFO, the initial sources sorted back to
 *    front by rearmost depth (a full rough sort of all cells measured ~15% of
 *    the re-sort time at 1M cells and is not needed for exactness); sequential,
 *    branch-free and prefetching. If it stalls, the strongly connected
 *    components of the rest are found (iterative Tarjan) and output in
 *    topological order of the condensation, each component's cells by
 *    rearmost depth; nontrivial components are reported as cycles.
 *
 * GraphSort keeps its per-view buffers between views (a re-sort allocates
 * and page-faults nothing once the first view has sized them).
 *
 * Thread safety: GraphSort::Sort runs in parallel internally; one sort per
 * GraphSort at a time.
 */
#ifndef hovSteinGraph_h
#define hovSteinGraph_h

#include "hovSteinBoundaryPairs.h" // BoundaryPairs, ViewFace
#include "hovSteinPlaneFilter.h"   // FilteredPlane
#include "hovSteinTopology.h"      // Topology
#include "hovSteinView.h"          // Geometry, View

#include <cstdint> // std::int32_t, std::uint8_t
#include <utility> // std::pair
#include <vector>  // storage

namespace hovStein
{
struct GraphStats
{
  vtkIdType Tests = 0;         ///< Obstructs() calls (PairStats::Tests)
  vtkIdType FacePairs = 0;        ///< PairStats::FacePairs
  vtkIdType DroppedFacePairs = 0; ///< PairStats::DroppedFacePairs
  vtkIdType KeptFacePairs = 0;    ///< PairStats::KeptFacePairs
  vtkIdType FaceEdges = 0;     ///< edges from interior faces
  vtkIdType ObstructEdges = 0; ///< edges from Obstructs()
  vtkIdType Undecided = 0;     ///< interior faces left to Obstructs()
  vtkIdType ExitCells = 0, EntryCells = 0;
  vtkIdType Cycles = 0;              ///< nontrivial strongly connected components
  std::vector<vtkIdType> CycleCells; ///< their cells, each id once
};

/// Cells that take part in the DAG (the others are output first).
inline bool Ordered(const View& v, vtkIdType c)
{
  return v.Status[c] == StatusVisible || v.Status[c] == StatusStraddle;
}

/**
 * The per-view visibility DAG: an edge u -> w means u is drawn before w (back
 * to front). The face edges of u are FaceTargets[FaceOffsets[u] + k],
 * k < FaceCount[u], in increasing interior face index (the slots are the
 * view-independent Topology::CellFaceOffsets); then come its Obstructs()
 * edges ExtraTargets[ExtraOffsets[u] ...], in increasing target id.
 */
struct Digraph
{
  const vtkIdType* FaceOffsets = nullptr;
  // Each element written per view before it is read (FillBuffer: no
  // serial zeroing of tens of MB at each allocation).
  FillBuffer<CellIndex> FaceTargets; ///< (slots past FaceCount are never read)
  FillBuffer<std::uint8_t> FaceCount;
  FillBuffer<vtkIdType> ExtraOffsets; ///< per cell + 1
  FillBuffer<vtkIdType> ExtraTargets;
  FillBuffer<std::int32_t> InDegree; ///< per cell: edges into it (consumed by the sort)

  vtkIdType Degree(vtkIdType u) const
  {
    return this->FaceCount[u] + this->ExtraOffsets[u + 1] - this->ExtraOffsets[u];
  }
  /// Target of the k-th edge of @p u (k < Degree(u)).
  vtkIdType Target(vtkIdType u, vtkIdType k) const
  {
    return k < this->FaceCount[u] ? this->FaceTargets[this->FaceOffsets[u] + k]
                                  : this->ExtraTargets[this->ExtraOffsets[u] + k - this->FaceCount[u]];
  }
};

/// The ADJACENCY_GRAPH sort with its per-view buffers.
class GraphSort
{
public:
  /// Back-to-front order of all cells of @p g for the view @p v.
  void Sort(const Geometry& g, const Topology& t, const View& v, std::vector<vtkIdType>& order,
    GraphStats& stats);
  /// Frees the per-view buffers (the boundary faces' planes, made once per
  /// topology, are kept).
  void ReleaseBuffers();
  /// BoundaryPairs::Culling: when to drop boundary face pairs that are never
  /// consecutive along a ray (hovSteinSheets.h).
  void SetSheetCulling(int mode) { this->Boundary.SheetCulling = mode; }
  /// Edges proved by a face pair without Obstructs() (default on; off for tests).
  void SetCertifiedEdges(bool on) { this->Boundary.CertifiedEdges = on; }
  /// The last view's edges from boundary face pairs: (behind, in front),
  /// sorted by the first, then the second (tests; none once the buffers are released).
  std::vector<std::pair<vtkIdType, vtkIdType>> GetObstructEdges() const;
  /// Where to write each view's dropped face pairs (tests; null: nowhere).
  void SetDroppedLog(std::vector<BoundaryPairs::FacePair>* log) { this->Boundary.DroppedLog = log; }

private:
  /// Counters of one block of cells in CellPass.
  struct BlockCounts
  {
    vtkIdType FaceEdges = 0, Undecided = 0;
  };
  void FaceDirections(const Geometry& g, const Topology& t, const View& v);
  void BoundaryRoles(const Geometry& g, const Topology& t, const View& v, bool buildPlanes);
  void CellPass(const Geometry& g, const Topology& t, const View& v, GraphStats& stats);
  void CellPart(const Geometry& g, const Topology& t, const View& v, vtkIdType c,
    BlockCounts& counts, std::vector<ViewFace>& undecided);
  void CollectFaces(const Topology& t, GraphStats& stats);

  /// The filtered planes (hovSteinPlaneFilter.h) of the exact boundary faces
  /// of the topology of generation PlanesGeneration: made during the first
  /// view from the points its exact predicates read anyway, by the threads
  /// that use them (not zeroed on allocation). Interior faces keep no plane:
  /// FaceDirections tests their corners (Topology::TripleA) each view.
  FillBuffer<FilteredPlane> BoundaryPlanes;
  unsigned long PlanesGeneration = 0;
  FillBuffer<std::int8_t> Directions; ///< per interior face: 1 A -> B, -1 B -> A, 0, 2 undecided
  std::vector<std::uint8_t> Roles;     ///< per boundary face: its role in step 2 (0: none)
  std::vector<vtkIdType> RoleStart;    ///< per block of boundary faces + 1: first face in Faces
  std::vector<BlockCounts> Counts;
  std::vector<std::vector<ViewFace>> Undecided; ///< per block of cells: undecided interior faces
  std::vector<ViewFace> Faces;
  Digraph Graph;
  BoundaryPairs Boundary;
};

/**
 * Topological order of the @p numOrdered cells with Ordered(v, c) (the others
 * must have no edges); the initial sources, and the cells of each cyclic
 * component, back to front by rearmost depth (ties by id); appends to
 * @p order. Consumes d.InDegree. Cycles: see the file doc.
 */
void TopologicalOrder(Digraph& d, const Geometry& g, const View& v, vtkIdType numOrdered,
  std::vector<vtkIdType>& order, GraphStats& stats);
}

#endif
