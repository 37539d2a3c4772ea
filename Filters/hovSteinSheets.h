/**
 * @file hovSteinSheets.h
 * @brief Covering sheets: which (EXIT face, ENTRY face) pairs of the boundary
 *        pair search (hovSteinBoundaryPairs.h) can never be consecutive along
 *        a view ray, so that their cells need no Obstructs() test.
 *
 * Why a pair may be dropped. For a generic ray r from the eye (through no
 * vertex or edge: the others have measure zero), let C1, C2, ... be the cells
 * it crosses in order. Consecutive cells share an interior face that r crosses
 * (the face-direction edge orders them), or Ci is left through a boundary face
 * F and Ci+1 entered through a boundary face G with nothing of the mesh in
 * between. If A obstructs B, an open set of rays crosses A and then B; a
 * generic one gives a chain A = Ci, ..., Cj = B of consecutive pairs, hence a
 * path in the graph, provided every boundary face pair that is consecutive for
 * some open set of rays keeps its Obstructs() edge. A face pair (F, G) may
 * therefore be dropped when every ray through F and then G crosses another
 * ENTRY boundary face strictly between them (that cell is entered in between;
 * it is neither A, left at F, nor B, entered at G: both are convex).
 *
 * The test. Sheet faces are the ENTRY boundary faces (the eye strictly
 * outside: front-facing; not undecided) of visible cells that are triangles
 * with exact planes. Two sheet faces are joined across a mesh edge that
 * exactly these two boundary faces share (BoundaryAdjacency); a border edge
 * is a sheet face's edge that joins it to no other sheet face (silhouettes,
 * edges to EXIT or excluded faces, open or non-manifold edges). Two
 * front-facing faces of a consistently oriented surface sharing an edge
 * project to opposite sides of it, and the faces around a vertex whose edges
 * are all joined cover its neighbourhood once, so the number of sheet faces of
 * a joined set over a screen point changes only across its border edges. Per
 * grid tile (hovSteinPairGrid.h), the sheet faces whose extents meet the tile
 * are joined into local sheets (an edge to a sheet face whose extents miss the
 * tile lies outside it). A local sheet with no border edge meeting the tile
 * (tested on the edge's outward-rounded extents) whose face contains the
 * tile's centre (exact Orient2d on the projected points) is crossed by every
 * ray through the tile, at a depth within [front, rear] of its faces: it
 * covers the tile. A face pair whose extents' intersection lies in tiles
 * that each have a covering local sheet with F's rear depth < front and
 * rear < G's front depth (each beyond the pair search's rounding margin) is
 * dropped. Depth (along the view direction) grows along every ray, as the
 * pair search's own depth test assumes. Every consecutive pair is kept: a
 * covering sheet strictly between would be crossed in between.
 *
 * Cost and benefit (BoundaryPairs::Culling): on the 0.5M-cell heatsink the
 * sheets drop ~75% of the face pairs and halve a re-sort; on single solids
 * (the bracket, blocks) they drop under 1% for a few ms per view, so by
 * default they are built only where the faces overlap deeply.
 *
 * Thread safety: Build() is not re-entrant; Separates() is const. The
 * buffers live with the pair search's (BoundaryPairs::ReleaseBuffers()).
 */
#ifndef hovSteinSheets_h
#define hovSteinSheets_h

#include "hovSteinBoundaryPairs.h" // ViewFace, SheetStats
#include "hovSteinPairGrid.h"      // FaceData, PairGrid, TileRecord
#include "hovSteinTopology.h"      // Topology

#include <cstdint> // std::int32_t
#include <utility> // std::pair
#include <vector>  // storage

namespace hovStein
{
/// View-independent: across each edge of each boundary face, the other one.
struct BoundaryAdjacency
{
  /// Per boundary face (Topology::Boundary), 4 entries: across edge e (from
  /// corner e to corner e + 1 of Geometry::OrientedFace), the boundary face
  /// sharing it when exactly two boundary faces share it, else -1.
  FillBuffer<std::int32_t> Across;
  unsigned long Generation = 0; ///< Topology::Generation it was built for

  void Build(const Geometry& g, const Topology& t);
};

class SheetCover
{
public:
  /**
   * The covering local sheets of view @p v in the tiles of @p grid. @p faces and
   * @p data: the pair search's faces and their data; @p entryStart and
   * @p entryRecords: the CSR lists of the ENTRY faces' records of every tile
   * (TileRecord::Face: indices into @p faces, increasing within each tile).
   * With @p adjacency built for @p t.
   */
  void Build(const Geometry& g, const Topology& t, const View& v,
    const BoundaryAdjacency& adjacency, const std::vector<ViewFace>& faces,
    const FillBuffer<FaceData>& data, const PairGrid& grid, const vtkIdType* entryStart,
    const TileRecord* entryRecords);

  /**
   * The least rear depth of the covering sheets of @p tile whose front depth
   * exceeds @p after (VTK_DOUBLE_MAX if none): a face pair of that tile with
   * DepthAfter(F's rear) <= @p after and DepthBefore(G's front) > the result
   * is separated there.
   */
  double NearestRear(vtkIdType tile, double after) const;

  /**
   * Whether every tile [ix0, ix1] x [iy0, iy1] has a covering sheet lying
   * strictly between depths @p after and @p before: DepthAfter(F's rear) and
   * DepthBefore(G's front) (hovSteinPairGrid.h), the pair search's margins.
   */
  bool Separates(int ix0, int ix1, int iy0, int iy1, double after, double before) const;
  /// The same for the tiles of [ix0, ix1] x [iy0, iy1] before (ix, iy) in row order.
  bool SeparatesBefore(
    int ix0, int ix1, int iy0, int iy1, int ix, int iy, double after, double before) const;

  const SheetStats& GetStats() const { return this->Stats; }

private:
  /// The covers of every tile; @p entryRecords in increasing face order within
  /// each tile (the records before the pair search sorts them by depth).
  void Cover(const FillBuffer<FaceData>& data, const PairGrid& grid, const vtkIdType* entryStart,
    const TileRecord* entryRecords);

  int NX = 0;
  /// Per boundary face: its face index in the view's faces if it is a sheet
  /// face, else -1.
  std::vector<std::int32_t> FaceOf;
  /// Per face of the view (what Cover() reads for each tile a face meets,
  /// made once per face): SheetFace bit if it is a sheet face, and the bits
  /// of its border edges; across each edge, the sheet face sharing it (a
  /// face index), else -1.
  static constexpr std::uint8_t SheetFace = 128;
  FillBuffer<std::uint8_t> Border;
  FillBuffer<std::int32_t> Across;
  /// Per tile (CSR): the covering sheets' depth ranges (front, rear) by
  /// decreasing front, each rear the least of those so far.
  std::vector<vtkIdType> CoverStart;
  std::vector<std::pair<double, double>> Covers;
  SheetStats Stats;
};
}

#endif
