#include "hovTestAnalytic.h"

#include "hovTestReference.h"

#include "vtkHighOrderVolumeMapper.h"

#include "vtkCamera.h"
#include "vtkTestErrorObserver.h"

#include <chrono>
#include <cmath>
#include <iostream>
#include <utility>

namespace hovTest
{
void PlaceCamera(vtkCamera* cam, const double focal[3], const double direction[3], double distance,
  const double up[3], bool parallel, double angleOrScale)
{
  const double n = std::sqrt(
    direction[0] * direction[0] + direction[1] * direction[1] + direction[2] * direction[2]);
  cam->SetFocalPoint(focal[0], focal[1], focal[2]);
  cam->SetPosition(focal[0] + distance * direction[0] / n, focal[1] + distance * direction[1] / n,
    focal[2] + distance * direction[2] / n);
  cam->SetViewUp(up[0], up[1], up[2]);
  cam->SetParallelProjection(parallel);
  if (parallel)
  {
    cam->SetParallelScale(angleOrScale);
  }
  else
  {
    cam->SetViewAngle(angleOrScale);
  }
}

bool CoverageOk(const char* view, int covered, int least, int total, const char* want)
{
  if (covered < least || covered == total)
  {
    std::cerr << "FAILED: test set-up, view " << view << " covers " << covered << " pixels (want "
              << want << ", not all of it)\n";
    return false;
  }
  return true;
}

CaseFailures::CaseFailures(std::string label)
  : Label(std::move(label))
{
}

void CaseFailures::operator()(const std::string& what)
{
  if (this->Count++ < 8)
  {
    std::cerr << "FAILED [" << this->Label << "]: " << what << "\n";
  }
}

const float* RenderCase(vtkHighOrderVolumeMapper* mapper, vtkCamera* cam, vtkVolume* volume,
  int width, int height, vtkTest::ErrorObserver* observer, CaseFailures& fail, double* seconds)
{
  observer->Clear();
  const auto start = std::chrono::steady_clock::now();
  if (mapper->RenderImage(cam, volume, width, height) != 1)
  {
    fail("RenderImage did not return 1");
  }
  if (seconds)
  {
    *seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
  if (observer->GetError() || observer->GetWarning())
  {
    fail("unexpected VTK message: " + observer->GetErrorMessage() + observer->GetWarningMessage());
  }
  std::string why;
  const float* px = hovTestRef::ImagePixels(mapper->GetFloatImage(), width, height, why);
  if (!px)
  {
    fail(why);
  }
  return px;
}
}
