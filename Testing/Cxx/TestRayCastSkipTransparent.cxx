// vtkHighOrderVolumeMapper::SkipTransparentCells in RAY_CAST (default on): a
// composite, unshaded ray computes no interval in a cell whose rigorous field
// hull is invisible under the table. Against the same render with the option
// off:
//  - on the bundled order-4 plate (von Mises) with no opacity over the lowest
//    35% of its range: cells are flagged (none with the option off), fewer
//    segments are integrated, and every pixel agrees within the sum of the
//    two renders' per-pixel error estimates (the field error budget is spread
//    over the visible segments only, so the images may differ below it);
//  - under Wilhelms-Van Gelder emission with colour where there is no
//    opacity (glow), with volume shading under Wilhelms-Van Gelder (whose
//    specular term glows without colour or opacity), and with maximum
//    intensity blending nothing is flagged and the images are bit for bit the
//    same; under Wilhelms-Van Gelder with black colour there, and with
//    shading or gradient opacity under Williams-Max, cells are flagged;
//  - on a lattice of quadratic tetrahedra whose field (a paraboloid) peaks
//    between nodes, with opacity only above every node value: a cell is
//    flagged only if its Bernstein hull, not its node values, proves it
//    invisible, so the peak is drawn (a test of node values alone would
//    flag every cell and draw nothing). The mapper renders the plate first:
//    its flags must not be used for the lattice.
#include "hovTestAnalytic.h"
#include "hovTestImages.h"
#include "hovTestMixed.h"
#include "hovTestReferenceDatasets.h"
#include "hovTestScenes.h"

#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkPoints.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

using namespace hovTest;

