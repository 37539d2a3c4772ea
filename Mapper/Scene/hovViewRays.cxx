#include "hovViewRays.h"

#include "vtkAbstractMapper3D.h"
#include "vtkCamera.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"

#include <algorithm> // std::min, std::max
#include <cmath>     // std::isfinite, std::sqrt

// No contraction into fused multiply-adds in this file (whatever -march a
// build uses): RowRays() and PixelRay() must round every operation alike.
#if defined(__clang__)
#pragma STDC FP_CONTRACT OFF
#elif defined(__GNUC__)
#pragma GCC optimize("fp-contract=off")
#endif

namespace
{
/// VTK matrices are row-major with column vectors; glm is column-major.
glm::dmat4 ToGlm(const vtkMatrix4x4* m)
{
  glm::dmat4 g(1.0);
  if (m)
  {
    for (int r = 0; r < 4; ++r)
    {
      for (int c = 0; c < 4; ++c)
      {
        g[c][r] = m->GetElement(r, c);
      }
    }
  }
  return g;
}
}

bool hov::ViewRays::Setup(
  vtkCamera* camera, vtkMatrix4x4* volumeMatrix, int width, int height, double aspect)
{
  if (!camera || width <= 0 || height <= 0 || !(aspect > 0.0))
  {
    return false;
  }
  this->Width = width;
  this->Height = height;
  // World -> NDC (z in [-1, 1]), as OpenGL uses it.
  const glm::dmat4 worldToClip =
    ToGlm(camera->GetCompositeProjectionTransformMatrix(aspect, -1.0, 1.0));
  this->DataToClip = worldToClip * ToGlm(volumeMatrix);
  const double det = glm::determinant(this->DataToClip);
  if (!std::isfinite(det) || det == 0.0)
  {
    return false;
  }
  this->ClipToData = glm::inverse(this->DataToClip);
  const glm::dvec3 nearC = this->Unproject(0.0, 0.0, -1.0);
  const glm::dvec3 farC = this->Unproject(0.0, 0.0, 1.0);
  this->DepthScale = glm::length(farC - nearC);
  this->PerturbX = this->Unproject(1.0, 0.0, -1.0) - nearC;
  this->PerturbY = this->Unproject(0.0, 1.0, -1.0) - nearC;
  return std::isfinite(this->DepthScale) && this->DepthScale > 0.0;
}

glm::dvec3 hov::ViewRays::Unproject(double xNdc, double yNdc, double zNdc) const
{
  const glm::dvec4 h = this->ClipToData * glm::dvec4(xNdc, yNdc, zNdc, 1.0);
  return glm::dvec3(h) / h.w;
}

hov::ViewRays::Ray hov::ViewRays::PixelRay(int i, int j) const
{
  const double x = 2.0 * (i + 0.5) / this->Width - 1.0;
  const double y = 2.0 * (j + 0.5) / this->Height - 1.0;
  Ray ray;
  ray.Origin = this->Unproject(x, y, -1.0);
  const glm::dvec3 delta = this->Unproject(x, y, 1.0) - ray.Origin;
  ray.TFar = glm::length(delta);
  ray.Direction = delta / ray.TFar;
  return ray;
}

#if defined(__GNUC__) // GCC and Clang: vector extensions
namespace
{
typedef double V4 __attribute__((vector_size(4 * sizeof(double))));

/// glm's mat4 * vec4 (x, y, z, 1) and the division by w, one pixel per lane
/// (y and z shared): ((m0 x + m1 y) + (m2 z + m3 1)) per component.
inline void UnprojectLanes(const glm::dmat4& m, const V4& x, double y, double z, V4 out[3])
{
  V4 h[4];
  for (int c = 0; c < 4; ++c)
  {
    h[c] = (m[0][c] * x + m[1][c] * y) + (m[2][c] * z + m[3][c] * 1.0);
  }
  for (int c = 0; c < 3; ++c)
  {
    out[c] = h[c] / h[3];
  }
}
}

void hov::ViewRays::RowRays(int i0, int j, int count, Ray* rays) const
{
  const double y = 2.0 * (j + 0.5) / this->Height - 1.0;
  int k = 0;
  for (; k + 4 <= count; k += 4)
  {
    const double base = i0 + k;
    const V4 i = V4{ 0.0, 1.0, 2.0, 3.0 } + base; // exact: small integers
    const V4 x = 2.0 * (i + 0.5) / this->Width - 1.0;
    V4 o[3], f[3], d[3];
    UnprojectLanes(this->ClipToData, x, y, -1.0, o);
    UnprojectLanes(this->ClipToData, x, y, 1.0, f);
    for (int c = 0; c < 3; ++c)
    {
      d[c] = f[c] - o[c];
    }
    // glm::length: sqrt((x x + y y) + z z).
    const V4 squared = (d[0] * d[0] + d[1] * d[1]) + d[2] * d[2];
    V4 tFar;
    for (int l = 0; l < 4; ++l)
    {
      tFar[l] = std::sqrt(squared[l]);
    }
    for (int c = 0; c < 3; ++c)
    {
      d[c] = d[c] / tFar;
    }
    for (int l = 0; l < 4; ++l)
    {
      Ray& ray = rays[k + l];
      ray.Origin = glm::dvec3(o[0][l], o[1][l], o[2][l]);
      ray.Direction = glm::dvec3(d[0][l], d[1][l], d[2][l]);
      ray.TFar = tFar[l];
    }
  }
  for (; k < count; ++k)
  {
    rays[k] = this->PixelRay(i0 + k, j);
  }
}
#else
void hov::ViewRays::RowRays(int i0, int j, int count, Ray* rays) const
{
  for (int k = 0; k < count; ++k)
  {
    rays[k] = this->PixelRay(i0 + k, j);
  }
}
#endif

