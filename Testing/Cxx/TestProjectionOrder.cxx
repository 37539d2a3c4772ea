// OPENGL_PROJECTION mode, approximate order (SetProjectionOrder(1): cells
// sorted by the distance of their corner centroid from the eye, a radix sort
// of float keys in parallel blocks of 512 cells or more, ties by cell index)
// against the exact Stein order on meshes
// where the two differ little: the 6x6x6 Kuhn cube (1296 tets, linear field)
// and the holed block (non-convex), perspective, M1 and M3. Checked: the
// approximate order covers the same pixels, its float image is within a
// small distance of the exact order's (measured: max 0.5/255 on the cube,
// 1.2/255 on the holed block where the centroid order inverts neighbours,
// mean 0.01/255; a broken sort would composite whole layers in the wrong
// order), its image does not change over frames and does not depend on the
// number of threads; CellOrdering PER_PIXEL_SORT does not change the exact
// order (it is a CPU-path setting).
#include "hovTestScenes.h"

#include "hovSortMeshes.h"     // HoledBlock
#include "hovTestReference.h" // MakeCubeOfTetras

#include "vtkCamera.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSMPTools.h"

#include <iostream>
#include <string>

using namespace hovTest;

int TestProjectionOrder(int, char*[])
{
  Checker ck;
  const int size = 160;
  const double origin[3] = { 0, 0, 0 }, gradient[3] = { 0.6, -0.4, 0.5 };
  struct Mesh
  {
    const char* Name;
    vtkSmartPointer<vtkUnstructuredGrid> Grid;
  };
  const Mesh meshes[] = {
    { "6x6x6 Kuhn cube", hovTestRef::MakeCubeOfTetras(6, origin, 1.0, 6, 0.5, gradient) },
    { "holed block", HoledBlock(6, 7) },
  };
  for (const Mesh& mesh : meshes)
  {
    VolumeScene scene(mesh.Grid);
    DefaultTF(scene.Tf, 0.3);
    scene.Mapper->SetRenderModeToOpenGLProjection();
    vtkNew<vtkCamera> cam;
    cam->SetPosition(2.3, -1.0, 2.0);
    cam->SetFocalPoint(0.5, 0.5, 0.5);
    cam->SetViewUp(0, 0, 1);
    cam->SetViewAngle(32);
    cam->SetClippingRange(0.5, 10);
    vtkSmartPointer<vtkRenderer> ren = BlackRenderer(cam);
    ren->AddVolume(scene.Volume);
    vtkSmartPointer<vtkRenderWindow> win = OffscreenWindow(ren, size, size, 0);
    for (int method : { 1, 3 })
    {
      const std::string tag = std::string(mesh.Name) + " M" + std::to_string(method) + ": ";
      scene.Mapper->SetProjectionColorMethod(method);
      scene.Mapper->SetProjectionOrder(0); // exact (Stein)
      win->Render();
      const Image exact = FloatImage(scene.Mapper);
      // CellOrdering (a CPU-path setting) must not change the projection's
      // exact order: with PER_PIXEL_SORT it once drew the cells in index order.
      scene.Mapper->SetCellOrderingToPerPixelSort();
      win->Render();
      const Image exactPerPixel = FloatImage(scene.Mapper);
      scene.Mapper->SetCellOrderingToVisibilitySort();
      ck.Check(Diff(exactPerPixel, exact).Max == 0.0,
        tag + "the exact order is the visibility sort's also with CellOrdering PER_PIXEL_SORT");
      scene.Mapper->SetProjectionOrder(1); // approximate
      win->Render();
      const Image approx = FloatImage(scene.Mapper);
      win->Render();
      const Image again = FloatImage(scene.Mapper);
      vtkSMPTools::Initialize(1);
      win->Render();
      const Image oneThread = FloatImage(scene.Mapper);
      vtkSMPTools::Initialize(0);
      const DiffStats d = Diff(approx, exact, 0, 4, 1.0 / 255);
      std::cout << "== " << tag << "approximate vs exact order: " << d.Str() << "\n";
      const Sanity se = CheckImage(exact), sa = CheckImage(approx);
      ck.Check(se.Covered > 0.1 * size * size && sa.Covered == se.Covered,
        tag + "same coverage (" + std::to_string(sa.Covered) + ")");
      ck.Check(d.Max <= 4.0 / 255 && d.Mean <= 0.05 / 255,
        tag + "approximate order within 4/255 (max) and 0.05/255 (mean) of the exact order");
      ck.Check(Diff(approx, again).Max == 0.0, tag + "the approximate order is stable over frames");
      ck.Check(Diff(approx, oneThread).Max == 0.0, tag + "and does not depend on the thread count");
      ck.Check(scene.NoMessages(), tag + "no messages");
    }
  }
  return ck.Result();
}
