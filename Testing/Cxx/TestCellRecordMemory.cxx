// vtkHighOrderVolumeMapper::SetCellRecordMemory is a memory/time knob only:
// with 0 MiB (no per-frame records of the whole cell order: every tile builds
// the records of its own cells) the CPU path's double image (GetDoubleImage)
// is the default's bit for bit, in both cell orderings,
//  - on the bundled bracket (tetrahedra; 203 x 157, tiles cut by the border),
//  - on a 3x3x3 lattice of cubes split alternately into tetrahedra,
//    hexahedra, wedges, pyramids and quadratic tetrahedra (general cells
//    between tetrahedra in the order: their indices in a tile's list differ
//    from their indices in the order).
// GetNumberOfCellRecords tells which way the records were built. The setting
// clamps to [0, 2^20] MiB.
#include "hovTestAnalytic.h"
#include "hovTestImages.h"
#include "hovTestMixed.h"
#include "hovTestScenes.h"

#include "vtkCamera.h"

#include <string>

using namespace hovTest;

namespace
{
/// Number of values of @p a and @p b that differ (all of them if the sizes differ).
size_t Differ(const Image& a, const Image& b)
{
  if (a.V.size() != b.V.size())
  {
    return a.V.size() + b.V.size();
  }
  size_t differ = 0;
  for (size_t i = 0; i < a.V.size(); ++i)
  {
    differ += a.V[i] != b.V[i];
  }
  return differ;
}

double Field(double x, double y, double z)
{
  return 0.5 + 0.4 * x - 0.3 * y + 0.25 * z + 0.2 * x * y;
}

MeshBuilder MixedLattice()
{
  MeshBuilder m;
  const double o[3] = { -0.9, -0.8, -0.85 };
  const double a[3][3] = { { 0.6, 0.05, 0.0 }, { -0.04, 0.55, 0.06 }, { 0.05, 0.0, 0.58 } };
  const std::vector<vtkIdType> ids = AddLattice(m, 3, 3, 3, o, a, Field);
  const CubeSplit splits[] = { CubeSplit::Tetras, CubeSplit::Hexahedron, CubeSplit::Wedges,
    CubeSplit::Tetras, CubeSplit::Pyramids, CubeSplit::QuadraticTetras };
  int n = 0;
  for (int k = 0; k < 3; ++k)
  {
    for (int j = 0; j < 3; ++j)
    {
      for (int i = 0; i < 3; ++i)
      {
        AddCube(m, LatticeCube(ids, 3, 3, i, j, k), splits[n++ % 6], Field);
      }
    }
  }
  return m;
}

/// The default image and the one with no whole-order records, compared.
void Compare(Checker& ck, VolumeScene& scene, vtkCamera* camera, int w, int h,
  const std::string& label, size_t minCovered)
{
  vtkHighOrderVolumeMapper* mapper = scene.Mapper;
  for (int order :
    { vtkHighOrderVolumeMapper::VISIBILITY_SORT, vtkHighOrderVolumeMapper::PER_PIXEL_SORT })
  {
    const std::string what = label + (order ? ", PER_PIXEL_SORT" : ", VISIBILITY_SORT");
    mapper->SetCellOrdering(order);
    mapper->SetCellRecordMemory(256);
    int status[2] = { 0, 0 };
    const Image whole = RenderDouble(mapper, camera, scene.Volume, w, h, &status[0]);
    const vtkIdType wholeRecords = mapper->GetNumberOfCellRecords();
    mapper->SetCellRecordMemory(0);
    const Image perTile = RenderDouble(mapper, camera, scene.Volume, w, h, &status[1]);
    const vtkIdType tileRecords = mapper->GetNumberOfCellRecords();
    // Whole: one record per ordered cell (visibility order: every rendered
    // cell; per-pixel: those covering a pixel centre); per tile: one per
    // (tile, cell) pair, so the budget did reach the tiles.
    const vtkIdType cells = mapper->GetNumberOfRenderedCells();
    ck.Check(wholeRecords > 0 && wholeRecords <= cells &&
        (order != vtkHighOrderVolumeMapper::VISIBILITY_SORT || wholeRecords == cells) &&
        tileRecords > 0,
      what + ": records built " + std::to_string(wholeRecords) + " (whole), " +
        std::to_string(tileRecords) + " (per tile), " + std::to_string(cells) + " cells");
    const Sanity sane = CheckImage(whole);
    ck.Check(status[0] == 1 && status[1] == 1 && sane.NonFinite == 0 &&
        sane.Covered >= minCovered,
      what + ": both rendered, " + std::to_string(sane.Covered) + " covered pixels");
    const size_t differ = Differ(whole, perTile);
    ck.Check(differ == 0,
      what + ": per-tile records == whole-order records, bit for bit (" +
        std::to_string(differ) + " values differ)");
  }
  mapper->SetCellRecordMemory(256);
}
}

int TestCellRecordMemory(int argc, char* argv[])
{
  Checker ck;
  std::unique_ptr<VolumeScene> bracket = BracketScene(ck, argc, argv);
  if (!bracket)
  {
    return ck.Result();
  }
  bracket->Mapper->SetRenderModeToCPUAccurate();
  ck.Check(bracket->Mapper->GetCellRecordMemory() == 256, "default: 256 MiB");
  bracket->Mapper->SetCellRecordMemory(-5);
  ck.Check(bracket->Mapper->GetCellRecordMemory() == 0, "clamped to 0");
  vtkNew<vtkCamera> camera;
  BracketCamera(camera);
  Compare(ck, *bracket, camera, 203, 157, "bracket", 5000);
  ck.Check(bracket->NoMessages(), "bracket: no messages");

  const MeshBuilder lattice = MixedLattice();
  VolumeScene mixed(lattice.Grid());
  DefaultTF(mixed.Tf, 0.5);
  mixed.Tf.Color->AddRGBPoint(0.55, 0.9, 0.8, 0.1);
  mixed.Tf.Opacity->AddPoint(0.35, 0.1);
  mixed.Mapper->SetRenderModeToCPUAccurate();
  vtkNew<vtkCamera> cam;
  const double focal[3] = { 0.02, 0.03, 0.01 };
  const double dir[3] = { 0.5, -0.62, 0.6 };
  const double up[3] = { 0, 0, 1 };
  PlaceCamera(cam, focal, dir, 5.0, up, false, 36.0);
  cam->SetClippingRange(1.0, 20.0);
  Compare(ck, mixed, cam, 96, 80, "mixed lattice", 96 * 80 / 5);
  ck.Check(mixed.Mapper->GetNumberOfRenderedCells() > 27 && mixed.NoMessages(),
    "mixed lattice: " + std::to_string(mixed.Mapper->GetNumberOfRenderedCells()) +
      " cells rendered, no messages ('" + Msg(mixed.Observer->GetWarningMessage()) + "')");
  return ck.Result();
}
