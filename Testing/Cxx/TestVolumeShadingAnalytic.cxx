// Volume shading and gradient opacity (vtkVolumeProperty Shade, Ambient,
// Diffuse, Specular, SpecularPower, the gradient-opacity function) against a
// closed form on an analytic scene, per pixel.
//
// Scene: a cube [-1, 1]^3 of tetrahedra (3x3x3 cubes x 6, Kuhn) with the
// affine field s = a + g.x (constant gradient g), a colour function linear in
// s over the whole field range (two nodes outside it) and a constant opacity
// (RAW_EXTINCTION: tau = 0.8 per unit length). RenderImage lights the volume
// with one white directional headlight along the direction of projection
// (hovShadingSetup.h), so on every ray the shaded colour is the affine map
//     c_sh(t) = (ka + kd |n.l|) c(s(t)) + ks |n.h|^p,   n = g/|g|, l = -dop,
//     h = (l + v)/|l + v|, v = -ray direction
// (two-sided lighting, VTK's single-headlight ambient ka c; no clamp: every
// channel stays below 1), linear in t, and the extinction is gamma tau with
// gamma = GO(|g|) constant. With c_sh(t) = alpha + beta t, k = gamma tau, the
// chord's premultiplied colour is, in closed form (E = e^{-kL}),
//     Williams-Max:        alpha (1 - E) + beta ((1 - E)/k - L E)
//     Wilhelms-Van Gelder: f (alpha (1 - E)/k + beta ((1 - E)/k^2 - L E/k))
// (f = EmissionScale / unit), A = 1 - E, whatever the tetrahedralisation
// (computed here in long double; nothing of the module is used).
//
// Cases: CPU_ACCURATE and RAY_CAST (tolerance 1e-9) x Shade on/off x gradient
// opacity on/off x both emission models x an orthographic and a perspective
// view (h varies per pixel), by RenderImage; then in a window (the renderer's
// automatic headlight) CPU_ACCURATE, and OPENGL_PROJECTION, which does not
// shade and must say so in exactly one warning per feature over three frames.
// Expected: max and mean error per channel <= 1e-6 over the covered pixels
// (and off the cube, where the image must be 0), no warning. Measured (GCC 12
// Release): max 3.0e-8 in every mode and case (the float image's rounding),
// mean <= 1.2e-8.
#include "hovTestAnalytic.h"
#include "hovTestReference.h"
#include "hovTestScenes.h"

#include "vtkCamera.h"
#include "vtkCommand.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkUnstructuredGrid.h"

