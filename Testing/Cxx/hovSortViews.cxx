// The random numbers, views, cameras and model transform of the sort tests
// (declared in hovSortMeshes.h beside the meshes they look at).
#include "hovSortMeshes.h"

#include "vtkCamera.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkTransform.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace hovTest
{
//------------------------------------------------------------------------------
SortRandom::SortRandom(unsigned seed)
  : State(0x9E3779B97F4A7C15ull ^ (static_cast<unsigned long long>(seed) * 0xBF58476D1CE4E5B9ull))
{
}

double SortRandom::Uniform()
{
  // splitmix64: the same stream on every platform.
  unsigned long long z = (this->State += 0x9E3779B97F4A7C15ull);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  z ^= z >> 31;
  return static_cast<double>(z >> 11) * (1.0 / 9007199254740992.0);
}

//------------------------------------------------------------------------------
void FigureCamera(vtkCamera* cam, bool parallel)
{
  cam->SetFocalPoint(0, 0, -10);
  cam->SetPosition(0, 0, 50);
  cam->SetViewUp(0, 1, 0);
  cam->SetViewAngle(40);
  cam->SetParallelProjection(parallel);
  cam->SetParallelScale(15);
  cam->SetClippingRange(1, 200);
}

//------------------------------------------------------------------------------
void SortView::Apply(vtkCamera* cam) const
{
  cam->SetPosition(this->Position);
  cam->SetFocalPoint(this->FocalPoint);
  cam->SetViewUp(this->ViewUp);
  cam->SetViewAngle(this->ViewAngle);
  cam->SetParallelProjection(this->Parallel);
  double d[3];
  for (int j = 0; j < 3; ++j)
  {
    d[j] = this->Position[j] - this->FocalPoint[j];
  }
  const double dist = vtkMath::Norm(d);
  cam->SetParallelScale(0.3 * dist);
  cam->SetClippingRange(1e-3 * dist, 10 * dist);
}

std::vector<SortView> RandomViews(const double b[6], int count, unsigned seed)
{
  SortRandom rng(seed);
  std::vector<SortView> views;
  const double ctr[3] = { 0.5 * (b[0] + b[1]), 0.5 * (b[2] + b[3]), 0.5 * (b[4] + b[5]) };
  const double radius =
    0.5 * std::sqrt((b[1] - b[0]) * (b[1] - b[0]) + (b[3] - b[2]) * (b[3] - b[2]) +
            (b[5] - b[4]) * (b[5] - b[4]));
  for (int v = 0; v < count; ++v)
  {
    SortView view;
    const double z = rng.Uniform(-1, 1), phi = rng.Uniform(0, 2 * vtkMath::Pi());
    const double r = std::sqrt(std::max(0.0, 1 - z * z));
    const double dir[3] = { r * std::cos(phi), r * std::sin(phi), z };
    const double dist = radius * rng.Uniform(2.5, 4.0);
    view.Parallel = v % 2 == 1;
    view.Name = std::string(view.Parallel ? "parallel" : "perspective") + " random " +
      std::to_string(v);
    for (int j = 0; j < 3; ++j)
    {
      view.FocalPoint[j] = ctr[j] + 0.1 * radius * rng.Uniform(-1, 1);
      view.Position[j] = view.FocalPoint[j] + dist * dir[j];
    }
    // An up vector not parallel to the view direction.
    const double up[3] = { std::abs(dir[2]) < 0.9 ? 0.0 : 1.0, 0.0,
      std::abs(dir[2]) < 0.9 ? 1.0 : 0.0 };
    std::copy(up, up + 3, view.ViewUp);
    views.push_back(view);
  }
  return views;
}

SortView InsideView(const std::string& name, const double eye[3], const double focal[3])
{
  SortView v;
  v.Name = name;
  std::copy(eye, eye + 3, v.Position);
  std::copy(focal, focal + 3, v.FocalPoint);
  double d[3] = { focal[0] - eye[0], focal[1] - eye[1], focal[2] - eye[2] };
  vtkMath::Normalize(d);
  const double up[3] = { std::abs(d[2]) < 0.9 ? 0.0 : 1.0, 0.0, std::abs(d[2]) < 0.9 ? 1.0 : 0.0 };
  std::copy(up, up + 3, v.ViewUp);
  v.ViewAngle = 60;
  return v;
}

void TestModelTransform(vtkMatrix4x4* m)
{
  vtkNew<vtkTransform> t;
  t->Translate(3, -2, 1);
  t->RotateWXYZ(37, 0.3, -1, 0.5);
  t->Scale(1.5, 0.7, 1.2);
  m->DeepCopy(t->GetMatrix());
}
}
