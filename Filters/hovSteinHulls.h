/**
 * @file hovSteinHulls.h
 * @brief Convex polygons of vtkSteinVisibilitySort's Obstructs() test: the
 *        convex hull of a cell's screen projection, containment, clipping and
 *        area, and a per-view cache of the hulls of the cells to be tested.
 *
 * Hull2d is Andrew's monotone chain with the exact Orient2d, so a cell's hull
 * does not depend on who computes it: the cache (HullCache) gives the very
 * hull the test would compute, once per cell and view instead of once per
 * tested pair (on the bracket a boundary cell takes part in about 3 pairs,
 * and most pairs need the hulls of both cells).
 *
 * Thread safety: the functions are pure; HullCache::Build runs in parallel
 * internally, the built cache is read-only.
 */
#ifndef hovSteinHulls_h
#define hovSteinHulls_h

#include "hovSteinView.h" // Geometry, View

#include <vector> // storage

namespace hovStein
{
/// Most points of a cell's visible part: a clipped hexahedron's 8 corners + 12 crossings.
constexpr int MaxVisiblePoints = 32;
/// Room a hull under construction needs (the monotone chain's two passes).
constexpr int HullCapacity = 2 * MaxVisiblePoints + 2;

/// Convex hull (counterclockwise, no collinear points) of the 2D points x, y
/// of the @p n triples @p xyz into @p hull (HullCapacity points); returns its size.
int Hull2d(const double* xyz, int n, double hull[][2]);
/// Signed area of a polygon.
double Area(const double poly[][2], int n);
/// Inside or on the boundary of a counterclockwise convex polygon (exact).
bool InHull(const double hull[][2], int n, const double* x);
/// Sutherland-Hodgman: @p poly (room for HullCapacity points) clipped by the
/// convex counterclockwise @p clip; returns the new size.
int ClipPolygon(double poly[][2], int n, const double clip[][2], int m);

/// The hulls of chosen cells for one view.
class HullCache
{
public:
  /// Computes the hulls of @p cells (each once; in parallel).
  void Build(const Geometry& g, const View& v, const std::vector<vtkIdType>& cells);
  /// The hull of cell @p c (nullptr if not built) with its size and area.
  const double (*Find(vtkIdType c, int& size, double& area) const)[2];

private:
  /// Where a hull is, its size and area: one record (one cache miss per lookup).
  struct Entry
  {
    vtkIdType Start; ///< first point in Points
    double Area;
    int Size;
  };
  std::vector<int> Slot;       ///< per cell: index in Entries, or -1
  std::vector<Entry> Entries;  ///< per hull
  std::vector<double> Points;  ///< x, y per hull point
};
}

#endif