namespace
{
std::string Num(double v)
{
  char text[32];
  std::snprintf(text, sizeof(text), "%.3g", v);
  return text;
}

struct Pair
{
  Image On, Off;
  std::vector<double> ErrorOn, ErrorOff;
  vtkIdType FlaggedOn = -1, FlaggedOff = -1, SegmentsOn = -1, SegmentsOff = -1;
  int Status[2] = { 0, 0 };
};

std::vector<double> ErrorImage(vtkHighOrderVolumeMapper* mapper)
{
  std::vector<double> e;
  vtkImageData* image = mapper->GetRayCastErrorImage();
  vtkDataArray* a = image ? image->GetPointData()->GetScalars() : nullptr;
  for (vtkIdType i = 0; a && i < a->GetNumberOfTuples(); ++i)
  {
    e.push_back(a->GetComponent(i, 0));
  }
  return e;
}

Pair RenderBoth(VolumeScene& scene, vtkCamera* camera, int w, int h)
{
  Pair p;
  vtkHighOrderVolumeMapper* mapper = scene.Mapper;
  mapper->SkipTransparentCellsOn();
  p.On = RenderDouble(mapper, camera, scene.Volume, w, h, &p.Status[0]);
  p.ErrorOn = ErrorImage(mapper);
  p.FlaggedOn = mapper->GetNumberOfTransparentCells();
  p.SegmentsOn = mapper->GetNumberOfSegments();
  mapper->SkipTransparentCellsOff();
  p.Off = RenderDouble(mapper, camera, scene.Volume, w, h, &p.Status[1]);
  p.ErrorOff = ErrorImage(mapper);
  p.FlaggedOff = mapper->GetNumberOfTransparentCells();
  p.SegmentsOff = mapper->GetNumberOfSegments();
  mapper->SkipTransparentCellsOn();
  return p;
}

/// Pixels whose channels differ by more than the two renders' error
/// estimates together (-1 if the images or error images do not match in size).
long long BeyondEstimates(const Pair& p)
{
  const size_t n = p.On.Pixels();
  if (p.Off.Pixels() != n || p.ErrorOn.size() != n || p.ErrorOff.size() != n || n == 0)
  {
    return -1;
  }
  long long beyond = 0;
  for (size_t i = 0; i < n; ++i)
  {
    const double allowed = p.ErrorOn[i] + p.ErrorOff[i] + 1e-12;
    for (int c = 0; c < 4; ++c)
    {
      if (!(std::abs(p.On.V[4 * i + c] - p.Off.V[4 * i + c]) <= allowed))
      {
        ++beyond;
        break;
      }
    }
  }
  return beyond;
}

std::string Counts(const Pair& p)
{
  return std::to_string(p.FlaggedOn) + " cells flagged (" + std::to_string(p.FlaggedOff) +
    " with the option off), segments " + std::to_string(p.SegmentsOn) + " against " +
    std::to_string(p.SegmentsOff);
}

/// Checks a pair in which nothing may be flagged: the same image bit for bit.
void CheckNothingFlagged(Checker& ck, const Pair& p, const std::string& what)
{
  const DiffStats d = Diff(p.On, p.Off, 0, 4, 0.0);
  ck.Check(p.Status[0] == 1 && p.Status[1] == 1 && p.FlaggedOn == 0 && p.FlaggedOff == 0 &&
      p.SegmentsOn == p.SegmentsOff && d.Max == 0 && p.On.Pixels() == p.Off.Pixels() &&
      CheckImage(p.On).Covered > 100,
    what + ": " + Counts(p) + ", max |diff| " + Num(d.Max));
}

/// Checks a pair in which cells must be flagged.
void CheckFlagged(Checker& ck, const Pair& p, const std::string& what, vtkIdType atLeast)
{
  const Sanity s = CheckImage(p.On);
  ck.Check(p.Status[0] == 1 && p.Status[1] == 1 && s.NonFinite == 0 && s.Covered > 100,
    what + ": rendered, " + std::to_string(s.Covered) + " covered pixels");
  ck.Check(p.FlaggedOn >= atLeast && p.FlaggedOff == 0 && p.SegmentsOn < p.SegmentsOff,
    what + ": " + Counts(p));
  const long long beyond = BeyondEstimates(p);
  ck.Check(beyond == 0,
    what + ": " + std::to_string(beyond) + " pixels differ by more than the error estimates, max |diff| " +
      Num(Diff(p.On, p.Off, 0, 4, 0.0).Max));
}

void PlateCamera(vtkCamera* cam, vtkUnstructuredGrid* grid)
{
  double b[6];
  grid->GetBounds(b);
  const double c[3] = { 0.5 * (b[0] + b[1]), 0.5 * (b[2] + b[3]), 0.5 * (b[4] + b[5]) };
  const double diag = std::sqrt((b[1] - b[0]) * (b[1] - b[0]) + (b[3] - b[2]) * (b[3] - b[2]) +
    (b[5] - b[4]) * (b[5] - b[4]));
  const double dir[3] = { 0.3, -0.5, 0.81 };
  cam->SetFocalPoint(c);
  cam->SetPosition(c[0] + 2.0 * diag * dir[0], c[1] + 2.0 * diag * dir[1], c[2] + 2.0 * diag * dir[2]);
  cam->SetViewUp(0, 0, 1);
  cam->SetViewAngle(30);
  cam->SetClippingRange(0.5 * diag, 4.0 * diag);
}

/// No opacity below lo + 0.35 span, and there black colour if @p blackBelow.
void PlateFunction(VolumeScene& scene, double lo, double hi, bool blackBelow)
{
  const double span = hi - lo, zero = lo + 0.35 * span;
  vtkColorTransferFunction* c = scene.Tf.Color;
  c->RemoveAllPoints();
  if (blackBelow)
  {
    c->AddRGBPoint(lo, 0.0, 0.0, 0.0);
    c->AddRGBPoint(zero, 0.0, 0.0, 0.0);
    c->AddRGBPoint(zero + 0.01 * span, 0.2, 0.9, 0.2);
  }
  else
  {
    c->AddRGBPoint(lo, 0.1, 0.2, 0.9);
    c->AddRGBPoint(lo + 0.5 * span, 0.2, 0.9, 0.2);
  }
  c->AddRGBPoint(hi, 0.9, 0.1, 0.1);
  vtkPiecewiseFunction* o = scene.Tf.Opacity;
  o->RemoveAllPoints();
  o->AddPoint(lo, 0.0);
  o->AddPoint(zero, 0.0);
  o->AddPoint(lo + 0.6 * span, 0.6);
  o->AddPoint(hi, 1.0);
}

/// The paraboloid 1 - |x - centre|^2 (exact on quadratic tetrahedra).
const double Centre[3] = { -0.26, 0.13, 0.02 };
double Peak(double x, double y, double z)
{
  return 1.0 - ((x - Centre[0]) * (x - Centre[0]) + (y - Centre[1]) * (y - Centre[1]) +
                 (z - Centre[2]) * (z - Centre[2]));
}

void TestPeakLattice(Checker& ck, vtkUnstructuredGrid* before)
{
  MeshBuilder m;
  const double o[3] = { -0.9, -0.8, -0.85 };
  const double a[3][3] = { { 0.45, 0.0, 0.0 }, { 0.0, 0.41, 0.0 }, { 0.0, 0.0, 0.44 } };
  const std::vector<vtkIdType> ids = AddLattice(m, 4, 4, 4, o, a, Peak);
  for (int k = 0; k < 4; ++k)
  {
    for (int j = 0; j < 4; ++j)
    {
      for (int i = 0; i < 4; ++i)
      {
        AddCube(m, LatticeCube(ids, 4, 4, i, j, k), CubeSplit::QuadraticTetras, Peak);
      }
    }
  }
  vtkSmartPointer<vtkUnstructuredGrid> grid = m.Grid();
  // The largest node value: the peak (1 at Centre) lies strictly above it.
  double top = -1e300;
  for (vtkIdType i = 0; i < grid->GetNumberOfPoints(); ++i)
  {
    double x[3];
    grid->GetPoints()->GetPoint(i, x);
    top = std::max(top, Peak(x[0], x[1], x[2]));
  }
  if (!ck.Check(top < 0.999 && top > 0.9, "peak lattice: largest node value " + std::to_string(top)))
  {
    return;
  }
  VolumeScene scene(grid);
  scene.Mapper->SetRenderModeToRayCast();
  DefaultTF(scene.Tf, 0.5);
  vtkPiecewiseFunction* op = scene.Tf.Opacity;
  op->RemoveAllPoints();
  const double threshold = top + 0.25 * (1.0 - top);
  op->AddPoint(-2.0, 0.0);
  op->AddPoint(threshold, 0.0);
  op->AddPoint(1.0, 1.0);
  scene.Tf.Property->SetScalarOpacityUnitDistance(0.02);
  vtkNew<vtkCamera> cam;
  const double up[3] = { 0, 0, 1 };
  const double dir[3] = { 0.5, -0.62, 0.6 };
  PlaceCamera(cam, Centre, dir, 3.0, up, false, 12.0);
  cam->SetClippingRange(0.5, 10.0);
  if (before)
  {
    // The same mapper on another input first: its flags (none here) must
    // not survive the caster's rebuild for the lattice.
    scene.Mapper->SetInputData(before);
    int status = 0;
    RenderDouble(scene.Mapper, cam, scene.Volume, 8, 8, &status);
    ck.Check(status == 1 && scene.Mapper->GetNumberOfRenderedCells() == before->GetNumberOfCells(),
      "peak lattice: another input rendered first by the same mapper");
    scene.Mapper->SetInputData(grid);
    scene.Observer->Clear();
  }
  const Pair p = RenderBoth(scene, cam, 40, 40);
  const Sanity s = CheckImage(p.On);
  ck.Check(p.Status[0] == 1 && p.Status[1] == 1 && s.Ok() && s.Covered > 10 && s.MaxA > 1e-4,
    "peak lattice: the peak between nodes is drawn, " + std::to_string(s.Covered) +
      " covered pixels, max alpha " + std::to_string(s.MaxA));
  ck.Check(p.FlaggedOn > grid->GetNumberOfCells() / 2 && p.FlaggedOn < grid->GetNumberOfCells() &&
      p.SegmentsOn < p.SegmentsOff,
    "peak lattice: " + Counts(p) + " of " + std::to_string(grid->GetNumberOfCells()) + " cells");
  ck.Check(BeyondEstimates(p) == 0,
    "peak lattice: images agree within the error estimates, max |diff| " +
      Num(Diff(p.On, p.Off, 0, 4, 0.0).Max));
  ck.Check(scene.NoMessages(), "peak lattice: no messages ('" + Msg(scene.Observer->GetWarningMessage()) + "')");
}
}

