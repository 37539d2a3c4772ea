/**
 * @file hovTestReferenceRun.h
 * @brief The acceptance loop of the single-cell tests of issue 4
 * (TestQuadraticTetra, TestQuadraticTrilinearHex): our mapper's float image
 * (RenderImage + GetFloatImage) of one cell against the independent reference
 * image (hovTestReferenceGeneral.h) for every view and optical model.
 *
 * A case fails if RenderImage reports an error or warning, if a pixel channel
 * differs from the reference by more than hovTest::AnalyticTolerance (1e-6),
 * or if the covered pixels differ (rays within hovTest::GrazeDistance of an
 * edge are left out of the coverage comparison).
 */
#ifndef hovTestReferenceRun_h
#define hovTestReferenceRun_h

#include "hovTestReferenceGeneral.h"

#include <vector>

class vtkUnstructuredGrid;
class vtkVolumeProperty;

namespace hovTestRef
{
/// A camera looking at a focal point (hovTest::PlaceCamera's arguments).
struct CellView
{
  const char* Name;
  bool Parallel;
  double Direction[3]; ///< from the focal point toward the camera
  double Distance;
  double Up[3];
  double AngleOrScale; ///< view angle (degrees) or parallel scale
};

/// Totals over the cases of RunCellCases.
struct RunTotals
{
  int Cases = 0;
  int Failures = 0;
  double MaxError = 0;
};

/**
 * Every (view, model) case: our mapper renders @p grid (GPU tolerance 1e-7)
 * at @p width x @p height, the reference integrates @p scene; one line per
 * case (covered pixels, max and mean error), failures printed with the worst
 * pixel and the inputs. Results are added to @p totals.
 */
void RunCellCases(const char* cellName, vtkUnstructuredGrid* grid, const CellScene& scene,
  const double focal[3], const std::vector<CellView>& views, const std::vector<Model>& models,
  vtkVolumeProperty* property, int width, int height, RunTotals& totals);
}

#endif