double hov::ViewRays::DepthToT(int i, int j, const Ray& ray, double windowDepth) const
{
  const double x = 2.0 * (i + 0.5) / this->Width - 1.0;
  const double y = 2.0 * (j + 0.5) / this->Height - 1.0;
  const glm::dvec3 p = this->Unproject(x, y, 2.0 * windowDepth - 1.0);
  return glm::dot(p - ray.Origin, ray.Direction);
}

bool hov::ViewRays::Project(const glm::dvec3& p, double& xWindow, double& yWindow) const
{
  const glm::dvec4 c = this->DataToClip * glm::dvec4(p, 1.0);
  if (!(c.w > 0.0))
  {
    return false;
  }
  xWindow = (c.x / c.w + 1.0) * 0.5 * this->Width;
  yWindow = (c.y / c.w + 1.0) * 0.5 * this->Height;
  return std::isfinite(xWindow) && std::isfinite(yWindow);
}

void hov::ViewRays::ClipRange(const Ray& ray, double& tMin, double& tMax) const
{
  for (const glm::dvec4& plane : this->ClipPlanes)
  {
    const glm::dvec3 normal(plane);
    // Kept where value(t) = num + t slope >= 0.
    const double num = glm::dot(normal, ray.Origin) + plane.w;
    const double slope = glm::dot(normal, ray.Direction);
    if (slope > 0.0)
    {
      tMin = std::max(tMin, -num / slope);
    }
    else if (slope < 0.0)
    {
      tMax = std::min(tMax, -num / slope);
    }
    else if (num < 0.0)
    {
      tMax = tMin; // parallel and outside
    }
  }
}

int hov::ViewRays::SetupClipping(vtkAbstractMapper3D* mapper, vtkCamera* camera,
  vtkMatrix4x4* volumeMatrix, const double* viewDepthRange)
{
  this->ClipPlanes.clear();
  vtkNew<vtkMatrix4x4> identity;
  vtkMatrix4x4* matrix = volumeMatrix ? volumeMatrix : identity.Get();
  int ignored = 0;
  for (int i = 0; mapper && i < mapper->GetNumberOfClippingPlanes(); ++i)
  {
    double h[4];
    mapper->GetClippingPlaneInDataCoords(matrix, i, h);
    const bool finite =
      std::isfinite(h[0]) && std::isfinite(h[1]) && std::isfinite(h[2]) && std::isfinite(h[3]);
    if (!finite || (h[0] == 0.0 && h[1] == 0.0 && h[2] == 0.0))
    {
      ++ignored; // NaN would keep every bound unchanged, a zero normal clip nothing
      continue;
    }
    this->ClipPlanes.emplace_back(h[0], h[1], h[2], h[3]);
  }
  if (viewDepthRange && camera)
  {
    double eye[3], dop[3];
    camera->GetPosition(eye);
    camera->GetDirectionOfProjection(dop);
    const double depthOfEye = vtkMath::Dot(dop, eye);
    // Near: dop.x - (dop.eye + near) >= 0; far: -dop.x + (dop.eye + far) >= 0.
    const double world[2][4] = { { dop[0], dop[1], dop[2], -(depthOfEye + viewDepthRange[0]) },
      { -dop[0], -dop[1], -dop[2], depthOfEye + viewDepthRange[1] } };
    for (const double* w : world)
    {
      // World to data: h_data = M^T h_world (M: data to world).
      double h[4] = { 0.0, 0.0, 0.0, 0.0 };
      for (int c = 0; c < 4; ++c)
      {
        for (int r = 0; r < 4; ++r)
        {
          h[c] += w[r] * matrix->GetElement(r, c);
        }
      }
      this->ClipPlanes.emplace_back(h[0], h[1], h[2], h[3]);
    }
  }
  return ignored;
}

hov::ViewRays::Ray hov::ViewRays::TracedPixelRay(
  int i, int j, double windowDepth, double& tMax) const
{
  Ray ray = this->PixelRay(i, j);
  tMax = ray.TFar;
  if (windowDepth < 1.0)
  {
    tMax = std::min(tMax, this->DepthToT(i, j, ray, windowDepth));
  }
  if (this->HasClipping())
  {
    double tMin = 0.0;
    this->ClipRange(ray, tMin, tMax);
    ray.Origin += tMin * ray.Direction;
    tMax = tMax > tMin ? tMax - tMin : 0.0;
  }
  return ray;
}
