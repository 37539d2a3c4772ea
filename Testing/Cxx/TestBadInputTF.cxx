// Extreme and absurd transfer functions and unit distances: opacity 1
// everywhere (all three semantics), NaN nodes, opacity outside [0,1], a single
// node, no nodes, huge/tiny scalar ranges, unit distance 1e-30 / 1e30 / 0 /
// negative / NaN. Every image must be finite with 0 <= alpha <= 1; bad
// functions must be reported with a warning (valid ones must not), and where
// the answer is known it is checked: analytically on an axis-aligned
// orthographic view of the unit cube (every ray inside crosses thickness 1,
// entering at z = 1 where s = x + y/2 + 1/4), or against the image of the
// equivalent sane function.
#include "hovTestScenes.h"

#include "vtkCamera.h"

#include <cmath>
#include <functional>
#include <iostream>
#include <limits>
#include <string>

using namespace hovTest;

namespace
{
const double NaN = std::numeric_limits<double>::quiet_NaN();
constexpr int N = 64; // axis image: pixels 16..47 cover the cube in x and y

/// Expected premultiplied RGBA of an axis pixel centre (x, y) inside the cube.
using Expectation = std::function<void(double x, double y, double rgba[4])>;

/// Max abs error of an axis-view image against @p expect (0 outside the cube).
double AxisError(const Image& img, const Expectation& expect, std::string& where)
{
  double worst = 0;
  for (int j = 0; j < img.H; ++j)
  {
    for (int i = 0; i < img.W; ++i)
    {
      const bool inside = i >= N / 4 && i < 3 * N / 4 && j >= N / 4 && j < 3 * N / 4;
      double e[4] = { 0, 0, 0, 0 };
      if (inside)
      {
        expect(OrthoPixelCoord(i, N, 1.0, 1.0, AxisOrthoShift), OrthoPixelCoord(j, N), e);
      }
      for (int c = 0; c < 4; ++c)
      {
        double d = std::abs(img.At(i, j, c) - e[c]);
        if (std::isnan(d))
        {
          d = std::numeric_limits<double>::infinity();
        }
        if (d > worst)
        {
          worst = d;
          where = "pixel (" + std::to_string(i) + "," + std::to_string(j) + ") ch " +
            std::to_string(c) + ": got " + Fmt(img.At(i, j, c)) + " expected " + Fmt(e[c]);
        }
      }
    }
  }
  return worst;
}
}

