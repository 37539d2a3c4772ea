/**
 * @file hovCurvedFaceNets.h
 * @brief The control-net tests of the curved face search (hovCurvedFaces.cxx):
 * a sub-patch's projected net (two components, row a along u, nv = dv + 1
 * values per row) is excluded when one component lies beyond the margin on
 * one side, proved to hold at most one crossing when det [h_u h_v] keeps its
 * sign (boxes or cones of the difference vectors), split by de Casteljau at
 * 1/2, and gives Newton its start. Internal (namespace hov::detail).
 *
 * Thread safety: pure functions.
 * @sa hovCurvedFaces.h
 */
#ifndef hovCurvedFaceNets_h
#define hovCurvedFaceNets_h

#include "hovCurvedFaces.h" // MaxFaceDegree

namespace hov
{
namespace detail
{
struct Interval
{
  double Lo, Hi;
};

/// The product of two intervals.
Interval Mul(const Interval& a, const Interval& b);

/// Split a (du+1) x (dv+1) net (row a along u, nv = dv + 1 per row) at the
/// middle of u (@p alongU) or v into @p left and @p right (one de Casteljau
/// subdivision at 1/2 per line: averages only).
void SplitStrided(const double* net, double* left, double* right, int du, int dv, int nv, bool alongU);

/**
 * The Newton start in a sub-patch, (a, b) in [0, 1]^2 of it: the zero of the
 * bilinear interpolant of h at its corners (the corner control points are h's
 * values there), by a few Newton steps on that interpolant from the centre;
 * the centre if they do not converge inside. Only the start: the crossing is
 * still Newton's on the face's net, under the same stopping rules, evaluated
 * on the exact map once accepted (FaceProblem::Newton, Crossing).
 */
void BilinearStart(const double* const net[2], int du, int nv, int n, double& a, double& b);

/// True if every v[k], k < n, is > @p margin, or every one is < -@p margin.
bool OneSide(const double* v, int n, double margin);

/**
 * True if a line separates the origin from the projected net (components
 * net[0][k], net[1][k], k < n) by more than @p margin: tried along the normals
 * of the edges of the corners' polygon (the control points at @p corners, in
 * cyclic order, @p count of them) and along the corners' mean. Any line
 * proves the exclusion (convex hull property); these catch the rays that
 * pass beside a sub-patch diagonally, which the axes of OneSide miss.
 */
bool SeparatedByCorners(const double* const net[2], int n, const int* corners, int count, double margin);

/// The range of @p v[0 .. n - 1].
Interval RangeOf(const double* v, int n);

/**
 * The extreme vectors of the cone of the 2D vectors (x[k], y[k]), k < n: the
 * most clockwise (@p lo) and most counter-clockwise (@p hi) about their sum.
 * False if some vector is not strictly within 90 degrees of the sum (the
 * angles relative to it are then not ordered by cross / dot).
 */
bool ConeOf(const double* x, const double* y, int n, double lo[2], double hi[2]);

/**
 * True if det(u, v) has one strict sign for every u in the cone of the
 * vectors (ux, uy) and v in the cone of (vx, vy): det is bilinear in the
 * cones' coefficients, so the four pairs of extreme vectors decide (each
 * beyond 1e-12 of |u| |v|: rounding).
 */
bool ConesSeparated(
  const double* ux, const double* uy, int nu, const double* vx, const double* vy, int nv);
}
}

#endif
