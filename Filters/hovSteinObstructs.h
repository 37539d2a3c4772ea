/**
 * @file hovSteinObstructs.h
 * @brief The Obstructs(P, Q) test of Stein et al. / HIAC 6 and 6.1:
 *        true when P must be drawn after Q (some view ray meets P in front of Q).
 *
 * The caller has already found that the screen extents of P and Q overlap.
 * One decision per unordered pair (evaluated for (min id, max id)), so
 * Obstructs(P, Q) and Obstructs(Q, P) are never both true. Tests, cheapest first:
 * 1. Separating face plane, exact: a face plane of one cell with every corner
 *    of the other on its closed outer side (exact Orient3d; shared faces and
 *    corners on the plane allowed). The exact side of the eye then decides
 *    (eye on the plane: no common ray). Non-planar (Newell) faces use their
 *    tolerant plane.
 * 2. Separating face plane up to rounding: the other cell outside within
 *    1e-11 times the coordinate magnitude (sheared non-conforming interfaces
 *    whose points are not exactly coplanar); the eye must be clearly on one
 *    side, else the cells share no ray of positive measure.
 *    When a plane puts P in front, Obstructs is true only if the projections
 *    overlap with positive area.
 * 3. Proper crossings of projected edges (exact Orient2d); a crossing decides
 *    only when the depth difference of the edges there exceeds its rounding
 *    error bound (nearly parallel, collinear or touching edges: inconclusive).
 * 4. No crossing at all and no vertex of either projection in the other's
 *    convex hull: the projections are disjoint -> false (HIAC 6.1).
 * 5. Otherwise (containment, inconclusive crossings, cells clipped by the near
 *    plane): clip the convex hulls of both projections; no area -> false; else
 *    cast the ray through the overlap's centroid (strictly inside both),
 *    intersect it with both cells' faces and compare the interval midpoints.
 *
 * Thread safety: one instance per thread.
 */
#ifndef hovSteinObstructs_h
#define hovSteinObstructs_h

#include "hovSteinView.h" // Geometry, View

namespace hovStein
{
class HullCache;

class Obstruction
{
public:
  /// @p hulls (optional): the cells' hulls computed ahead for this view.
  Obstruction(const Geometry& g, const View& v, const HullCache* hulls = nullptr);
  /// P must be drawn after Q (cells by id; their screen extents overlap).
  bool Obstructs(vtkIdType p, vtkIdType q);

private:
  static constexpr int NotSeparated = 5;
  static constexpr int WeakFront = 3; ///< "in front" by a warped (Newell) face: to be confirmed
  /// Plane tests: +1 a in front, -1 b in front, 0 no common ray, +-WeakFront, or NotSeparated.
  int PlaneRelation(vtkIdType a, vtkIdType b) const;
  /// Crossings, then the ray test: +2 a in front, -2 b in front, 0 no common ray.
  int Evidence(vtkIdType a, vtkIdType b) const;
  /// Face f of x separates y (tol 0: exact): +1 x in front, -1 y in front, 0, WeakFront, NotSeparated.
  int FaceSeparates(vtkIdType x, int f, vtkIdType y, double tol) const;
  int EdgeCrossings(vtkIdType p, vtkIdType q, bool& crossed) const;
  int CrossingOrder(const double* a, const double* b, const double* c, const double* d) const;
  /// The hull of cell c: cached, or computed into @p hull; its size and area.
  const double (*Hull(vtkIdType c, double hull[][2], int& size, double& area) const)[2];
  bool ProjectionsTouchOnly(vtkIdType p, vtkIdType q) const;
  bool Overlap(vtkIdType p, vtkIdType q, double centre[2]) const;
  int RayTest(vtkIdType p, vtkIdType q) const;
  bool RayInterval(vtkIdType c, const double origin[3], const double dir[3], double t[2]) const;

  const Geometry& G;
  const View& V;
  const HullCache* Hulls;
};
}

#endif