int TestBadInputTF(int, char*[])
{
  Checker ck;
  VolumeScene scene; // every case sets its own property
  scene.Mapper->SetCellOrdering(vtkHighOrderVolumeMapper::PER_PIXEL_SORT);
  vtkNew<vtkCamera> axis, oblique;
  AxisOrthoCamera(axis, 1.0, AxisOrthoShift);
  ObliqueCamera(oblique);

  const MeshBuilder block = UnitBlock(2);
  auto grid = block.Grid();
  scene.Mapper->SetInputData(grid);

  const char* semName[3] = { "GPU_COMPATIBLE", "VTK_UNSTRUCTURED", "RAW_EXTINCTION" };

  // Reference images of the default transfer function (oblique view), per semantics.
  Image defaultImage[3];
  for (int sem = 0; sem < 3; ++sem)
  {
    TF tf;
    DefaultTF(tf);
    scene.Volume->SetProperty(tf.Property);
    scene.Mapper->SetOpacitySemantics(sem);
    scene.Observer->Clear();
    defaultImage[sem] = Render(scene.Mapper, oblique, scene.Volume, N, N);
    const Sanity s = CheckImage(defaultImage[sem]);
    std::cout << "== default TF, " << semName[sem] << ": " << s.Str() << "\n";
    ck.Check(
      !scene.Observer->GetWarning() && !scene.Observer->GetError() && s.Ok() && s.Covered > 500,
      std::string("default TF renders cleanly in ") + semName[sem]);
  }

  // One case: configure a fresh property, render axis + oblique, check.
  // expectWarning: 1 yes, 0 no, -1 not asserted.
  auto runCase = [&](const std::string& name, int sem,
                   const std::function<void(TF&)>& configure, int expectWarning,
                   const Expectation& axisExpect, double axisTol, const Image* obliqueRef,
                   double obliqueTol) {
    TF tf;
    configure(tf);
    scene.Volume->SetProperty(tf.Property);
    scene.Mapper->SetOpacitySemantics(sem);
    scene.Observer->Clear();
    int st1 = -1, st2 = -1;
    const Image ax = Render(scene.Mapper, axis, scene.Volume, N, N, &st1);
    const std::string warn1 = scene.Observer->GetWarningMessage();
    const bool warned = scene.Observer->GetWarning();
    const bool erred = scene.Observer->GetError();
    const Image ob = Render(scene.Mapper, oblique, scene.Volume, N, N, &st2);
    const Sanity sa = CheckImage(ax), so = CheckImage(ob);
    std::cout << "== " << name << " [" << semName[sem] << "]\n    axis:    " << sa.Str()
              << "\n    oblique: " << so.Str() << "\n    warning: '" << Msg(warn1) << "' error: '"
              << Msg(scene.Observer->GetErrorMessage()) << "'\n";
    ck.Check(st1 == 1 && st2 == 1 && !erred && !scene.Observer->GetError(),
      name + ": renders (status 1), no error");
    ck.Check(sa.Ok() && so.Ok(), name + ": finite images, 0 <= alpha <= 1, 0 <= rgb <= alpha");
    if (expectWarning >= 0)
    {
      ck.Check(warned == (expectWarning == 1),
        name + (expectWarning ? ": a warning is issued" : ": no warning (the function is valid)"));
    }
    if (axisExpect)
    {
      std::string where;
      const double err = AxisError(ax, axisExpect, where);
      std::cout << "    axis view vs analytic: max error " << Fmt(err) << " at " << where << "\n";
      ck.Check(err <= axisTol, name + ": axis view matches the analytic image within " + Fmt(axisTol));
    }
    if (obliqueRef)
    {
      const DiffStats d = Diff(ob, *obliqueRef);
      std::cout << "    oblique vs reference: " << d.Str() << "\n";
      ck.Check(d.Max <= obliqueTol, name + ": oblique view equals the reference within " + Fmt(obliqueTol));
    }
    return ax;
  };

  const double c0[3] = { 0.9, 0.5, 0.2 };
  auto constantColor = [&](TF& tf) {
    tf.Color->AddRGBPoint(0.0, c0[0], c0[1], c0[2]);
    tf.Color->AddRGBPoint(1.75, c0[0], c0[1], c0[2]);
  };
  auto uniform = [&](double alpha) {
    return [=](double, double, double e[4]) {
      e[3] = alpha;
      for (int c = 0; c < 3; ++c)
      {
        e[c] = c0[c] * alpha;
      }
    };
  };
  // Colour of DefaultTF at the entry point (z = 1) of the axis ray, times alpha.
  TF defaultColors;
  DefaultTF(defaultColors);
  auto entryColor = [&](double alpha) {
    return [&, alpha](double x, double y, double e[4]) {
      defaultColors.Color->GetColor(DefaultField(x, y, 1.0), e);
      for (int c = 0; c < 3; ++c)
      {
        e[c] *= alpha;
      }
      e[3] = alpha;
    };
  };

  const double u = 0.5;
  // Constant colour, opacity a0 at s = 0 and a1 at s = 1.75, unit distance u.
  auto constantColorRamp = [&](double a0, double a1) {
    return [&, a0, a1](TF& tf) {
      constantColor(tf);
      tf.Opacity->AddPoint(0.0, a0);
      tf.Opacity->AddPoint(1.75, a1);
      tf.Property->SetScalarOpacityUnitDistance(u);
    };
  };

  // ---- Opacity 1 everywhere.
  const double opaqueAlpha[3] = { 1.0, -std::expm1(-1.0 / u), -std::expm1(-1.0) };
  Image opaque[3];
  for (int sem = 0; sem < 3; ++sem)
  {
    opaque[sem] = runCase("opacity 1 everywhere, constant colour", sem, constantColorRamp(1.0, 1.0),
      0, uniform(opaqueAlpha[sem]), 1e-6, nullptr, 0);
  }
  runCase("opacity 1 everywhere, DefaultTF colours (GPU: the entry colour)", 0,
    [&](TF& tf) {
      DefaultTF(tf, u);
      tf.Opacity->RemoveAllPoints();
      tf.Opacity->AddPoint(0.0, 1.0);
      tf.Opacity->AddPoint(1.75, 1.0);
    },
    0, entryColor(1.0), 1e-6, nullptr, 0);

  // ---- Opacity outside [0,1].
  for (int sem = 0; sem < 2; ++sem)
  {
    runCase("opacity 5 everywhere (clamped to 1)", sem, constantColorRamp(5.0, 5.0), 1,
      uniform(opaqueAlpha[sem]), 1e-6, nullptr, 0);
    runCase("opacity -0.5 everywhere (clamped to 0: invisible)", sem, constantColorRamp(-0.5, -0.5),
      1, uniform(0.0), 0.0, nullptr, 0);
    runCase(
      "opacity ramp -0.5 -> 1.7", sem, constantColorRamp(-0.5, 1.7), 1, nullptr, 0, nullptr, 0);
  }

  // ---- A single node each: constant functions.
  const double c1[3] = { 0.3, 0.6, 0.9 };
  const double singleAlpha[3] = { 1.0 - std::pow(0.5, 1.0 / u), -std::expm1(-0.5 / u),
    -std::expm1(-0.5) };
  for (int sem = 0; sem < 3; ++sem)
  {
    runCase("single colour node and single opacity node (0.5)", sem,
      [&](TF& tf) {
        tf.Color->AddRGBPoint(0.8, c1[0], c1[1], c1[2]);
        tf.Opacity->AddPoint(0.8, 0.5);
        tf.Property->SetScalarOpacityUnitDistance(u);
      },
      0,
      [&, sem](double, double, double e[4]) {
        e[3] = singleAlpha[sem];
        for (int c = 0; c < 3; ++c)
        {
          e[c] = c1[c] * singleAlpha[sem];
        }
      },
      sem == 0 ? 4e-4 : 1e-6, nullptr, 0);
  }

  // ---- No nodes.
  runCase("no opacity nodes (transparent)", 0,
    [&](TF& tf) {
      constantColor(tf);
      tf.Property->SetScalarOpacityUnitDistance(u);
    },
    1, uniform(0.0), 0.0, nullptr, 0);
  runCase("no colour nodes (black), opacity 0.5", 1,
    [&](TF& tf) {
      tf.Opacity->AddPoint(0.0, 0.5);
      tf.Opacity->AddPoint(1.75, 0.5);
      tf.Property->SetScalarOpacityUnitDistance(u);
    },
    1,
    [&](double, double, double e[4]) {
      e[0] = e[1] = e[2] = 0.0;
      e[3] = -std::expm1(-0.5 / u);
    },
    1e-6, nullptr, 0);
  runCase("no nodes at all", 0, [&](TF& tf) { tf.Property->SetScalarOpacityUnitDistance(u); }, 1,
    uniform(0.0), 0.0, nullptr, 0);

  // ---- NaN nodes: dropped (as documented), the rest renders as without them.
  for (int sem = 0; sem < 2; ++sem)
  {
    runCase("NaN opacity value at s=0.3", sem,
      [&](TF& tf) {
        DefaultTF(tf);
        tf.Opacity->AddPoint(0.3, NaN);
      },
      1, nullptr, 0, &defaultImage[sem], 1e-6);
    runCase("NaN opacity position", sem,
      [&](TF& tf) {
        DefaultTF(tf);
        tf.Opacity->AddPoint(NaN, 0.9);
      },
      1, nullptr, 0, &defaultImage[sem], 1e-6);
    runCase("NaN colour value at s=0.5", sem,
      [&](TF& tf) {
        DefaultTF(tf);
        tf.Color->AddRGBPoint(0.5, NaN, 0.5, 0.5);
      },
      1, nullptr, 0, &defaultImage[sem], 1e-6);
  }

  // ---- Huge and tiny scalar ranges: scalars and nodes scaled together.
  for (double scale : { 1e300, 1e-300, 1e-30, 1e30 })
  {
    MeshBuilder scaled = block;
    for (double& s : scaled.Scalars)
    {
      s *= scale;
    }
    auto sg = scaled.Grid();
    scene.Mapper->SetInputData(sg);
    for (int sem = 0; sem < 3; sem += 1)
    {
      runCase("scalars and TF nodes scaled by " + Fmt(scale), sem,
        [&](TF& tf) {
          DefaultTF(tf);
          TF plain;
          DefaultTF(plain);
          tf.Color->RemoveAllPoints();
          tf.Opacity->RemoveAllPoints();
          for (int i = 0; i < plain.Color->GetSize(); ++i)
          {
            double v[6];
            plain.Color->GetNodeValue(i, v);
            tf.Color->AddRGBPoint(v[0] * scale, v[1], v[2], v[3]);
          }
          for (int i = 0; i < plain.Opacity->GetSize(); ++i)
          {
            double v[4];
            plain.Opacity->GetNodeValue(i, v);
            tf.Opacity->AddPoint(v[0] * scale, v[1]);
          }
        },
        0, nullptr, 0, &defaultImage[sem], 1e-6);
    }
  }
  scene.Mapper->SetInputData(grid);

  // ---- Node positions +-1.5e308 (their distance overflows to +inf): VTK
  // evaluates such a function to its left node value (0.3, (0.2,0.4,0.6)).
  {
    TF probe;
    probe.Color->AddRGBPoint(-1.5e308, 0.2, 0.4, 0.6);
    probe.Color->AddRGBPoint(1.5e308, 1.0, 1.0, 1.0);
    probe.Opacity->AddPoint(-1.5e308, 0.3);
    probe.Opacity->AddPoint(1.5e308, 0.9);
    double rgb[3];
    probe.Color->GetColor(0.8, rgb);
    const double a = probe.Opacity->GetValue(0.8);
    std::cout << "== nodes at +-1.5e308: VTK evaluates s=0.8 to opacity " << Fmt(a) << ", colour ("
              << Fmt(rgb[0]) << "," << Fmt(rgb[1]) << "," << Fmt(rgb[2]) << ")\n";
    const double alpha = -std::expm1(-a / u);
    runCase("colour/opacity nodes at +-1.5e308", 1,
      [&](TF& tf) {
        tf.Color->AddRGBPoint(-1.5e308, 0.2, 0.4, 0.6);
        tf.Color->AddRGBPoint(1.5e308, 1.0, 1.0, 1.0);
        tf.Opacity->AddPoint(-1.5e308, 0.3);
        tf.Opacity->AddPoint(1.5e308, 0.9);
        tf.Property->SetScalarOpacityUnitDistance(u);
      },
      -1,
      [&](double, double, double e[4]) {
        e[3] = alpha;
        for (int c = 0; c < 3; ++c)
        {
          e[c] = rgb[c] * alpha;
        }
      },
      1e-6, nullptr, 0);
  }

  // ---- Unit distance extremes.
  for (int sem = 0; sem < 3; ++sem)
  {
    // 1e-30: optically infinitely dense: alpha 1, the colour at the entry point.
    runCase("unit distance 1e-30 (opacity 0.5, DefaultTF colours)", sem,
      [&](TF& tf) {
        DefaultTF(tf, 1e-30);
        tf.Opacity->RemoveAllPoints();
        tf.Opacity->AddPoint(0.0, 0.5);
        tf.Opacity->AddPoint(1.75, 0.5);
      },
      sem == 2 ? -1 : 0, sem == 2 ? Expectation() : entryColor(1.0), 1e-6, nullptr, 0);
    // 1e30: almost transparent; alpha = 1 - exp(-tau), tau = 0.5/u or -ln(0.5)/u.
    const double tau = sem == 0 ? std::log(2.0) / 1e30 : (sem == 1 ? 0.5 / 1e30 : 0.5);
    const double alpha = -std::expm1(-tau);
    runCase("unit distance 1e30 (opacity 0.5, constant colour)", sem,
      [&](TF& tf) {
        constantColor(tf);
        tf.Opacity->AddPoint(0.0, 0.5);
        tf.Opacity->AddPoint(1.75, 0.5);
        tf.Property->SetScalarOpacityUnitDistance(1e30);
      },
      0,
      [&, alpha](double, double, double e[4]) {
        e[3] = alpha;
        for (int c = 0; c < 3; ++c)
        {
          e[c] = c0[c] * alpha;
        }
      },
      sem == 2 ? 1e-6 : alpha * 1e-5, nullptr, 0);
  }
  // 1e300: alpha ~ 1e-300 in double, 0 in the float image: the image is empty
  // and must say so (the empty-image check once looked at the double values;
  // hovRobustness case 7004413). In every mode.
  for (int mode : { vtkHighOrderVolumeMapper::CPU_ACCURATE,
         vtkHighOrderVolumeMapper::OPENGL_PROJECTION, vtkHighOrderVolumeMapper::RAY_CAST })
  {
    scene.Mapper->SetRenderMode(mode);
    for (int sem = 0; sem < 2; ++sem)
    {
      runCase(std::string("unit distance 1e300 (below float: empty, warned), mode ") +
          std::to_string(mode),
        sem,
        [&](TF& tf) {
          constantColor(tf);
          tf.Opacity->AddPoint(0.0, 0.5);
          tf.Opacity->AddPoint(1.75, 0.5);
          tf.Property->SetScalarOpacityUnitDistance(1e300);
        },
        1, [](double, double, double e[4]) { e[0] = e[1] = e[2] = e[3] = 0.0; }, 0.0, nullptr, 0);
    }
  }
  scene.Mapper->SetRenderMode(vtkHighOrderVolumeMapper::CPU_ACCURATE);
  // Invalid unit distances: a warning, rendered as u = 1.
  {
    Image unitOne[2];
    for (int sem = 0; sem < 2; ++sem)
    {
      unitOne[sem] = runCase("unit distance 1 (reference)", sem, [&](TF& tf) { DefaultTF(tf, 1.0); },
        0, nullptr, 0, nullptr, 0);
    }
    for (double bad : { 0.0, -1.0, NaN })
    {
      for (int sem = 0; sem < 2; ++sem)
      {
        const Image ax = runCase("unit distance " + Fmt(bad) + " (invalid)", sem,
          [&](TF& tf) { DefaultTF(tf, bad); }, 1, nullptr, 0, nullptr, 0);
        const DiffStats d = Diff(ax, unitOne[sem]);
        std::cout << "    vs unit distance 1: " << d.Str() << "\n";
        ck.Check(d.Max <= 1e-6, "unit distance " + Fmt(bad) + ": rendered as unit distance 1");
      }
    }
  }
  // A table the ray caster cannot afford: opacity 1 at a node (a log
  // singularity of the GPU-compatible extinction) refined to 1e-8 would take
  // ~10^5 nodes, each a breakpoint to locate on every segment (the frame took
  // minutes: hovRobustness seed 7, case 7040481). The ray caster's table
  // stops at its budget with a warning, and the image stays that of the table
  // refined as far as the budget goes: compared with the CPU path's exact
  // integral of its own (default-tolerance) table.
  {
    auto singular = [&](TF& tf) {
      constantColor(tf);
      tf.Opacity->AddPoint(0.0, 0.15);
      tf.Opacity->AddPoint(0.9, 1.0);
      tf.Opacity->AddPoint(1.75, 0.03);
      tf.Property->SetScalarOpacityUnitDistance(u);
    };
    // 24^2: the ray caster pays ~16k breakpoints per segment here.
    constexpr int n = 24;
    vtkNew<vtkCamera> small;
    AxisOrthoCamera(small, 1.0, AxisOrthoShift);
    TF ref;
    singular(ref);
    scene.Volume->SetProperty(ref.Property);
    scene.Mapper->SetOpacitySemantics(0);
    scene.Mapper->SetRenderMode(vtkHighOrderVolumeMapper::CPU_ACCURATE);
    const Image cpu = Render(scene.Mapper, small, scene.Volume, n, n);
    scene.Mapper->SetRenderMode(vtkHighOrderVolumeMapper::RAY_CAST);
    scene.Mapper->SetGPUOpacityTolerance(1e-8);
    scene.Mapper->SetRayCastTolerance(1e-12);
    TF tf;
    singular(tf);
    scene.Volume->SetProperty(tf.Property);
    scene.Mapper->SetOpacitySemantics(0);
    scene.Observer->Clear();
    int st = -1;
    const Image rc = Render(scene.Mapper, small, scene.Volume, n, n, &st);
    const std::string warning = scene.Observer->GetWarningMessage();
    std::cout << "== opacity 1 at a node, RAY_CAST, GPU tolerance 1e-8\n    warning: '"
              << Msg(warning) << "'\n";
    ck.Check(st == 1 && CheckImage(rc).Ok(), "opacity 1 at a node, RAY_CAST: renders, finite");
    ck.Check(warning.find("budget") != std::string::npos,
      "opacity 1 at a node, RAY_CAST at GPU tolerance 1e-8: the table's budget is reported");
    const DiffStats d = Diff(rc, cpu);
    std::cout << "    vs the CPU path: " << d.Str() << "\n";
    ck.Check(d.Max <= 1e-4, "opacity 1 at a node, RAY_CAST at its budget: within 1e-4 of the CPU path");
    scene.Mapper->SetGPUOpacityTolerance(1e-4);
    scene.Mapper->SetRayCastTolerance(1e-3);
    scene.Mapper->SetRenderMode(vtkHighOrderVolumeMapper::CPU_ACCURATE);
  }
  return ck.Result();
}
