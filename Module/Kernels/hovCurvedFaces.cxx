// Faces of curved Lagrange cells and ray-face crossings: see hovCurvedFaces.h.
#include "hovCurvedFaces.h"

#include "hovBernstein.h"       // the net evaluation
#include "hovCurvedFaceNets.h" // exclusion, uniqueness, subdivision of the nets
#include "hovRayClip.h"   // ClipRayToBox

#include <algorithm> // std::min, std::max, std::swap
#include <cmath>     // std::abs, std::sqrt
#include <limits>    // epsilon

namespace hov
{
using namespace detail;
namespace
{
constexpr double Eps = std::numeric_limits<double>::epsilon();
constexpr int NetSize = (MaxFaceDegree + 1) * (MaxFaceDegree + 1);
/// Newton may start anywhere in its sub-patch; a root this far outside it
/// (in u, v) belongs to a neighbour, which finds it itself.
constexpr double AcceptSlack = 1e-9;
/// Crossings of one face closer than this in (u, v) are one crossing.
constexpr double MergeDistance = 1e-9;



/// The ray's frame: unit e1, e2 perpendicular to d.
void RayFrame(const double d[3], double e1[3], double e2[3])
{
  const double len = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
  const double n[3] = { d[0] / len, d[1] / len, d[2] / len };
  // e1 perpendicular to n, built from the axis of n's smallest component.
  int k = 0;
  for (int i = 1; i < 3; ++i)
  {
    k = std::abs(n[i]) < std::abs(n[k]) ? i : k;
  }
  double a[3] = { 0.0, 0.0, 0.0 };
  a[k] = 1.0;
  e1[0] = a[1] * n[2] - a[2] * n[1];
  e1[1] = a[2] * n[0] - a[0] * n[2];
  e1[2] = a[0] * n[1] - a[1] * n[0];
  const double l1 = std::sqrt(e1[0] * e1[0] + e1[1] * e1[1] + e1[2] * e1[2]);
  for (int i = 0; i < 3; ++i)
  {
    e1[i] /= l1;
  }
  e2[0] = n[1] * e1[2] - n[2] * e1[1];
  e2[1] = n[2] * e1[0] - n[0] * e1[2];
  e2[2] = n[0] * e1[1] - n[1] * e1[0];
}

double Dot(const double a[3], const double b[3])
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/// The ray problem on one face: its exact map and the projection frame.
struct FaceProblem
{
  const LagrangeCellView* Cell;
  const CurvedFacePatch* Face;
  const double* O;
  const double* D;
  double E1[3], E2[3];
  double Extent;

  /// h(u, v), its Jacobian and the point (and, if given, x_u x x_v).
  void Evaluate(double u, double v, double h[2], double jac[4], double x[3], double pc[3],
    double* normal = nullptr) const
  {
    double pu[3], pv[3], J[9];
    FaceParametricPoint(*this->Face, u, v, pc, pu, pv);
    EvaluateLagrangePosition(*this->Cell, pc, x, J);
    double xu[3], xv[3], rel[3];
    for (int i = 0; i < 3; ++i)
    {
      xu[i] = J[3 * i] * pu[0] + J[3 * i + 1] * pu[1] + J[3 * i + 2] * pu[2];
      xv[i] = J[3 * i] * pv[0] + J[3 * i + 1] * pv[1] + J[3 * i + 2] * pv[2];
      rel[i] = x[i] - this->O[i];
    }
    this->Project(rel, xu, xv, h, jac);
    if (normal)
    {
      normal[0] = xu[1] * xv[2] - xu[2] * xv[1];
      normal[1] = xu[2] * xv[0] - xu[0] * xv[2];
      normal[2] = xu[0] * xv[1] - xu[1] * xv[0];
    }
  }

  /// h(u, v) and its Jacobian from the face's Bernstein net (the cell's map on
  /// the face, to the net's rounding): a fraction of the cost of Evaluate
  /// (a (du + 1)(dv + 1) net instead of every node of the cell).
  void EvaluateNet(double u, double v, double h[2], double jac[4]) const
  {
    const CurvedFacePatch& f = *this->Face;
    const int du = f.DegreeU, dv = f.DegreeV, nv = dv + 1;
    double bu[MaxFaceDegree + 1], dbu[MaxFaceDegree + 1], bv[MaxFaceDegree + 1],
      dbv[MaxFaceDegree + 1];
    BernsteinBasis(du, u, bu, dbu);
    BernsteinBasis(dv, v, bv, dbv);
    double x[3] = { 0.0, 0.0, 0.0 }, xu[3] = { 0.0, 0.0, 0.0 }, xv[3] = { 0.0, 0.0, 0.0 };
    const double* net = f.Net.data();
    for (int a = 0; a <= du; ++a)
    {
      double r[3] = { 0.0, 0.0, 0.0 }, rv[3] = { 0.0, 0.0, 0.0 };
      for (int b = 0; b <= dv; ++b)
      {
        const double* q = net + 3 * (nv * a + b);
        for (int i = 0; i < 3; ++i)
        {
          r[i] += bv[b] * q[i];
          rv[i] += dbv[b] * q[i];
        }
      }
      for (int i = 0; i < 3; ++i)
      {
        x[i] += bu[a] * r[i];
        xu[i] += dbu[a] * r[i];
        xv[i] += bu[a] * rv[i];
      }
    }
    const double rel[3] = { x[0] - this->O[0], x[1] - this->O[1], x[2] - this->O[2] };
    this->Project(rel, xu, xv, h, jac);
  }

