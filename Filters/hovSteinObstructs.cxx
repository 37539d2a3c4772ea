// Obstructs(P, Q) of vtkSteinVisibilitySort (see hovSteinObstructs.h).
#include "hovSteinObstructs.h"

#include "hovGeometricPredicates.h" // exact Orient2d / Orient3d

#include <algorithm>
#include <array>
#include <cmath>

namespace hovStein
{
namespace
{
constexpr int MaxPts = 32; // visible part of a clipped hexahedron: 8 corners + 12 crossings

/// Convex hull (counterclockwise, no collinear points) of 2D points; returns its size.
int Hull2d(const double* xyz, int n, double hull[][2])
{
  std::array<double, 2> p[MaxPts];
  for (int i = 0; i < n; ++i)
  {
    p[i] = { xyz[3 * i], xyz[3 * i + 1] };
  }
  std::sort(p, p + n);
  int k = 0;
  for (int i = 0; i < n; ++i)
  {
    while (k >= 2 && hov::Orient2d(hull[k - 2], hull[k - 1], p[i].data()) <= 0)
    {
      --k;
    }
    hull[k][0] = p[i][0];
    hull[k++][1] = p[i][1];
  }
  const int lower = k + 1;
  for (int i = n - 2; i >= 0; --i)
  {
    while (k >= lower && hov::Orient2d(hull[k - 2], hull[k - 1], p[i].data()) <= 0)
    {
      --k;
    }
    hull[k][0] = p[i][0];
    hull[k++][1] = p[i][1];
  }
  return std::max(k - 1, 0);
}

double Area(const double poly[][2], int n)
{
  double a = 0;
  for (int i = 0; i < n; ++i)
  {
    const int j = (i + 1) % n;
    a += poly[i][0] * poly[j][1] - poly[j][0] * poly[i][1];
  }
  return 0.5 * a;
}

/// Inside or on the boundary of a counterclockwise convex polygon (exact).
bool InHull(const double hull[][2], int n, const double* x)
{
  if (n < 3)
  {
    return false;
  }
  for (int i = 0; i < n; ++i)
  {
    if (hov::Orient2d(hull[i], hull[(i + 1) % n], x) < 0)
    {
      return false;
    }
  }
  return true;
}

/// Sutherland-Hodgman: @p poly clipped by the convex counterclockwise @p clip.
int ClipPolygon(double poly[][2], int n, const double clip[][2], int m)
{
  double tmp[2 * MaxPts][2];
  for (int e = 0; e < m && n > 0; ++e)
  {
    const double* a = clip[e];
    const double* b = clip[(e + 1) % m];
    auto side = [&](const double* x) {
      return (b[0] - a[0]) * (x[1] - a[1]) - (b[1] - a[1]) * (x[0] - a[0]);
    };
    int k = 0;
    for (int i = 0; i < n && k < 2 * MaxPts - 2; ++i)
    {
      const double* u = poly[i];
      const double* v = poly[(i + 1) % n];
      const double su = side(u), sv = side(v);
      if (su >= 0)
      {
        tmp[k][0] = u[0];
        tmp[k++][1] = u[1];
      }
      if ((su >= 0) != (sv >= 0))
      {
        const double t = su / (su - sv);
        tmp[k][0] = u[0] + t * (v[0] - u[0]);
        tmp[k++][1] = u[1] + t * (v[1] - u[1]);
      }
    }
    n = std::min(k, MaxPts);
    std::copy(&tmp[0][0], &tmp[0][0] + 2 * n, &poly[0][0]);
  }
  return n;
}

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
}

Obstruction::Obstruction(const Geometry& g, const View& v)
  : G(g)
  , V(v)
  , Facing(g.NumberOfCells, 0)
{
}

std::uint8_t Obstruction::FrontFaces(vtkIdType c)
{
  std::uint8_t& cached = this->Facing[c];
  if (cached & 0x80)
  {
    return cached & 0x3f;
  }
  const ViewFrame& f = this->V.Frame;
  const double back[3] = { -f.Dop[0], -f.Dop[1], -f.Dop[2] };
  std::uint8_t mask = 0;
  const int nf = GetShape(this->G.Kinds[c]).NumFaces;
  for (int i = 0; i < nf; ++i)
  {
    const int mode = this->G.FaceCode(c, i) & 3;
    bool front = false;
    if (mode == FaceExact)
    {
      vtkIdType t[3];
      this->G.ExactTriple(c, i, t);
      const double *a = this->G.Point(t[0]), *b = this->G.Point(t[1]), *cc = this->G.Point(t[2]);
      front = (f.Parallel ? hov::Orient3dDirection(a, b, cc, back) : hov::Orient3d(a, b, cc, f.Eye)) < 0;
    }
    else if (mode == FaceNewell)
    {
      const Plane& pl = this->G.FacePlane(c, i);
      const double* x = f.Parallel ? back : f.Eye;
      const double v = pl.N[0] * x[0] + pl.N[1] * x[1] + pl.N[2] * x[2] + (f.Parallel ? 0 : pl.D);
      front = v > 0;
    }
    mask |= front ? (1 << i) : 0;
  }
  cached = static_cast<std::uint8_t>(0x80 | mask);
  return mask;
}

bool Obstruction::AllOuter(vtkIdType faceCell, int f, vtkIdType other) const
{
  const int n = this->G.NumberOfCorners(other);
  const vtkIdType* ids = this->G.CellCorners(other);
  if ((this->G.FaceCode(faceCell, f) & 3) == FaceExact)
  {
    vtkIdType t[3];
    this->G.ExactTriple(faceCell, f, t);
    const double *a = this->G.Point(t[0]), *b = this->G.Point(t[1]), *c = this->G.Point(t[2]);
    for (int i = 0; i < n; ++i)
    {
      if (ids[i] != t[0] && ids[i] != t[1] && ids[i] != t[2] &&
        hov::Orient3d(a, b, c, this->G.Point(ids[i])) > 0)
      {
        return false;
      }
    }
    return true;
  }
  const Plane& pl = this->G.FacePlane(faceCell, f);
  for (int i = 0; i < n; ++i)
  {
    const double* x = this->G.Point(ids[i]);
    if (pl.N[0] * x[0] + pl.N[1] * x[1] + pl.N[2] * x[2] + pl.D + pl.Deviation < 0)
    {
      return false;
    }
  }
  return true;
}

bool Obstruction::SeparatedByFace(vtkIdType p, vtkIdType q)
{
  const std::uint8_t frontQ = this->FrontFaces(q);
  const int nq = GetShape(this->G.Kinds[q]).NumFaces;
  for (int f = 0; f < nq; ++f)
  {
    // P behind a back face of Q.
    if ((this->G.FaceCode(q, f) & 3) != FaceSkip && !(frontQ & (1 << f)) && this->AllOuter(q, f, p))
    {
      return true;
    }
  }
  const std::uint8_t frontP = this->FrontFaces(p);
  const int np = GetShape(this->G.Kinds[p]).NumFaces;
  for (int f = 0; f < np; ++f)
  {
    // Q in front of a front face of P.
    if ((this->G.FaceCode(p, f) & 3) != FaceSkip && (frontP & (1 << f)) && this->AllOuter(p, f, q))
    {
      return true;
    }
  }
  return false;
}

int Obstruction::EdgeCrossings(vtkIdType p, vtkIdType q, bool& crossed) const
{
  const Shape& sp = GetShape(this->G.Kinds[p]);
  const Shape& sq = GetShape(this->G.Kinds[q]);
  const vtkIdType* ip = this->G.CellCorners(p);
  const vtkIdType* iq = this->G.CellCorners(q);
  const double* proj = this->V.Proj.data();
  const bool parallel = this->V.Frame.Parallel;
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
      // Screen parameters of the crossing on both edges, then the depths there.
      const double r[2] = { b[0] - a[0], b[1] - a[1] }, s[2] = { d[0] - c[0], d[1] - c[1] };
      const double w[2] = { c[0] - a[0], c[1] - a[1] };
      const double den = r[0] * s[1] - r[1] * s[0];
      const double lam = std::min(1.0, std::max(0.0, (w[0] * s[1] - w[1] * s[0]) / den));
      const double mu = std::min(1.0, std::max(0.0, (w[0] * r[1] - w[1] * r[0]) / den));
      const double zp = parallel ? a[2] + lam * (b[2] - a[2]) : 1 / ((1 - lam) / a[2] + lam / b[2]);
      const double zq = parallel ? c[2] + mu * (d[2] - c[2]) : 1 / ((1 - mu) / c[2] + mu / d[2]);
      const double tol = 1e-9 * (std::fabs(zp) + std::fabs(zq)) + 1e-12 * this->G.Diagonal;
      if (std::fabs(zp - zq) > tol)
      {
        return zp < zq ? 1 : -1;
      }
    }
  }
  return 0;
}

