/**
 * @file hovCurvedSharedFaces.h
 * @brief A face shared by two curved Lagrange cells is searched once per ray:
 * the crossings one cell's face search finds are handed to its neighbour.
 *
 * In a conforming mesh the two cells on either side of an interior face
 * interpolate the same face nodes, so the face is one polynomial surface and
 * a ray crosses it at the same points whichever cell searches it. Without
 * sharing, every interior face is searched twice per ray (the face search is
 * half or more of a ray's time on tetrahedral meshes).
 *
 * Links (LinkSharedFaces, once per mesh): faces are matched by their corner
 * point ids. Each face gets a canonical frame: its corner of smallest point
 * id O and two corners E1 < E2 (a triangle's other two; a quad's two
 * neighbours of O). The reference faces are flat in parametric space, so a
 * point of the face is O + a (E1 - O) + b (E2 - O) in either cell's
 * parametric coordinates, with the same (a, b). A pair is linked only if the
 * two cells' geometry maps agree at three points of the face to 1e-12 times
 * their extent (same face nodes and orders); otherwise both search it.
 *
 * Per ray (FaceCrossingCache): a searched face's crossings are kept as
 * (a, b), T, Side and Grazing with the searching cell; the neighbour takes
 * them with its own coordinates O' + a (E1' - O') + b (E2' - O') and the
 * opposite Side (leaving one cell is entering the other). A face searched
 * without crossings is kept too (the neighbour skips it).
 *
 * Thread safety: links are read-only once built; one cache per thread.
 */
#ifndef hovCurvedSharedFaces_h
#define hovCurvedSharedFaces_h

#include "hovConfig.h"
#include "hovCurvedFaces.h" // CurvedCellFaces, FaceCrossing

#include <cstdint> // std::int64_t
#include <vector>  // storage

namespace hov
{
/// The shared faces of one cell: per cell face, its global id (-1: not
/// shared) and its canonical frame O, E1, E2 in the cell's parametric space.
struct CellFaceLinks
{
  std::vector<int> FaceIds;
  std::vector<double> Frames; ///< 9 per face: O, E1, E2
};

/// What LinkSharedFaces needs of one cell.
struct SharedFaceCell
{
  LagrangeCellView View;
  const CurvedCellFaces* Faces = nullptr;
  const std::int64_t* CornerIds = nullptr; ///< point ids of the corner nodes (VTK order)
};

/**
 * Links the faces that two cells share (see file doc) into @p links (one per
 * cell). Returns the number of shared faces.
 */
HOV_EXPORT int LinkSharedFaces(
  const std::vector<SharedFaceCell>& cells, std::vector<CellFaceLinks>& links);

/// The crossings of one ray with the shared faces searched so far.
class HOV_EXPORT FaceCrossingCache
{
public:
  void Clear();
  /// The crossings stored for face @p id as crossings of @p cell (see file
  /// doc) appended to @p out; false if the face has not been searched.
  bool Take(int id, int cell, const double* frame, std::vector<FaceCrossing>& out,
    bool& complete) const;
  /// Stores crossings [first, end) of @p found, found by @p cell on face @p id.
  void Store(int id, int cell, const double* frame, const std::vector<FaceCrossing>& found,
    size_t first, bool complete);

private:
  struct Entry
  {
    int Face, Cell, First, Count;
    bool Complete;
  };
  struct Point
  {
    double A, B, T;
    int Side;
    bool Grazing;
  };
  std::vector<Entry> Entries;
  std::vector<Point> Points;
};

/// Face crossings to share while computing one cell's inside intervals.
struct SharedFaceContext
{
  const CellFaceLinks* Links = nullptr; ///< the cell's links
  FaceCrossingCache* Cache = nullptr;   ///< the ray's cache
  int Cell = -1;                        ///< the cell's index (as in the links)
};
}

#endif
