// hovStein::FilteredPlane (Filters/hovSteinPlaneFilter.h), the precomputed
// filter of the Stein sort for the side of the eye with respect to a boundary
// face: whenever it decides, its answer must equal the exact predicates
// hov::Orient3d(a, b, c, eye) (perspective) and hov::Orient3dDirection(a, b,
// c, w) (parallel), and it must decide almost every generic case (else it
// would be useless). Cases (fixed seed): random triangles of sizes 1e-6 to
// 1e6 at 0, 1e3 and 1e6 sizes from the origin with eyes 1e-3 to 1e3 sizes
// from their planes (generic), at the absolute offsets 0, 1e3 and 1e6 with
// eyes 1e-9 to 1e-14 sizes from the planes or on them up to rounding (near:
// where the rounding errors of an unsafe filter exceed the distance), all up
// to 5 sizes from the triangle along the plane; slivers; eyes exactly on the
// plane (dyadic combinations of the corners, so the exact predicate
// gives 0) and one unit in the last place off it; eyes and directions with
// NaN and huge coordinates (the filter must then not decide).
#include "hovGeometricPredicates.h"
#include "hovSteinPlaneFilter.h"
#include "hovTestScenes.h"

#include <cmath>
#include <iostream>
#include <limits>
#include <random>
#include <string>

using namespace hovTest;

namespace
{
struct Tally
{
  long Cases = 0, Decided = 0, Wrong = 0;
  std::string FirstWrong;
};

/// Compares the filter with the exact predicate for one triangle and one eye or direction.
void Compare(Tally& tally, const double* a, const double* b, const double* c, const double* x,
  bool parallel)
{
  hovStein::FilteredPlane plane;
  plane.Set(a, b, c);
  const int filtered = plane.Side(x, parallel);
  const int exact = parallel ? hov::Orient3dDirection(a, b, c, x) : hov::Orient3d(a, b, c, x);
  ++tally.Cases;
  if (filtered == 0)
  {
    return;
  }
  ++tally.Decided;
  if (filtered != exact && tally.Wrong++ == 0)
  {
    tally.FirstWrong = ": first at a (" + std::to_string(a[0]) + ", " + std::to_string(a[1]) + ", " +
      std::to_string(a[2]) + ") x (" + std::to_string(x[0]) + ", " + std::to_string(x[1]) + ", " +
      std::to_string(x[2]) + ") parallel " + std::to_string(parallel) + ": filter " +
      std::to_string(filtered) + ", exact " + std::to_string(exact);
  }
}

/// A random triangle at @p offset and @p scale, and a point at @p distance (in
/// triangle sizes) from its plane, or a direction (parallel).
void Generic(Tally& tally, std::mt19937_64& rng, double offset, double scale, double distance,
  bool parallel, bool sliver)
{
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  double a[3], b[3], c[3], x[3];
  for (int k = 0; k < 3; ++k)
  {
    a[k] = offset + scale * u(rng);
    b[k] = offset + scale * u(rng);
    c[k] = sliver ? 0.5 * (a[k] + b[k]) + 1e-7 * scale * u(rng) : offset + scale * u(rng);
  }
  const double n[3] = { (b[1] - a[1]) * (c[2] - a[2]) - (b[2] - a[2]) * (c[1] - a[1]),
    (b[2] - a[2]) * (c[0] - a[0]) - (b[0] - a[0]) * (c[2] - a[2]),
    (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]) };
  const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  const double s = u(rng) < 0 ? -1.0 : 1.0;
  const double alpha = 5 * u(rng), beta = 5 * u(rng); // along the plane
  for (int k = 0; k < 3; ++k)
  {
    const double inPlane = alpha * (b[k] - a[k]) + beta * (c[k] - a[k]);
    x[k] = parallel ? inPlane / scale + s * distance * n[k] / len
                    : a[k] + inPlane + s * distance * scale * n[k] / len;
  }
  Compare(tally, a, b, c, x, parallel);
}
}

int TestSteinPlaneFilter(int, char*[])
{
  Checker ck;
  std::mt19937_64 rng(20261122);
  for (const bool parallel : { false, true })
  {
    Tally generic, near;
    for (const double offset : { 0.0, 1e3, 1e6 })
    {
      for (const double scale : { 1e-6, 1e-2, 1.0, 1e3, 1e6 })
      {
        for (int i = 0; i < 2000; ++i)
        {
          // Generic: offsets of 0, 1e3 and 1e6 triangle sizes (meshes far from the origin).
          Generic(generic, rng, offset * scale, scale, std::pow(10.0, -3 + i % 7), parallel, false);
          const double distance = i % 7 == 6 ? 0.0 : std::pow(10.0, -9 - (i % 7)); // 0: rounded
          Generic(near, rng, offset, scale, distance, parallel, i % 2 == 0);
        }
      }
    }
    const std::string mode = parallel ? "parallel" : "perspective";
    std::cout << mode << ": generic " << generic.Decided << " of " << generic.Cases
              << " decided, near the plane or slivers " << near.Decided << " of " << near.Cases
              << "\n";
    ck.Check(generic.Wrong == 0 && near.Wrong == 0,
      mode + ": every decided side equals the exact predicate" +
        (generic.FirstWrong.empty() ? near.FirstWrong : generic.FirstWrong));
    ck.Check(generic.Decided >= 0.99 * generic.Cases,
      mode + ": the filter decides at least 99% of generic cases");
    ck.Check(near.Decided < near.Cases, mode + ": near the plane some cases are left to the exact predicate");
  }
  // Exactly on the plane (dyadic combinations: the exact predicate gives 0),
  // then one unit in the last place off it.
  Tally on;
  std::mt19937_64 grid(7);
  std::uniform_int_distribution<int> small(-64, 64);
  for (int i = 0; i < 5000; ++i)
  {
    double a[3], b[3], c[3], x[3];
    for (int k = 0; k < 3; ++k)
    {
      a[k] = small(grid) * 0.125 + 1024;
      b[k] = small(grid) * 0.125 + 1024;
      c[k] = small(grid) * 0.125 + 1024;
      x[k] = a[k] + 0.25 * (b[k] - a[k]) + 0.5 * (c[k] - a[k]);
    }
    Compare(on, a, b, c, x, false);
    x[i % 3] = std::nextafter(x[i % 3], i % 2 ? 2048.0 : 0.0);
    Compare(on, a, b, c, x, false);
  }
  std::cout << "on the plane and 1 ulp off: " << on.Decided << " of " << on.Cases << " decided\n";
  ck.Check(on.Wrong == 0, "on and next to the plane: every decided side is exact" + on.FirstWrong);
  // NaN and overflowing eyes: never decided.
  const double a[3] = { 0, 0, 0 }, b[3] = { 1, 0, 0 }, c[3] = { 0, 1, 0 };
  hovStein::FilteredPlane plane;
  plane.Set(a, b, c);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double bad[3][3] = { { nan, 0, 1 }, { 0, 0, nan }, { 1e308, 1e308, 1e308 } };
  bool none = true;
  for (const auto& x : bad)
  {
    none = none && plane.Side(x, false) == 0 && plane.Side(x, true) == 0;
  }
  ck.Check(none, "NaN or overflowing eyes and directions are left to the exact predicate");
  const double above[3] = { 0.2, 0.2, 1 };
  ck.Check(plane.Side(above, false) == hov::Orient3d(a, b, c, above) && plane.Side(above, false) != 0,
    "a plain case is decided like Orient3d");
  return ck.Result();
}
