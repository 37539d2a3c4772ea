// Obstructs(P, Q) of vtkSteinVisibilitySort (see hovSteinObstructs.h).
#include "hovSteinObstructs.h"

#include "hovGeometricPredicates.h" // exact Orient2d / Orient3d
#include "hovSteinHulls.h"          // Hull2d, InHull, ClipPolygon, Area, HullCache

#include <algorithm>
#include <array>
#include <cfloat>
#include <cmath>

namespace hovStein
{
namespace
{
/// Ray-triangle intersection parameter (Moller-Trumbore, slightly inclusive).
bool RayTriangle(const double* o, const double* d, const double* a, const double* b,
  const double* c, double& t)
{
  double e1[3], e2[3], s[3], p[3], q[3];
  for (int k = 0; k < 3; ++k)
  {
    e1[k] = b[k] - a[k];
    e2[k] = c[k] - a[k];
    s[k] = o[k] - a[k];
  }
  p[0] = d[1] * e2[2] - d[2] * e2[1];
  p[1] = d[2] * e2[0] - d[0] * e2[2];
  p[2] = d[0] * e2[1] - d[1] * e2[0];
  const double det = e1[0] * p[0] + e1[1] * p[1] + e1[2] * p[2];
  if (det == 0 || !std::isfinite(det))
  {
    return false;
  }
  const double u = (s[0] * p[0] + s[1] * p[1] + s[2] * p[2]) / det;
  q[0] = s[1] * e1[2] - s[2] * e1[1];
  q[1] = s[2] * e1[0] - s[0] * e1[2];
  q[2] = s[0] * e1[1] - s[1] * e1[0];
  const double v = (d[0] * q[0] + d[1] * q[1] + d[2] * q[2]) / det;
  constexpr double tol = 1e-7;
  if (u < -tol || v < -tol || u + v > 1 + tol)
  {
    return false;
  }
  t = (e2[0] * q[0] + e2[1] * q[1] + e2[2] * q[2]) / det;
  return std::isfinite(t);
}

/// Largest absolute coordinate of the corners of cells @p a and @p b.
double CoordinateScale(const Geometry& g, vtkIdType a, vtkIdType b)
{
  double m = 0;
  for (vtkIdType c : { a, b })
  {
    const vtkIdType* ids = g.CellCorners(c);
    for (int i = 0; i < g.NumberOfCorners(c); ++i)
    {
      const double* x = g.Point(ids[i]);
      m = std::max({ m, std::fabs(x[0]), std::fabs(x[1]), std::fabs(x[2]) });
    }
  }
  return m;
}
}

Obstruction::Obstruction(const Geometry& g, const View& v, const HullCache* hulls)
  : G(g)
  , V(v)
  , Hulls(hulls)
{
}

int Obstruction::FaceSeparates(vtkIdType x, int f, vtkIdType y, double tol) const
{
  const ViewFrame& fr = this->V.Frame;
  const double back[3] = { -fr.Dop[0], -fr.Dop[1], -fr.Dop[2] };
  const int n = this->G.NumberOfCorners(y);
  const vtkIdType* ids = this->G.CellCorners(y);
  const int mode = this->G.FaceCode(x, f) & 3;
  if (mode == FaceNewell)
  {
    if (tol > 0)
    {
      return NotSeparated; // already tolerant: decided in the first pass
    }
    const Plane& pl = this->G.FacePlane(x, f);
    for (int i = 0; i < n; ++i)
    {
      const double* p = this->G.Point(ids[i]);
      if (pl.N[0] * p[0] + pl.N[1] * p[1] + pl.N[2] * p[2] + pl.D + pl.Deviation < 0)
      {
        return NotSeparated;
      }
    }
    const double* e = fr.Parallel ? back : fr.Eye;
    const double side = pl.N[0] * e[0] + pl.N[1] * e[1] + pl.N[2] * e[2] + (fr.Parallel ? 0 : pl.D);
    // Not a true separation (the face is warped): only "y not behind x" is
    // decided; "x in front" must be confirmed by the other tests.
    return side > 0 ? -WeakFront : WeakFront;
  }
  if (mode != FaceExact)
  {
    return NotSeparated;
  }
  vtkIdType t[3];
  this->G.ExactTriple(x, f, t);
  const double *a = this->G.Point(t[0]), *b = this->G.Point(t[1]), *c = this->G.Point(t[2]);
  if (tol == 0)
  {
    // Exact: every corner of y on the closed outer side of the plane. On an
    // axis-aligned plane (grid-aligned meshes, whose corners often lie exactly
    // on other cells' face planes, where Orient3d's filter fails) the same
    // exact sign from two comparisons.
    int axis, sigma;
    const bool aligned = this->G.AxisPlane(x, f, axis, sigma);
    for (int i = 0; i < n; ++i)
    {
      if (ids[i] == t[0] || ids[i] == t[1] || ids[i] == t[2])
      {
        continue;
      }
      const double* p = this->G.Point(ids[i]);
      if ((aligned ? hov::AxisOrient3d(axis, sigma, a, p) : hov::Orient3d(a, b, c, p)) > 0)
      {
        return NotSeparated;
      }
    }
    const int eye = fr.TriangleSide(a, b, c);
    return eye; // < 0: eye outside, y in front; > 0: x in front; 0: edge-on, no common ray
  }
  // Tolerant: y outside up to tol (rounding of touching cells), the eye clearly on one side.
  double nrm[3];
  const double u[3] = { b[0] - a[0], b[1] - a[1], b[2] - a[2] };
  const double w[3] = { c[0] - a[0], c[1] - a[1], c[2] - a[2] };
  nrm[0] = u[1] * w[2] - u[2] * w[1];
  nrm[1] = u[2] * w[0] - u[0] * w[2];
  nrm[2] = u[0] * w[1] - u[1] * w[0];
  const double len = std::sqrt(nrm[0] * nrm[0] + nrm[1] * nrm[1] + nrm[2] * nrm[2]);
  if (!(len > 0) || !std::isfinite(len))
  {
    return NotSeparated;
  }
  auto dist = [&](const double* p) {
    return ((p[0] - a[0]) * nrm[0] + (p[1] - a[1]) * nrm[1] + (p[2] - a[2]) * nrm[2]) / len;
  };
  for (int i = 0; i < n; ++i)
  {
    if (dist(this->G.Point(ids[i])) < -tol)
    {
      return NotSeparated;
    }
  }
  const double eye = fr.Parallel
    ? (back[0] * nrm[0] + back[1] * nrm[1] + back[2] * nrm[2]) / len
    : dist(fr.Eye);
  const double eyeTol = fr.Parallel ? 1e-12 : tol;
  return eye > eyeTol ? -1 : (eye < -eyeTol ? 1 : 0);
}

int Obstruction::PlaneRelation(vtkIdType a, vtkIdType b) const
{
  double tol = 0;
  int weak = NotSeparated;
  for (int pass = 0; pass < 2; ++pass)
  {
    for (int side = 0; side < 2; ++side)
    {
      const vtkIdType x = side ? b : a, y = side ? a : b;
      const int nf = GetShape(this->G.Kinds[x]).NumFaces;
      for (int f = 0; f < nf; ++f)
      {
        const int r = this->FaceSeparates(x, f, y, tol);
        if (r == -1 || r == 0 || r == 1)
        {
          return side ? -r : r;
        }
        if ((r == WeakFront || r == -WeakFront) && weak == NotSeparated)
        {
          weak = side ? -r : r; // kept unless a true separating plane follows
        }
      }
    }
    tol = 1e-11 * std::max(CoordinateScale(this->G, a, b), 1e-300);
  }
  return weak;
}

int Obstruction::EdgeCrossings(vtkIdType p, vtkIdType q, bool& crossed) const
{
  const Shape& sp = GetShape(this->G.Kinds[p]);
  const Shape& sq = GetShape(this->G.Kinds[q]);
  const vtkIdType* ip = this->G.CellCorners(p);
  const vtkIdType* iq = this->G.CellCorners(q);
  const double* proj = this->V.Proj.data();
  crossed = false;
  for (int e = 0; e < sp.NumEdges; ++e)
  {
    const vtkIdType ia = ip[sp.Edges[e][0]], ib = ip[sp.Edges[e][1]];
    const double *a = proj + 3 * ia, *b = proj + 3 * ib;
    for (int h = 0; h < sq.NumEdges; ++h)
    {
      const vtkIdType ic = iq[sq.Edges[h][0]], id = iq[sq.Edges[h][1]];
      if (ia == ic || ia == id || ib == ic || ib == id)
      {
        continue; // edges sharing a vertex never cross properly
      }
      const double *c = proj + 3 * ic, *d = proj + 3 * id;
      if (std::max(a[0], b[0]) <= std::min(c[0], d[0]) || std::max(c[0], d[0]) <= std::min(a[0], b[0]) ||
        std::max(a[1], b[1]) <= std::min(c[1], d[1]) || std::max(c[1], d[1]) <= std::min(a[1], b[1]))
      {
        continue;
      }
      const int o1 = hov::Orient2d(a, b, c), o2 = hov::Orient2d(a, b, d);
      if (o1 == 0 || o2 == 0 || o1 == o2)
      {
        continue;
      }
      const int o3 = hov::Orient2d(c, d, a), o4 = hov::Orient2d(c, d, b);
      if (o3 == 0 || o4 == 0 || o3 == o4)
      {
        continue;
      }
      crossed = true;
      const int r = this->CrossingOrder(a, b, c, d);
      if (r != 0)
      {
        return r;
      }
    }
  }
  return 0;
}

int Obstruction::CrossingOrder(const double* a, const double* b, const double* c, const double* d) const
{
  // Screen parameters of the crossing on both edges, with their rounding error
  // bounds: nearly parallel (e.g. collinear edges on a shared plane, "crossing"
  // only by rounding) give huge bounds and stay inconclusive.
  const double r[2] = { b[0] - a[0], b[1] - a[1] }, s[2] = { d[0] - c[0], d[1] - c[1] };
  const double w[2] = { c[0] - a[0], c[1] - a[1] };
  const double den = r[0] * s[1] - r[1] * s[0];
  const double lr = std::hypot(r[0], r[1]), ls = std::hypot(s[0], s[1]), lw = std::hypot(w[0], w[1]);
  if (!(std::fabs(den) > 1e-9 * lr * ls))
  {
    return 0;
  }
  const double m = std::max({ std::fabs(a[0]), std::fabs(a[1]), std::fabs(b[0]), std::fabs(b[1]),
    std::fabs(c[0]), std::fabs(c[1]), std::fabs(d[0]), std::fabs(d[1]) });
  const double err = 64 * DBL_EPSILON * m * (lr + ls + lw) / std::fabs(den); // of lam and mu
  const double lam = std::min(1.0, std::max(0.0, (w[0] * s[1] - w[1] * s[0]) / den));
  const double mu = std::min(1.0, std::max(0.0, (w[0] * r[1] - w[1] * r[0]) / den));
  double zp, zq, slopeP, slopeQ; // depths and |dz/dparameter| there
  if (this->V.Frame.Parallel)
  {
    zp = a[2] + lam * (b[2] - a[2]);
    zq = c[2] + mu * (d[2] - c[2]);
    slopeP = std::fabs(b[2] - a[2]);
    slopeQ = std::fabs(d[2] - c[2]);
  }
  else
  {
    zp = 1 / ((1 - lam) / a[2] + lam / b[2]);
    zq = 1 / ((1 - mu) / c[2] + mu / d[2]);
    slopeP = zp * zp * std::fabs(1 / b[2] - 1 / a[2]);
    slopeQ = zq * zq * std::fabs(1 / d[2] - 1 / c[2]);
  }
  const double tol = 1e-9 * (std::fabs(zp) + std::fabs(zq)) + 1e-12 * this->G.Diagonal +
    err * (slopeP + slopeQ);
  if (!(std::fabs(zp - zq) > tol))
  {
    return 0; // touching at the crossing (or too ill-conditioned): inconclusive
  }
  return zp < zq ? 1 : -1;
}

const double (*Obstruction::Hull(vtkIdType c, double hull[][2], int& size, double& area) const)[2]
{
  const double(*cached)[2] = this->Hulls ? this->Hulls->Find(c, size, area) : nullptr;
  if (cached)
  {
    return cached;
  }
  double xyz[3 * MaxVisiblePoints];
  size = Hull2d(xyz, this->V.VisiblePoints(this->G, c, xyz), hull);
  area = Area(hull, size);
  return hull;
}

bool Obstruction::ProjectionsTouchOnly(vtkIdType p, vtkIdType q) const
{
  double xp[3 * MaxVisiblePoints], xq[3 * MaxVisiblePoints], bp[HullCapacity][2], bq[HullCapacity][2];
  const int np = this->V.VisiblePoints(this->G, p, xp);
  const int nq = this->V.VisiblePoints(this->G, q, xq);
  int mp, mq;
  double areaP, areaQ;
  const double(*hp)[2] = this->Hull(p, bp, mp, areaP);
  const double(*hq)[2] = this->Hull(q, bq, mq, areaQ);
  for (int i = 0; i < np; ++i)
  {
    if (InHull(hq, mq, xp + 3 * i))
    {
      return false;
    }
  }
  for (int i = 0; i < nq; ++i)
  {
    if (InHull(hp, mp, xq + 3 * i))
    {
      return false;
    }
  }
  return true;
}

bool Obstruction::Overlap(vtkIdType p, vtkIdType q, double centre[2]) const
{
  double poly[HullCapacity][2], bq[HullCapacity][2];
  int mp, mq;
  double areaP, areaQ;
  const double(*hp)[2] = this->Hull(p, poly, mp, areaP);
  const double(*hq)[2] = this->Hull(q, bq, mq, areaQ);
  if (mp < 3 || mq < 3)
  {
    return false; // a projection without area hides nothing
  }
  if (hp != poly)
  {
    std::copy(&hp[0][0], &hp[0][0] + 2 * mp, &poly[0][0]); // clipped in place below
  }
  const int m = ClipPolygon(poly, mp, hq, mq);
  const double area = m >= 3 ? Area(poly, m) : 0.0;
  if (!(area > 1e-10 * std::min(areaP, areaQ)))
  {
    return false;
  }
  double cx = 0, cy = 0; // area centroid of the overlap: strictly inside both
  for (int i = 0; i < m; ++i)
  {
    const int j = (i + 1) % m;
    const double w = poly[i][0] * poly[j][1] - poly[j][0] * poly[i][1];
    cx += (poly[i][0] + poly[j][0]) * w;
    cy += (poly[i][1] + poly[j][1]) * w;
  }
  centre[0] = cx / (6 * area);
  centre[1] = cy / (6 * area);
  return true;
}

bool Obstruction::RayInterval(
  vtkIdType c, const double origin[3], const double dir[3], double t[2]) const
{
  const Shape& s = GetShape(this->G.Kinds[c]);
  const vtkIdType* ids = this->G.CellCorners(c);
  t[0] = VTK_DOUBLE_MAX;
  t[1] = -VTK_DOUBLE_MAX;
  for (int f = 0; f < s.NumFaces; ++f)
  {
    const int* loc = s.Faces[f];
    for (int k = 1; k + 1 < s.FaceSize[f]; ++k)
    {
      double hit;
      if (RayTriangle(origin, dir, this->G.Point(ids[loc[0]]), this->G.Point(ids[loc[k]]),
            this->G.Point(ids[loc[k + 1]]), hit))
      {
        t[0] = std::min(t[0], hit);
        t[1] = std::max(t[1], hit);
      }
    }
  }
  if (t[0] > t[1])
  {
    return false;
  }
  if (!this->V.Frame.Parallel)
  {
    t[0] = std::max(t[0], this->V.Frame.Near);
    t[1] = std::max(t[1], this->V.Frame.Near);
  }
  return true;
}

int Obstruction::RayTest(vtkIdType p, vtkIdType q) const
{
  double centre[2];
  if (!this->Overlap(p, q, centre))
  {
    return 0;
  }
  const ViewFrame& f = this->V.Frame;
  double origin[3], dir[3];
  for (int k = 0; k < 3; ++k)
  {
    origin[k] = f.Parallel ? centre[0] * f.Right[k] + centre[1] * f.Up[k] : f.Eye[k];
    dir[k] = f.Parallel ? f.Dop[k] : f.Dop[k] + centre[0] * f.Right[k] + centre[1] * f.Up[k];
  }
  double tp[2], tq[2];
  double front, rear;
  if (!this->RayInterval(p, origin, dir, tp))
  {
    this->V.DepthRange(this->G, p, front, rear);
    tp[0] = tp[1] = 0.5 * (front + rear);
  }
  if (!this->RayInterval(q, origin, dir, tq))
  {
    this->V.DepthRange(this->G, q, front, rear);
    tq[0] = tq[1] = 0.5 * (front + rear);
  }
  const double mp = tp[0] + tp[1], mq = tq[0] + tq[1];
  return mp < mq ? 1 : (mq < mp ? -1 : 0);
}

int Obstruction::Evidence(vtkIdType a, vtkIdType b) const
{
  const bool clipped = this->V.Clip(a) >= 0 || this->V.Clip(b) >= 0;
  if (!clipped)
  {
    bool crossed = false;
    const int decided = this->EdgeCrossings(a, b, crossed);
    if (decided != 0)
    {
      return 2 * decided; // a clear crossing: the projections overlap
    }
    if (!crossed && this->ProjectionsTouchOnly(a, b))
    {
      return 0;
    }
  }
  return 2 * this->RayTest(a, b); // the ray test has checked the overlap
}

bool Obstruction::Obstructs(vtkIdType p, vtkIdType q)
{
  // Decided for the ordered pair (min, max) so that Obstructs(p, q) and
  // Obstructs(q, p) come from one decision and are never both true.
  const bool swapped = q < p;
  int r = swapped ? this->PlaneRelation(q, p) : this->PlaneRelation(p, q);
  if (r == NotSeparated)
  {
    r = swapped ? this->Evidence(q, p) : this->Evidence(p, q);
  }
  r = swapped ? -r : r;
  if (r == 1)
  {
    double centre[2];
    return this->Overlap(p, q, centre); // separated with p in front: do they overlap?
  }
  if (r == WeakFront)
  {
    return this->Evidence(p, q) > 0; // Obstructs(q, p) is false without evaluation
  }
  return r > 0;
}
}
