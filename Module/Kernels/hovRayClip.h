/**
 * @file hovRayClip.h
 * @brief Exact clipping of rays against the four face planes of a linear
 * tetrahedron (HIAC section 5.1: the ray's entry and exit), written once over
 * the value type: one ray (double) or one ray per lane (a GCC/Clang vector of
 * doubles, several pixels per instruction in the CPU projector's tiles).
 *
 * The ray o + t d, 0 <= t <= tMax, is inside where n_k . x <= h_k for the four
 * planes k (outward normals, any length). Per plane: denominator n . d and
 * numerator h - n . o (dot products as (x x + y y) + z z, glm::dot's order);
 * a plane with n . d < 0 is entered at t = num / denom, one with n . d > 0
 * left there. tIn = max(0, entries), tOut = min(tMax, exits), each as
 * (a < b ? b : a) / (b < a ? b : a) in a fixed order: for every ray that hits
 * (tIn < tOut) the results are those of taking the planes one after the other
 * in any order, bit for bit (the max starts from +0, so a zero entry is +0).
 *
 * A ray parallel to a plane (n . d == 0) is not decided here: such a ray is
 * inside or outside that plane as a whole, and one lying in the plane needs a
 * tie rule (the symbolic perturbation of the CPU projector,
 * hovTileGeometry.h). ClipFourPlanes() sets @p parallel for it; its tIn/tOut
 * are then not the answer.
 *
 * Thread safety: pure functions.
 * @sa hovRayCell.h (general cells), hovTileGeometry.h, hovProjectorTileLanes.cxx
 */
#ifndef hovRayClip_h
#define hovRayClip_h

#include <algorithm> // std::min, std::max, std::swap

namespace hov
{
/**
 * [@p tIn, @p tOut] of the rays (origins @p ox, @p oy, @p oz, directions
 * @p dx, @p dy, @p dz, ends @p tMax) inside the planes (@p nx, @p ny, @p nz)[k]
 * . x <= @p h[k], k = 0..3 (see the file doc); ORs into @p parallel (per lane:
 * all bits set, or true) where a plane is parallel to the ray. T: double or a
 * vector of doubles; M: bool or the vector's comparison mask.
 */
template <typename T, typename M>
inline void ClipFourPlanes(const double* nx, const double* ny, const double* nz, const double* h,
  const T& ox, const T& oy, const T& oz, const T& dx, const T& dy, const T& dz, const T& tMax,
  T& tIn, T& tOut, M& parallel)
{
  const T zero = T{};
  const T big = zero + 1e300 * 1e300; // +inf: no constraint
  T enter[4], leave[4];
  for (int k = 0; k < 4; ++k)
  {
    const T denom = (nx[k] * dx + ny[k] * dy) + nz[k] * dz;
    const T num = h[k] - ((nx[k] * ox + ny[k] * oy) + nz[k] * oz);
    parallel |= denom == zero;
    const T t = num / denom;
    enter[k] = denom < zero ? t : -big;
    leave[k] = denom > zero ? t : big;
  }
  // std::max(a, b) is a < b ? b : a, std::min(a, b) is b < a ? b : a, per lane.
  const T in0 = zero < enter[0] ? enter[0] : zero;
  const T in12 = enter[1] < enter[2] ? enter[2] : enter[1];
  const T in012 = in0 < in12 ? in12 : in0;
  tIn = in012 < enter[3] ? enter[3] : in012;
  const T out0 = leave[0] < tMax ? leave[0] : tMax;
  const T out12 = leave[2] < leave[1] ? leave[2] : leave[1];
  const T out012 = out12 < out0 ? out12 : out0;
  tOut = leave[3] < out012 ? leave[3] : out012;
}

/**
 * The slab test: [t0, t1] = the part of [tMin, tMax] where o + t d lies in
 * the axis-aligned box (xmin, xmax, ymin, ymax, zmin, zmax); false if empty.
 * A zero direction component keeps the whole range if o is inside that slab.
 * Shared by the curved ray caster's BVH and the curved face search.
 */
inline bool ClipRayToBox(const double box[6], const double o[3], const double d[3], double tMin,
  double tMax, double& t0, double& t1)
{
  t0 = tMin;
  t1 = tMax;
  for (int k = 0; k < 3; ++k)
  {
    if (d[k] == 0.0)
    {
      if (o[k] < box[2 * k] || o[k] > box[2 * k + 1])
      {
        return false;
      }
      continue;
    }
    double a = (box[2 * k] - o[k]) / d[k], b = (box[2 * k + 1] - o[k]) / d[k];
    if (a > b)
    {
      std::swap(a, b);
    }
    t0 = std::max(t0, a);
    t1 = std::min(t1, b);
  }
  return t0 <= t1;
}
}

#endif
