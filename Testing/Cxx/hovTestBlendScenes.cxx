#include "hovTestBlendScenes.h"

#include "vtkCamera.h"
#include "vtkCellType.h"

void hovTest::BlendCamera(vtkCamera* cam)
{
  cam->SetPosition(3.1, 2.3, 4.4);
  cam->SetFocalPoint(0.05, -0.03, 0.02);
  cam->SetViewUp(0, 1, 0);
  cam->SetViewAngle(32);
  cam->SetClippingRange(1.0, 20.0);
}

void hovTest::BlendTF(TF& tf)
{
  tf.Color->AddRGBPoint(-0.2, 0.9, 0.2, 0.1);
  tf.Color->AddRGBPoint(0.55, 0.2, 0.9, 0.3);
  tf.Color->AddRGBPoint(1.4, 0.1, 0.3, 0.95);
  tf.Opacity->AddPoint(-0.2, 0.1);
  tf.Opacity->AddPoint(0.4, 0.75);
  tf.Opacity->AddPoint(0.9, 0.35);
  tf.Opacity->AddPoint(1.4, 0.9);
  tf.Property->SetScalarOpacityUnitDistance(0.5);
}

vtkSmartPointer<vtkUnstructuredGrid> hovTest::TriquadraticHex(
  const std::function<double(double, double, double)>& f)
{
  // VTK's node order: corners, edges, face centres, body centre (parametric).
  const double pc[27][3] = { { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 0 }, { 0, 0, 1 },
    { 1, 0, 1 }, { 1, 1, 1 }, { 0, 1, 1 }, { .5, 0, 0 }, { 1, .5, 0 }, { .5, 1, 0 }, { 0, .5, 0 },
    { .5, 0, 1 }, { 1, .5, 1 }, { .5, 1, 1 }, { 0, .5, 1 }, { 0, 0, .5 }, { 1, 0, .5 },
    { 1, 1, .5 }, { 0, 1, .5 }, { 0, .5, .5 }, { 1, .5, .5 }, { .5, 0, .5 }, { .5, 1, .5 },
    { .5, .5, 0 }, { .5, .5, 1 }, { .5, .5, .5 } };
  MeshBuilder m;
  std::vector<vtkIdType> ids;
  for (const auto& p : pc)
  {
    const double x = 2 * p[0] - 1, y = 2 * p[1] - 1, z = 2 * p[2] - 1;
    ids.push_back(m.AddPoint(x, y, z, f(x, y, z)));
  }
  m.AddCell(VTK_TRIQUADRATIC_HEXAHEDRON, ids);
  return m.Grid();
}
