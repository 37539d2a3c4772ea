// The published float image (GetFloatImage) of CPU_ACCURATE, written with
// the pixel check in one parallel pass over blocks of pixels:
// - every value is the double image's (GetDoubleImage) rounded to float, on
//   an image whose covered pixels span several of the pass's blocks;
// - the array is reused from frame to frame when nobody else holds it, and
//   left alone (a new one published) when somebody does;
// - pixels whose colour float cannot hold (EmissionScale 1e300) are zeroed in
//   both images and counted exactly once in the frame's warning.
#include "vtkHighOrderVolumeMapper.h"

#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkDataSetTriangleFilter.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkRTAnalyticSource.h"
#include "vtkSmartPointer.h"
#include "vtkTestErrorObserver.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include "vtkCommand.h"

#include <cfloat>
#include <cctype>
#include <cmath>
#include <iostream>
#include <set>
#include <string>
#include <vector>

namespace
{
constexpr int Width = 257, Height = 203; // 52,171 pixels: blocks of 16,384 and a partial one

vtkFloatArray* Published(vtkHighOrderVolumeMapper* mapper)
{
  return vtkFloatArray::SafeDownCast(mapper->GetFloatImage()->GetPointData()->GetScalars());
}

std::vector<double> DoubleImage(vtkHighOrderVolumeMapper* mapper)
{
  vtkNew<vtkDoubleArray> rgba;
  mapper->GetDoubleImage(rgba);
  const double* v = rgba->GetPointer(0);
  return std::vector<double>(v, v + 4 * rgba->GetNumberOfTuples());
}

/// Number of values of the float image that differ from the double image's
/// values rounded to float (or all of them if the sizes differ).
size_t Mismatches(vtkHighOrderVolumeMapper* mapper)
{
  vtkFloatArray* f = Published(mapper);
  const std::vector<double> d = DoubleImage(mapper);
  if (!f || d.size() != static_cast<size_t>(4 * Width * Height) ||
    f->GetNumberOfValues() != static_cast<vtkIdType>(d.size()))
  {
    return static_cast<size_t>(-1);
  }
  size_t bad = 0;
  for (size_t i = 0; i < d.size(); ++i)
  {
    bad += f->GetValue(static_cast<vtkIdType>(i)) != static_cast<float>(d[i]);
  }
  return bad;
}
}

