// Issue 4, acceptance 1(c): a mesh of 48 straight-edged quadratic
// tetrahedra (a 2^3 block of cubes, 6 Kuhn tetrahedra each) with the nodal
// values of a quadratic field f (interior minimum, a cross term) rendered
// directly by our mapper, against the same field on linear tetrahedra: each
// quadratic tetrahedron subdivided into 8^k (k = 1, 2, 3: 8, 64, 512) linear
// ones by the regular split of its parametric domain, the scalar at the new
// nodes being the quadratic interpolant there (hovTestReferenceGeneral.h,
// SubdivideQuadraticTetras, independent of the module). The linear field is
// the piecewise-linear interpolant of the quadratic one on a mesh of size
// h ~ 2^-k, so the image difference must shrink like h^2: each step halves h
// and should divide the error by ~4.
//
// Checks: our direct image is sane and covers the block; max and mean
// differences decrease at every step; the observed order of the mean
// difference log2(e_k / e_{k+1}) over the last step lies in [1.5, 2.5] (and
// is printed for every step, max and mean), and so does the least-squares
// order over the three levels. Semantics VTK_UNSTRUCTURED and
// RAW_EXTINCTION (GPU_COMPATIBLE at tolerance 1e-8 gives the same orders,
// 1.84 / 1.97, but takes ~15 s), Williams-Max, 96 x 96, oblique perspective
// view.
#include "hovTestReferenceGeneral.h"
#include "hovTestAnalytic.h"
#include "hovTestScenes.h"

#include "vtkCamera.h"
#include "vtkUnstructuredGrid.h"

#include <chrono>
#include <cmath>
#include <iomanip>
#include <iostream>

namespace
{
double F(const double* x)
{
  const double d[3] = { x[0] - 0.45, x[1] - 0.55, x[2] - 0.5 };
  return 0.1 + 1.5 * (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]) + 0.4 * x[0] * x[1];
}
}

