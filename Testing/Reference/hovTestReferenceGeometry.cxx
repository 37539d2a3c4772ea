// Rays of the reference (hovTestReference.h): pixel rays built from the
// camera's parameters, the change to dataset coordinates, exact ray/box and
// ray/tetrahedron intersection and distances to edges.
#include "hovTestReference.h"
#include "hovTestReferenceVector.h"

#include "vtkCamera.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <utility>

namespace hovTestRef
{
/// Segment-segment distance (Ericson, Real-Time Collision Detection 5.1.9).
Real SegmentDistance(const Vec3& p1, const Vec3& q1, const Vec3& p2, const Vec3& q2)
{
  const Vec3 d1 = Sub(q1, p1), d2 = Sub(q2, p2), r = Sub(p1, p2);
  const Real a = Dot(d1, d1), e = Dot(d2, d2), f = Dot(d2, r);
  Real s = 0, t = 0;
  auto clamp01 = [](Real v) { return std::min(std::max(v, Real(0)), Real(1)); };
  if (a <= 0 && e <= 0)
  {
    return Norm(r);
  }
  if (a <= 0)
  {
    t = clamp01(f / e);
  }
  else
  {
    const Real c = Dot(d1, r);
    if (e <= 0)
    {
      s = clamp01(-c / a);
    }
    else
    {
      const Real b = Dot(d1, d2);
      const Real denom = a * e - b * b;
      s = denom > 0 ? clamp01((b * f - c * e) / denom) : 0;
      t = (b * s + f) / e;
      if (t < 0)
      {
        t = 0;
        s = clamp01(-c / a);
      }
      else if (t > 1)
      {
        t = 1;
        s = clamp01((b - c) / a);
      }
    }
  }
  return Norm(Sub(Add(p1, Scale(d1, s)), Add(p2, Scale(d2, t))));
}

std::string CameraSpec::ToString() const
{
  std::ostringstream os;
  os << std::setprecision(17) << "camera{position=(" << (double)Position[0] << ", "
     << (double)Position[1] << ", " << (double)Position[2] << ") focal=(" << (double)FocalPoint[0]
     << ", " << (double)FocalPoint[1] << ", " << (double)FocalPoint[2] << ") up=("
     << (double)ViewUp[0] << ", " << (double)ViewUp[1] << ", " << (double)ViewUp[2] << ") "
     << (Parallel ? "parallel scale=" : "view angle=")
     << (double)(Parallel ? ParallelScale : ViewAngle) << " clip=[" << (double)Near << ", "
     << (double)Far << "]}";
  return os.str();
}

CameraSpec ReadCamera(vtkCamera* camera)
{
  CameraSpec c;
  c.Position = FromDouble(camera->GetPosition());
  c.FocalPoint = FromDouble(camera->GetFocalPoint());
  c.ViewUp = FromDouble(camera->GetViewUp());
  c.ViewAngle = camera->GetViewAngle();
  c.Parallel = camera->GetParallelProjection() != 0;
  c.ParallelScale = camera->GetParallelScale();
  c.Near = camera->GetClippingRange()[0];
  c.Far = camera->GetClippingRange()[1];
  return c;
}

Ray PixelRay(const CameraSpec& cam, int i, int j, int width, int height)
{
  const Vec3 d = Unit(Sub(cam.FocalPoint, cam.Position));
  const Vec3 right = Unit(Cross(d, cam.ViewUp));
  const Vec3 up = Cross(right, d);
  const Real aspect = Real(width) / height;
  const Real x = 2 * (i + Real(0.5)) / width - 1;
  const Real y = 2 * (j + Real(0.5)) / height - 1;
  const Vec3 lateral = Add(Scale(right, x * aspect), Scale(up, y));
  Ray ray;
  if (cam.Parallel)
  {
    ray.Origin = Add(Add(cam.Position, Scale(lateral, cam.ParallelScale)), Scale(d, cam.Near));
    ray.Direction = d;
    ray.TFar = cam.Far - cam.Near;
  }
  else
  {
    const Real pi = 3.141592653589793238462643383279502884L;
    const Real h = std::tan(cam.ViewAngle * pi / 360);
    const Vec3 w = Add(d, Scale(lateral, h));
    ray.Origin = Add(cam.Position, Scale(w, cam.Near));
    ray.Direction = Unit(w);
    ray.TFar = (cam.Far - cam.Near) * Norm(w);
  }
  return ray;
}

Ray ToDataCoordinates(const Ray& worldRay, vtkMatrix4x4* m)
{
  if (!m)
  {
    return worldRay;
  }
  vtkNew<vtkMatrix4x4> inv;
  vtkMatrix4x4::Invert(m, inv);
  auto apply = [&](const Vec3& p) {
    Vec3 q;
    for (int r = 0; r < 3; ++r)
    {
      q[r] = inv->GetElement(r, 0) * p[0] + inv->GetElement(r, 1) * p[1] +
        inv->GetElement(r, 2) * p[2] + inv->GetElement(r, 3);
    }
    return q;
  };
  Ray ray;
  ray.Origin = apply(worldRay.Origin);
  const Vec3 delta = Sub(apply(worldRay.At(worldRay.TFar)), ray.Origin);
  ray.TFar = Norm(delta);
  ray.Direction = Scale(delta, 1 / ray.TFar);
  return ray;
}

bool IntersectBox(const Ray& ray, const double bounds[6], Real& tIn, Real& tOut)
{
  tIn = 0;
  tOut = ray.TFar;
  for (int a = 0; a < 3; ++a)
  {
    const Real o = ray.Origin[a], d = ray.Direction[a];
    const Real lo = bounds[2 * a], hi = bounds[2 * a + 1];
    if (d == 0)
    {
      if (o < lo || o > hi)
      {
        return false;
      }
      continue;
    }
    Real t1 = (lo - o) / d, t2 = (hi - o) / d;
    if (t1 > t2)
    {
      std::swap(t1, t2);
    }
    tIn = std::max(tIn, t1);
    tOut = std::min(tOut, t2);
  }
  return tIn < tOut;
}

bool IntersectTetra(const Ray& ray, const double pts[4][3], Real& tIn, Real& tOut)
{
  tIn = 0;
  tOut = ray.TFar;
  for (int k = 0; k < 4; ++k)
  {
    Vec3 f[3];
    int m = 0;
    for (int v = 0; v < 4; ++v)
    {
      if (v != k)
      {
        f[m++] = FromDouble(pts[v]);
      }
    }
    Vec3 n = Cross(Sub(f[1], f[0]), Sub(f[2], f[0]));
    Real h = Dot(n, f[0]);
    if (Dot(n, FromDouble(pts[k])) > h)
    {
      n = Scale(n, -1);
      h = -h;
    }
    const Real den = Dot(n, ray.Direction);
    const Real num = h - Dot(n, ray.Origin);
    if (den > 0)
    {
      tOut = std::min(tOut, num / den);
    }
    else if (den < 0)
    {
      tIn = std::max(tIn, num / den);
    }
    else if (num < 0)
    {
      return false;
    }
  }
  return tIn < tOut;
}

Real DistanceToTetraEdges(const Ray& ray, const double pts[4][3])
{
  Real best = 1e300L;
  const Vec3 end = ray.At(ray.TFar);
  for (int a = 0; a < 4; ++a)
  {
    for (int b = a + 1; b < 4; ++b)
    {
      best = std::min(best, SegmentDistance(ray.Origin, end, FromDouble(pts[a]), FromDouble(pts[b])));
    }
  }
  return best;
}

Real DistanceToBoxEdges(const Ray& ray, const double bounds[6])
{
  Real best = 1e300L;
  const Vec3 end = ray.At(ray.TFar);
  for (int axis = 0; axis < 3; ++axis)
  {
    const int u = (axis + 1) % 3, v = (axis + 2) % 3;
    for (int cu = 0; cu < 2; ++cu)
    {
      for (int cv = 0; cv < 2; ++cv)
      {
        Vec3 p, q;
        p[axis] = bounds[2 * axis];
        q[axis] = bounds[2 * axis + 1];
        p[u] = q[u] = bounds[2 * u + cu];
        p[v] = q[v] = bounds[2 * v + cv];
        best = std::min(best, SegmentDistance(ray.Origin, end, p, q));
      }
    }
  }
  return best;
}
}
