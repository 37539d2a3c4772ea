#include "hovTestReference.h"

#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkCellType.h"
#include "vtkColorTransferFunction.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkUnstructuredGrid.h"
#include "vtkVolumeProperty.h"

#include <boost/math/quadrature/gauss_kronrod.hpp>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <utility>
#include <vector>

namespace hovTestRef
{
namespace
{
/// A 3-vector the Boost quadrature can integrate (abs = max norm).
struct QVec
{
  Real V[3];
  QVec(Real x = 0)
    : V{ x, x, x }
  {
  }
  QVec(Real a, Real b, Real c)
    : V{ a, b, c }
  {
  }
  QVec& operator+=(const QVec& o)
  {
    for (int c = 0; c < 3; ++c)
    {
      this->V[c] += o.V[c];
    }
    return *this;
  }
  QVec operator-() const { return QVec(-V[0], -V[1], -V[2]); }
};
inline QVec operator+(QVec a, const QVec& b)
{
  return a += b;
}
inline QVec operator-(const QVec& a, const QVec& b)
{
  return QVec(a.V[0] - b.V[0], a.V[1] - b.V[1], a.V[2] - b.V[2]);
}
inline QVec operator*(const QVec& a, Real s)
{
  return QVec(a.V[0] * s, a.V[1] * s, a.V[2] * s);
}
inline QVec operator*(Real s, const QVec& a)
{
  return a * s;
}
inline Real abs(const QVec& a)
{
  return std::max({ std::fabs(a.V[0]), std::fabs(a.V[1]), std::fabs(a.V[2]) });
}

Vec3 Sub(const Vec3& a, const Vec3& b)
{
  return { a[0] - b[0], a[1] - b[1], a[2] - b[2] };
}
Vec3 Add(const Vec3& a, const Vec3& b)
{
  return { a[0] + b[0], a[1] + b[1], a[2] + b[2] };
}
Vec3 Scale(const Vec3& a, Real s)
{
  return { a[0] * s, a[1] * s, a[2] * s };
}
Real Dot(const Vec3& a, const Vec3& b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
Vec3 Cross(const Vec3& a, const Vec3& b)
{
  return { a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0] };
}
Real Norm(const Vec3& a)
{
  return std::sqrt(Dot(a, a));
}
Vec3 Unit(const Vec3& a)
{
  return Scale(a, 1 / Norm(a));
}
Vec3 FromDouble(const double* p)
{
  return { p[0], p[1], p[2] };
}

/// Optical depth of a piece of length x on which the opacity goes linearly
/// from aFront to a (exact for every semantics, see the header).
Real PieceDepth(Real x, Real aFront, Real a, int semantics, Real unit)
{
  if (!(x > 0))
  {
    return 0;
  }
  if (semantics != 0)
  {
    return x * (Extinction(aFront, semantics, unit) + Extinction(a, semantics, unit)) / 2;
  }
  const Real p0 = 1 - aFront;
  const Real p = 1 - a;
  const Real r = (p - p0) / p0;
  const Real l = r == 0 ? Real(1) : std::log1p(r) / r;
  return x / unit * (1 - std::log(p0) - (1 + r) * l);
}

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
}

const char* SemanticsName(int semantics)
{
  switch (semantics)
  {
    case 0:
      return "GPU_COMPATIBLE";
    case 1:
      return "VTK_UNSTRUCTURED";
    default:
      return "RAW_EXTINCTION";
  }
}

const char* EmissionName(int emission)
{
  return emission == 0 ? "WILLIAMS_MAX" : "WILHELMS_VAN_GELDER";
}

Real Extinction(Real a, int semantics, Real unit)
{
  switch (semantics)
  {
    case 0:
      return -std::log1p(-a) / unit;
    case 1:
      return a / unit;
    default:
      return a;
  }
}

RGBA IntegrateRay(vtkVolumeProperty* property, const Model& model, double s0, double s1, Real length)
{
  RGBA out;
  if (!(length > 0))
  {
    return out;
  }
  vtkColorTransferFunction* ctf = property->GetRGBTransferFunction(0);
  vtkPiecewiseFunction* otf = property->GetScalarOpacity(0);
  const Real unit = property->GetScalarOpacityUnitDistance(0);

  // Pieces: (t, s) at every crossing of a colour or opacity node.
  std::vector<std::pair<Real, double>> cuts{ { Real(0), s0 }, { length, s1 } };
  if (s0 != s1)
  {
    std::vector<double> nodes;
    for (int i = 0; i < ctf->GetSize(); ++i)
    {
      double v[6];
      ctf->GetNodeValue(i, v);
      nodes.push_back(v[0]);
    }
    for (int i = 0; i < otf->GetSize(); ++i)
    {
      double v[4];
      otf->GetNodeValue(i, v);
      nodes.push_back(v[0]);
    }
    const double lo = std::min(s0, s1), hi = std::max(s0, s1);
    for (double x : nodes)
    {
      if (x > lo && x < hi)
      {
        cuts.emplace_back(length * ((Real(x) - s0) / (Real(s1) - s0)), x);
      }
    }
    std::sort(cuts.begin(), cuts.end());
  }

  const Real sSlope = (Real(s1) - s0) / length;
  auto scalarAt = [&](Real t) { return static_cast<double>(s0 + sSlope * t); };
  const bool wm = model.Emission == 0;
  const Real emissionFactor = Real(model.EmissionScale) / unit;
  Real depth = 0; // optical depth from the ray's front to the current piece
  QVec color(0);
  for (size_t k = 0; k + 1 < cuts.size(); ++k)
  {
    const Real tA = cuts[k].first, tB = cuts[k + 1].first;
    if (!(tB > tA))
    {
      continue;
    }
    const Real aA = otf->GetValue(cuts[k].second);
    const Real aB = otf->GetValue(cuts[k + 1].second);
    auto integrand = [&](Real t) -> QVec {
      const double s = scalarAt(t);
      const Real a = otf->GetValue(s);
      double c[3];
      ctf->GetColor(s, c);
      const Real transmittance = std::exp(-(depth + PieceDepth(t - tA, aA, a, model.Semantics, unit)));
      const Real weight =
        transmittance * (wm ? Extinction(a, model.Semantics, unit) : emissionFactor);
      return QVec(weight * c[0], weight * c[1], weight * c[2]);
    };
    color += boost::math::quadrature::gauss_kronrod<Real, 31>::integrate(
      integrand, tA, tB, 10, Real(1e-12));
    depth += PieceDepth(tB - tA, aA, aB, model.Semantics, unit);
  }
  out.R = color.V[0];
  out.G = color.V[1];
  out.B = color.V[2];
  out.A = -std::expm1(-depth);
  return out;
}

RGBA IntegrateRayBruteForce(
  vtkVolumeProperty* property, const Model& model, double s0, double s1, Real length, long steps)
{
  RGBA out;
  if (!(length > 0) || steps < 1)
  {
    return out;
  }
  vtkColorTransferFunction* ctf = property->GetRGBTransferFunction(0);
  vtkPiecewiseFunction* otf = property->GetScalarOpacity(0);
  const Real unit = property->GetScalarOpacityUnitDistance(0);
  const Real dt = length / steps;
  const Real emissionFactor = Real(model.EmissionScale) / unit;
  Real transmittance = 1;
  for (long k = 0; k < steps; ++k)
  {
    const Real w = (k + Real(0.5)) / steps;
    const double s = static_cast<double>(s0 + (Real(s1) - s0) * w);
    const Real tau = Extinction(otf->GetValue(s), model.Semantics, unit);
    double c[3];
    ctf->GetColor(s, c);
    const Real absorbed = -std::expm1(-tau * dt);
    const Real weight = transmittance *
      (model.Emission == 0 ? absorbed : emissionFactor * (tau > 0 ? absorbed / tau : dt));
    out.R += weight * c[0];
    out.G += weight * c[1];
    out.B += weight * c[2];
    transmittance *= std::exp(-tau * dt);
  }
  out.A = 1 - transmittance;
  return out;
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

vtkSmartPointer<vtkUnstructuredGrid> MakeTetra(const double pts[4][3], const double scalars[4])
{
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkDoubleArray> s;
  s->SetName("s");
  for (int v = 0; v < 4; ++v)
  {
    points->InsertNextPoint(pts[v]);
    s->InsertNextValue(scalars[v]);
  }
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  grid->SetPoints(points);
  const vtkIdType ids[4] = { 0, 1, 2, 3 };
  grid->InsertNextCell(VTK_TETRA, 4, ids);
  grid->GetPointData()->SetScalars(s);
  return grid;
}

vtkSmartPointer<vtkUnstructuredGrid> MakeCubeOfTetras(
  int n, const double origin[3], double size, int tetsPerCube, double a, const double g[3])
{
  const int np = n + 1;
  auto id = [np](int i, int j, int k) { return static_cast<vtkIdType>(i + np * (j + np * k)); };
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkDoubleArray> s;
  s->SetName("s");
  for (int k = 0; k < np; ++k)
  {
    for (int j = 0; j < np; ++j)
    {
      for (int i = 0; i < np; ++i)
      {
        const double x[3] = { origin[0] + size * i / n, origin[1] + size * j / n,
          origin[2] + size * k / n };
        points->InsertNextPoint(x);
        s->InsertNextValue(a + g[0] * x[0] + g[1] * x[1] + g[2] * x[2]);
      }
    }
  }
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  grid->SetPoints(points);
  grid->GetPointData()->SetScalars(s);
  grid->Allocate(static_cast<vtkIdType>(n) * n * n * tetsPerCube);

  auto insert = [&](vtkIdType ids[4]) {
    double x[4][3];
    for (int v = 0; v < 4; ++v)
    {
      points->GetPoint(ids[v], x[v]);
    }
    const Vec3 e1 = Sub(FromDouble(x[1]), FromDouble(x[0]));
    const Vec3 e2 = Sub(FromDouble(x[2]), FromDouble(x[0]));
    const Vec3 e3 = Sub(FromDouble(x[3]), FromDouble(x[0]));
    if (Dot(Cross(e1, e2), e3) < 0)
    {
      std::swap(ids[1], ids[2]); // positive VTK orientation
    }
    grid->InsertNextCell(VTK_TETRA, 4, ids);
  };

  for (int k = 0; k < n; ++k)
  {
    for (int j = 0; j < n; ++j)
    {
      for (int i = 0; i < n; ++i)
      {
        // Corner c = bit0 x + bit1 y + bit2 z.
        vtkIdType c[8];
        for (int b = 0; b < 8; ++b)
        {
          c[b] = id(i + (b & 1), j + ((b >> 1) & 1), k + ((b >> 2) & 1));
        }
        if (tetsPerCube == 6)
        {
          // Kuhn: paths 0 -> 7 along the axes in every order.
          const int perms[6][3] = { { 0, 1, 2 }, { 0, 2, 1 }, { 1, 0, 2 }, { 1, 2, 0 },
            { 2, 0, 1 }, { 2, 1, 0 } };
          for (const auto& p : perms)
          {
            const int b1 = 1 << p[0];
            const int b2 = b1 | (1 << p[1]);
            vtkIdType ids[4] = { c[0], c[b1], c[b2], c[7] };
            insert(ids);
          }
        }
        else
        {
          const bool even = (i + j + k) % 2 == 0;
          const int tets[2][5][4] = {
            { { 1, 2, 4, 7 }, { 0, 1, 2, 4 }, { 3, 1, 2, 7 }, { 5, 1, 4, 7 }, { 6, 2, 4, 7 } },
            { { 0, 3, 5, 6 }, { 1, 0, 3, 5 }, { 2, 0, 3, 6 }, { 4, 0, 5, 6 }, { 7, 3, 5, 6 } }
          };
          for (const auto& t : tets[even ? 0 : 1])
          {
            vtkIdType ids[4] = { c[t[0]], c[t[1]], c[t[2]], c[t[3]] };
            insert(ids);
          }
        }
      }
    }
  }
  return grid;
}

const float* ImagePixels(vtkImageData* image, int width, int height, std::string& why)
{
  if (!image)
  {
    why = "no image";
    return nullptr;
  }
  const int* dims = image->GetDimensions();
  if (dims[0] != width || dims[1] != height || dims[2] != 1)
  {
    std::ostringstream os;
    os << "image is " << dims[0] << "x" << dims[1] << "x" << dims[2] << ", expected " << width
       << "x" << height << "x1";
    why = os.str();
    return nullptr;
  }
  auto* rgba = vtkFloatArray::SafeDownCast(image->GetPointData()->GetScalars());
  if (!rgba || rgba->GetNumberOfComponents() != 4 ||
    rgba->GetNumberOfTuples() != static_cast<vtkIdType>(width) * height || !rgba->GetName() ||
    std::string(rgba->GetName()) != "RGBA")
  {
    why = "point scalars are not a 4-component float array named RGBA of the image's size";
    return nullptr;
  }
  return rgba->GetPointer(0);
}

std::string DescribeProperty(vtkVolumeProperty* property)
{
  std::ostringstream os;
  os << std::setprecision(17);
  vtkColorTransferFunction* ctf = property->GetRGBTransferFunction(0);
  vtkPiecewiseFunction* otf = property->GetScalarOpacity(0);
  os << "colour nodes:";
  for (int i = 0; i < ctf->GetSize(); ++i)
  {
    double v[6];
    ctf->GetNodeValue(i, v);
    os << " (" << v[0] << ": " << v[1] << ", " << v[2] << ", " << v[3] << ")";
  }
  os << "; opacity nodes:";
  for (int i = 0; i < otf->GetSize(); ++i)
  {
    double v[4];
    otf->GetNodeValue(i, v);
    os << " (" << v[0] << ": " << v[1] << ")";
  }
  os << "; unit distance " << property->GetScalarOpacityUnitDistance(0);
  return os.str();
}
}
