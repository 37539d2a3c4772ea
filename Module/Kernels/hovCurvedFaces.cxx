// Faces of curved Lagrange cells and ray-face crossings: see hovCurvedFaces.h.
#include "hovCurvedFaces.h"

#include "hovCurvedFaceNets.h" // exclusion, uniqueness, subdivision of the nets
#include "hovCurvedFaceProblem.h" // the ray problem, Newton, the triangle search
#include "hovCurvedTriangleNets.h" // TriangleNetSize
#include "hovRayClip.h"   // ClipRayToBox

#include <algorithm> // std::min, std::max, std::swap
#include <cmath>     // std::abs, std::sqrt

namespace hov
{
using namespace detail;
namespace
{
/// Crossings of one face closer than this in (u, v) are one crossing.
constexpr double MergeDistance = 1e-9;

/// Sub-patch of a face: the two projected nets restricted to [U0,U1] x [V0,V1].
struct SubPatch
{
  double U0, U1, V0, V1;
};

/// True if the crossings @p a and @p b are the same point (see MergeDistance).
bool SameCrossing(const FaceCrossing& a, const FaceCrossing& b, double minSize)
{
  double dist = 0.0;
  for (int k = 0; k < 3; ++k)
  {
    dist = std::max(dist, std::abs(a.PC[k] - b.PC[k]));
  }
  return dist <= MergeDistance || ((a.Grazing || b.Grazing) && dist <= 64.0 * minSize);
}

/// Examine one sub-patch: 0 excluded, 1 done (crossing appended if found), 2 split.
/// @p net: the sub-patch's two projected nets (component c at net + c * n).
int Examine(const FaceProblem& prob, const double* netIn, const SubPatch& s,
  const FaceSearchSettings& settings, int faceIndex, std::vector<FaceCrossing>& out, bool& splitU)
{
  const CurvedFacePatch& face = *prob.Face;
  const int du = face.DegreeU, dv = face.DegreeV, nv = dv + 1, n = (du + 1) * nv;
  const double* net[2] = { netIn, netIn + n };
  const double margin = settings.NetMargin * prob.Extent;
  // Exclusion first (most sub-patches the search meets are excluded): the
  // convex hull of the net misses the ray if one component's control values
  // all lie beyond the margin on one side (the scan stops at the first value
  // that is not), then the derivative nets.
  const int corners[4] = { 0, du * nv, n - 1, nv - 1 };
  if (OneSide(net[0], n, margin) || OneSide(net[1], n, margin) ||
    SeparatedByCorners(net, n, corners, 4, margin))
  {
    return 0;
  }
  Interval deriv[2][2];
  // The difference vectors of the projected net along u and along v: h_u and
  // h_v are (degree x) convex combinations of them.
  constexpr int MaxDiffs = MaxFaceDegree * (MaxFaceDegree + 1);
  double ux[MaxDiffs], uy[MaxDiffs], vx[MaxDiffs], vy[MaxDiffs];
  int nu = 0, nvd = 0;
  for (int k = 0; k < du * nv; ++k, ++nu)
  {
    ux[nu] = net[0][k + nv] - net[0][k];
    uy[nu] = net[1][k + nv] - net[1][k];
  }
  for (int a = 0; a <= du; ++a)
  {
    for (int b = 0; b < dv; ++b, ++nvd)
    {
      const int k = a * nv + b;
      vx[nvd] = net[0][k + 1] - net[0][k];
      vy[nvd] = net[1][k + 1] - net[1][k];
    }
  }
  deriv[0][0] = RangeOf(ux, nu);
  deriv[1][0] = RangeOf(uy, nu);
  deriv[0][1] = RangeOf(vx, nvd);
  deriv[1][1] = RangeOf(vy, nvd);
  const Interval ad = Mul(deriv[0][0], deriv[1][1]), bc = Mul(deriv[0][1], deriv[1][0]);
  // det [h_u h_v] keeps its sign over the sub-patch: by the boxes of the
  // difference vectors, or else by their cones (tighter where the vectors
  // turn little but vary in length).
  const bool unique = (ad.Lo - bc.Hi > 0.0) || (ad.Hi - bc.Lo < 0.0) ||
    ConesSeparated(ux, uy, nu, vx, vy, nvd);
  // Split where h varies most (a face parallel to the ray varies along one
  // direction only: splitting the other would multiply sub-patches for
  // nothing); a direction already at MinSize, or along which h varies by
  // less than the exclusion margin, is not split.
  const double gu = std::max(std::max(std::abs(deriv[0][0].Lo), std::abs(deriv[0][0].Hi)),
    std::max(std::abs(deriv[1][0].Lo), std::abs(deriv[1][0].Hi)));
  const double gv = std::max(std::max(std::abs(deriv[0][1].Lo), std::abs(deriv[0][1].Hi)),
    std::max(std::abs(deriv[1][1].Lo), std::abs(deriv[1][1].Hi)));
  const bool canU = s.U1 - s.U0 > settings.MinSize && gu * face.DegreeU > margin;
  const bool canV = s.V1 - s.V0 > settings.MinSize && gv * face.DegreeV > margin;
  splitU = canU && (!canV || gu >= gv);
  const bool small = !canU && !canV;
  if (!unique && !small)
  {
    return 2;
  }
  FaceCrossing c;
  c.Face = faceIndex;
  c.Grazing = !unique;
  double a = 0.5, b = 0.5;
  BilinearStart(net, du, nv, n, a, b);
  double u = s.U0 + a * (s.U1 - s.U0), v = s.V0 + b * (s.V1 - s.V0);
  const double box[4] = { s.U0, s.U1, s.V0, s.V1 };
  const bool accepted = prob.Newton(u, v, box) && u >= s.U0 - AcceptSlack &&
    u <= s.U1 + AcceptSlack && v >= s.V0 - AcceptSlack && v <= s.V1 + AcceptSlack;
  return FinishSubPatch(prob, accepted, small, u, v, 0.5 * (s.U0 + s.U1), 0.5 * (s.V0 + s.V1),
    net, n, settings, c, out);
}
}

namespace
{
/// True if the line o + t d (any t) meets the box (xmin, xmax, ...).
bool LineMeetsBox(const double box[6], const double o[3], const double d[3])
{
  double t0, t1;
  return ClipRayToBox(box, o, d, -1e300, 1e300, t0, t1);
}

/// The depth-first search of one face (see FaceRayCrossings): the sub-patch
/// nets in a workspace where slot (depth, child) holds 2 n values; a child's
/// net is one de Casteljau split of its parent's.
struct FaceSearch
{
  const FaceProblem& Prob;
  const FaceSearchSettings& Settings;
  int FaceIndex, N, NV;
  double* Work;
  std::vector<FaceCrossing>& Out;
  int Examined = 0;
  bool Complete = true;
  static constexpr int MaxDepth = 2 * 23 + 2;

