/**
 * @file hovCurvedTriangleNets.h
 * @brief Triangular Bernstein nets of the curved face search
 * (hovCurvedFaces.h): a polynomial of total degree n on a triangle
 * V0 V1 V2 with barycentric coordinates (l0, l1, l2) is
 *   x = sum_{i + j + k = n} n! / (i! j! k!) l0^i l1^j l2^k b_{ijk},
 * its control point b_{ijk} stored at TriangleNetIndex(n, j, k) (i is implied).
 * On a face, V0 V1 V2 are (u, v) = (0, 0), (1, 0), (0, 1): l1 = u, l2 = v.
 * Internal (namespace hov::detail).
 *
 * Thread safety: pure functions; the conversion tables are built once, on
 * first use (a function-local static).
 * @sa hovCurvedFaceNets.h (the tensor nets of quadrilateral faces)
 */
#ifndef hovCurvedTriangleNets_h
#define hovCurvedTriangleNets_h

namespace hov
{
namespace detail
{
/// Number of control points of a degree-@p n triangular net.
constexpr int TriangleNetSize(int n)
{
  return (n + 1) * (n + 2) / 2;
}

/// Storage index of b_{ijk}, i = n - j - k (rows of constant j, k along each row).
constexpr int TriangleNetIndex(int n, int j, int k)
{
  return j * (n + 1) - j * (j - 1) / 2 + k;
}

/**
 * The Bernstein coefficients of the degree-@p n polynomial (1 <= n <= 10)
 * whose values at the equispaced points (u, v) = (j / n, k / n) are
 * values[stride * TriangleNetIndex(n, j, k) + c], c < @p dim, into
 * out[dim * TriangleNetIndex(n, j, k) + c] (out and values distinct). The
 * conversion is the triangle factor's inverse collocation matrix of
 * hovBernsteinFactors.h (the field hull's), computed once per degree. False
 * for n outside [1, 10].
 */
bool EquispacedTriangleBernstein(int n, const double* values, int stride, int dim, double* out);

/**
 * x(u, v), dx/du and dx/dv of a degree-@p n net of points (b_{ijk} at
 * net[3 * TriangleNetIndex(n, j, k)]), l0 = 1 - u - v, l1 = u, l2 = v (any u,
 * v: the polynomial, not only the triangle).
 */
void EvaluateTriangleNet(
  const double* net, int n, double u, double v, double x[3], double xu[3], double xv[3]);

/**
 * Split a degree-@p n net (one value per control point) at the midpoint M of
 * the edge opposite vertex @p m (0, 1 or 2): the edge's vertices are a < b;
 * @p first is the net of the triangle with b replaced by M, @p second the one
 * with a replaced by M (each keeps the parent's vertex slots, so its
 * barycentric indices mean the same). One univariate de Casteljau split at 1/2
 * per row of constant index m (M lies on the edge, where l_m = 0): averages only.
 */
void SplitTriangleNet(const double* net, double* first, double* second, int n, int m);
}
}

#endif
