// Three fields (issue 4, HIAC 5): the colour from a second point array.
//
// [0,1]^3 as 3^3 Kuhn-split cubes; extinction field s1 = x + 2y + 0.5z (the
// active scalars), colour field s2 = 1 - x + z (array "c", SetColorArrayName),
// both linear, so along every ray both are linear in t. Transfer function
// (VTK_UNSTRUCTURED: tau = a/u, u = 1): colour (0.2,0.4,0.9) -> (0.9,0.2,0.1)
// -> (0.1,0.8,0.3) at -1, 1, 3; opacity 0.1, 0.6, 0.3 at -1, 0.8, 3; the
// colour is read at s2, the extinction at s1.
//
// Reference (independent of the mapper's kernels): per pixel, the analytic
// chord through the cube (slab method), split at every t where s1 or s2
// crosses a node; on each piece tau and c are linear in t, the optical depth
// is integrated exactly (quadratic) and the Williams-Max colour
// int c(t) tau(t) exp(-D(t)) dt by 24-point Gauss-Legendre in long double
// (the integrand is entire; the rule is exact to ~1e-18 on these pieces).
// Every pixel farther than 1e-7 from the cube's silhouette edges must match
// to 1e-9 (the mapper's quadrature tolerance), orthographic oblique view,
// both orderings. Also: a missing colour array and one shorter than the
// points are errors with nothing drawn.
#include "hovTestMixed.h"
#include "hovTestScenes.h"

#include "vtkCamera.h"
#include "vtkDoubleArray.h"
#include "vtkPointData.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <vector>

using namespace hovTest;

