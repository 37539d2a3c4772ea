// vtkHighOrderVolumeMapper::SkipTransparentCells (CPU_ACCURATE, default on)
// skips each tetrahedron whose scalar range lies where the transfer function
// has no extinction. On the bundled bracket (von Mises stress, 203 x 157) with
// no opacity below 17.3 MPa, against the same render with the option off:
//  - in each opacity semantics, both cell orderings and both ways of building
//    the cell records, many cells are skipped (and none with the option off),
//    fewer segments are integrated, and the double images agree to 1e-12
//    (each skipped segment is exactly zero; only the round-off of a computed
//    scalar just outside a cell's range can differ);
//  - under Wilhelms-Van Gelder emission (glow without extinction) and with a
//    transfer function that absorbs everywhere nothing is skipped and the
//    images are bit for bit the same;
//  - with no extinction over the whole data range every cell is skipped, the
//    image is empty, and the mapper says why, as it does with the option off;
//  - on a lattice of hexahedra, wedges and pyramids (linear: the field stays
//    within the node values) the low cells are skipped too, with the same
//    image to 1e-12; on a lattice of quadratic tetrahedra (whose field can
//    leave the node range) none is, and the images are bit for bit the same.
#include "hovTestAnalytic.h"
#include "hovTestImages.h"
#include "hovTestMixed.h"
#include "hovTestScenes.h"

#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkPiecewiseFunction.h"

#include <algorithm>
#include <cmath>
#include <string>

using namespace hovTest;

namespace
{
/// The bracket's opacity with none below @p zeroBelow (nodes 0 and that value at 0).
void SetOpacity(VolumeScene& scene, double zeroBelow)
{
  vtkPiecewiseFunction* o = scene.Tf.Opacity;
  o->RemoveAllPoints();
  o->AddPoint(0.0, 0.0);
  o->AddPoint(zeroBelow, 0.0);
  const double nodes[3][2] = { { 30.0, 0.3 }, { 80.0, 0.6 }, { 170.0, 0.9 } };
  for (const auto& n : nodes)
  {
    if (n[0] > zeroBelow)
    {
      o->AddPoint(n[0], n[1]);
    }
  }
}

struct Pair
{
  Image On, Off;
  vtkIdType SkippedOn = -1, SkippedOff = -1, SegmentsOn = -1, SegmentsOff = -1;
  int Status[2] = { 0, 0 };
};

Pair RenderBoth(VolumeScene& scene, vtkCamera* camera, int w = 203, int h = 157)
{
  Pair p;
  vtkHighOrderVolumeMapper* mapper = scene.Mapper;
  mapper->SkipTransparentCellsOn();
  p.On = RenderDouble(mapper, camera, scene.Volume, w, h, &p.Status[0]);
  p.SkippedOn = mapper->GetNumberOfTransparentCells();
  p.SegmentsOn = mapper->GetNumberOfSegments();
  mapper->SkipTransparentCellsOff();
  p.Off = RenderDouble(mapper, camera, scene.Volume, w, h, &p.Status[1]);
  p.SkippedOff = mapper->GetNumberOfTransparentCells();
  p.SegmentsOff = mapper->GetNumberOfSegments();
  mapper->SkipTransparentCellsOn();
  return p;
}

double Field(double x, double y, double z)
{
  return 0.5 + 0.4 * x - 0.3 * y + 0.25 * z + 0.2 * x * y;
}

/// A 4x4x4 lattice of skewed cubes, each split as @p splits (in turn).
MeshBuilder Lattice(const std::vector<CubeSplit>& splits)
{
  MeshBuilder m;
  const double o[3] = { -0.9, -0.8, -0.85 };
  const double a[3][3] = { { 0.45, 0.04, 0.0 }, { -0.03, 0.41, 0.05 }, { 0.04, 0.0, 0.44 } };
  const std::vector<vtkIdType> ids = AddLattice(m, 4, 4, 4, o, a, Field);
  size_t n = 0;
  for (int k = 0; k < 4; ++k)
  {
    for (int j = 0; j < 4; ++j)
    {
      for (int i = 0; i < 4; ++i)
      {
        AddCube(m, LatticeCube(ids, 4, 4, i, j, k), splits[n++ % splits.size()], Field);
      }
    }
  }
  return m;
}

/// Renders @p lattice with no opacity below 0.45 both ways; returns the pair.
Pair RenderLattice(Checker& ck, const MeshBuilder& lattice, const std::string& label)
{
  VolumeScene scene(lattice.Grid());
  DefaultTF(scene.Tf, 0.5);
  vtkPiecewiseFunction* o = scene.Tf.Opacity;
  o->RemoveAllPoints();
  o->AddPoint(-1.0, 0.0);
  o->AddPoint(0.45, 0.0);
  o->AddPoint(0.6, 0.5);
  o->AddPoint(1.75, 0.8);
  scene.Mapper->SetRenderModeToCPUAccurate();
  vtkNew<vtkCamera> cam;
  const double focal[3] = { 0.0, 0.0, 0.0 };
  const double dir[3] = { 0.5, -0.62, 0.6 };
  const double up[3] = { 0, 0, 1 };
  PlaceCamera(cam, focal, dir, 5.0, up, false, 36.0);
  cam->SetClippingRange(1.0, 20.0);
  const Pair p = RenderBoth(scene, cam, 96, 80);
  ck.Check(p.Status[0] == 1 && p.Status[1] == 1 && CheckImage(p.On).Covered > 96 * 80 / 10 &&
      scene.NoMessages(),
    label + ": rendered, " + std::to_string(CheckImage(p.On).Covered) + " covered pixels, " +
      std::to_string(scene.Mapper->GetNumberOfRenderedCells()) + " cells, messages '" +
      Msg(scene.Observer->GetWarningMessage()) + "'");
  return p;
}
}