#include <array>
#include <cmath>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace
{
using hovTestRef::Real;

constexpr int Width = 40;
constexpr int Height = 36;
const double Origin[3] = { -1.0, -1.0, -1.0 };
const double Bounds[6] = { -1.0, 1.0, -1.0, 1.0, -1.0, 1.0 };
constexpr double FieldOffset = 0.5;
const double FieldGradient[3] = { 0.3, -0.2, 0.25 }; // s in [-0.25, 1.25]
constexpr double SA = -0.5, SB = 1.5;                // the colour nodes
const double ColorA[3] = { 0.1, 0.5, 0.2 }, ColorB[3] = { 0.6, 0.1, 0.4 };
constexpr double Tau = 0.8;
constexpr double Ka = 0.3, Kd = 0.5, Ks = 0.2, Power = 8.0;
constexpr double GO0 = 0.2, GO1 = 1.0; // gradient opacity: (0, GO0) to (1, GO1)
constexpr double EmissionScale = 0.7;

Real Dot(const hovTestRef::Vec3& a, const hovTestRef::Vec3& b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

hovTestRef::Vec3 Unit(const hovTestRef::Vec3& a)
{
  const Real n = std::sqrt(Dot(a, a));
  return { a[0] / n, a[1] / n, a[2] / n };
}

/// The closed form of one pixel (see the file comment).
hovTestRef::RGBA ClosedForm(const hovTestRef::Ray& ray, Real tIn, Real tOut,
  const hovTestRef::Vec3& light, bool shade, bool gradientOpacity, int emission)
{
  const hovTestRef::Vec3 x0 = ray.At(tIn), x1 = ray.At(tOut);
  auto field = [](const hovTestRef::Vec3& x) {
    return Real(FieldOffset) + FieldGradient[0] * x[0] + FieldGradient[1] * x[1] +
      FieldGradient[2] * x[2];
  };
  const Real L = tOut - tIn, s0 = field(x0), s1 = field(x1);
  const hovTestRef::Vec3 g{ FieldGradient[0], FieldGradient[1], FieldGradient[2] };
  const Real gNorm = std::sqrt(Dot(g, g));
  Real m = 1, k0 = 0;
  if (shade)
  {
    const hovTestRef::Vec3 n = Unit(g);
    const hovTestRef::Vec3 v{ -ray.Direction[0], -ray.Direction[1], -ray.Direction[2] };
    const hovTestRef::Vec3 h = Unit({ light[0] + v[0], light[1] + v[1], light[2] + v[2] });
    m = Ka + Kd * std::fabs(Dot(n, light));
    k0 = Ks * std::pow(std::fabs(Dot(n, h)), Real(Power));
  }
  const Real gamma = gradientOpacity ? GO0 + (GO1 - GO0) * std::min(gNorm, Real(1)) : Real(1);
  const Real k = gamma * Tau;
  const Real E = std::exp(-k * L), oneMinusE = -std::expm1(-k * L);
  hovTestRef::RGBA out;
  Real rgb[3];
  for (int c = 0; c < 3; ++c)
  {
    const Real slope = (Real(ColorB[c]) - ColorA[c]) / (SB - SA);
    const Real alpha = m * (ColorA[c] + slope * (s0 - SA)) + k0;
    const Real beta = m * slope * (s1 - s0) / L;
    rgb[c] = emission == 0 ? alpha * oneMinusE + beta * (oneMinusE / k - L * E)
                           : Real(EmissionScale) *
        (alpha * oneMinusE / k + beta * (oneMinusE / (k * k) - L * E / k));
  }
  out.R = rgb[0];
  out.G = rgb[1];
  out.B = rgb[2];
  out.A = oneMinusE;
  return out;
}
}

int TestVolumeShadingAnalytic(int, char*[])
{
  int failures = 0;
  vtkSmartPointer<vtkUnstructuredGrid> grid =
    hovTestRef::MakeCubeOfTetras(3, Origin, 2.0, 6, FieldOffset, FieldGradient);
  hovTest::VolumeScene scene(grid);
  vtkHighOrderVolumeMapper* mapper = scene.Mapper;
  vtkVolumeProperty* property = scene.Tf.Property;
  hovTest::LinearShadingTF(scene.Tf, SA, SB, ColorA, ColorB, Tau, Tau, Ka, Kd, Ks, Power);
  vtkNew<vtkPiecewiseFunction> gradientOpacity;
  gradientOpacity->AddPoint(0.0, GO0);
  gradientOpacity->AddPoint(1.0, GO1);
  mapper->SetOpacitySemanticsToRawExtinction();
  mapper->SetEmissionScale(EmissionScale);
  mapper->SetRayCastTolerance(1e-9);
  vtkNew<hovTest::MessageCounter> counter;
  mapper->AddObserver(vtkCommand::WarningEvent, counter);
  mapper->AddObserver(vtkCommand::ErrorEvent, counter);

  struct View
  {
    const char* Name;
    bool Parallel;
    double Direction[3];
    double AngleOrScale;
  };
  const View views[] = { { "orthographic", true, { 1.3, 0.8, 1.7 }, 1.9 },
    { "perspective", false, { -1.1, 1.6, 0.9 }, 40.0 } };
  std::cout << "max / mean |error| over covered pixels, channels R G B A\n";
  for (const View& view : views)
  {
    vtkNew<vtkCamera> camera;
    const double focal[3] = { 0.0, 0.0, 0.0 }, up[3] = { 0.0, 0.0, 1.0 };
    hovTest::PlaceCamera(camera, focal, view.Direction, 6.0, up, view.Parallel, view.AngleOrScale);
    camera->SetClippingRange(2.0, 10.0);
    const hovTestRef::CameraSpec spec = hovTestRef::ReadCamera(camera);
    double dop[3];
    camera->GetDirectionOfProjection(dop);
    const hovTestRef::Vec3 light = Unit({ -dop[0], -dop[1], -dop[2] });
    for (int shade = 0; shade < 2; ++shade)
    {
      for (int go = 0; go < 2; ++go)
      {
        property->SetShade(shade);
        property->SetGradientOpacity(go ? gradientOpacity.Get() : nullptr);
        for (int em = 0; em < 4; ++em)
        {
          const int mode = em / 2; // CPU_ACCURATE, then RAY_CAST
          mapper->SetEmissionModel(em % 2);
          mapper->SetRenderMode(mode == 0 ? vtkHighOrderVolumeMapper::CPU_ACCURATE
                                          : vtkHighOrderVolumeMapper::RAY_CAST);
          std::ostringstream label;
          label << (mode == 0 ? "CPU_ACCURATE" : "RAY_CAST") << " / " << view.Name << " / Shade "
                << shade << " / gradient opacity " << go << " / "
                << hovTestRef::EmissionName(em % 2);
          hovTest::CaseFailures fail(label.str());
          counter->Clear();
          if (mapper->RenderImage(camera, scene.Volume, Width, Height) != 1)
          {
            fail("RenderImage did not return 1");
          }
          if (counter->Warnings || counter->Errors)
          {
            fail("unexpected message: " + counter->Text);
          }
          if (mode == 1 && mapper->GetNumberOfRays() <= 0)
          {
            fail("RAY_CAST traced no ray");
          }
          std::string why;
          const float* px =
            hovTestRef::ImagePixels(mapper->GetFloatImage(), Width, Height, why);
          if (!px)
          {
            fail(why);
            failures += fail.Count;
            continue;
          }
          std::array<double, 4> maxErr{ 0, 0, 0, 0 }, sum{ 0, 0, 0, 0 };
          int covered = 0;
          for (int j = 0; j < Height; ++j)
          {
            for (int i = 0; i < Width; ++i)
            {
              const int p = j * Width + i;
              const hovTestRef::Ray ray = hovTestRef::PixelRay(spec, i, j, Width, Height);
              if (hovTestRef::DistanceToBoxEdges(ray, Bounds) < hovTest::GrazeDistance)
              {
                continue;
              }
              Real tIn, tOut;
              hovTestRef::RGBA want;
              if (hovTestRef::IntersectBox(ray, Bounds, tIn, tOut) && tOut > tIn)
              {
                want = ClosedForm(ray, tIn, tOut, light, shade != 0, go != 0, em % 2);
                ++covered;
              }
              for (int c = 0; c < 4; ++c)
              {
                const double err = std::fabs(double(px[4 * p + c]) - double(want[c]));
                maxErr[c] = std::max(maxErr[c], err);
                sum[c] += err;
                if (!(err <= hovTest::AnalyticTolerance))
                {
                  std::ostringstream os;
                  os << "pixel (" << i << ", " << j << ") channel " << c << ": " << px[4 * p + c]
                     << " vs closed form " << double(want[c]);
                  fail(os.str());
                }
              }
            }
          }
          if (!hovTest::CoverageOk(view.Name, covered, Width * Height / 4, Width * Height,
                "most of the image"))
          {
            ++failures;
          }
          std::cout << "  " << label.str() << ": max";
          for (int c = 0; c < 4; ++c)
          {
            std::cout << " " << maxErr[c];
          }
          std::cout << " / mean";
          for (int c = 0; c < 4; ++c)
          {
            const double mean = sum[c] / std::max(covered, 1);
            std::cout << " " << mean;
            if (!(mean <= hovTest::AnalyticTolerance))
            {
              fail("mean error above the tolerance");
            }
          }
          std::cout << "\n";
          failures += fail.Count;
        }
      }
    }
  }

  // In a window: the renderer's automatic headlight (at the camera, toward the
  // focal point: the same light), CPU_ACCURATE against the closed form; then
  // OPENGL_PROJECTION, which does not shade: exactly one warning per feature.
  {
    mapper->SetRenderModeToCPUAccurate();
    mapper->SetEmissionModel(0);
    property->SetShade(1);
    property->SetGradientOpacity(gradientOpacity);
    vtkNew<vtkCamera> camera;
    const double focal[3] = { 0.0, 0.0, 0.0 }, up[3] = { 0.0, 0.0, 1.0 };
    hovTest::PlaceCamera(camera, focal, views[1].Direction, 6.0, up, false, 40.0);
    camera->SetClippingRange(2.0, 10.0);
    vtkSmartPointer<vtkRenderer> ren = hovTest::BlackRenderer(camera);
    ren->AddVolume(scene.Volume);
    vtkSmartPointer<vtkRenderWindow> win = hovTest::OffscreenWindow(ren, Width, Height);
    counter->Clear();
    win->Render();
    const hovTestRef::CameraSpec spec = hovTestRef::ReadCamera(camera);
    double dop[3];
    camera->GetDirectionOfProjection(dop);
    const hovTestRef::Vec3 light = Unit({ -dop[0], -dop[1], -dop[2] });
    std::string why;
    const float* px = hovTestRef::ImagePixels(mapper->GetFloatImage(), Width, Height, why);
    double worst = 0.0;
    for (int p = 0; px && p < Width * Height; ++p)
    {
      const hovTestRef::Ray ray = hovTestRef::PixelRay(spec, p % Width, p / Width, Width, Height);
      Real tIn, tOut;
      hovTestRef::RGBA want;
      if (hovTestRef::DistanceToBoxEdges(ray, Bounds) < hovTest::GrazeDistance)
      {
        continue;
      }
      if (hovTestRef::IntersectBox(ray, Bounds, tIn, tOut) && tOut > tIn)
      {
        want = ClosedForm(ray, tIn, tOut, light, true, true, 0);
      }
      for (int c = 0; c < 4; ++c)
      {
        worst = std::max(worst, std::fabs(double(px[4 * p + c]) - double(want[c])));
      }
    }
    std::cout << "window, renderer's headlight, CPU_ACCURATE: max error " << worst << "\n";
    if (!px || !(worst <= hovTest::AnalyticTolerance) || counter->Warnings || counter->Errors)
    {
      std::cerr << "FAILED: window CPU_ACCURATE: max error " << worst << " " << why << " "
                << counter->Text << "\n";
      ++failures;
    }
    mapper->SetRenderModeToOpenGLProjection();
    counter->Clear();
    for (int frame = 0; frame < 3; ++frame)
    {
      win->Render();
    }
    const bool named = counter->Text.find("Shade") != std::string::npos &&
      counter->Text.find("gradient opacity") != std::string::npos &&
      counter->Text.find("OPENGL_PROJECTION") != std::string::npos;
    std::cout << "OPENGL_PROJECTION: " << counter->Warnings << " warnings over 3 frames\n";
    if (counter->Warnings != 2 || counter->Errors != 0 || !named)
    {
      std::cerr << "FAILED: OPENGL_PROJECTION with Shade and gradient opacity: want exactly 2 "
                   "warnings naming them and the mode, got "
                << counter->Warnings << ": " << counter->Text << "\n";
      ++failures;
    }
  }
  if (failures)
  {
    std::cerr << failures << " failures\n";
  }
  return failures ? 1 : 0;
}
