// Degenerate view geometry: rays that lie exactly in an interior face (or
// run along an interior edge) of the mesh. An axis-aligned orthographic view
// of a structured tetrahedral block puts pixel centres exactly on the
// diagonal faces x = y of its cubes (a common setup: voxel grids split into
// tetrahedra, viewed along an axis). Each such ray must still cross the
// medium once: with a constant transfer function every pixel inside the
// cube's footprint has alpha = 1 - exp(-a L / u), L = 1 (VTK semantics).
// Checked in the CPU path (both orderings) and in RAY_CAST mode (without
// its shared-face fix, RAY_CAST composited face rays twice: alpha 0.63 and
// edge rays 0.95 instead of 0.39).
#include "hovTestScenes.h"

#include "vtkCamera.h"

#include <cmath>
#include <iostream>

using namespace hovTest;

int TestBadInputFaceRays(int, char*[])
{
  Checker ck;
  VolumeScene scene(UnitBlock(2).Grid());
  scene.Mapper->SetOpacitySemanticsToVTKUnstructured();
  const double a = 0.5, u = 1.0, white[3] = { 1, 1, 1 };
  ConstantTF(scene.Tf, white, a, u);
  const double alphaIn = -std::expm1(-a / u);

  for (const double shift : { AxisOrthoShift, 0.0 })
  {
    vtkNew<vtkCamera> cam;
    AxisOrthoCamera(cam, 1.0, shift);
    // Unshifted: 64 puts centres on the faces x = y (i == j); 63 also on the
    // faces x = 1/2 and y = 1/2, and its centre pixel runs along the interior
    // edge x = y = 1/2. Shifted: only 63's centre row (y = 1/2) is in a face.
    for (int n : { 64, 63 })
    {
      // The CPU path in both orderings, then the RAY_CAST mode (order 1
      // Lagrange tetrahedra through the curved ray caster).
      for (int order : { static_cast<int>(vtkHighOrderVolumeMapper::PER_PIXEL_SORT),
             static_cast<int>(vtkHighOrderVolumeMapper::VISIBILITY_SORT), -1 })
      {
        const bool rayCast = order < 0;
        scene.Mapper->SetRenderMode(
          rayCast ? vtkHighOrderVolumeMapper::RAY_CAST : vtkHighOrderVolumeMapper::CPU_ACCURATE);
        scene.Mapper->SetCellOrdering(rayCast ? vtkHighOrderVolumeMapper::VISIBILITY_SORT : order);
        scene.Observer->Clear();
        const Image img = Render(scene.Mapper, cam, scene.Volume, n, n);
        size_t inside = 0, bad = 0, onDiagonal = 0, badOnDiagonal = 0;
        double worst = 0, worstAlpha = alphaIn;
        int wi = -1, wj = -1;
        for (int j = 0; j < n; ++j)
        {
          const double y = OrthoPixelCoord(j, n);
          for (int i = 0; i < n; ++i)
          {
            const double x = OrthoPixelCoord(i, n, 1.0, 1.0, shift);
            const bool in = x >= 0 && x <= 1 && y >= 0 && y <= 1;
            // Rays on a cube boundary (x or y = 0 or 1) graze the block: skip.
            const bool boundary = x == 0 || x == 1 || y == 0 || y == 1;
            if (boundary)
            {
              continue;
            }
            // Interior faces of UnitBlock(2) that contain the view direction.
            const bool diagonal =
              in && (x == y || x == y + 0.5 || y == x + 0.5 || x == 0.5 || y == 0.5);
            inside += in;
            onDiagonal += diagonal;
            const double e = std::abs(img.At(i, j, 3) - (in ? alphaIn : 0.0));
            if (e > 1e-6)
            {
              ++bad;
              badOnDiagonal += diagonal;
            }
            if (e > worst)
            {
              worst = e;
              worstAlpha = img.At(i, j, 3);
              wi = i;
              wj = j;
            }
          }
        }
        std::cout << "== axis view, shift " << shift << ", " << n << "x" << n << ", "
                  << (rayCast ? "RAY_CAST" : (order ? "PER_PIXEL_SORT" : "VISIBILITY_SORT"))
                  << ": pixels inside " << inside
                  << ", with a ray in an interior face " << onDiagonal
                  << "; pixels off by > 1e-6: " << bad << " (" << badOnDiagonal
                  << " of them in a face); worst at (" << wi << "," << wj << "): alpha "
                  << worstAlpha << " expected " << alphaIn
                  << " (1-exp(-2a/u) = " << -std::expm1(-2 * a / u)
                  << "); witness=" << scene.Mapper->GetWitnessViolations() << "\n";
        ck.Check(scene.NoMessages(), "no messages");
        ck.Check(bad == 0,
          "every ray crosses thickness 1 exactly once (rays lying in shared faces are not "
          "composited twice)");
        if (shift == 0.0)
        {
          ck.Check(onDiagonal > 0, "(the unshifted view does put rays in interior faces)");
        }
      }
    }
  }
  return ck.Result();
}
