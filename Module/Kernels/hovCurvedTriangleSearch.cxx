// The search of a triangular face patch (SearchTriangle): see hovCurvedFaceProblem.h.
//
// The same decisions as the tensor search of hovCurvedFaces.cxx, on
// sub-triangles of the face's (u, v) triangle: exclusion by the convex hull of
// the projected net; uniqueness when det [h_s h_t] keeps its sign, h_s and h_t
// the derivatives along the sub-triangle's edges V0 V1 and V0 V2 (n times convex
// combinations of the net's differences b_{i,j+1,k} - b_{i+1,j,k} and
// b_{i,j,k+1} - b_{i+1,j,k}; boxes or cones); Newton on the net from the zero
// of the corners' linear interpolant; otherwise a split at the midpoint of the
// edge along which h varies most (the third edge's differences are
// b_{i,j,k+1} - b_{i,j+1,k}), down to MinSize or the margin.
#include "hovCurvedFaceNets.h"    // OneSide, RangeOf, Mul, ConesSeparated
#include "hovCurvedFaceProblem.h"
#include "hovCurvedTriangleNets.h"

#include <algorithm> // std::min, std::max
#include <cmath>     // std::abs, std::sqrt

namespace hov
{
namespace detail
{
namespace
{
/// Each split halves one edge: three times the tensor search's depth.
constexpr int MaxDepth = 3 * 23 + 2;

/// A sub-triangle: its vertices V0, V1, V2 in the face's (u, v).
struct SubTriangle
{
  double P[3][2];
};

/// True if (u, v) lies within @p slack (distance in (u, v)) of the sub-triangle.
bool InsideWithin(const SubTriangle& s, double u, double v, double slack)
{
  const double area = (s.P[1][0] - s.P[0][0]) * (s.P[2][1] - s.P[0][1]) -
    (s.P[1][1] - s.P[0][1]) * (s.P[2][0] - s.P[0][0]);
  const double sign = area >= 0.0 ? 1.0 : -1.0;
  for (int e = 0; e < 3; ++e)
  {
    const double* a = s.P[e];
    const double* b = s.P[(e + 1) % 3];
    const double ex = b[0] - a[0], ey = b[1] - a[1];
    const double len = std::sqrt(ex * ex + ey * ey);
    const double cross = ex * (v - a[1]) - ey * (u - a[0]);
    if (!(sign * cross >= -slack * len))
    {
      return false;
    }
  }
  return true;
}

/// The Newton start (s, t) in the sub-triangle's own coordinates (V0 + s (V1 -
/// V0) + t (V2 - V0)): the zero of the linear interpolant of h at its corners
/// (the corner control points), clamped into it; the centroid if it is far outside.
void LinearStart(const double* const net[2], int n, double& s, double& t)
{
  const int c0 = TriangleNetIndex(n, 0, 0), c1 = TriangleNetIndex(n, n, 0),
            c2 = TriangleNetIndex(n, 0, n);
  const double a00 = net[0][c1] - net[0][c0], a01 = net[0][c2] - net[0][c0];
  const double a10 = net[1][c1] - net[1][c0], a11 = net[1][c2] - net[1][c0];
  const double det = a00 * a11 - a01 * a10;
  s = t = 1.0 / 3.0;
  if (!(std::abs(det) > 0.0))
  {
    return;
  }
  const double x = -(a11 * net[0][c0] - a01 * net[1][c0]) / det;
  const double y = -(-a10 * net[0][c0] + a00 * net[1][c0]) / det;
  if (!(x >= -0.25 && y >= -0.25 && x + y <= 1.25))
  {
    return;
  }
  s = std::max(0.0, x);
  t = std::max(0.0, y);
  if (s + t > 1.0)
  {
    const double sum = s + t;
    s /= sum;
    t /= sum;
  }
}

/// Examine one sub-triangle: 0 excluded, 1 done (crossing appended if found), 2
/// split at the midpoint of the edge opposite vertex @p split.
int ExamineTriangle(const FaceProblem& prob, const double* netIn, const SubTriangle& s,
  const FaceSearchSettings& settings, int faceIndex, std::vector<FaceCrossing>& out, int& split)
{
  const int n = prob.Face->DegreeU, size = TriangleNetSize(n);
  const double* net[2] = { netIn, netIn + size };
  const double margin = settings.NetMargin * prob.Extent;
  const int corners[3] = { TriangleNetIndex(n, 0, 0), TriangleNetIndex(n, n, 0),
    TriangleNetIndex(n, 0, n) };
  if (OneSide(net[0], size, margin) || OneSide(net[1], size, margin) ||
    SeparatedByCorners(net, size, corners, 3, margin))
  {
    return 0;
  }
  // The difference vectors along V0 V1 (a) and V0 V2 (b), and the largest
  // component of those along V1 V2 (b - a).
  constexpr int MaxDiffs = TriangleNetSize(MaxFaceDegree - 1);
  double ax[MaxDiffs], ay[MaxDiffs], bx[MaxDiffs], by[MaxDiffs];
  double g12 = 0.0;
  int m = 0;
  for (int j = 0; j < n; ++j)
  {
    for (int k = 0; j + k < n; ++k, ++m)
    {
      const int pi = TriangleNetIndex(n, j, k), pj = TriangleNetIndex(n, j + 1, k),
                pk = TriangleNetIndex(n, j, k + 1);
      ax[m] = net[0][pj] - net[0][pi];
      ay[m] = net[1][pj] - net[1][pi];
      bx[m] = net[0][pk] - net[0][pi];
      by[m] = net[1][pk] - net[1][pi];
      g12 = std::max(g12, std::max(std::abs(bx[m] - ax[m]), std::abs(by[m] - ay[m])));
    }
  }
  const Interval a0 = RangeOf(ax, m), a1 = RangeOf(ay, m), b0 = RangeOf(bx, m), b1 = RangeOf(by, m);
  const Interval ad = Mul(a0, b1), bc = Mul(b0, a1);
  const bool unique =
    (ad.Lo - bc.Hi > 0.0) || (ad.Hi - bc.Lo < 0.0) || ConesSeparated(ax, ay, m, bx, by, m);
  auto largest = [](const Interval& p, const Interval& q) {
    return std::max(std::max(std::abs(p.Lo), std::abs(p.Hi)), std::max(std::abs(q.Lo), std::abs(q.Hi)));
  };
  // Variation along the edge opposite vertex 0 (V1 V2), 1 (V0 V2), 2 (V0 V1).
  const double g[3] = { g12, largest(b0, b1), largest(a0, a1) };
  split = -1;
  for (int e = 0; e < 3; ++e)
  {
    const double* p = s.P[e == 0 ? 1 : 0];
    const double* q = s.P[e == 2 ? 1 : 2];
    const double length = std::max(std::abs(p[0] - q[0]), std::abs(p[1] - q[1]));
    if (length > settings.MinSize && g[e] * n > margin && (split < 0 || g[e] > g[split]))
    {
      split = e;
    }
  }
  const bool small = split < 0;
  if (!unique && !small)
  {
    return 2;
  }
  FaceCrossing c;
  c.Face = faceIndex;
  c.Grazing = !unique;
  double st[2];
  LinearStart(net, n, st[0], st[1]);
  double u = s.P[0][0] + st[0] * (s.P[1][0] - s.P[0][0]) + st[1] * (s.P[2][0] - s.P[0][0]);
  double v = s.P[0][1] + st[0] * (s.P[1][1] - s.P[0][1]) + st[1] * (s.P[2][1] - s.P[0][1]);
  const double box[4] = { std::min({ s.P[0][0], s.P[1][0], s.P[2][0] }),
    std::max({ s.P[0][0], s.P[1][0], s.P[2][0] }), std::min({ s.P[0][1], s.P[1][1], s.P[2][1] }),
    std::max({ s.P[0][1], s.P[1][1], s.P[2][1] }) };
  const bool accepted = prob.Newton(u, v, box) && InsideWithin(s, u, v, AcceptSlack);
  return FinishSubPatch(prob, accepted, small, u, v, (s.P[0][0] + s.P[1][0] + s.P[2][0]) / 3.0,
    (s.P[0][1] + s.P[1][1] + s.P[2][1]) / 3.0, net, size, settings, c, out);
}

/// Depth first over sub-triangles; slot (depth, child) of the workspace holds
/// 2 N values (the two projected nets), a child's one split of its parent's.
struct TriangleSearch
{
  const FaceProblem& Prob;
  const FaceSearchSettings& Settings;
  int FaceIndex, N;
  double* Work;
  std::vector<FaceCrossing>& Out;
  int Examined = 0;
  bool Complete = true;

