/**
 * @file hovSplat.h
 * @brief Subpixel splatting (HIAC section 5.3): the contribution of a cell
 * whose projection covers too few pixels, spread over 3 x 3 pixels by the
 * biquadratic B-spline kernel.
 *
 * Pixel coordinates: pixel (i, j) has its centre at (x, y) = (i, j) (VTK
 * display coordinates minus 0.5). The projected cell centre (x, y) is given
 * in these coordinates.
 *
 * Kernel: K(u, v) = B(u) B(v), B the quadratic B-spline (the box filter
 * convolved twice with itself; Fourier transform sinc^3):
 *   B(d) = 3/4 - d^2 for |d| <= 1/2,  (|d| - 3/2)^2 / 2 for 1/2 <= |d| <= 3/2.
 * With c = floor(x + 1/2) the nearest pixel and f = x - c in [-1/2, 1/2), the
 * weights of pixels c-1, c, c+1 are
 *   w- = (1/2 - f)^2 / 2,  w0 = 3/4 - f^2,  w+ = (1/2 + f)^2 / 2,
 * a partition of unity (sum 1 for every f, exactly in real arithmetic; in
 * double within a few ulp), symmetric (f -> -f swaps w- and w+),
 * continuous across f = +-1/2 (the kernel is C1), with first moment
 * sum w (i - x) = 0 (the splat is centred on the cell) and second moment
 * 1/4 (the blur: the variance of B).
 *
 * Contribution (HIAC: "a delta function at the projection of the cell's
 * center of gravity, multiplied by the volume of the cell, the perspective
 * projection area shrinkage factor, and the color and opacity", convolved
 * with K). For a cell of volume V, mean extinction tau and colour c, the
 * integral over the image plane (in pixel units) of the optical depth along
 * the rays through the cell is
 *   M = V tau / a,    a = the cross-section area of one pixel's ray bundle
 * at the cell (PixelArea*): orthographic a = pixel width x height in world
 * units; perspective a = (z w_1)(z h_1) cos(theta), z the cell centre's depth
 * along the view axis, w_1 x h_1 the pixel at unit depth, theta the angle of
 * the ray through the centre to the view axis (then dV = a dz/cos(theta) per
 * pixel and path length dl = dz / cos(theta): M = integral tau dV / a to first
 * order in the cell size over z). Pixel (i, j) receives optical depth
 * D = w_ij M and path length l = w_ij V / a, and
 *   opacity   A = 1 - exp(-D)        (-expm1; A <= 1 whatever the cell),
 *   colour    Williams-Max  C = c A,
 *             Wilhelms-Van Gelder  C = g l (1 - e^-D)/D  (-> g l as D -> 0),
 * i.e. the exact integral of a uniform slab of depth D (HIAC's linear
 * "colour x opacity x weight" is the D -> 0 limit). Use the cell-average
 * extinction (V tau = integral of tau over the cell, exact) or, as HIAC, the
 * value at the centroid (second-order accurate in the cell size for smooth
 * fields).
 *
 * Approximation error relative to the exact projection filtered by the same
 * kernel (the ideal: integrate the cell's exact optical depth D(u, v) over
 * the image against K(u - i, v - j)), uniform cell:
 *  - total depth sum_ij D_ij = M: exact in orthographic projection (the
 *    weights sum to 1); in perspective the relative error is O((r/z)^2), r the
 *    cell radius: ~ (a^2/24) |laplacian(r/z^3)| / (r/z^3) ~ a^2/(2 z^2) for a
 *    cube of side a near the axis (measured 0.35 (a/z)^2 with order 2.0 at
 *    a/z = 0.2, 0.1, 0.05; TestSplat: PerspectiveDepthIntegral) -- for a
 *    cell smaller than a pixel a/z is below the pixel's angular size, so
 *    this is ~1e-7 or less;
 *  - per pixel, the kernel is sampled at the centre instead of averaged over
 *    the footprint: |w_ij - filtered| <= (1/2) max|K''| (second moment of the
 *    footprint) = O(s^2) for a footprint of side s pixels (measured order 2.0;
 *    worst pixel 1.25e-3 of the cell's total depth M for s = 0.1, 2.0e-2 for
 *    s = 0.4, i.e. ~0.125 s^2; TestSplat: OrthographicCubeAgainstExactFootprint);
 *  - opacity: exp(-w M) instead of the kernel-weighted exp(-D(u, v)): relative
 *    error O(D_peak) (saturation inside the footprint is lost), small for the
 *    optically thin cells splatting is meant for; HIAC's own caveat (a tiny
 *    opaque cell in front of a tiny bright one: per-pixel compositing of the
 *    blurred splats does not occlude exactly) applies.
 *
 * Thread safety: stateless, re-entrant.
 * @sa hovCompositing.h (the splat's pixels are composited with Over like any
 * segment)
 */
#ifndef hovSplat_h
#define hovSplat_h

#include "hovCompositing.h"
#include "hovConfig.h"
#include "hovSegmentIntegral.h" // EmissionModel

namespace hov
{
/**
 * Quadratic B-spline weights of the three pixels nearest to @p x (pixel-centre
 * coordinates): @p w[0..2] for pixels c-1, c, c+1; returns c = floor(x + 1/2).
 * Non-finite x: c = 0 and weights 0; |x| > 1e9 (off any image): c = +-1e9
 * and weights 0.
 */
HOV_EXPORT int QuadraticBSplineWeights(double x, double w[3]);

/// 3 x 3 weights of the biquadratic kernel: W[j][i] for pixel (X0 + i, Y0 + j).
struct SplatWeights
{
  int X0 = 0;
  int Y0 = 0;
  double W[3][3] = {};
};

/// Weights of the splat centred at (@p x, @p y): W[j][i] = wx[i] wy[j].
HOV_EXPORT SplatWeights BiquadraticSplatWeights(double x, double y);

/// A cell small enough to be splatted.
struct SplatCell
{
  double Volume = 0.0;                 ///< world units^3 (>= 0)
  double Tau = 0.0;                    ///< mean extinction per unit length (>= 0)
  double Color[3] = { 0.0, 0.0, 0.0 }; ///< chromaticity (WM) or emission per length (WVG)
};

/// Pixel cross-section in orthographic projection: pixel width x height in world units.
HOV_EXPORT double OrthographicPixelArea(double pixelWidthWorld, double pixelHeightWorld);

/**
 * Pixel cross-section in perspective projection at depth @p depth along the
 * view axis: (depth w1)(depth h1) cos(theta), @p w1 x @p h1 the pixel size on
 * the plane at unit depth (2 tan(viewAngle/2) / image height for square
 * pixels), @p cosAngle = cos(theta) of the ray through the cell centre.
 */
HOV_EXPORT double PerspectivePixelArea(double depth, double w1, double h1, double cosAngle);

/// The 3 x 3 premultiplied RGBA of a splat: Pixel[j][i] for pixel (X0 + i, Y0 + j).
struct SplatFootprint
{
  int X0 = 0;
  int Y0 = 0;
  RGBA Pixel[3][3];
};

/**
 * Splat of @p cell centred at (@p x, @p y) with pixel cross-section
 * @p pixelArea (> 0; see the file doc for the formulas). Invalid input
 * (negative or non-finite volume or area, negative or NaN extinction,
 * non-finite centre, V / a overflowing) gives a transparent splat; infinite
 * extinction is an opaque cell.
 */
HOV_EXPORT SplatFootprint SplatCellContribution(
  const SplatCell& cell, double pixelArea, double x, double y, EmissionModel emission);
}

#endif
