// Reference images of one cell (hovTestReferenceGeneral.h: RenderReference,
// CompareImage).
#include "hovTestReferenceGeneral.h"

#include "vtkColorTransferFunction.h"
#include "vtkPiecewiseFunction.h"
#include "vtkSMPTools.h" // rows of the reference image in parallel
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace hovTestRef
{
ReferenceImage RenderReference(const CellScene& scene, const CameraSpec& cam,
  vtkVolumeProperty* property, const Model& model, int width, int height, Real grazeDistance)
{
  ReferenceImage ref;
  ref.W = width;
  ref.H = height;
  const size_t n = static_cast<size_t>(width) * height;
  ref.Pixels.assign(n, RGBA{});
  ref.Length.assign(n, 0);
  ref.Covered.assign(n, 0);
  ref.Grazing.assign(n, 0);
  // The colour and opacity functions are only read (GetValue/GetColor build
  // no cache once built): build them before the threads start.
  property->GetScalarOpacity(0)->GetValue(0.0);
  double rgb[3];
  property->GetRGBTransferFunction(0)->GetColor(0.0, rgb);
  vtkSMPTools::For(0, height, 1, [&](vtkIdType j0, vtkIdType j1) {
    const CellScene local = scene; // per-thread copy of stateful fields
    for (vtkIdType j = j0; j < j1; ++j)
    {
      for (int i = 0; i < width; ++i)
      {
        const size_t p = static_cast<size_t>(j) * width + i;
        const Ray ray = PixelRay(cam, i, static_cast<int>(j), width, height);
        Real tIn, tOut;
        ref.Grazing[p] = local.EdgeDistance(ray) < grazeDistance;
        if (!local.Intersect(ray, tIn, tOut))
        {
          continue;
        }
        ref.Covered[p] = 1;
        ref.Length[p] = tOut - tIn;
        auto s = [&](Real t) { return local.Field(ray.At(tIn + t)); };
        ref.Pixels[p] = IntegrateRayGeneral(property, model, s, tOut - tIn);
      }
    }
  });
  for (size_t p = 0; p < n; ++p)
  {
    ref.ExpectedCovered += ref.Covered[p] && !ref.Grazing[p];
  }
  return ref;
}

ImageComparison CompareImage(const ReferenceImage& ref, const float* px, double tolerance)
{
  ImageComparison cmp;
  double sum = 0;
  size_t count = 0;
  for (int j = 0; j < ref.H; ++j)
  {
    for (int i = 0; i < ref.W; ++i)
    {
      const size_t p = static_cast<size_t>(j) * ref.W + i;
      const float* got = px + 4 * p;
      const bool nonZero = got[0] != 0 || got[1] != 0 || got[2] != 0 || got[3] != 0;
      if (!ref.Grazing[p])
      {
        cmp.GotCovered += nonZero;
        cmp.CoverageMismatches += nonZero != (ref.Covered[p] != 0);
      }
      double worst = 0;
      for (int c = 0; c < 4; ++c)
      {
        const double err = std::fabs(double(got[c]) - double(ref.Pixels[p][c]));
        worst = std::max(worst, err);
        if (ref.Covered[p])
        {
          sum += err;
          ++count;
        }
      }
      cmp.Above += worst > tolerance;
      if (worst > cmp.MaxError || (p == 0 && cmp.Worst.empty()))
      {
        cmp.MaxError = worst;
        std::ostringstream os;
        os << std::setprecision(10) << "pixel (" << i << ", " << j << "): got RGBA " << got[0]
           << " " << got[1] << " " << got[2] << " " << got[3] << ", reference "
           << double(ref.Pixels[p].R) << " " << double(ref.Pixels[p].G) << " "
           << double(ref.Pixels[p].B) << " " << double(ref.Pixels[p].A) << " (chord "
           << double(ref.Length[p]) << (ref.Grazing[p] ? ", grazing" : "") << ")";
        cmp.Worst = os.str();
      }
    }
  }
  cmp.MeanError = count ? sum / count : 0;
  return cmp;
}
}
