/**
 * @class   vtkHighOrderImageComparison
 * @brief   Strict per-pixel comparison of an 8-bit image with its baseline, for regression tests.
 *
 * VTK's regression comparison (vtkRegressionTestImage, threshold 0.15, through
 * vtkImageDifference) ignores per-channel differences up to 105/255, allows a
 * shift of 2 pixels and averages 3x3 neighbourhoods: it passes
 * vtkProjectedTetrahedraMapper's image, 23/255 away, against our exact one.
 * This comparison counts, per pixel, the largest absolute difference over the
 * colour channels (in 8-bit levels, no shift, no averaging):
 *
 *   d(i,j) = max_c |baseline(i,j,c) - candidate(i,j,c)|,  c = R, G, B
 *
 * and passes when no pixel has d > Tolerance and at most AllowedPixels pixels
 * have d > 0: Tolerance bounds how much a pixel may change, AllowedPixels how
 * many may change at all (both 0 by default: identical images). Alpha is
 * ignored (RGB and RGBA images compare alike, as PNG baselines may be either).
 *
 * Compare() fails, with a message, on images that are missing, not 8-bit, or of
 * different sizes. After a comparison, GetDifferenceImage() is an RGB image of
 * d (x DifferenceScale, clamped to 255; red where d > Tolerance) for the
 * candidate's "<name>.strict-diff.png".
 *
 * The module's regression tests (Testing/Regression) use it next to
 * vtkRegressionTestImage; the README ("Regression tests") shows how to use it in
 * one's own tests, from C++ or Python.
 *
 * Thread safety: one instance per thread.
 * @sa vtkTesting, vtkImageDifference
 */
#ifndef vtkHighOrderImageComparison_h
#define vtkHighOrderImageComparison_h

#include "vtkObject.h"
#include "vtkRenderingHighOrderVolumeModule.h" // For export macro
#include "vtkSmartPointer.h"                   // For the difference image

#include <string> // For the message

class vtkImageData;

class VTKRENDERINGHIGHORDERVOLUME_EXPORT vtkHighOrderImageComparison : public vtkObject
{
public:
  static vtkHighOrderImageComparison* New();
  vtkTypeMacro(vtkHighOrderImageComparison, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// Largest per-pixel difference d, in 8-bit levels, that is not counted (default 0).
  vtkSetClampMacro(Tolerance, int, 0, 255);
  vtkGetMacro(Tolerance, int);
  ///@}

  ///@{
  /// Number of pixels allowed to differ at all, d > 0 (default 0).
  vtkSetClampMacro(AllowedPixels, vtkIdType, 0, VTK_ID_MAX);
  vtkGetMacro(AllowedPixels, vtkIdType);
  ///@}

  ///@{
  /// Scale of d in the difference image (default 16).
  vtkSetClampMacro(DifferenceScale, int, 1, 255);
  vtkGetMacro(DifferenceScale, int);
  ///@}

  /**
   * Compares @p candidate with @p baseline (8-bit, 3 or 4 components, same
   * size). True if no pixel differs by more than Tolerance and at most
   * AllowedPixels pixels differ.
   */
  bool Compare(vtkImageData* baseline, vtkImageData* candidate);

  /// Largest d of the last comparison (-1 if the images could not be compared).
  vtkGetMacro(MaximumDifference, int);

  /// Pixels with d > Tolerance in the last comparison.
  vtkGetMacro(PixelsAboveTolerance, vtkIdType);

  /// Pixels with d > 0 in the last comparison.
  vtkGetMacro(PixelsDifferent, vtkIdType);

  ///@{
  /// Column and row (from the bottom) of the first pixel with the largest d (-1 if none).
  vtkGetMacro(WorstI, int);
  vtkGetMacro(WorstJ, int);
  ///@}

  /// One line describing the outcome (the reason, if the images could not be compared).
  const char* GetSummary() { return this->Message.c_str(); }

  /// The difference image of the last comparison (null if the images could not be compared).
  vtkImageData* GetDifferenceImage();

protected:
  vtkHighOrderImageComparison();
  ~vtkHighOrderImageComparison() override;

private:
  vtkHighOrderImageComparison(const vtkHighOrderImageComparison&) = delete;
  void operator=(const vtkHighOrderImageComparison&) = delete;

  bool Refuse(const std::string& why);

  int Tolerance = 0;
  vtkIdType AllowedPixels = 0;
  int DifferenceScale = 16;
  int MaximumDifference = -1;
  vtkIdType PixelsAboveTolerance = 0;
  vtkIdType PixelsDifferent = 0;
  int WorstI = -1;
  int WorstJ = -1;
  std::string Message;
  vtkSmartPointer<vtkImageData> Difference;
};

#endif