int TestSkipTransparentCells(int argc, char* argv[])
{
  Checker ck;
  std::unique_ptr<VolumeScene> bracket = BracketScene(ck, argc, argv);
  if (!bracket)
  {
    return ck.Result();
  }
  vtkHighOrderVolumeMapper* mapper = bracket->Mapper;
  mapper->SetRenderModeToCPUAccurate();
  ck.Check(mapper->GetSkipTransparentCells(), "on by default");
  vtkNew<vtkCamera> camera;
  BracketCamera(camera);
  const vtkIdType cells = 56071; // the bracket's tetrahedra

  SetOpacity(*bracket, 17.3);
  for (const int semantics : { vtkHighOrderVolumeMapper::GPU_COMPATIBLE,
         vtkHighOrderVolumeMapper::VTK_UNSTRUCTURED, vtkHighOrderVolumeMapper::RAW_EXTINCTION })
  {
    mapper->SetOpacitySemantics(semantics);
    for (const int order :
      { vtkHighOrderVolumeMapper::VISIBILITY_SORT, vtkHighOrderVolumeMapper::PER_PIXEL_SORT })
    {
      mapper->SetCellOrdering(order);
      for (const int memory : { 256, 0 })
      {
        mapper->SetCellRecordMemory(memory);
        const std::string what = "semantics " + std::to_string(semantics) + ", ordering " +
          std::to_string(order) + ", records " + std::to_string(memory) + " MiB";
        const Pair p = RenderBoth(*bracket, camera);
        const Sanity sane = CheckImage(p.On);
        ck.Check(p.Status[0] == 1 && p.Status[1] == 1 && sane.NonFinite == 0 &&
            sane.Covered > 1000,
          what + ": rendered, " + std::to_string(sane.Covered) + " covered pixels");
        ck.Check(p.SkippedOn > cells / 4 && p.SkippedOn < cells && p.SkippedOff == 0,
          what + ": " + std::to_string(p.SkippedOn) + " cells skipped (" +
            std::to_string(p.SkippedOff) + " with the option off)");
        ck.Check(p.SegmentsOn > 0 && p.SegmentsOn < p.SegmentsOff,
          what + ": " + std::to_string(p.SegmentsOn) + " segments against " +
            std::to_string(p.SegmentsOff));
        const DiffStats d = Diff(p.On, p.Off, 0, 4, 0.0);
        ck.Check(d.Max <= 1e-12,
          what + ": images agree, max |diff| " + std::to_string(d.Max) + " (" +
            std::to_string(d.Above) + " pixels differ)");
      }
    }
  }
  mapper->SetOpacitySemantics(vtkHighOrderVolumeMapper::GPU_COMPATIBLE);
  mapper->SetCellOrdering(vtkHighOrderVolumeMapper::VISIBILITY_SORT);
  mapper->SetCellRecordMemory(256);
  ck.Check(bracket->NoMessages(),
    "no messages ('" + Msg(bracket->Observer->GetWarningMessage()) + "')");

  // Nothing to skip: glow without extinction, and a function with none zero.
  mapper->SetEmissionModel(vtkHighOrderVolumeMapper::WILHELMS_VAN_GELDER);
  {
    const Pair p = RenderBoth(*bracket, camera);
    const DiffStats d = Diff(p.On, p.Off, 0, 4, 0.0);
    // Pixels that only glow (colour, no opacity): the transparent cells' share.
    const size_t glow = GlowPixels(p.On);
    ck.Check(p.Status[0] == 1 && p.Status[1] == 1 && p.SkippedOn == 0 && d.Max == 0 && glow > 1000,
      "Wilhelms-Van Gelder: none skipped (" + std::to_string(p.SkippedOn) + "), " +
        std::to_string(d.Above) + " pixels differ, " + std::to_string(glow) +
        " pixels glow without opacity");
  }
  mapper->SetEmissionModel(vtkHighOrderVolumeMapper::WILLIAMS_MAX);
  SetOpacity(*bracket, 0.0);
  bracket->Tf.Opacity->AddPoint(0.0, 0.02);
  {
    const Pair p = RenderBoth(*bracket, camera);
    const DiffStats d = Diff(p.On, p.Off, 0, 4, 0.0);
    const size_t covered = CheckImage(p.On).Covered;
    ck.Check(p.Status[0] == 1 && p.Status[1] == 1 && p.SkippedOn == 0 && d.Max == 0 &&
        covered > 1000,
      "opacity everywhere: none skipped (" + std::to_string(p.SkippedOn) + "), " +
        std::to_string(d.Above) + " pixels differ, " + std::to_string(covered) + " covered");
  }
  ck.Check(bracket->NoMessages(),
    "no messages ('" + Msg(bracket->Observer->GetWarningMessage()) + "')");

  // No extinction over the data range (the bracket's stress stays below 1e4):
  // an empty image either way, and a message either way.
  vtkPiecewiseFunction* o = bracket->Tf.Opacity;
  o->RemoveAllPoints();
  o->AddPoint(0.0, 0.0);
  o->AddPoint(1e4, 0.0);
  o->AddPoint(2e4, 0.5);
  for (const bool skip : { true, false })
  {
    bracket->Observer->Clear();
    mapper->SetSkipTransparentCells(skip);
    int status = 0;
    const Image img = RenderDouble(mapper, camera, bracket->Volume, 203, 157, &status);
    const std::string warning = Msg(bracket->Observer->GetWarningMessage());
    ck.Check(CheckImage(img).Covered == 0 && !warning.empty() &&
        mapper->GetNumberOfTransparentCells() == (skip ? cells : 0),
      std::string("transparent over the data range, skip ") + (skip ? "on" : "off") + ": " +
        std::to_string(CheckImage(img).Covered) + " covered pixels, " +
        std::to_string(mapper->GetNumberOfTransparentCells()) + " skipped, warning '" +
        warning + "'");
  }

  // General cells: linear ones skipped, quadratic ones not.
  {
    const Pair p = RenderLattice(ck,
      Lattice({ CubeSplit::Hexahedron, CubeSplit::Wedges, CubeSplit::Pyramids }), "linear lattice");
    const double worst = Diff(p.On, p.Off, 0, 4, 0.0).Max;
    ck.Check(p.SkippedOn > 10 && p.SkippedOff == 0 && p.SegmentsOn < p.SegmentsOff &&
        worst <= 1e-12,
      "linear lattice: " + std::to_string(p.SkippedOn) + " cells skipped, segments " +
        std::to_string(p.SegmentsOn) + " against " + std::to_string(p.SegmentsOff) +
        ", max |diff| " + std::to_string(worst));
  }
  {
    const Pair p = RenderLattice(ck, Lattice({ CubeSplit::QuadraticTetras }), "quadratic lattice");
    const DiffStats d = Diff(p.On, p.Off, 0, 4, 0.0);
    ck.Check(p.SkippedOn == 0 && d.Max == 0,
      "quadratic lattice: none skipped (" + std::to_string(p.SkippedOn) + "), " +
        std::to_string(d.Above) + " pixels differ");
  }
  return ck.Result();
}
