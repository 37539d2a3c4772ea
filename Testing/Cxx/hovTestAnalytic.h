/**
 * @file hovTestAnalytic.h
 * @brief Set-up and case bookkeeping shared by the analytic tests
 * (TestAnalyticCube, TestAnalyticSingleTetra): camera placement, the sanity
 * check of a view's coverage, failures counted per case (the first few
 * printed with the case's label) and the checked RenderImage every case
 * starts with.
 */
#ifndef hovTestAnalytic_h
#define hovTestAnalytic_h

#include <string>

class vtkCamera;
class vtkHighOrderVolumeMapper;
class vtkVolume;
namespace vtkTest
{
class ErrorObserver;
}

namespace hovTest
{
/// The accuracy the analytic tests ask of every pixel channel: |got -
/// reference| <= AnalyticTolerance.
constexpr double AnalyticTolerance = 1e-6;

/// Rays passing closer than GrazeDistance to an edge of the geometry graze it:
/// whether they hit it is not compared.
constexpr double GrazeDistance = 1e-9;

/**
 * Points @p cam at @p focal from @p distance along @p direction (any
 * length), view up @p up: orthographic with parallel scale @p angleOrScale if
 * @p parallel, else perspective with view angle @p angleOrScale (degrees).
 * The clipping range is left to the caller.
 */
void PlaceCamera(vtkCamera* cam, const double focal[3], const double direction[3], double distance,
  const double up[3], bool parallel, double angleOrScale);

/// False (and a set-up failure printed) unless @p covered of the @p total
/// pixels of view @p view are at least @p least and not all of them; @p want
/// says how much is wanted.
bool CoverageOk(const char* view, int covered, int least, int total, const char* want);

/// The failures of one case: counted, the first eight printed as
/// "FAILED [label]: what".
struct CaseFailures
{
  explicit CaseFailures(std::string label);
  void operator()(const std::string& what);
  std::string Label;
  int Count = 0;
};

/**
 * RenderImage(@p cam, @p volume, @p width, @p height) of @p mapper after
 * clearing @p observer: a failure of the case unless it returns 1, no error or
 * warning is observed and the float image is @p width x @p height RGBA
 * (hovTestRef::ImagePixels). Returns the image's pixels, or null if there is
 * no such image; the wall time of RenderImage in @p seconds if given.
 */
const float* RenderCase(vtkHighOrderVolumeMapper* mapper, vtkCamera* cam, vtkVolume* volume,
  int width, int height, vtkTest::ErrorObserver* observer, CaseFailures& fail,
  double* seconds = nullptr);
}

#endif