  void Visit(int depth, int child, const SubPatch& s)
  {
    double* net = this->Work + static_cast<size_t>(2 * this->N) * (2 * depth + child);
    if (++this->Examined > this->Settings.MaxPatches)
    {
      this->Complete = false;
      return;
    }
    bool alongU = true;
    if (Examine(this->Prob, net, s, this->Settings, this->FaceIndex, this->Out, alongU) != 2)
    {
      return;
    }
    if (depth + 1 > MaxDepth)
    {
      this->Complete = false;
      return;
    }
    const CurvedFacePatch& face = *this->Prob.Face;
    double* left = this->Work + static_cast<size_t>(2 * this->N) * (2 * (depth + 1));
    double* right = left + 2 * this->N;
    for (int c = 0; c < 2; ++c)
    {
      SplitStrided(net + c * this->N, left + c * this->N, right + c * this->N, face.DegreeU,
        face.DegreeV, this->NV, alongU);
    }
    if (alongU)
    {
      const double m = 0.5 * (s.U0 + s.U1);
      this->Visit(depth + 1, 0, { s.U0, m, s.V0, s.V1 });
      this->Visit(depth + 1, 1, { m, s.U1, s.V0, s.V1 });
    }
    else
    {
      const double m = 0.5 * (s.V0 + s.V1);
      this->Visit(depth + 1, 0, { s.U0, s.U1, s.V0, m });
      this->Visit(depth + 1, 1, { s.U0, s.U1, m, s.V1 });
    }
  }
};
}

int FaceRayCrossings(const LagrangeCellView& cell, const CurvedCellFaces& faces, int f,
  const double origin[3], const double direction[3], std::vector<FaceCrossing>& out,
  const FaceSearchSettings& settings, FaceSearchStatus* status)
{
  if (f < 0 || f >= static_cast<int>(faces.Faces.size()))
  {
    return 0;
  }
  const CurvedFacePatch& face = faces.Faces[f];
  // The net's box (widened by the margin) contains the patch: a line missing
  // it has no crossing (most patches of a cell a ray meets).
  if (!LineMeetsBox(face.Box, origin, direction))
  {
    if (status)
    {
      ++status->Patches;
    }
    return 0;
  }
  FaceProblem prob{ &cell, &face, origin, direction, {}, {}, faces.Extent };
  RayFrame(direction, prob.E1, prob.E2);
  const int n = face.Triangle ? TriangleNetSize(face.DegreeU) : (face.DegreeU + 1) * (face.DegreeV + 1);
  // Workspace: one per thread, grown once (no allocation per call).
  thread_local std::vector<double> work;
  const size_t need = face.Triangle ? TriangleWorkspaceSize(face.DegreeU)
                                    : static_cast<size_t>(2 * n) * 2 * (FaceSearch::MaxDepth + 1);
  if (work.size() < need)
  {
    work.resize(need);
  }
  for (int k = 0; k < n; ++k)
  {
    const double* x = &face.Net[3 * k];
    const double rel[3] = { x[0] - origin[0], x[1] - origin[1], x[2] - origin[2] };
    work[k] = Dot(prob.E1, rel);
    work[n + k] = Dot(prob.E2, rel);
  }
  const size_t first = out.size();
  int examined = 0;
  bool complete = true;
  if (face.Triangle)
  {
    complete = SearchTriangle(prob, settings, f, work.data(), out, examined);
  }
  else
  {
    FaceSearch search{ prob, settings, f, n, face.DegreeV + 1, work.data(), out };
    search.Visit(0, 0, { 0.0, 1.0, 0.0, 1.0 });
    examined = search.Examined;
    complete = search.Complete;
  }
  // Merge repeats (a root on a split line is found from both sides).
  size_t kept = first;
  for (size_t i = first; i < out.size(); ++i)
  {
    bool repeat = false;
    for (size_t j = first; j < kept && !repeat; ++j)
    {
      repeat = SameCrossing(out[i], out[j], settings.MinSize);
    }
    if (!repeat)
    {
      out[kept++] = out[i];
    }
  }
  out.resize(kept);
  if (status)
  {
    status->Patches += examined;
    status->Complete = status->Complete && complete;
  }
  return static_cast<int>(kept - first);
}
}
