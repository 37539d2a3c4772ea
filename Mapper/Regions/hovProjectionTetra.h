/**
 * @class   hov::ProjectionTetra
 * @brief   Fast path of the OpenGL cell projection for a linear tetrahedron
 *          that lies in one transfer-function slab (HIAC section 7 with
 *          Shirley-Tuchman's classification instead of polygon clipping).
 *
 * When no transfer-function node lies strictly inside the tetrahedron's
 * scalar range, the slab is the whole tetrahedron and the homogeneous
 * regions of its projection are those of Shirley and Tuchman (1990): either
 * one corner projects inside the triangle of the other three (class 1: three
 * triangles around that "thick" point, the corner in front of or behind the
 * opposite face) or two projected edges cross (class 2: four triangles
 * around the crossing). These are exactly the regions of the front/back face
 * overlay of hov::ProjectionPolyhedron, found with four orientation
 * tests instead of clipping. The thick vertex gets the full segment
 * (front and back points unprojected in double, L in dataset units, the
 * cell's affine field at both ends clamped to the slab, colour by M0-M3);
 * the outer corners have L = 0 (hov::ProjectionVertex::WriteCorner).
 * Each triangle lies in one front face, so the perspective-correct
 * interpolation of the vertex quantities is the same as on the regions of
 * the general path.
 *
 * Output: 4 (class 1) or 5 (class 2) vertices and 9 or 12 indices appended
 * to a chunk. Degenerate projections (a corner on the line of an edge, a face
 * seen edge-on: no strict class) are left to the general path.
 *
 * Thread safety: re-entrant.
 * @sa hov::ProjectionPolyhedron, hov::ProjectionRegions
 */
#ifndef hovProjectionTetra_h
#define hovProjectionTetra_h

#include "hovProjectionVertex.h" // frame, chunk
#include "hovCellSetup.h"       // Tetra

#include <vector> // points

namespace hov
{
class ProjectionTetra
{
public:
  /// Result of Emit: a number of triangles (3 or 4), or one of these.
  enum
  {
    BehindEye = -1, ///< a corner on or behind the eye plane: nothing drawn
    Degenerate = -2 ///< no strict Shirley-Tuchman class: use the general path
  };

  /**
   * Project tetrahedron @p t as the single slab of interval @p k, scalars
   * clamped to [@p lo, @p hi], into @p out. Returns the number of triangles
   * or BehindEye / Degenerate (then @p out is unchanged).
   */
  static int Emit(const hov::CellSetup::Tetra& t, const std::vector<glm::dvec3>& points,
    const hov::ProjectionFrame& f, int k, double lo, double hi,
    hov::ProjectionChunk& out);
};
}

#endif
