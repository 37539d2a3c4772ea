/**
 * @file hovCurvedFaceProblem.h
 * @brief The ray problem on one curved face (hovCurvedFaces.h): the face's
 * exact map and its net projected on the ray's frame, h(u, v) = (e1 . (x -
 * o), e2 . (x - o)), Newton on the net with the crossing evaluated on the
 * exact map, and the two searches that call it (tensor sub-patches of a
 * quadrilateral patch, sub-triangles of a triangular one). Internal
 * (namespace hov::detail).
 *
 * Thread safety: re-entrant (the workspace is the caller's).
 * @sa hovCurvedFaces.h, hovCurvedFaceNets.h, hovCurvedTriangleNets.h
 */
#ifndef hovCurvedFaceProblem_h
#define hovCurvedFaceProblem_h

#include "hovCurvedFaces.h"

#include <vector> // crossings

namespace hov
{
namespace detail
{
/// Newton may start anywhere in its sub-patch; a root this far outside it
/// (in u, v) belongs to a neighbour, which finds it itself.
constexpr double AcceptSlack = 1e-9;

inline double Dot(const double a[3], const double b[3])
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/// The ray's frame: unit e1, e2 perpendicular to d.
void RayFrame(const double d[3], double e1[3], double e2[3]);

/// The ray problem on one face: its exact map and the projection frame.
struct FaceProblem
{
  const LagrangeCellView* Cell;
  const CurvedFacePatch* Face;
  const double* O;
  const double* D;
  double E1[3], E2[3];
  double Extent;

  /// h(u, v), its Jacobian and the point (and, if given, x_u x x_v) on the exact map.
  void Evaluate(double u, double v, double h[2], double jac[4], double x[3], double pc[3],
    double* normal = nullptr) const;

  /// h(u, v) and its Jacobian from the face's Bernstein net (the cell's map on
  /// the face, to the net's rounding): a fraction of the cost of Evaluate
  /// (the face's control points instead of every node of the cell).
  void EvaluateNet(double u, double v, double h[2], double jac[4]) const;

  /// h = the ray frame's components of @p rel = x - o, and its Jacobian from x_u, x_v.
  void Project(const double rel[3], const double xu[3], const double xv[3], double h[2],
    double jac[4]) const;

  /// FaceCrossing::Side from the normal x_u x x_v at the crossing.
  int Side(const double n[3]) const;

  /// Newton on the net from (u, v), kept within @p box (u0, u1, v0, v1)
  /// widened by half its size; true if it converged (a step < 1e-15, or a
  /// residual at its rounding floor and a step < 1e-9).
  bool Newton(double& u, double& v, const double box[4]) const;

  /// The crossing at a converged (u, v): point, T, coordinates and Side on the exact map.
  void Crossing(double u, double v, FaceCrossing& out) const;
};

/**
 * The end of examining a sub-patch (tensor or triangular) once it is unique or
 * too small to split: @p accepted (Newton converged inside it): the crossing
 * at (u, v) is appended (Side 0 if @p c is Grazing), 1. Otherwise 2 (split)
 * unless @p small; then a contact at (cu, cv) is appended if the projected net
 * (n values per component) lies within GrazeTolerance x extent of the ray, 1.
 */
int FinishSubPatch(const FaceProblem& prob, bool accepted, bool small, double u, double v,
  double cu, double cv, const double* const net[2], int n, const FaceSearchSettings& settings,
  FaceCrossing& c, std::vector<FaceCrossing>& out);

/// Depth-first search of a triangular patch (CurvedFacePatch::Triangle): the
/// projected net (2 components of TriangleNetSize(n) values) at @p work, which
/// must hold TriangleWorkspaceSize(n) values. Appends crossings (unmerged) to
/// @p out; adds the sub-triangles examined to @p examined; false if
/// MaxPatches or the depth limit ran out.
bool SearchTriangle(const FaceProblem& prob, const FaceSearchSettings& settings, int faceIndex,
  double* work, std::vector<FaceCrossing>& out, int& examined);

/// Values of workspace SearchTriangle needs for degree @p n.
size_t TriangleWorkspaceSize(int n);
}
}

#endif