  void Visit(int depth, int child, const SubTriangle& s)
  {
    double* net = this->Work + static_cast<size_t>(2 * this->N) * (2 * depth + child);
    if (++this->Examined > this->Settings.MaxPatches)
    {
      this->Complete = false;
      return;
    }
    int m = -1;
    if (ExamineTriangle(this->Prob, net, s, this->Settings, this->FaceIndex, this->Out, m) != 2)
    {
      return;
    }
    if (depth + 1 > MaxDepth)
    {
      this->Complete = false;
      return;
    }
    double* first = this->Work + static_cast<size_t>(2 * this->N) * (2 * (depth + 1));
    double* second = first + 2 * this->N;
    const int n = this->Prob.Face->DegreeU;
    for (int c = 0; c < 2; ++c)
    {
      SplitTriangleNet(net + c * this->N, first + c * this->N, second + c * this->N, n, m);
    }
    const int a = m == 0 ? 1 : 0, b = m == 2 ? 1 : 2;
    const double mid[2] = { 0.5 * (s.P[a][0] + s.P[b][0]), 0.5 * (s.P[a][1] + s.P[b][1]) };
    SubTriangle l = s, r = s;
    l.P[b][0] = r.P[a][0] = mid[0];
    l.P[b][1] = r.P[a][1] = mid[1];
    this->Visit(depth + 1, 0, l);
    this->Visit(depth + 1, 1, r);
  }
};
}

size_t TriangleWorkspaceSize(int n)
{
  return static_cast<size_t>(2 * TriangleNetSize(n)) * 2 * (MaxDepth + 1);
}

bool SearchTriangle(const FaceProblem& prob, const FaceSearchSettings& settings, int faceIndex,
  double* work, std::vector<FaceCrossing>& out, int& examined)
{
  TriangleSearch search{ prob, settings, faceIndex, TriangleNetSize(prob.Face->DegreeU), work,
    out };
  search.Visit(0, 0, { { { 0.0, 0.0 }, { 1.0, 0.0 }, { 0.0, 1.0 } } });
  examined += search.Examined;
  return search.Complete;
}
}
}