int TestPublishedImage(int, char*[])
{
  int failures = 0;
  auto check = [&](bool ok, const std::string& what) {
    std::cout << (ok ? "ok: " : "FAILED: ") << what << "\n";
    failures += ok ? 0 : 1;
  };

  vtkNew<vtkRTAnalyticSource> source;
  source->SetWholeExtent(-8, 8, -8, 8, -8, 8);
  vtkNew<vtkDataSetTriangleFilter> tets;
  tets->SetInputConnection(source->GetOutputPort());
  tets->Update();
  vtkNew<vtkColorTransferFunction> color;
  color->AddRGBPoint(37.0, 1.0, 0.9, 0.8);
  color->AddRGBPoint(277.0, 0.9, 1.0, 1.0);
  vtkNew<vtkPiecewiseFunction> opacity;
  opacity->AddPoint(37.0, 0.2);
  opacity->AddPoint(277.0, 0.8);
  vtkNew<vtkVolumeProperty> property;
  property->SetColor(color);
  property->SetScalarOpacity(opacity);
  property->SetScalarOpacityUnitDistance(8.0);
  vtkNew<vtkHighOrderVolumeMapper> mapper;
  mapper->SetInputConnection(tets->GetOutputPort());
  mapper->SetRenderModeToCPUAccurate();
  vtkNew<vtkVolume> volume;
  volume->SetMapper(mapper);
  volume->SetProperty(property);
  vtkNew<vtkCamera> camera;
  camera->SetPosition(30, 25, 40);
  camera->SetFocalPoint(0, 0, 0);
  camera->SetViewUp(0, 0, 1);
  camera->SetClippingRange(1, 200);

  // 1. The float image is the double image rounded, in every block.
  check(mapper->RenderImage(camera, volume, Width, Height) == 1, "first render");
  check(Mismatches(mapper) == 0, "float image == double image rounded to float, every value");
  {
    const std::vector<double> d = DoubleImage(mapper);
    std::set<size_t> blocks;
    size_t covered = 0;
    for (size_t p = 0; 4 * p < d.size(); ++p)
    {
      if (d[4 * p + 3] > 0.0)
      {
        blocks.insert(p / 16384);
        ++covered;
      }
    }
    check(blocks.size() >= 3 && covered > 10000,
      "the covered pixels (" + std::to_string(covered) + ") span " +
        std::to_string(blocks.size()) + " blocks of 16384 pixels (at least 3)");
  }

  // 2. Not held: the next frame writes into the same array.
  vtkFloatArray* first = Published(mapper);
  camera->Azimuth(20.0);
  check(mapper->RenderImage(camera, volume, Width, Height) == 1, "second render");
  check(Published(mapper) == first, "the array nobody else holds is reused");
  check(Mismatches(mapper) == 0, "second frame: float image == double image rounded");

  // 3. Held: left as it was, a new array published.
  vtkSmartPointer<vtkFloatArray> held = Published(mapper);
  const float* h = held->GetPointer(0);
  const std::vector<float> before(h, h + held->GetNumberOfValues());
  camera->Azimuth(20.0);
  check(mapper->RenderImage(camera, volume, Width, Height) == 1, "third render");
  check(Published(mapper) != held.Get(), "a held array is not written: a new one is published");
  check(std::vector<float>(held->GetPointer(0), held->GetPointer(0) + held->GetNumberOfValues()) ==
      before,
    "the held array keeps the previous frame");
  check(Mismatches(mapper) == 0, "third frame: float image == double image rounded");

  // 4. Colours beyond float's range (Wilhelms-Van Gelder emission, red 1e37,
  // then EmissionScale 1e6): zeroed, counted once, in every block. The
  // expected count comes from the same frame at scale 1 (the scale multiplies
  // the colour; pixels within 1e-6 of the threshold may go either way).
  mapper->SetEmissionModelToWilhelmsVanGelder();
  color->RemoveAllPoints();
  color->AddRGBPoint(37.0, 1e37, 0.9, 0.8);
  color->AddRGBPoint(277.0, 1e37, 1.0, 1.0);
  check(mapper->RenderImage(camera, volume, Width, Height) == 1, "render with red 1e37");
  const std::vector<double> plain = DoubleImage(mapper);
  size_t surely = 0, maybe = 0;
  for (size_t p = 0; 4 * p < plain.size(); ++p)
  {
    surely += plain[4 * p] * 1e6 > FLT_MAX * (1 + 1e-6) ? 1 : 0;
    maybe += plain[4 * p] * 1e6 > FLT_MAX * (1 - 1e-6) ? 1 : 0;
  }
  vtkNew<vtkTest::ErrorObserver> observer;
  mapper->AddObserver(vtkCommand::WarningEvent, observer);
  mapper->SetEmissionScale(1e6);
  check(mapper->RenderImage(camera, volume, Width, Height) == 1, "render with EmissionScale 1e6");
  const std::string warning = observer->GetWarningMessage();
  const std::string tail = " of " + std::to_string(Width * Height) + " pixels had a colour";
  const size_t at = warning.find(tail);
  size_t reported = 0;
  if (at != std::string::npos)
  {
    size_t begin = at;
    while (begin > 0 && std::isdigit(static_cast<unsigned char>(warning[begin - 1])))
    {
      --begin;
    }
    reported = std::stoul(warning.substr(begin, at - begin));
  }
  check(surely > 5000 && surely <= reported && reported <= maybe,
    "one warning counting every overflowing pixel: " + std::to_string(reported) + " in [" +
      std::to_string(surely) + ", " + std::to_string(maybe) + "]: '" + warning + "'");
  check(Mismatches(mapper) == 0, "overflow frame: float image == double image rounded");
  const std::vector<double> glowing = DoubleImage(mapper);
  size_t nonFinite = 0, zeroed = 0;
  vtkFloatArray* f = Published(mapper);
  for (size_t p = 0; 4 * p < glowing.size(); ++p)
  {
    bool allZero = true;
    for (int c = 0; c < 4; ++c)
    {
      nonFinite += std::isfinite(f->GetValue(static_cast<vtkIdType>(4 * p + c))) ? 0 : 1;
      allZero = allZero && glowing[4 * p + c] == 0.0;
    }
    zeroed += allZero && plain[4 * p] * 1e6 > FLT_MAX * (1 + 1e-6) ? 1 : 0;
  }
  check(nonFinite == 0, "no non-finite value in the float image");
  check(zeroed == surely,
    "every overflowing pixel is transparent (" + std::to_string(zeroed) + " of " +
      std::to_string(surely) + ")");
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
