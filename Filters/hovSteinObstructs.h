/**
 * @file hovSteinObstructs.h
 * @brief The Obstructs(P, Q) test of Stein et al. / HIAC 6 and 6.1:
 *        true when P must be drawn after Q (some view ray meets P in front of Q).
 *
 * The caller has already found that the screen extents of P and Q overlap.
 * Tests, cheapest first:
 * 1. P on the outer side (closed) of a back-facing face plane of Q -> false.
 * 2. Q on the outer side (closed) of a front-facing face plane of P -> false.
 *    ("front-facing": the eye strictly on the outer side.) Exact faces use the
 *    exact Orient3d on world coordinates, so shared faces decide exactly.
 * 3. ProjectsBehind: proper crossings of projected edges (exact Orient2d);
 *    the depths of both edges at a crossing decide when they differ clearly.
 * 4. No crossing at all and no vertex of either projection in the other's
 *    convex hull: the projections are disjoint -> false (HIAC 6.1).
 * 5. Otherwise (containment, inconclusive or near-degenerate crossings,
 *    cells clipped by the near plane): clip the convex hulls of both
 *    projections; no area -> false; else cast the ray through the overlap's
 *    centroid, intersect it with both cells' faces and compare the midpoints of
 *    the two parameter intervals.
 * For disjoint convex cells every common ray meets them in the same order, so
 * Obstructs(P, Q) and Obstructs(Q, P) are never both true.
 *
 * Thread safety: one instance per thread (it caches face orientations).
 */
#ifndef hovSteinObstructs_h
#define hovSteinObstructs_h

#include "hovSteinView.h" // Geometry, View

namespace hovStein
{
class Obstruction
{
public:
  Obstruction(const Geometry& g, const View& v);
  /// P must be drawn after Q (cells by id; their screen extents overlap).
  bool Obstructs(vtkIdType p, vtkIdType q);

private:
  std::uint8_t FrontFaces(vtkIdType c);
  bool AllOuter(vtkIdType faceCell, int f, vtkIdType other) const;
  bool SeparatedByFace(vtkIdType p, vtkIdType q);
  int EdgeCrossings(vtkIdType p, vtkIdType q, bool& crossed) const;
  bool ProjectionsTouchOnly(vtkIdType p, vtkIdType q) const;
  bool RayTest(vtkIdType p, vtkIdType q) const;
  bool RayInterval(vtkIdType c, const double origin[3], const double dir[3], double t[2]) const;

  const Geometry& G;
  const View& V;
  std::vector<std::uint8_t> Facing; ///< per cell: bit 7 computed, bits 0-5 front-facing faces
};
}

#endif
