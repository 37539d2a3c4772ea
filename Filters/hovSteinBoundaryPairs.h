/**
 * @file hovSteinBoundaryPairs.h
 * @brief Step 3 of vtkSteinVisibilitySort's ADJACENCY_GRAPH algorithm: the
 *        Obstructs() edges between cells with boundary faces, found face by face.
 *
 * A view ray that leaves cell A through a boundary face F (an EXIT face: the
 * eye strictly on the inner side of F's plane, or undecided) and later enters
 * cell B through a boundary face G (an ENTRY face: the eye strictly outside,
 * or undecided) crosses F at a point x and G at a point y farther along the
 * ray. Hence a face pair (F, G) can only be needed when
 * - the screen extents of F and G overlap (both contain the image of x and y);
 *   for triangles of visible cells, no edge of one has the other's corners
 *   all clearly outside its line (more than 1e-9 of the extents): a ray
 *   through both exists only if the projections overlap;
 * - rear depth of G > front depth of F (depth grows along the ray; compared
 *   with a rounding margin, pruned only when clearly violated);
 * - if F is an exact face: some corner of G lies on the closed outer side of
 *   F's plane (y does: the ray crosses F's plane once, at x, from the inner
 *   side; G lies in the convex hull of its corners). Closed: y lies on F's
 *   plane when F and G are coplanar (touching cells, sliding interfaces);
 *   pruned only when every corner is inside by more than 1e-9 times the
 *   coordinate magnitude, so that interfaces coplanar up to rounding (which
 *   Obstructs() treats as touching) stay candidates;
 * - if G is an exact face: some corner of F lies on the closed outer side of
 *   G's plane (x does: it is on the eye's side of y, and the eye is outside).
 * Every cell pair (A, B) with a face pair passing these tests gets the edge
 * B -> A if Obstructs(A, B), the exact cell-level test; without the test when
 * one of its face pairs proves it (triangles whose projections share a point
 * inside both by a margin, F entirely in front of G in depth: an open set of
 * rays leaves A and then enters B).
 * Faces of straddling cells (clipped by the near plane) use the cell's
 * visible-part extents and depth range. Undecided interior faces (non-planar
 * faces with the eye near them) are EXIT and ENTRY faces of both their cells.
 *
 * Face pairs are found with a uniform screen grid, per tile the EXIT faces
 * against the ENTRY faces (each pair in the tile of
 * the lower-left corner of the intersection of the extents), in parallel over
 * blocks of tiles; the cell pairs are made unique and tested in parallel
 * (hovSteinPairEdges.h). Results do not depend on the thread count.
 */
#ifndef hovSteinBoundaryPairs_h
#define hovSteinBoundaryPairs_h

#include "hovSteinTopology.h" // Topology
#include "hovSteinView.h"     // Geometry, View

#include <array>   // FacePair
#include <cstdint> // std::int32_t, std::uint8_t
#include <memory>  // std::unique_ptr
#include <vector>  // storage

namespace hovStein
{
struct BoundaryAdjacency;

/// A face taking part in step 3: bit 0 of Roles EXIT, bit 1 ENTRY.
struct ViewFace
{
  vtkIdType Cell;
  std::uint8_t Face;
  std::uint8_t Roles;
  /// Its index in Topology::Boundary, -1 for an undecided interior face.
  std::int32_t Boundary = -1;
};

/// Counters of the covering sheets of one view (hovSteinSheets.h).
struct SheetStats
{
  vtkIdType Sheets = 0;       ///< sheets with at least one face
  vtkIdType CoveredTiles = 0; ///< tiles with at least one covering sheet
  vtkIdType Covers = 0;       ///< (tile, covering sheet) pairs
};

/// Counters of step 3.
struct PairStats
{
  /// Face pairs with overlapping extents and depth ranges that the search met
  /// (where it skips the faces behind covering sheets, not those).
  vtkIdType FacePairs = 0;
  /// Of those, never consecutive along a ray (covering sheets; before the
  /// plane tests); 0 where the search skips (it skips every pair it would drop).
  vtkIdType DroppedFacePairs = 0;
  /// Face pairs passed on to the screen and plane tests, each once: FacePairs
  /// less DroppedFacePairs, whether the search skips or not.
  vtkIdType KeptFacePairs = 0;
  /// Distinct cell pairs tested with Obstructs() (not those a face pair proves).
  vtkIdType Tests = 0;
  SheetStats Sheets;
};

/**
 * Finds the edges of step 3 for one view after another, keeping its buffers
 * between views (no allocation once the first view has sized them) unless
 * ReleaseBuffers() frees them.
 */
class BoundaryPairs
{
public:
  BoundaryPairs();
  ~BoundaryPairs();
  /// The edges b -> a, b before a, for the cell pairs that need them (see the
  /// file doc), as a CSR over the cells: @p offsets per cell + 1, @p targets
  /// (each cell's a in increasing order).
  void Edges(const Geometry& g, const Topology& t, const View& v,
    const std::vector<ViewFace>& faces, FillBuffer<vtkIdType>& offsets,
    FillBuffer<vtkIdType>& targets, PairStats& stats);

  /// Dropping the face pairs that covering sheets prove never consecutive
  /// along a ray (hovSteinSheets.h): never (every candidate is tested), where
  /// the faces overlap deeply in depth (default: the sheets cost a few ms per
  /// view, worth it only there), or always.
  enum Culling
  {
    CullNever = 0,
    CullWhereDeep = 1,
    CullAlways = 2
  };
  int SheetCulling = CullWhereDeep;
  /// Cell pairs with a face pair that InFrontOnScreen() (hovSteinFacePairs.h)
  /// proves ordered get their edge without Obstructs() (off: for tests).
  bool CertifiedEdges = true;
  /// A dropped face pair: EXIT cell and face, ENTRY cell and face.
  using FacePair = std::array<vtkIdType, 4>;
  /// If set, the dropped face pairs of each view are written there (for the
  /// tests that check every drop against rays; costs memory).
  std::vector<FacePair>* DroppedLog = nullptr;

  /// Frees the per-view buffers (the next view allocates them again); the
  /// boundary faces' adjacency, made once per topology, is kept.
  void ReleaseBuffers();

  struct Buffers; ///< opaque: the per-view buffers

private:
  BoundaryPairs(const BoundaryPairs&) = delete;
  void operator=(const BoundaryPairs&) = delete;
  std::unique_ptr<Buffers> B;
  std::unique_ptr<BoundaryAdjacency> Adjacency; ///< of the last topology (view-independent)
};
}

#endif