int TestRayCastSkipTransparent(int argc, char* argv[])
{
  Checker ck;
  const std::string data = ArgAfter(argc, argv, "-D", ".");
  vtkSmartPointer<vtkUnstructuredGrid> plate =
    hovTestRef::LoadDataset(data, "platehole_lagrange_hex_q4.vtu", "von_mises");
  if (ck.Check(plate && plate->GetNumberOfCells() == 192, "plate loaded"))
  {
    const double lo = 1.8, hi = 361.0;
    VolumeScene scene(plate);
    vtkHighOrderVolumeMapper* mapper = scene.Mapper;
    mapper->SetRenderModeToRayCast();
    mapper->SetOpacitySemanticsToVTKUnstructured();
    ck.Check(mapper->GetSkipTransparentCells(), "on by default");
    double b[6];
    plate->GetBounds(b);
    scene.Tf.Property->SetScalarOpacityUnitDistance(0.05 * (b[1] - b[0]));
    vtkNew<vtkCamera> cam;
    PlateCamera(cam, plate);
    const int size = 64;

    PlateFunction(scene, lo, hi, false);
    CheckFlagged(ck, RenderBoth(scene, cam, size, size), "plate, Williams-Max", 20);
    mapper->SetEmissionModelToWilhelmsVanGelder();
    CheckNothingFlagged(ck, RenderBoth(scene, cam, size, size), "plate, Wilhelms-Van Gelder, glow");
    PlateFunction(scene, lo, hi, true);
    CheckFlagged(ck, RenderBoth(scene, cam, size, size), "plate, Wilhelms-Van Gelder, black", 20);
    // Shaded under Wilhelms-Van Gelder: the specular term glows where there is
    // neither colour nor opacity, so nothing may be skipped.
    scene.Tf.Property->ShadeOn();
    scene.Tf.Property->SetSpecular(0.6);
    {
      const Pair p = RenderBoth(scene, cam, size, size);
      CheckNothingFlagged(ck, p, "plate, shaded, Wilhelms-Van Gelder");
      ck.Check(GlowPixels(p.Off) > 50,
        "plate, shaded, Wilhelms-Van Gelder: " + std::to_string(GlowPixels(p.Off)) +
          " pixels glow without opacity");
    }
    mapper->SetEmissionModelToWilliamsMax();
    CheckFlagged(ck, RenderBoth(scene, cam, size, size), "plate, shaded, Williams-Max", 20);
    scene.Tf.Property->ShadeOff();
    vtkNew<vtkPiecewiseFunction> gradient;
    gradient->AddPoint(0.0, 0.2);
    gradient->AddPoint(50.0, 1.0);
    scene.Tf.Property->SetGradientOpacity(gradient);
    scene.Tf.Property->DisableGradientOpacityOff();
    CheckFlagged(ck, RenderBoth(scene, cam, size, size), "plate, gradient opacity", 20);
    scene.Tf.Property->DisableGradientOpacityOn();
    PlateFunction(scene, lo, hi, false);
    mapper->SetBlendModeToMaximumIntensity();
    CheckNothingFlagged(ck, RenderBoth(scene, cam, size, size), "plate, maximum intensity");
    mapper->SetBlendModeToComposite();
    ck.Check(scene.NoMessages(), "plate: no messages ('" + Msg(scene.Observer->GetWarningMessage()) + "')");
  }
  TestPeakLattice(ck, plate && plate->GetNumberOfCells() > 0 ? plate.Get() : nullptr);
  return ck.Result();
}
