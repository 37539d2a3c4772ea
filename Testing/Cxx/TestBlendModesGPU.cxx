// The blend modes beside vtkGPUVolumeRayCastMapper (issue 19): a triquadratic
// hexahedron on [-1,1]^3 carrying f = 1.2 - 0.45 |x|^2 + 0.2 x - 0.1 y z
// (interior maximum), rendered by us (CPU_ACCURATE, exact per ray) and, after
// vtkResampleToImage at n^3 points (n = 5, 9, 17), by the GPU ray caster
// with the same property (linear interpolation), camera and blend mode
// (MAXIMUM_INTENSITY, MINIMUM_INTENSITY and AVERAGE_INTENSITY; the GPU
// mapper's MIP/MinIP read the raw opacity table, as ours). The difference is the resampling's
// (trilinear interpolation of a quadratic: O(h^2)) plus the GPU's 8-bit
// window (1/255) and its sampling: the max and mean RGB differences are
// printed per resolution and must shrink from n = 5 to n = 17 (mean: at every
// step). Numbers in the README, "Blend modes".
#include "hovTestBlendScenes.h"

#include "vtkCamera.h"
#include "vtkGPUVolumeRayCastMapper.h"
#include "vtkImageData.h"
#include "vtkPointData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkResampleToImage.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <cmath>
#include <iostream>

namespace
{
constexpr int W = 64, H = 56;

double Field(double x, double y, double z)
{
  return 1.2 - 0.45 * (x * x + y * y + z * z) + 0.2 * x - 0.1 * y * z;
}

struct Difference
{
  double Max = 0, Mean = 0;
};

/// RGB differences between our float image and the GPU's capture (over black).
Difference Compare(const hovTest::Image& ours, const hovTest::Image& gpu)
{
  Difference d;
  for (int j = 0; j < H; ++j)
  {
    for (int i = 0; i < W; ++i)
    {
      for (int c = 0; c < 3; ++c)
      {
        const double e = std::abs(ours.At(i, j, c) - gpu.At(i, j, c));
        d.Max = std::max(d.Max, e);
        d.Mean += e / (3.0 * W * H);
      }
    }
  }
  return d;
}
}

int TestBlendModesGPU(int, char*[])
{
  hovTest::Checker check;
  vtkNew<vtkCamera> cam;
  hovTest::BlendCamera(cam);
  vtkSmartPointer<vtkUnstructuredGrid> grid = hovTest::TriquadraticHex(Field);
  hovTest::VolumeScene scene(grid);
  hovTest::BlendTF(scene.Tf);
  scene.Tf.Property->SetInterpolationTypeToLinear();
  const int sizes[3] = { 5, 9, 17 };
  for (int blend = 1; blend <= 3; ++blend)
  {
    const char* name = blend == 1 ? "MIP" : (blend == 2 ? "MinIP" : "average");
    scene.Mapper->SetBlendMode(blend);
    const hovTest::Image ours = hovTest::Render(scene.Mapper, cam, scene.Volume, W, H);
    Difference d[3];
    for (int r = 0; r < 3; ++r)
    {
      const int n = sizes[r];
      vtkNew<vtkResampleToImage> resample;
      resample->SetInputDataObject(grid);
      resample->SetSamplingDimensions(n, n, n);
      resample->UseInputBoundsOn();
      resample->Update();
      vtkImageData* image = vtkImageData::SafeDownCast(resample->GetOutputDataObject(0));
      image->GetPointData()->SetActiveScalars("s");
      vtkNew<vtkGPUVolumeRayCastMapper> gpu;
      gpu->SetInputData(image);
      gpu->SetBlendMode(blend);
      gpu->AutoAdjustSampleDistancesOff();
      gpu->SetSampleDistance(0.002);
      vtkNew<vtkVolume> volume;
      volume->SetMapper(gpu);
      volume->SetProperty(scene.Tf.Property);
      vtkSmartPointer<vtkRenderer> ren = hovTest::BlackRenderer(cam);
      ren->AddVolume(volume);
      vtkSmartPointer<vtkRenderWindow> win = hovTest::OffscreenWindow(ren, W, H, 0);
      win->Render();
      d[r] = Compare(ours, hovTest::Capture(win));
      std::cout << "[measured] " << name << ", resampled " << n << "^3 (spacing "
                << hovTest::Fmt(2.0 / (n - 1)) << "): vtkGPUVolumeRayCastMapper - ours RGB max "
                << hovTest::Fmt(d[r].Max) << " mean " << hovTest::Fmt(d[r].Mean) << "\n";
      ren->RemoveAllViewProps();
      win->Finalize();
    }
    check.Check(d[0].Mean > d[1].Mean && d[1].Mean > d[2].Mean,
      std::string(name) + ": the mean difference shrinks with the grid spacing");
    check.Check(d[0].Max > d[2].Max, std::string(name) + ": so does the max difference");
  }
  check.Check(scene.NoMessages(), "no message from our mapper");
  return check.Result();
}
