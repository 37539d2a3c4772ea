// OPENGL_PROJECTION mode against VTK's vtkProjectedTetrahedraMapper (issue 5,
// acceptance 2): on tetrahedral meshes in VTK-unstructured semantics
// (extinction a/u, what VTK's mapper uses), both are compared with our CPU
// float image (exact) over a black background: our M1 (average colour, the
// method closest to VTK's) and M3 through our float image, VTK's through its
// 8-bit screen image (RGB: premultiplied over black). Meshes: the 4x4x4 Kuhn
// cube (384 tets, linear field) and a holed block (non-convex). Views:
// perspective. VTK's mapper gets the same exact Stein order, so the
// difference is the integration, not the sort. Ours must have the smaller
// maximum RGB error; both are printed.
#include "hovTestScenes.h"

#include "hovSortMeshes.h"     // HoledBlock
#include "hovTestReference.h" // MakeCubeOfTetras

#include "vtkCamera.h"
#include "vtkProjectedTetrahedraMapper.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSteinVisibilitySort.h"
#include "vtkUnstructuredGrid.h"

#include <cmath>
#include <iostream>
#include <string>

using namespace hovTest;

namespace
{
/// Max and mean |a - b| over RGB at pixels covered in @p ref.
void RGBError(const Image& a, const Image& ref, double& maxErr, double& meanErr)
{
  maxErr = meanErr = 0;
  size_t n = 0;
  for (size_t k = 0; k < ref.Pixels(); ++k)
  {
    if (ref.V[4 * k + 3] <= 1e-6)
    {
      continue;
    }
    ++n;
    for (int c = 0; c < 3; ++c)
    {
      const double d = std::fabs(a.V[4 * k + c] - ref.V[4 * k + c]);
      maxErr = std::max(maxErr, d);
      meanErr += d;
    }
  }
  meanErr = n ? meanErr / (3.0 * n) : 0.0;
}
}

int TestProjectionCompareVTK(int, char*[])
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
    { "4x4x4 Kuhn cube", hovTestRef::MakeCubeOfTetras(4, origin, 1.0, 6, 0.5, gradient) },
    { "holed block", HoledBlock(6, 7) },
  };
  for (const Mesh& mesh : meshes)
  {
    VolumeScene scene(mesh.Grid);
    DefaultTF(scene.Tf, 0.3);
    scene.Mapper->SetOpacitySemanticsToVTKUnstructured();
    vtkNew<vtkCamera> cam;
    cam->SetPosition(2.3, -1.0, 2.0);
    cam->SetFocalPoint(0.5, 0.5, 0.5);
    cam->SetViewUp(0, 0, 1);
    cam->SetViewAngle(32);
    cam->SetClippingRange(0.5, 10);
    vtkSmartPointer<vtkRenderer> ren = BlackRenderer(cam);
    ren->AddVolume(scene.Volume);
    vtkSmartPointer<vtkRenderWindow> win = OffscreenWindow(ren, size, size, 0);
    win->Render();
    const Image cpu = FloatImage(scene.Mapper);
    scene.Mapper->SetRenderModeToOpenGLProjection();
    double ours[4][2];
    for (int m : { 1, 3 })
    {
      scene.Mapper->SetProjectionColorMethod(m);
      win->Render();
      RGBError(FloatImage(scene.Mapper), cpu, ours[m][0], ours[m][1]);
    }
    ren->RemoveVolume(scene.Volume);

    vtkNew<vtkProjectedTetrahedraMapper> pt;
    pt->SetInputData(mesh.Grid);
    vtkNew<vtkSteinVisibilitySort> stein;
    pt->SetVisibilitySort(stein);
    vtkNew<vtkVolume> vol;
    vol->SetMapper(pt);
    vol->SetProperty(scene.Tf.Property);
    vtkSmartPointer<vtkRenderer> ren2 = BlackRenderer(cam);
    ren2->AddVolume(vol);
    vtkSmartPointer<vtkRenderWindow> win2 = OffscreenWindow(ren2, size, size, 0);
    win2->Render();
    win2->Render(); // (the first frame of VTK's mapper may be incomplete)
    double ptMax, ptMean;
    const Image ptImage = Capture(win2);
    RGBError(ptImage, cpu, ptMax, ptMean);
    std::cout << "  mean intensity: CPU " << MeanIntensity(cpu) << ", VTK " << MeanIntensity(ptImage)
              << "\n";
    std::cout << "== " << mesh.Name << " (" << mesh.Grid->GetNumberOfCells() << " tets, " << size
              << "^2, VTK-unstructured), RGB error against our CPU float image, max / mean:\n"
              << "  ours M1 (float)                 " << ours[1][0] * 255 << " / " << ours[1][1] * 255
              << " (x 1/255)\n"
              << "  ours M3 (float)                 " << ours[3][0] * 255 << " / " << ours[3][1] * 255
              << "\n"
              << "  vtkProjectedTetrahedraMapper    " << ptMax * 255 << " / " << ptMean * 255 << "\n";
    ck.Check(CheckImage(cpu).Covered > 0.1 * size * size, std::string(mesh.Name) + ": volume drawn");
    ck.Check(ours[1][0] < ptMax, std::string(mesh.Name) + ": our M1 has the smaller maximum error");
    ck.Check(ours[3][0] <= ours[1][0], std::string(mesh.Name) + ": M3 no worse than M1");
    ck.Check(scene.NoMessages(), std::string(mesh.Name) + ": no messages");
  }
  return ck.Result();
}