int TestQuadraticConvergence(int, char*[])
{
  hovTest::Checker ck;
  const double origin[3] = { 0, 0, 0 };
  vtkSmartPointer<vtkUnstructuredGrid> quadratic =
    hovTestRef::MakeQuadraticTetraBlock(2, origin, 1.0, F);

  hovTest::TF tf;
  tf.Color->AddRGBPoint(0.1, 0.1, 0.2, 0.9);
  tf.Color->AddRGBPoint(0.3, 0.2, 0.9, 0.8);
  tf.Color->AddRGBPoint(0.55, 1.0, 0.8, 0.1);
  tf.Color->AddRGBPoint(0.9, 0.9, 0.2, 0.2);
  tf.Color->AddRGBPoint(1.6, 0.8, 0.8, 0.9);
  tf.Opacity->AddPoint(0.1, 0.05);
  tf.Opacity->AddPoint(0.25, 0.7);
  tf.Opacity->AddPoint(0.4, 0.1);
  tf.Opacity->AddPoint(0.7, 0.5);
  tf.Opacity->AddPoint(1.6, 0.2);
  tf.Property->SetScalarOpacityUnitDistance(0.5);

  vtkNew<vtkCamera> cam;
  const double focal[3] = { 0.5, 0.5, 0.5 }, dir[3] = { 0.55, -0.7, 0.45 }, up[3] = { 0, 0, 1 };
  hovTest::PlaceCamera(cam, focal, dir, 3.2, up, false, 32.0);
  cam->SetClippingRange(1.0, 6.0);
  const int size = 96;

  for (int sem : { 1, 2 })
  {
    const std::string name = hovTestRef::SemanticsName(sem);
    hovTest::VolumeScene direct(quadratic);
    direct.Volume->SetProperty(tf.Property);
    direct.Mapper->SetOpacitySemantics(sem);
    direct.Mapper->SetGPUOpacityTolerance(1e-8);
    direct.Observer->Clear();
    const hovTest::Image ref = hovTest::Render(direct.Mapper, cam, direct.Volume, size, size);
    const hovTest::Sanity sane = hovTest::CheckImage(ref);
    ck.Check(direct.NoMessages() && sane.Ok() && sane.Covered > size * size / 5,
      name + ": direct image of the 48 quadratic tets: no messages, " + sane.Str() +
        (direct.NoMessages() ? "" : " | messages: " +
            hovTest::Msg(direct.Observer->GetErrorMessage() + direct.Observer->GetWarningMessage())));

    std::vector<double> maxErr, meanErr;
    std::cout << "  " << name << ": level  linear tets   max |diff|    mean |diff|   order(max)  order(mean)  subdivide s  render s\n";
    for (int level = 1; level <= 3; ++level)
    {
      auto t0 = std::chrono::steady_clock::now();
      vtkSmartPointer<vtkUnstructuredGrid> linear = hovTestRef::SubdivideQuadraticTetras(quadratic, level);
      const double tSub = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      hovTest::VolumeScene lin(linear);
      lin.Volume->SetProperty(tf.Property);
      lin.Mapper->SetOpacitySemantics(sem);
      lin.Mapper->SetGPUOpacityTolerance(1e-8);
      t0 = std::chrono::steady_clock::now();
      const hovTest::Image img = hovTest::Render(lin.Mapper, cam, lin.Volume, size, size);
      const double tRen = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      ck.Check(lin.NoMessages() && img.Pixels() == ref.Pixels(),
        name + " level " + std::to_string(level) + ": linear image rendered without messages");
      double mx = 0, sum = 0;
      size_t n = 0;
      for (size_t p = 0; p < img.Pixels() && img.Pixels() == ref.Pixels(); ++p)
      {
        if (ref.V[4 * p + 3] == 0 && img.V[4 * p + 3] == 0)
        {
          continue;
        }
        for (int c = 0; c < 4; ++c)
        {
          const double e = std::fabs(img.V[4 * p + c] - ref.V[4 * p + c]);
          mx = std::max(mx, e);
          sum += e;
          ++n;
        }
      }
      maxErr.push_back(mx);
      meanErr.push_back(n ? sum / n : 0);
      std::cout << "  " << std::setw(static_cast<int>(name.size())) << "" << std::setw(7) << level << std::setw(13)
                << linear->GetNumberOfCells() << std::scientific << std::setprecision(3)
                << std::setw(14) << mx << std::setw(14) << meanErr.back() << std::fixed
                << std::setprecision(2);
      if (level > 1)
      {
        std::cout << std::setw(12) << std::log2(maxErr[level - 2] / mx) << std::setw(13)
                  << std::log2(meanErr[level - 2] / meanErr.back());
      }
      else
      {
        std::cout << std::setw(25) << "";
      }
      std::cout << std::setw(13) << tSub << std::setw(10) << tRen << std::defaultfloat << "\n";
    }
    const double lastOrder = std::log2(meanErr[1] / meanErr[2]);
    // Least-squares fit of log2(e) = c - p k over k = 1..3 (h = 2^-k).
    auto fit = [](const std::vector<double>& e) {
      const double l[3] = { std::log2(e[0]), std::log2(e[1]), std::log2(e[2]) };
      return -((l[2] - l[0]) / 2); // slope of the LS line through 3 equidistant points
    };
    std::cout << "  " << name << ": fitted order over 8 -> 512 sub-tets: max " << fit(maxErr)
              << ", mean " << fit(meanErr) << "\n";
    ck.Check(fit(meanErr) >= 1.5 && fit(meanErr) <= 2.5,
      name + ": fitted order of the mean difference " + hovTest::Fmt(fit(meanErr)) +
        " in [1.5, 2.5]");
    ck.Check(maxErr[0] > maxErr[1] && maxErr[1] > maxErr[2],
      name + ": max difference decreases with refinement (" + hovTest::Fmt(maxErr[0]) + " > " +
        hovTest::Fmt(maxErr[1]) + " > " + hovTest::Fmt(maxErr[2]) + ")");
    ck.Check(meanErr[0] > meanErr[1] && meanErr[1] > meanErr[2],
      name + ": mean difference decreases with refinement (" + hovTest::Fmt(meanErr[0]) + " > " +
        hovTest::Fmt(meanErr[1]) + " > " + hovTest::Fmt(meanErr[2]) + ")");
    ck.Check(lastOrder >= 1.5 && lastOrder <= 2.5,
      name + ": observed order of the mean difference, 64 -> 512 sub-tets: " +
        hovTest::Fmt(lastOrder) + " (expected ~2 in h)");
  }
  return ck.Result();
}
