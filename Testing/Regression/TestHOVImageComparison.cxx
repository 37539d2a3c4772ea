// vtkHighOrderImageComparison against deliberately perturbed images, next to
// VTK's own comparison (vtkImageDifference, as vtkRegressionTestImage uses it
// with threshold 0.15), on the bracket's baseline (-V):
//  - the image against itself: passes, max difference 0;
//  - one pixel +1 level: fails at tolerance 0, fails at tolerance 1 with no
//    pixel allowed to differ, passes at tolerance 1 with one pixel allowed;
//  - one pixel +2 levels: fails at the CPU modes' allowance (hovRegression::Tolerance);
//    VTK's comparison passes it (error 0);
//  - a 10 x 10 block +23 levels (the error of vtkProjectedTetrahedraMapper against
//    our exact image): fails strictly; VTK's thresholded error is printed and
//    must be below its 0.15 (the reason for the strict comparison);
//  - images of different sizes, a float image, a missing image: refused with a message;
//  - the difference image marks exactly the pixels beyond the tolerance in red.
#include "hovRegression.h" // the regression tests' tolerances

#include "vtkHighOrderImageComparison.h" // the class under test
#include "vtkHighOrderVolumeMapper.h" // render-mode constants

#include "vtkFloatArray.h" // a float image, refused
#include "vtkImageData.h" // perturbed copies
#include "vtkImageDifference.h" // VTK's comparison, for contrast
#include "vtkNew.h" // owned objects
#include "vtkPNGReader.h" // the baseline
#include "vtkPointData.h" // pixels
#include "vtkUnsignedCharArray.h" // 8-bit pixels

#include <algorithm> // std::min
#include <iostream>  // verdicts
#include <string> // messages

namespace
{
int Failures = 0;

void Check(bool ok, const std::string& what)
{
  std::cout << (ok ? "ok      " : "FAILED  ") << what << "\n";
  Failures += ok ? 0 : 1;
}

std::string Baseline(int argc, char* argv[])
{
  for (int i = 1; i + 1 < argc; ++i)
  {
    if (std::string(argv[i]) == "-V")
    {
      return argv[i + 1];
    }
  }
  return "";
}

/// A copy of @p image with @p levels added to the RGB of a w x h block at (x, y).
vtkSmartPointer<vtkImageData> Perturbed(vtkImageData* image, int x, int y, int w, int h, int levels)
{
  auto out = vtkSmartPointer<vtkImageData>::New();
  out->DeepCopy(image);
  int dims[3];
  out->GetDimensions(dims);
  auto* pixels = vtkUnsignedCharArray::SafeDownCast(out->GetPointData()->GetScalars());
  const int nc = pixels->GetNumberOfComponents();
  for (int j = y; j < y + h; ++j)
  {
    for (int i = x; i < x + w; ++i)
    {
      unsigned char* p = pixels->GetPointer(nc * (static_cast<vtkIdType>(j) * dims[0] + i));
      for (int k = 0; k < 3; ++k)
      {
        // Towards the middle, so the change is never clamped away.
        p[k] = static_cast<unsigned char>(p[k] < 128 ? p[k] + levels : p[k] - levels);
      }
    }
  }
  return out;
}

/// VTK's thresholded error of @p candidate against @p baseline (vtkImageDifference defaults).
double VTKError(vtkImageData* baseline, vtkImageData* candidate)
{
  vtkNew<vtkImageDifference> difference;
  difference->SetInputData(candidate);
  difference->SetImageData(baseline);
  difference->Update();
  return difference->GetThresholdedError();
}
}

