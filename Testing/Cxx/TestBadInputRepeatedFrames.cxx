// An empty image always comes with a warning saying why, once until a setting
// changes (README, "Failures and messages: the rule"). Two causes are found
// when the input or the transfer function is read, not per frame: an input of
// which no cell is rendered (triangles only) and a transfer function with no
// opacity. Each is warned on the first frame, not on a second identical one,
// and again after a mapper setting changes (TileSize here), in CPU_ACCURATE
// and RAY_CAST (RenderImage) and in OPENGL_PROJECTION (a window). Before,
// the frame after the setting change was empty without any message.
#include "hovTestMeshes.h"
#include "hovTestScenes.h"

#include "vtkCamera.h"
#include "vtkCellType.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkUnstructuredGrid.h"

#include <iostream>
#include <string>

using namespace hovTest;

namespace
{
/// Triangles only: no cell any mode renders as a volume.
vtkSmartPointer<vtkUnstructuredGrid> TrianglesOnly()
{
  MeshBuilder m;
  const vtkIdType a = m.AddPoint(0, 0, 0, 0.2), b = m.AddPoint(1, 0, 0, 0.8);
  const vtkIdType c = m.AddPoint(0, 1, 0, 1.2), d = m.AddPoint(1, 1, 0.5, 1.5);
  m.AddCell(VTK_TRIANGLE, { a, b, c });
  m.AddCell(VTK_TRIANGLE, { b, d, c });
  return m.Grid();
}
}

int TestBadInputRepeatedFrames(int, char*[])
{
  Checker ck;
  vtkNew<vtkCamera> cam;
  ObliqueCamera(cam);
  const int W = 40, H = 30;
  for (int cause = 0; cause < 2; ++cause)
  {
    const std::string causeName = cause == 0 ? "triangles only" : "no opacity";
    // The first frame's reason (the input's cells, the table), then the frame's own.
    const std::string firstKey = cause == 0 ? "cells" : "no opacity anywhere";
    const std::string key = cause == 0 ? "none of the input" : "no opacity anywhere";
    for (int mode : { vtkHighOrderVolumeMapper::CPU_ACCURATE, vtkHighOrderVolumeMapper::RAY_CAST,
           vtkHighOrderVolumeMapper::OPENGL_PROJECTION })
    {
      vtkSmartPointer<vtkUnstructuredGrid> grid =
        cause == 0 ? TrianglesOnly() : UnitBlock(2).Grid();
      VolumeScene scene(grid);
      DefaultTF(scene.Tf);
      if (cause == 1)
      {
        scene.Tf.Opacity->RemoveAllPoints(); // transparent everywhere
      }
      scene.Mapper->SetRenderMode(mode);
      vtkSmartPointer<vtkRenderer> ren;
      vtkSmartPointer<vtkRenderWindow> win;
      if (mode == vtkHighOrderVolumeMapper::OPENGL_PROJECTION)
      {
        ren = BlackRenderer(cam);
        ren->AddVolume(scene.Volume);
        win = OffscreenWindow(ren, W, H, 0);
      }
      // One frame: its status (RenderImage), the float image's coverage, the warnings.
      auto frame = [&](const std::string& step, bool expectWarning, const std::string& key) {
        scene.Observer->Clear();
        int status = 1;
        Image img;
        if (win)
        {
          win->Render();
          img = FloatImage(scene.Mapper);
        }
        else
        {
          img = Render(scene.Mapper, cam, scene.Volume, W, H, &status);
        }
        const std::string warning = scene.Observer->GetWarningMessage();
        const std::string tag = causeName + ", " + ModeName(mode) + ", " + step;
        std::cout << tag << ": status " << status << ", covered " << CheckImage(img).Covered
                  << ", warning '" << Msg(warning) << "'" << std::endl;
        ck.Check(status == 1 && !scene.Observer->GetError() && CheckImage(img).Covered == 0 &&
            CheckImage(img).Ok(),
          tag + ": status 1, no error, an empty image");
        if (expectWarning)
        {
          ck.Check(scene.Observer->GetWarning() && warning.find(key) != std::string::npos,
            tag + ": a warning says why ('" + key + "')");
        }
        else
        {
          ck.Check(!scene.Observer->GetWarning(), tag + ": no warning (said once)");
        }
      };
      frame("first frame", true, firstKey);
      frame("the same frame again", false, key);
      scene.Mapper->SetTileSize(scene.Mapper->GetTileSize() == 16 ? 32 : 16);
      frame("after a setting changed", true, key);
      frame("the same frame again after it", false, key);
      if (win)
      {
        scene.Mapper->ReleaseGraphicsResources(win);
      }
    }
  }
  return ck.Result();
}