namespace
{
constexpr int N = 40;
const double View[3] = { 0.35, 0.25, 1.0 };
const double CX[3] = { -1, 1, 3 };
const double CRGB[3][3] = { { 0.2, 0.4, 0.9 }, { 0.9, 0.2, 0.1 }, { 0.1, 0.8, 0.3 } };
const double OX[3] = { -1, 0.8, 3 };
const double OA[3] = { 0.1, 0.6, 0.3 };

double S1(const long double* p)
{
  return static_cast<double>(p[0] + 2 * p[1] + 0.5L * p[2]);
}
double S2(const long double* p)
{
  return static_cast<double>(1 - p[0] + p[2]);
}

long double Lerp(const double* x, const double* y, int n, long double s)
{
  if (s <= x[0])
    return y[0];
  if (s >= x[n - 1])
    return y[n - 1];
  int k = 0;
  while (s > x[k + 1])
    ++k;
  return y[k] + (y[k + 1] - y[k]) * (s - x[k]) / (x[k + 1] - x[k]);
}

/// 24-point Gauss-Legendre nodes and weights on [-1, 1] (Newton on P_24).
void Gauss(std::vector<long double>& xs, std::vector<long double>& ws)
{
  const int n = 24;
  for (int i = 1; i <= n; ++i)
  {
    long double x = std::cos(3.14159265358979323846264338327950288L * (i - 0.25L) / (n + 0.5L));
    long double dp = 0;
    for (int it = 0; it < 100; ++it)
    {
      long double p0 = 1, p1 = x;
      for (int k = 2; k <= n; ++k)
      {
        const long double p2 = ((2 * k - 1) * x * p1 - (k - 1) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      dp = n * (x * p1 - p0) / (x * x - 1);
      const long double dx = p1 / dp;
      x -= dx;
      if (std::abs(dx) < 1e-19L)
        break;
    }
    xs.push_back(x);
    ws.push_back(2 / ((1 - x * x) * dp * dp));
  }
}

/// Reference RGBA of the ray o + t d through [0,1]^3 (d unit).
void Reference(const long double o[3], const long double d[3], long double out[4])
{
  static std::vector<long double> gx, gw;
  if (gx.empty())
    Gauss(gx, gw);
  long double t0 = -1e30L, t1 = 1e30L;
  for (int k = 0; k < 3; ++k)
  {
    long double a = (0 - o[k]) / d[k], b = (1 - o[k]) / d[k];
    t0 = std::max(t0, std::min(a, b));
    t1 = std::min(t1, std::max(a, b));
  }
  out[0] = out[1] = out[2] = out[3] = 0;
  if (!(t0 < t1))
    return;
  auto field = [&](int f, long double t) {
    const long double p[3] = { o[0] + t * d[0], o[1] + t * d[1], o[2] + t * d[2] };
    return f == 1 ? (long double)p[0] + 2 * p[1] + 0.5L * p[2] : 1 - p[0] + p[2];
  };
  std::vector<long double> cuts = { t0, t1 };
  for (int f = 1; f <= 2; ++f)
  {
    const long double a = field(f, t0), b = field(f, t1);
    for (double node : (f == 1 ? OX : CX))
    {
      const long double u = (node - a) / (b - a);
      if (u > 0 && u < 1)
        cuts.push_back(t0 + u * (t1 - t0));
    }
  }
  std::sort(cuts.begin(), cuts.end());
  long double depth = 0;
  for (size_t p = 0; p + 1 < cuts.size(); ++p)
  {
    const long double ta = cuts[p], h = cuts[p + 1] - cuts[p];
    if (h <= 0)
      continue;
    const long double tauA = Lerp(OX, OA, 3, field(1, ta)), tauB = Lerp(OX, OA, 3, field(1, ta + h));
    for (size_t q = 0; q < gx.size(); ++q)
    {
      const long double y = 0.5L * (gx[q] + 1), t = ta + y * h;
      const long double tau = tauA + (tauB - tauA) * y;
      const long double dd = depth + h * (tauA * y + (tauB - tauA) * y * y / 2);
      const long double s2 = field(2, t);
      for (int c = 0; c < 3; ++c)
      {
        const double col[3] = { CRGB[0][c], CRGB[1][c], CRGB[2][c] };
        out[c] += 0.5L * h * gw[q] * Lerp(CX, col, 3, s2) * tau * std::exp(-dd);
      }
    }
    depth += h * (tauA + tauB) / 2;
  }
  out[3] = 1 - std::exp(-depth);
}

vtkSmartPointer<vtkUnstructuredGrid> Mesh(vtkIdType colourTuples)
{
  MeshBuilder m;
  const double o[3] = { 0, 0, 0 }, size[3] = { 1, 1, 1 };
  m.AddTetBlock(3, 3, 3, o, size, [](double x, double y, double z) { return x + 2 * y + 0.5 * z; });
  auto grid = m.Grid();
  vtkNew<vtkDoubleArray> c;
  c->SetName("c");
  c->SetNumberOfTuples(colourTuples);
  for (vtkIdType i = 0; i < colourTuples; ++i)
  {
    const auto& p = m.Points[i];
    c->SetValue(i, 1 - p[0] + p[2]);
  }
  grid->GetPointData()->AddArray(c);
  return grid;
}

void SetupScene(VolumeScene& scene)
{
  for (int k = 0; k < 3; ++k)
  {
    scene.Tf.Color->AddRGBPoint(CX[k], CRGB[k][0], CRGB[k][1], CRGB[k][2]);
    scene.Tf.Opacity->AddPoint(OX[k], OA[k]);
  }
  scene.Tf.Property->SetScalarOpacityUnitDistance(1.0);
  scene.Mapper->SetOpacitySemanticsToVTKUnstructured();
  scene.Mapper->SetColorArrayName("c");
}
}

int TestFieldsTwoArrays(int, char*[])
{
  Checker check;
  auto grid = Mesh(0);
  const vtkIdType numPoints = grid->GetNumberOfPoints();
  grid = Mesh(numPoints);
  for (bool perPixel : { false, true })
  {
    VolumeScene scene(grid);
    SetupScene(scene);
    scene.Mapper->SetCellOrdering(perPixel ? 1 : 0);
    vtkNew<vtkCamera> cam;
    cam->ParallelProjectionOn();
    cam->SetFocalPoint(0.5, 0.5, 0.5);
    cam->SetPosition(0.5 + 4 * View[0], 0.5 + 4 * View[1], 0.5 + 4 * View[2]);
    cam->SetViewUp(0, 1, 0);
    cam->SetParallelScale(0.95);
    cam->SetClippingRange(1, 10);
    int status = 0;
    const Image img = RenderDouble(scene.Mapper, cam, scene.Volume, N, N, &status);
    // The camera frame (orthonormal, as VTK builds it).
    long double v[3], up[3] = { 0, 1, 0 }, r[3], u[3];
    const long double len = std::sqrt((long double)View[0] * View[0] + View[1] * View[1] + View[2] * View[2]);
    for (int k = 0; k < 3; ++k)
      v[k] = -View[k] / len;
    r[0] = v[1] * up[2] - v[2] * up[1];
    r[1] = v[2] * up[0] - v[0] * up[2];
    r[2] = v[0] * up[1] - v[1] * up[0];
    const long double rn = std::sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2]);
    for (int k = 0; k < 3; ++k)
      r[k] /= rn;
    u[0] = r[1] * v[2] - r[2] * v[1];
    u[1] = r[2] * v[0] - r[0] * v[2];
    u[2] = r[0] * v[1] - r[1] * v[0];
    double worst = 0.0;
    int pixels = 0;
    for (int j = 0; j < N; ++j)
    {
      for (int i = 0; i < N; ++i)
      {
        const long double a = (i + 0.5L - N / 2.0L) * (2 * 0.95L / N);
        const long double b = (j + 0.5L - N / 2.0L) * (2 * 0.95L / N);
        long double o[3];
        for (int k = 0; k < 3; ++k)
          o[k] = 0.5L + a * r[k] + b * u[k] - 4 * v[k];
        // Skip rays within 1e-7 of a silhouette edge: chord length sensitive there.
        long double ref[4], refA[4], refB[4];
        Reference(o, v, ref);
        long double o2[3] = { o[0] + 1e-7L * r[0], o[1] + 1e-7L * r[1], o[2] + 1e-7L * r[2] };
        long double o3[3] = { o[0] - 1e-7L * u[0], o[1] - 1e-7L * u[1], o[2] - 1e-7L * u[2] };
        Reference(o2, v, refA);
        Reference(o3, v, refB);
        if (std::abs(refA[3] - ref[3]) > 1e-6L || std::abs(refB[3] - ref[3]) > 1e-6L)
          continue;
        for (int c = 0; c < 4; ++c)
          worst = std::max(worst, static_cast<double>(std::abs(img.At(i, j, c) - ref[c])));
        pixels += ref[3] > 0;
      }
    }
    check.Check(status == 1 && scene.NoMessages() && pixels > 400 && worst < 1e-9,
      std::string(perPixel ? "per pixel" : "visibility order") +
        ": colour from array 'c', max error vs the long double reference " + Fmt(worst) +
        " over " + std::to_string(pixels) + " pixels");
  }
  // Bad colour arrays: an error, nothing drawn.
  for (int bad = 0; bad < 2; ++bad)
  {
    VolumeScene scene(bad == 0 ? grid.GetPointer() : Mesh(numPoints / 2).GetPointer());
    SetupScene(scene);
    if (bad == 0)
      scene.Mapper->SetColorArrayName("missing");
    vtkNew<vtkCamera> cam;
    cam->SetPosition(0.5, 0.5, 4);
    cam->SetFocalPoint(0.5, 0.5, 0.5);
    int status = -1;
    const Image img = RenderDouble(scene.Mapper, cam, scene.Volume, 16, 16, &status);
    double sum = 0;
    for (double x : img.V)
      sum += std::abs(x);
    check.Check(scene.Observer->GetError() && sum == 0.0 && status == 0 &&
        !scene.Observer->GetWarning(),
      std::string(bad == 0 ? "missing" : "short") + " colour array: error '" +
        Msg(scene.Observer->GetErrorMessage()) + "', status " + std::to_string(status) +
        ", warning '" + Msg(scene.Observer->GetWarningMessage()) + "', image sum " + Fmt(sum));
  }
  return check.Result();
}
