// Settings round-trip, PrintSelf, and rendering without input or with an
// empty grid: a clear error or warning, a zero image, no crash.
#include "vtkHighOrderVolumeMapper.h"

#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkTestErrorObserver.h"
#include "vtkUnstructuredGrid.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include "vtkCommand.h"

#include <cmath>
#include <iostream>
#include <limits>
#include <sstream>

int TestMapperBasics(int, char*[])
{
  int failures = 0;
  auto check = [&](bool ok, const char* what) {
    if (!ok)
    {
      std::cerr << "FAILED: " << what << "\n";
      ++failures;
    }
  };
  vtkNew<vtkHighOrderVolumeMapper> mapper;
  check(mapper->GetOpacitySemantics() == vtkHighOrderVolumeMapper::GPU_COMPATIBLE,
    "default semantics is GPU-compatible");
  check(mapper->GetEmissionModel() == vtkHighOrderVolumeMapper::WILLIAMS_MAX,
    "default emission is Williams-Max");
  mapper->SetOpacitySemanticsToRawExtinction();
  check(mapper->GetOpacitySemantics() == vtkHighOrderVolumeMapper::RAW_EXTINCTION, "raw extinction");
  mapper->SetOpacitySemantics(99);
  check(mapper->GetOpacitySemantics() == vtkHighOrderVolumeMapper::RAW_EXTINCTION, "clamped setter");
  check(mapper->GetVisibilitySort() != nullptr, "a default visibility sort");
  {
    // Real-valued knobs: clamped like vtkSetClampMacro, NaN/Inf refused with
    // an error naming the setter (vtkSetClampMacro would store the NaN).
    vtkNew<vtkTest::ErrorObserver> observer;
    mapper->AddObserver(vtkCommand::ErrorEvent, observer);
    mapper->SetRayCastTolerance(1e-4);
    mapper->SetRayCastTolerance(std::numeric_limits<double>::quiet_NaN());
    check(mapper->GetRayCastTolerance() == 1e-4 && observer->GetError() &&
        observer->GetErrorMessage().find("SetRayCastTolerance") != std::string::npos,
      "NaN tolerance refused with an error, value kept");
    observer->Clear();
    mapper->SetTerminationTransmittance(std::numeric_limits<double>::infinity());
    mapper->SetGPUOpacityTolerance(-std::numeric_limits<double>::infinity());
    mapper->SetSplatPixelThreshold(std::numeric_limits<double>::quiet_NaN());
    mapper->SetRayCastInteractiveUpdateRate(std::numeric_limits<double>::quiet_NaN());
    check(observer->GetError() && std::isfinite(mapper->GetTerminationTransmittance()) &&
        std::isfinite(mapper->GetGPUOpacityTolerance()) &&
        std::isfinite(mapper->GetSplatPixelThreshold()) &&
        std::isfinite(mapper->GetRayCastInteractiveUpdateRate()),
      "non-finite values refused by every real-valued setter");
    observer->Clear();
    mapper->SetRayCastTolerance(5.0);
    mapper->SetTerminationTransmittance(-1.0);
    check(mapper->GetRayCastTolerance() == 0.1 && mapper->GetTerminationTransmittance() == 0.0 &&
        !observer->GetError(),
      "finite values clamped silently");
    mapper->SetRayCastTolerance(1e-3);
    mapper->SetTerminationTransmittance(1e-9);
    mapper->RemoveObserver(observer);
  }
  std::ostringstream printed;
  mapper->Print(printed);
  check(printed.str().find("OpacitySemantics: 2") != std::string::npos, "PrintSelf");

  vtkNew<vtkColorTransferFunction> ctf;
  ctf->AddRGBPoint(0.0, 1.0, 1.0, 1.0);
  vtkNew<vtkPiecewiseFunction> otf;
  otf->AddPoint(0.0, 0.5);
  vtkNew<vtkVolumeProperty> property;
  property->SetColor(ctf);
  property->SetScalarOpacity(otf);
  vtkNew<vtkVolume> volume;
  volume->SetMapper(mapper);
  volume->SetProperty(property);
  vtkNew<vtkCamera> camera;

  // No input: an error, a zero image of the requested size.
  vtkNew<vtkTest::ErrorObserver> errors;
  mapper->AddObserver(vtkCommand::ErrorEvent, errors);
  mapper->AddObserver(vtkCommand::WarningEvent, errors);
  check(mapper->RenderImage(camera, volume, 8, 4) == 0, "no input is an error");
  check(errors->GetError(), "an error was reported for a missing input");
  vtkImageData* image = mapper->GetFloatImage();
  check(image->GetDimensions()[0] == 8 && image->GetDimensions()[1] == 4, "image size");
  errors->Clear();

  // Empty grid: a warning, a zero image.
  vtkNew<vtkUnstructuredGrid> empty;
  vtkNew<vtkPoints> points;
  empty->SetPoints(points);
  vtkNew<vtkFloatArray> scalars;
  scalars->SetName("s");
  empty->GetPointData()->SetScalars(scalars);
  mapper->SetInputData(empty);
  check(mapper->RenderImage(camera, volume, 3, 3) == 1, "an empty grid renders");
  check(errors->GetWarning() || errors->GetError(), "the empty grid was reported");
  auto* rgba = vtkFloatArray::SafeDownCast(mapper->GetFloatImage()->GetPointData()->GetScalars());
  check(rgba && rgba->GetNumberOfTuples() == 9, "3x3 image");
  for (vtkIdType i = 0; rgba && i < 36; ++i)
  {
    check(rgba->GetValue(i) == 0.0f, "empty grid gives a zero image");
  }
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
