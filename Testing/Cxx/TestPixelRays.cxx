// The CPU path's pixel rays, a row of four pixels per vector where nothing
// clips them, are the per-pixel rays bit for bit: the double image
// (GetDoubleImage) of a perspective and of a parallel view is the same,
// value for value, with and without a clipping plane that cuts nothing (the
// rays of a clipped view are traced one pixel at a time, and such a plane
// leaves every ray as it is).
#include "vtkHighOrderVolumeMapper.h"

#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkDataSetTriangleFilter.h"
#include "vtkDoubleArray.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPlane.h"
#include "vtkRTAnalyticSource.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <iostream>
#include <string>
#include <vector>

namespace
{
std::vector<double> Render(vtkHighOrderVolumeMapper* mapper, vtkCamera* camera, vtkVolume* volume)
{
  std::vector<double> image;
  if (mapper->RenderImage(camera, volume, 203, 157) != 1)
  {
    return image;
  }
  vtkNew<vtkDoubleArray> rgba;
  mapper->GetDoubleImage(rgba);
  const double* v = rgba->GetPointer(0);
  image.assign(v, v + 4 * rgba->GetNumberOfTuples());
  return image;
}
}

int TestPixelRays(int, char*[])
{
  int failures = 0;
  auto check = [&](bool ok, const std::string& what) {
    std::cout << (ok ? "ok: " : "FAILED: ") << what << "\n";
    failures += ok ? 0 : 1;
  };
  vtkNew<vtkRTAnalyticSource> source;
  source->SetWholeExtent(-6, 6, -6, 6, -6, 6);
  vtkNew<vtkDataSetTriangleFilter> tets;
  tets->SetInputConnection(source->GetOutputPort());
  vtkNew<vtkColorTransferFunction> color;
  color->AddRGBPoint(37.0, 0.2, 0.4, 0.9);
  color->AddRGBPoint(160.0, 0.9, 0.9, 0.8);
  color->AddRGBPoint(277.0, 0.9, 0.2, 0.1);
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(37.0, 0.1);
  opacity->AddPoint(277.0, 0.9);
  vtkNew<vtkVolumeProperty> property;
  property->SetColor(color);
  property->SetScalarOpacity(opacity);
  property->SetScalarOpacityUnitDistance(6.0);
  vtkNew<vtkHighOrderVolumeMapper> mapper;
  mapper->SetInputConnection(tets->GetOutputPort());
  mapper->SetRenderModeToCPUAccurate();
  vtkNew<vtkVolume> volume;
  volume->SetMapper(mapper);
  volume->SetProperty(property);
  // A plane far outside the data, keeping all of it (and every ray).
  vtkNew<vtkPlane> far;
  far->SetOrigin(0.0, 0.0, -1000.0);
  far->SetNormal(0.0, 0.0, 1.0);

  for (const bool parallel : { false, true })
  {
    const std::string view = parallel ? "parallel view" : "perspective view";
    vtkNew<vtkCamera> camera;
    camera->SetPosition(23, 17, 29);
    camera->SetFocalPoint(0.3, -0.2, 0.1);
    camera->SetViewUp(0, 0, 1);
    camera->SetClippingRange(1, 100);
    camera->SetParallelProjection(parallel);
    camera->SetParallelScale(9.0);
    mapper->RemoveAllClippingPlanes();
    const std::vector<double> rows = Render(mapper, camera, volume);
    mapper->AddClippingPlane(far);
    const std::vector<double> pixels = Render(mapper, camera, volume);
    size_t covered = 0, differ = 0;
    for (size_t i = 0; i < rows.size() && rows.size() == pixels.size(); ++i)
    {
      covered += i % 4 == 3 && rows[i] > 0.0;
      differ += rows[i] != pixels[i];
    }
    check(!rows.empty() && rows.size() == pixels.size() && covered > 5000,
      view + ": both images rendered, " + std::to_string(covered) + " covered pixels");
    check(differ == 0,
      view + ": row rays == per-pixel rays, bit for bit (" + std::to_string(differ) +
        " values differ)");
  }
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
