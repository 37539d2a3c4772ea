/**
 * @file hovSteinView.h
 * @brief Per-view data of vtkSteinVisibilitySort: projected points, each cell's
 *        visible part, screen extents and depth range.
 *
 * Depth z = (x - E).dop for perspective (E the eye, dop the unit direction of
 * projection), x.dop for parallel projection. Screen coordinates: perspective
 * ((x-E).right / z, (x-E).up / z), parallel (x.right, x.up). Perspective
 * views clip at the near plane z = Near (a tiny distance in front of the eye):
 * a cell straddling it is represented by its visible part (visible corners and
 * the intersections of its edges with the near plane); a cell entirely behind
 * it is hidden. Screen extents are rounded outward to float.
 *
 * Thread safety: Setup() runs in parallel internally; not re-entrant.
 */
#ifndef hovSteinView_h
#define hovSteinView_h

#include "hovGeometricPredicates.h" // Orient3d, Orient3dDirection
#include "hovSteinGeometry.h"        // Geometry

#include <cassert> // assert
#include <cstdint> // std::uint8_t
#include <vector>  // storage

class vtkCamera;

namespace hovStein
{
enum Status : std::uint8_t
{
  StatusVisible = 0, ///< entirely in front of the near plane
  StatusStraddle,    ///< partly behind the near plane (clipped)
  StatusHidden,      ///< entirely behind the near plane
  StatusBad          ///< not ordered (Geometry KindBad)
};

struct ViewFrame
{
  bool Parallel = false;
  double Eye[3] = { 0, 0, 0 }; ///< perspective only
  double Dop[3] = { 0, 0, 1 }, Right[3] = { 1, 0, 0 }, Up[3] = { 0, 1, 0 };
  double Near = 0;        ///< perspective only
  double Window[4] = {};  ///< sane screen region for tiling: xmin, xmax, ymin, ymax
  void FromCamera(vtkCamera* camera, double diagonal);
  /// The exact side of the eye with respect to the plane of the triangle
  /// (a, b, c): hov::Orient3d(a, b, c, Eye), or for parallel projection
  /// hov::Orient3dDirection(a, b, c, -Dop) (the direction towards the eye).
  int TriangleSide(const double* a, const double* b, const double* c) const
  {
    if (this->Parallel)
    {
      const double back[3] = { -this->Dop[0], -this->Dop[1], -this->Dop[2] };
      return hov::Orient3dDirection(a, b, c, back);
    }
    return hov::Orient3d(a, b, c, this->Eye);
  }
};

struct View
{
  ViewFrame Frame;
  std::vector<double> Proj;            ///< per point: screen x, y, depth z
  std::vector<std::uint8_t> Valid;     ///< per point: in front of the near plane
  std::vector<std::uint8_t> Status;    ///< per cell
  bool AllOrdered = false; ///< every cell visible or straddling (none hidden or bad)
  /// Depth range of the visible part and screen extents (xmin, xmax, ymin,
  /// ymax, outward): per cell after Setup(..., true); otherwise only for the
  /// straddling cells, by clip index (FrontOf(), RearOf(), BoxOf() read either).
  std::vector<double> Front, Rear;
  std::vector<float> Box;
  /// Per cell: index in Clipped, or -1; empty when no cell straddles (Clip()).
  std::vector<int> ClipIndex;
  std::vector<std::vector<double>> Clipped; ///< visible parts: x, y, z per point

  /// Index of cell @p c's visible part in Clipped, or -1 (not straddling).
  int Clip(vtkIdType c) const { return this->ClipIndex.empty() ? -1 : this->ClipIndex[c]; }
  /// Front, Rear and Box of cell @p c: of every cell after Setup(..., true),
  /// else only of straddling cells (Clip(c) >= 0).
  double FrontOf(vtkIdType c) const { return this->Front[this->ExtentSlot(c)]; }
  double RearOf(vtkIdType c) const { return this->Rear[this->ExtentSlot(c)]; }
  const float* BoxOf(vtkIdType c) const { return this->Box.data() + 4 * this->ExtentSlot(c); }

  /**
   * The view of @p camera. @p cellExtents: fill Front, Rear and Box for every
   * cell (the multitiled merge needs them; the adjacency graph reads them only
   * for the faces of cut cells, FrontOf() / RearOf() / BoxOf(), and otherwise
   * computes a depth range where it needs one, DepthRange()).
   */
  void Setup(const Geometry& g, vtkCamera* camera, bool cellExtents = true);
  /// Front and Rear of cell @p c (read, or computed as Setup computes them).
  void DepthRange(const Geometry& g, vtkIdType c, double& front, double& rear) const;
  double RearDepth(const Geometry& g, vtkIdType c) const
  {
    double front, rear;
    this->DepthRange(g, c, front, rear);
    return rear;
  }
  /// Screen points (x, y, z triples) of the visible part of a cell; returns their number.
  int VisiblePoints(const Geometry& g, vtkIdType c, double* xyz) const;
  /// Depth of a world point.
  double Depth(const double* x) const;

private:
  /// Status, depth range and screen extents of cells [begin, end) from the projected points.
  void CellExtents(const Geometry& g, vtkIdType begin, vtkIdType end);
  /// Screen coordinates, depths and near-plane validity of every point.
  void ProjectPoints(const Geometry& g);
  /// The visible parts, extents and depth ranges of the straddling cells.
  void ClipStraddling(const Geometry& g, bool cellExtents);
  /// Status only of cells [begin, end); @p allValid: every point is in front of the near plane.
  void CellStatus(const Geometry& g, vtkIdType begin, vtkIdType end, bool allValid);
  vtkIdType ExtentSlot(vtkIdType c) const
  {
    assert(this->HasCellExtents || this->Clip(c) >= 0); // kept only for cut cells
    return this->HasCellExtents ? c : this->ClipIndex[c];
  }
  bool HasCellExtents = false;
};
}

#endif
