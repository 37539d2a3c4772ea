// RAY_CAST on the two real curved order-4 datasets (issue 6 acceptance 3):
// platehole_lagrange_hex_q4.vtu (192 Lagrange hexahedra, von_mises) and
// tjunction_lagrange_tet_p4.vtu (3790 Lagrange tetrahedra, speed), oblique
// perspective views, small images (the caster costs ~1-50 ms per ray on this
// machine: see hovCurvedRayCaster.h). Checked: every cell used, no message,
// finite premultiplied pixels, a visible image, the error image's maximum
// within the 1e-3 tolerance. Times printed, not checked. "-T dir" writes PNGs.
#include "hovTestReferenceDatasets.h"
#include "hovTestScenes.h"

#include "vtkCamera.h"
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkPointData.h"

#include <algorithm>
#include <cmath>
#include <iostream>

using namespace hovTest;

namespace
{
void RenderDataset(Checker& ck, vtkUnstructuredGrid* grid, const std::string& name, double lo,
  double hi, const double direction[3], int size, const std::string& png)
{
  VolumeScene scene(grid);
  scene.Mapper->SetRenderModeToRayCast();
  scene.Mapper->SetOpacitySemanticsToVTKUnstructured();
  const double span = hi - lo;
  scene.Tf.Color->AddRGBPoint(lo, 0.1, 0.2, 0.9);
  scene.Tf.Color->AddRGBPoint(lo + 0.5 * span, 0.2, 0.9, 0.2);
  scene.Tf.Color->AddRGBPoint(hi, 0.9, 0.1, 0.1);
  scene.Tf.Opacity->AddPoint(lo, 0.0);
  scene.Tf.Opacity->AddPoint(lo + 0.3 * span, 0.2);
  scene.Tf.Opacity->AddPoint(lo + 0.6 * span, 0.6);
  scene.Tf.Opacity->AddPoint(hi, 1.0);
  double b[6];
  grid->GetBounds(b);
  const double c[3] = { 0.5 * (b[0] + b[1]), 0.5 * (b[2] + b[3]), 0.5 * (b[4] + b[5]) };
  const double diag = std::sqrt((b[1] - b[0]) * (b[1] - b[0]) + (b[3] - b[2]) * (b[3] - b[2]) +
    (b[5] - b[4]) * (b[5] - b[4]));
  scene.Tf.Property->SetScalarOpacityUnitDistance(0.05 * (b[1] - b[0]));
  vtkNew<vtkCamera> cam;
  cam->SetFocalPoint(c);
  cam->SetPosition(c[0] + 2.0 * diag * direction[0], c[1] + 2.0 * diag * direction[1],
    c[2] + 2.0 * diag * direction[2]);
  cam->SetViewUp(0, 0, 1);
  cam->SetViewAngle(30);
  cam->SetClippingRange(0.5 * diag, 4.0 * diag);
  int status = 0;
  const Image img = Render(scene.Mapper, cam, scene.Volume, size, size, &status);
  const Sanity s = CheckImage(img);
  vtkDataArray* e = scene.Mapper->GetRayCastErrorImage()->GetPointData()->GetScalars();
  double maxError = -1.0;
  for (vtkIdType i = 0; e && i < e->GetNumberOfTuples(); ++i)
  {
    maxError = std::max(maxError, e->GetComponent(i, 0));
  }
  std::cout << "[measured] " << name << " RAY_CAST " << size << "x" << size << ": "
            << scene.Mapper->GetLastImageTime() << " s (incl. first-frame set-up), " << s.Str()
            << ", max error estimate " << maxError << std::endl;
  ck.Check(status == 1 && scene.NoMessages(),
    name + ": no error or warning ('" + Msg(scene.Observer->GetWarningMessage()) + "')");
  ck.Check(scene.Mapper->GetNumberOfSkippedCells() == 0 &&
      scene.Mapper->GetNumberOfRenderedCells() == grid->GetNumberOfCells(),
    name + ": every cell used");
  ck.Check(s.Ok() && s.Covered > img.Pixels() / 10 && s.MaxA > 0.05,
    name + ": finite, premultiplied, visible");
  ck.Check(maxError >= 0.0 && maxError <= 1e-3, name + ": error estimate <= 1e-3");
  if (!png.empty())
  {
    WritePNG(img, png);
  }
}
}

int TestRayCastDatasets(int argc, char* argv[])
{
  Checker ck;
  const std::string data = ArgAfter(argc, argv, "-D", ".");
  const std::string tmp = ArgAfter(argc, argv, "-T", "");
  struct Set
  {
    const char* File;
    const char* Array;
    int Cells;
    double Lo, Hi;
    double Direction[3];
    int Size;
  };
  const Set sets[2] = {
    { "platehole_lagrange_hex_q4.vtu", "von_mises", 192, 1.8, 361.0, { 0.3, -0.5, 0.81 }, 32 },
    { "tjunction_lagrange_tet_p4.vtu", "speed", 3790, 0.05, 2.63, { 0.35, -0.8, 0.49 }, 16 }
  };
  for (const Set& set : sets)
  {
    vtkSmartPointer<vtkUnstructuredGrid> grid = hovTestRef::LoadDataset(data, set.File, set.Array);
    if (!ck.Check(grid->GetNumberOfCells() == set.Cells && grid->GetPointData()->GetScalars(),
          std::string(set.File) + ": loaded"))
    {
      continue;
    }
    RenderDataset(ck, grid, set.File, set.Lo, set.Hi, set.Direction, set.Size,
      tmp.empty() ? std::string() : tmp + "/raycast_" + set.File + ".png");
  }
  return ck.Result();
}
