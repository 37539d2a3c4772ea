#include "hovViewCheck.h"

#include "vtkCamera.h"
#include "vtkMatrix4x4.h"

#include <cmath>   // std::isfinite, std::sqrt
#include <sstream> // the reason

namespace
{
bool Finite(const double* v, int n)
{
  for (int i = 0; i < n; ++i)
  {
    if (!std::isfinite(v[i]))
    {
      return false;
    }
  }
  return true;
}

std::string Vec(const double* v)
{
  std::ostringstream s;
  s << "(" << v[0] << ", " << v[1] << ", " << v[2] << ")";
  return s.str();
}
}

std::string hov::CheckView(vtkCamera* camera, vtkMatrix4x4* volumeMatrix, double aspect)
{
  if (!camera)
  {
    return "no camera";
  }
  double position[3], focal[3], up[3], range[2];
  camera->GetPosition(position);
  camera->GetFocalPoint(focal);
  camera->GetViewUp(up);
  camera->GetClippingRange(range);
  if (!Finite(position, 3))
  {
    return "the camera position " + Vec(position) + " is not finite";
  }
  if (!Finite(focal, 3))
  {
    return "the camera focal point " + Vec(focal) + " is not finite";
  }
  if (!Finite(up, 3))
  {
    return "the camera view-up vector " + Vec(up) + " is not finite";
  }
  const double d[3] = { focal[0] - position[0], focal[1] - position[1], focal[2] - position[2] };
  const double dd = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
  if (!(dd > 0.0) || !std::isfinite(dd))
  {
    return "the camera position equals its focal point " + Vec(focal) +
      " (no direction of projection)";
  }
  // |up x d| relative to |up| |d|: the sine of their angle.
  const double c[3] = { up[1] * d[2] - up[2] * d[1], up[2] * d[0] - up[0] * d[2],
    up[0] * d[1] - up[1] * d[0] };
  const double uu = up[0] * up[0] + up[1] * up[1] + up[2] * up[2];
  const double cc = c[0] * c[0] + c[1] * c[1] + c[2] * c[2];
  if (!(cc > 1e-24 * uu * dd))
  {
    return "the camera view-up vector " + Vec(up) +
      " is zero or parallel to the direction of projection";
  }
  if (camera->GetParallelProjection())
  {
    const double scale = camera->GetParallelScale();
    if (!(scale > 0.0) || !std::isfinite(scale))
    {
      std::ostringstream s;
      s << "the camera's parallel scale " << scale << " is not a positive finite number";
      return s.str();
    }
  }
  else if (!(camera->GetViewAngle() > 0.0 && camera->GetViewAngle() < 180.0))
  {
    std::ostringstream s;
    s << "the camera's view angle " << camera->GetViewAngle() << " is not in (0, 180) degrees";
    return s.str();
  }
  const bool nearOk = camera->GetParallelProjection() ? std::isfinite(range[0]) : range[0] > 0.0;
  if (!Finite(range, 2) || !nearOk || !(range[1] > range[0]))
  {
    std::ostringstream s;
    s << "the camera's clipping range [" << range[0] << ", " << range[1] << "] is not a finite "
      << "interval with near < far" << (camera->GetParallelProjection() ? "" : " and near > 0");
    return s.str();
  }
  if (!(aspect > 0.0) || !std::isfinite(aspect))
  {
    std::ostringstream s;
    s << "the aspect ratio " << aspect << " is not a positive finite number";
    return s.str();
  }
  if (volumeMatrix)
  {
    const double* m = volumeMatrix->GetData();
    if (!Finite(m, 16) || vtkMatrix4x4::Determinant(m) == 0.0)
    {
      return "the volume's matrix is singular or not finite";
    }
  }
  vtkMatrix4x4* composite = camera->GetCompositeProjectionTransformMatrix(aspect, -1.0, 1.0);
  const double* m = composite->GetData();
  const double det = vtkMatrix4x4::Determinant(m);
  if (!Finite(m, 16) || !std::isfinite(det) || det == 0.0)
  {
    return "the camera's projection matrix is singular or not finite";
  }
  return std::string();
}