int TestHOVImageComparison(int argc, char* argv[])
{
  vtkNew<vtkPNGReader> reader;
  const std::string path = Baseline(argc, argv);
  if (path.empty() || !reader->CanReadFile(path.c_str()))
  {
    std::cout << "no readable baseline (-V '" << path << "')\n";
    return EXIT_FAILURE;
  }
  reader->SetFileName(path.c_str());
  reader->Update();
  vtkImageData* base = reader->GetOutput();
  int dims[3];
  base->GetDimensions(dims);
  const int cx = dims[0] / 2, cy = dims[1] / 2;

  vtkNew<vtkHighOrderImageComparison> cmp;
  Check(cmp->Compare(base, base) && cmp->GetMaximumDifference() == 0, "identical: passes, max 0");

  // (Each comparison runs before its message is made: argument order is unspecified.)
  auto one = Perturbed(base, cx, cy, 1, 1, 1);
  bool passed = cmp->Compare(base, one);
  Check(!passed && cmp->GetMaximumDifference() == 1 &&
      cmp->GetPixelsDifferent() == 1 && cmp->GetWorstI() == cx && cmp->GetWorstJ() == cy,
    std::string("one pixel +1, tolerance 0: fails at its pixel: ") + cmp->GetSummary());
  cmp->SetTolerance(1);
  Check(!cmp->Compare(base, one), "one pixel +1, tolerance 1, no pixel allowed: fails");
  cmp->SetAllowedPixels(1);
  Check(cmp->Compare(base, one), "one pixel +1, tolerance 1, one pixel allowed: passes");

  const hovRegression::Allowance cpu =
    hovRegression::Tolerance(vtkHighOrderVolumeMapper::CPU_ACCURATE);
  cmp->SetTolerance(cpu.Levels);
  cmp->SetAllowedPixels(static_cast<vtkIdType>(cpu.PixelFraction * dims[0] * dims[1]));
  auto two = Perturbed(base, cx, cy, 1, 1, cpu.Levels + 1);
  passed = cmp->Compare(base, two);
  Check(!passed,
    "one pixel beyond the CPU allowance: fails: " + std::string(cmp->GetSummary()));
  const double vtkTwo = VTKError(base, two);
  Check(vtkTwo <= 0.15,
    "... while VTK's comparison passes it (error " + std::to_string(vtkTwo) + ")");

  auto block = Perturbed(base, cx - 5, cy - 5, 10, 10, 23);
  passed = cmp->Compare(base, block);
  Check(!passed && cmp->GetMaximumDifference() == 23 &&
      cmp->GetPixelsAboveTolerance() == 100,
    "10 x 10 pixels +23 levels: fails: " + std::string(cmp->GetSummary()));
  const double vtkBlock = VTKError(base, block);
  Check(vtkBlock <= 0.15,
    "... while VTK's comparison passes it (error " + std::to_string(vtkBlock) + " <= 0.15)");

  vtkImageData* diff = cmp->GetDifferenceImage();
  auto* d = diff ? vtkUnsignedCharArray::SafeDownCast(diff->GetPointData()->GetScalars()) : nullptr;
  bool marked = d && d->GetNumberOfTuples() == static_cast<vtkIdType>(dims[0]) * dims[1];
  for (vtkIdType p = 0; marked && p < d->GetNumberOfTuples(); ++p)
  {
    const int i = static_cast<int>(p % dims[0]), j = static_cast<int>(p / dims[0]);
    const bool inBlock = i >= cx - 5 && i < cx + 5 && j >= cy - 5 && j < cy + 5;
    const unsigned char* v = d->GetPointer(3 * p);
    marked = inBlock ? (v[0] == std::min(255, 23 * cmp->GetDifferenceScale()) && v[1] == 0)
                     : (v[0] == 0 && v[1] == 0 && v[2] == 0);
  }
  Check(marked, "difference image: red exactly on the perturbed block");

  vtkNew<vtkImageData> small;
  small->SetDimensions(dims[0] / 2, dims[1], 1);
  small->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  passed = cmp->Compare(base, small);
  Check(!passed && cmp->GetMaximumDifference() == -1 &&
      std::string(cmp->GetSummary()).find("pixels") != std::string::npos,
    "different sizes: refused: " + std::string(cmp->GetSummary()));
  vtkNew<vtkImageData> floats;
  floats->SetDimensions(dims);
  floats->AllocateScalars(VTK_FLOAT, 3);
  passed = cmp->Compare(base, floats);
  Check(!passed, "float image: refused: " + std::string(cmp->GetSummary()));
  passed = cmp->Compare(nullptr, base);
  Check(!passed, "no baseline: refused: " + std::string(cmp->GetSummary()));

  std::cout << Failures << " failed checks\n";
  return Failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