bool Obstruction::ProjectionsTouchOnly(vtkIdType p, vtkIdType q) const
{
  double xp[3 * MaxPts], xq[3 * MaxPts], hp[2 * MaxPts + 2][2], hq[2 * MaxPts + 2][2];
  const int np = this->V.VisiblePoints(this->G, p, xp);
  const int nq = this->V.VisiblePoints(this->G, q, xq);
  const int mp = Hull2d(xp, np, hp), mq = Hull2d(xq, nq, hq);
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

bool Obstruction::RayTest(vtkIdType p, vtkIdType q) const
{
  double xp[3 * MaxPts], xq[3 * MaxPts], hp[2 * MaxPts + 2][2], hq[2 * MaxPts + 2][2];
  const int mp = Hull2d(xp, this->V.VisiblePoints(this->G, p, xp), hp);
  const int mq = Hull2d(xq, this->V.VisiblePoints(this->G, q, xq), hq);
  if (mp < 3 || mq < 3)
  {
    return false; // a projection without area hides nothing
  }
  const double areaP = Area(hp, mp), areaQ = Area(hq, mq);
  const int m = ClipPolygon(hp, mp, hq, mq);
  const double area = m >= 3 ? Area(hp, m) : 0.0;
  if (!(area > 1e-10 * std::min(areaP, areaQ)))
  {
    return false;
  }
  double cx = 0, cy = 0; // area centroid of the overlap
  for (int i = 0; i < m; ++i)
  {
    const int j = (i + 1) % m;
    const double w = hp[i][0] * hp[j][1] - hp[j][0] * hp[i][1];
    cx += (hp[i][0] + hp[j][0]) * w;
    cy += (hp[i][1] + hp[j][1]) * w;
  }
  cx /= 6 * area;
  cy /= 6 * area;
  const ViewFrame& f = this->V.Frame;
  double origin[3], dir[3];
  for (int k = 0; k < 3; ++k)
  {
    origin[k] = f.Parallel ? cx * f.Right[k] + cy * f.Up[k] : f.Eye[k];
    dir[k] = f.Parallel ? f.Dop[k] : f.Dop[k] + cx * f.Right[k] + cy * f.Up[k];
  }
  double tp[2], tq[2];
  if (!this->RayInterval(p, origin, dir, tp))
  {
    tp[0] = tp[1] = 0.5 * (this->V.Front[p] + this->V.Rear[p]);
  }
  if (!this->RayInterval(q, origin, dir, tq))
  {
    tq[0] = tq[1] = 0.5 * (this->V.Front[q] + this->V.Rear[q]);
  }
  return tp[0] + tp[1] < tq[0] + tq[1];
}

bool Obstruction::Obstructs(vtkIdType p, vtkIdType q)
{
  if (this->SeparatedByFace(p, q))
  {
    return false;
  }
  const bool clipped = this->V.ClipIndex[p] >= 0 || this->V.ClipIndex[q] >= 0;
  if (!clipped)
  {
    bool crossed = false;
    const int decided = this->EdgeCrossings(p, q, crossed);
    if (decided != 0)
    {
      return decided > 0;
    }
    if (!crossed && this->ProjectionsTouchOnly(p, q))
    {
      return false;
    }
  }
  return this->RayTest(p, q);
}
}
