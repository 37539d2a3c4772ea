// Input through a pipeline connection (SetInputConnection) that nobody has
// updated yet, and that changes upstream between images. VTK's mappers bring
// their input up to date themselves (vtkUnstructuredGridVolumeRayCastMapper
// calls Update() in Render); RenderImage must do the same, or the caller
// silently gets a stale or empty grid ("no scalars" on an un-executed
// pipeline). Expected: RenderImage renders what the pipeline produces now,
// equal to rendering the same grid given with SetInputData.
#include "hovTestScenes.h"

#include "vtkCamera.h"
#include "vtkDataSetTriangleFilter.h"
#include "vtkDoubleArray.h"
#include "vtkImageData.h"
#include "vtkPointData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkTransform.h"
#include "vtkTransformFilter.h"
#include "vtkUnstructuredGrid.h"

#include <iostream>

using namespace hovTest;

int TestBadInputPipeline(int, char*[])
{
  Checker ck;
  // Source: 4^3 voxels with a scalar field, split into tets, then moved.
  vtkNew<vtkImageData> voxels;
  voxels->SetDimensions(5, 5, 5);
  voxels->SetSpacing(0.25, 0.25, 0.25);
  vtkNew<vtkDoubleArray> s;
  s->SetName("s");
  for (vtkIdType i = 0; i < voxels->GetNumberOfPoints(); ++i)
  {
    double p[3];
    voxels->GetPoint(i, p);
    s->InsertNextValue(DefaultField(p[0], p[1], p[2]));
  }
  voxels->GetPointData()->SetScalars(s);
  vtkNew<vtkDataSetTriangleFilter> tri;
  tri->SetInputData(voxels);
  vtkNew<vtkTransform> move;
  vtkNew<vtkTransformFilter> mover;
  mover->SetTransform(move);
  mover->SetInputConnection(tri->GetOutputPort());

  VolumeScene scene;
  scene.Mapper->SetInputConnection(mover->GetOutputPort()); // never updated by the test
  DefaultTF(scene.Tf);
  vtkNew<vtkCamera> cam;
  ObliqueCamera(cam);
  cam->SetViewAngle(45);

  // Reference mapper fed with explicitly updated copies.
  vtkNew<vtkHighOrderVolumeMapper> refMapper;
  vtkNew<vtkVolume> refVolume;
  refVolume->SetMapper(refMapper);
  refVolume->SetProperty(scene.Tf.Property);
  auto reference = [&]() {
    mover->Update();
    vtkNew<vtkUnstructuredGrid> copy;
    copy->DeepCopy(mover->GetOutput());
    refMapper->SetInputData(copy);
    return Render(refMapper, cam, refVolume, 80, 80);
  };

  // 1. Never executed pipeline.
  scene.Observer->Clear();
  int status = -1;
  const Image first = Render(scene.Mapper, cam, scene.Volume, 80, 80, &status);
  const Sanity s1 = CheckImage(first);
  std::cout << "== RenderImage on a pipeline that was never updated: status=" << status << " "
            << s1.Str() << " error: '" << Msg(scene.Observer->GetErrorMessage()) << "'\n";
  const Image ref1 = reference();
  const DiffStats d1 = Diff(first, ref1);
  std::cout << "  vs the updated grid via SetInputData: " << d1.Str() << "\n";
  ck.Check(status == 1 && !scene.Observer->GetError(),
    "renders without error (the mapper updates its input)");
  ck.Check(d1.Max <= 1e-6 && s1.Covered > 500, "equals the image of the updated grid");

  // 2. The pipeline changes upstream: the volume moves by 0.3 in x.
  move->Translate(0.3, 0, 0);
  scene.Observer->Clear();
  const Image second = Render(scene.Mapper, cam, scene.Volume, 80, 80, &status);
  const Image ref2 = reference();
  const DiffStats d2 = Diff(second, ref2), moved = Diff(ref2, ref1);
  std::cout << "== after moving the volume upstream: status=" << status << " vs updated grid "
            << d2.Str() << " (the move itself changes the image by " << Fmt(moved.Max) << ")\n";
  ck.Check(moved.Max > 0.05, "(the move is visible)");
  ck.Check(status == 1 && !scene.Observer->GetError() && d2.Max <= 1e-6,
    "RenderImage shows the pipeline's current output");

  // 3. On screen the renderer asks the volume for its bounds, which updates
  // the mapper's input: the same change is seen there.
  move->Translate(-0.1, 0.1, 0);
  const Image ref4 = reference();
  vtkNew<vtkRenderer> ren;
  ren->SetActiveCamera(cam);
  ren->AddVolume(scene.Volume);
  vtkSmartPointer<vtkRenderWindow> win = OffscreenWindow(ren, 80, 80);
  move->Translate(0.05, 0, 0);
  const Image ref5 = reference();
  move->Translate(-0.05, 0, 0); // back to the state of ref4, not updated by anyone
  scene.Observer->Clear();
  win->Render();
  const Image onScreen = FloatImage(scene.Mapper);
  const DiffStats d4 = Diff(onScreen, ref4), d5 = Diff(onScreen, ref5);
  std::cout << "== on screen after an upstream change: vs current pipeline output " << d4.Str()
            << "; vs the previous output " << Fmt(d5.Max) << "\n";
  ck.Check(!scene.Observer->GetError() && d4.Max <= 1e-6,
    "on screen the current pipeline output is rendered");
  scene.Mapper->ReleaseGraphicsResources(win);
  return ck.Result();
}