  /// h = the ray frame's components of @p rel = x - o, and its Jacobian from x_u, x_v.
  void Project(const double rel[3], const double xu[3], const double xv[3], double h[2],
    double jac[4]) const
  {
    h[0] = Dot(this->E1, rel);
    h[1] = Dot(this->E2, rel);
    jac[0] = Dot(this->E1, xu);
    jac[1] = Dot(this->E1, xv);
    jac[2] = Dot(this->E2, xu);
    jac[3] = Dot(this->E2, xv);
  }

  /// The Bernstein basis of degree @p n at @p t and its derivatives.
  static void BernsteinBasis(int n, double t, double* b, double* db)
  {
    const double s = 1.0 - t;
    b[0] = 1.0;
    for (int k = 1; k <= n; ++k)
    {
      if (k == n)
      {
        // Derivatives from the degree n - 1 values: n (B_{i-1} - B_i).
        for (int i = 0; i <= n; ++i)
        {
          db[i] = n * ((i > 0 ? b[i - 1] : 0.0) - (i < n ? b[i] : 0.0));
        }
      }
      b[k] = t * b[k - 1];
      for (int i = k - 1; i > 0; --i)
      {
        b[i] = s * b[i] + t * b[i - 1];
      }
      b[0] *= s;
    }
    if (n == 0)
    {
      db[0] = 0.0;
    }
  }

  /// FaceCrossing::Side from the normal x_u x x_v at the crossing.
  int Side(const double n[3]) const
  {
    const double dn = Dot(this->D, n);
    const double scale = std::sqrt(Dot(this->D, this->D) * Dot(n, n));
    if (this->Face->Orientation == 0 || !(std::abs(dn) > SideTolerance * scale))
    {
      return 0;
    }
    return (dn > 0.0) == (this->Face->Orientation > 0) ? 1 : -1;
  }

  /// Newton from (u, v) kept within the box widened by half its size.
  bool Newton(double& u, double& v, const double box[4], FaceCrossing& out) const
  {
    const double wu = 0.5 * (box[1] - box[0]), wv = 0.5 * (box[3] - box[2]);
    double h[2], jac[4], x[3], pc[3];
    for (int iter = 0; iter < 40; ++iter)
    {
      // The iterations on the net; the crossing itself on the cell's map.
      this->EvaluateNet(u, v, h, jac);
      const double det = jac[0] * jac[3] - jac[1] * jac[2];
      if (!(std::abs(det) > 0.0))
      {
        return false;
      }
      const double du = -(jac[3] * h[0] - jac[1] * h[1]) / det;
      const double dv = -(-jac[2] * h[0] + jac[0] * h[1]) / det;
      u += du;
      v += dv;
      if (!(u >= box[0] - wu && u <= box[1] + wu && v >= box[2] - wv && v <= box[3] + wv))
      {
        return false;
      }
      const double step = std::max(std::abs(du), std::abs(dv));
      const bool floor = std::max(std::abs(h[0]), std::abs(h[1])) <= 16.0 * Eps * this->Extent;
      if (step <= 1e-15 || (floor && step <= 1e-9))
      {
        double normal[3];
        this->Evaluate(u, v, h, jac, x, pc, normal);
        out.Side = this->Side(normal);
        out.U = u;
        out.V = v;
        std::copy(pc, pc + 3, out.PC);
        double rel[3] = { x[0] - this->O[0], x[1] - this->O[1], x[2] - this->O[2] };
        out.T = Dot(this->D, rel) / Dot(this->D, this->D);
        return true;
      }
    }
    return false;
  }
};
}

namespace
{
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
  for (int c = 0; c < 2; ++c)
  {
    if (OneSide(net[c], n, margin))
    {
      return 0;
    }
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
  // turn little but vary in length, as on the thirds of a curved triangle).
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
  if (prob.Newton(u, v, box, c) && u >= s.U0 - AcceptSlack && u <= s.U1 + AcceptSlack &&
    v >= s.V0 - AcceptSlack && v <= s.V1 + AcceptSlack)
  {
    c.Side = c.Grazing ? 0 : c.Side;
    out.push_back(c);
    return 1;
  }
  if (!small)
  {
    return 2;
  }
  // Resolution limit: a contact if the sub-patch's image hugs the ray.
  const Interval range[2] = { RangeOf(net[0], n), RangeOf(net[1], n) };
  if (std::max(range[0].Hi - range[0].Lo, range[1].Hi - range[1].Lo) <=
    settings.GrazeTolerance * prob.Extent)
  {
    double h[2], jac[4], x[3];
    c.U = 0.5 * (s.U0 + s.U1);
    c.V = 0.5 * (s.V0 + s.V1);
    prob.Evaluate(c.U, c.V, h, jac, x, c.PC);
    const double rel[3] = { x[0] - prob.O[0], x[1] - prob.O[1], x[2] - prob.O[2] };
    c.T = Dot(prob.D, rel) / Dot(prob.D, prob.D);
    out.push_back(c);
  }
  return 1;
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
  const int n = (face.DegreeU + 1) * (face.DegreeV + 1);
  // Workspace: one per thread, grown once (no allocation per call).
  thread_local std::vector<double> work;
  const size_t need = static_cast<size_t>(2 * n) * 2 * (FaceSearch::MaxDepth + 1);
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
  FaceSearch search{ prob, settings, f, n, face.DegreeV + 1, work.data(), out };
  search.Visit(0, 0, { 0.0, 1.0, 0.0, 1.0 });
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
    status->Patches += search.Examined;
    status->Complete = status->Complete && search.Complete;
  }
  return static_cast<int>(kept - first);
}
}
