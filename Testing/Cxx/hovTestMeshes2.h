// Header-only helpers of the TestBadInput*, TestOpenGL*, TestCompareVTK* and
// TestWitness* tests: small tetrahedral meshes built by hand, transfer
// functions, float-image and screen-image statistics.
//
// Everything is inline in namespace hovTest2 so that several tests can
// include it without clashing.
#ifndef hovTestMeshes2_h
#define hovTestMeshes2_h

#include "vtkHighOrderVolumeMapper.h"

#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkCellType.h"
#include "vtkColorTransferFunction.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkIdList.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkRenderWindow.h"
#include "vtkSmartPointer.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"
#include "vtkWindowToImageFilter.h"
#include "vtkPNGWriter.h"
#include "vtkUnsignedCharArray.h"
#include "vtkActor.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <functional>
#include <iostream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace hovTest2
{
//------------------------------------------------------------------------------
// Failure bookkeeping: every check prints its verdict and the measured values.
struct Checker
{
  int Failures = 0;
  int Checks = 0;
  bool Check(bool ok, const std::string& what)
  {
    ++this->Checks;
    if (!ok)
    {
      ++this->Failures;
      std::cout << "  FAILED: " << what << "\n";
    }
    else
    {
      std::cout << "  ok: " << what << "\n";
    }
    return ok;
  }
  int Result() const
  {
    std::cout << this->Checks << " checks, " << this->Failures << " failed\n";
    return this->Failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
  }
};

inline std::string Fmt(double v)
{
  char buf[64];
  std::snprintf(buf, sizeof(buf), "%.6g", v);
  return buf;
}

/// The text of VTK error/warning messages without their "ERROR: In file, line"
/// headers (printing those would make ctest's FAIL_REGULAR_EXPRESSION fire).
inline std::string Msg(const std::string& raw)
{
  std::string out, line;
  std::istringstream in(raw);
  while (std::getline(in, line))
  {
    if (line.empty() || line.rfind("ERROR: In ", 0) == 0 || line.rfind("Warning: In ", 0) == 0 ||
      line.rfind("Generic Warning: In ", 0) == 0)
    {
      continue;
    }
    const size_t k = line.find("): ");
    if (!out.empty())
    {
      out += " | ";
    }
    out += k != std::string::npos ? line.substr(k + 3) : line;
  }
  // Never echo the markers ctest looks for.
  for (const char* marker : { "ERROR:", "ERR|" })
  {
    size_t k;
    while ((k = out.find(marker)) != std::string::npos)
    {
      out.replace(k, 3, "Err");
    }
  }
  return out;
}

//------------------------------------------------------------------------------
// A hand-built unstructured grid.
struct MeshBuilder
{
  std::vector<std::array<double, 3>> Points;
  std::vector<double> Scalars;
  std::vector<int> Types;
  std::vector<std::vector<vtkIdType>> Cells;

  vtkIdType AddPoint(double x, double y, double z, double s)
  {
    this->Points.push_back({ x, y, z });
    this->Scalars.push_back(s);
    return static_cast<vtkIdType>(this->Points.size() - 1);
  }
  void AddCell(int type, const std::vector<vtkIdType>& ids)
  {
    this->Types.push_back(type);
    this->Cells.push_back(ids);
  }
  double SignedVolume6(const std::vector<vtkIdType>& t) const
  {
    const auto& a = this->Points[t[0]];
    const auto& b = this->Points[t[1]];
    const auto& c = this->Points[t[2]];
    const auto& d = this->Points[t[3]];
    const double e1[3] = { b[0] - a[0], b[1] - a[1], b[2] - a[2] };
    const double e2[3] = { c[0] - a[0], c[1] - a[1], c[2] - a[2] };
    const double e3[3] = { d[0] - a[0], d[1] - a[1], d[2] - a[2] };
    const double cr[3] = { e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
      e1[0] * e2[1] - e1[1] * e2[0] };
    return cr[0] * e3[0] + cr[1] * e3[1] + cr[2] * e3[2];
  }
  /// A tetrahedron with VTK's positive orientation (vertex 3 on the side of
  /// the right-hand normal of 0,1,2), or inverted if @p inverted.
  void AddTet(vtkIdType a, vtkIdType b, vtkIdType c, vtkIdType d, bool inverted = false)
  {
    std::vector<vtkIdType> t{ a, b, c, d };
    const double v = this->SignedVolume6(t);
    if ((v < 0.0) != inverted)
    {
      std::swap(t[1], t[2]);
    }
    this->AddCell(VTK_TETRA, t);
  }
  /// nx*ny*nz cubes over [o, o+size], each split into 6 tetrahedra (Kuhn:
  /// conforming), scalar f(x,y,z) at the points.
  void AddTetBlock(int nx, int ny, int nz, const double o[3], const double size[3],
    const std::function<double(double, double, double)>& f, bool inverted = false)
  {
    std::vector<vtkIdType> ids((nx + 1) * (ny + 1) * (nz + 1));
    for (int k = 0; k <= nz; ++k)
    {
      for (int j = 0; j <= ny; ++j)
      {
        for (int i = 0; i <= nx; ++i)
        {
          const double x = o[0] + size[0] * i / nx;
          const double y = o[1] + size[1] * j / ny;
          const double z = o[2] + size[2] * k / nz;
          ids[(k * (ny + 1) + j) * (nx + 1) + i] = this->AddPoint(x, y, z, f(x, y, z));
        }
      }
    }
    static const int perms[6][3] = { { 0, 1, 2 }, { 0, 2, 1 }, { 1, 0, 2 }, { 1, 2, 0 },
      { 2, 0, 1 }, { 2, 1, 0 } };
    for (int k = 0; k < nz; ++k)
    {
      for (int j = 0; j < ny; ++j)
      {
        for (int i = 0; i < nx; ++i)
        {
          for (const auto& p : perms)
          {
            int c[3] = { i, j, k };
            vtkIdType v[4];
            v[0] = ids[(c[2] * (ny + 1) + c[1]) * (nx + 1) + c[0]];
            for (int s = 0; s < 3; ++s)
            {
              ++c[p[s]];
              v[s + 1] = ids[(c[2] * (ny + 1) + c[1]) * (nx + 1) + c[0]];
            }
            this->AddTet(v[0], v[1], v[2], v[3], inverted);
          }
        }
      }
    }
  }
  /// A lone tetrahedron with its own four points (scalar s at every vertex
  /// unless @p svals is given).
  void AddLooseTet(const double p[4][3], const double svals[4])
  {
    vtkIdType v[4];
    for (int i = 0; i < 4; ++i)
    {
      v[i] = this->AddPoint(p[i][0], p[i][1], p[i][2], svals[i]);
    }
    this->AddTet(v[0], v[1], v[2], v[3]);
  }

  /// The grid; point scalars "s" (double) are the active scalars unless
  /// @p withScalars is false.
  vtkSmartPointer<vtkUnstructuredGrid> Grid(bool withScalars = true) const
  {
    auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
    vtkNew<vtkPoints> pts;
    pts->SetDataTypeToDouble();
    pts->SetNumberOfPoints(static_cast<vtkIdType>(this->Points.size()));
    for (size_t i = 0; i < this->Points.size(); ++i)
    {
      pts->SetPoint(static_cast<vtkIdType>(i), this->Points[i].data());
    }
    grid->SetPoints(pts);
    grid->Allocate(static_cast<vtkIdType>(this->Cells.size()));
    for (size_t c = 0; c < this->Cells.size(); ++c)
    {
      grid->InsertNextCell(this->Types[c], static_cast<vtkIdType>(this->Cells[c].size()),
        this->Cells[c].data());
    }
    if (withScalars)
    {
      vtkNew<vtkDoubleArray> s;
      s->SetName("s");
      s->SetNumberOfTuples(static_cast<vtkIdType>(this->Scalars.size()));
      for (size_t i = 0; i < this->Scalars.size(); ++i)
      {
        s->SetValue(static_cast<vtkIdType>(i), this->Scalars[i]);
      }
      grid->GetPointData()->SetScalars(s);
    }
    return grid;
  }
};

/// The default linear scalar field of the test blocks.
inline double DefaultField(double x, double y, double z)
{
  return x + 0.5 * y + 0.25 * z;
}

/// Unit cube [0,1]^3 of n^3 Kuhn cubes with DefaultField scalars (range [0, 1.75]).
inline MeshBuilder UnitBlock(int n = 2, bool inverted = false)
{
  MeshBuilder m;
  const double o[3] = { 0, 0, 0 }, size[3] = { 1, 1, 1 };
  m.AddTetBlock(n, n, n, o, size, DefaultField, inverted);
  return m;
}

//------------------------------------------------------------------------------
// Transfer functions.
struct TF
{
  vtkSmartPointer<vtkColorTransferFunction> Color = vtkSmartPointer<vtkColorTransferFunction>::New();
  vtkSmartPointer<vtkPiecewiseFunction> Opacity = vtkSmartPointer<vtkPiecewiseFunction>::New();
  vtkSmartPointer<vtkVolumeProperty> Property = vtkSmartPointer<vtkVolumeProperty>::New();
  TF()
  {
    this->Property->SetColor(this->Color);
    this->Property->SetScalarOpacity(this->Opacity);
    this->Property->SetInterpolationTypeToLinear();
    this->Property->ShadeOff();
  }
};

/// Colour red->green->blue over [0, 1.75], opacity 0.2 -> 0.8 with a bump.
inline void DefaultTF(TF& tf, double unit = 0.5)
{
  tf.Color->RemoveAllPoints();
  tf.Color->AddRGBPoint(0.0, 1.0, 0.1, 0.1);
  tf.Color->AddRGBPoint(0.9, 0.1, 1.0, 0.2);
  tf.Color->AddRGBPoint(1.75, 0.1, 0.2, 1.0);
  tf.Opacity->RemoveAllPoints();
  tf.Opacity->AddPoint(0.0, 0.2);
  tf.Opacity->AddPoint(0.6, 0.7);
  tf.Opacity->AddPoint(1.0, 0.3);
  tf.Opacity->AddPoint(1.75, 0.8);
  tf.Property->SetScalarOpacityUnitDistance(unit);
}

//------------------------------------------------------------------------------
// Cameras.
/// Oblique perspective view of the unit cube.
inline void ObliqueCamera(vtkCamera* cam)
{
  cam->SetFocalPoint(0.5, 0.5, 0.5);
  cam->SetPosition(2.6, 1.9, 3.1);
  cam->SetViewUp(0, 1, 0);
  cam->SetViewAngle(30);
  cam->ParallelProjectionOff();
  cam->SetClippingRange(0.5, 20);
}

/// Orthographic view of the unit cube along -z; with parallel scale 1 and a
/// square image of N pixels the cube covers pixel centres N/4 .. 3N/4-1 in x
/// and y (no pixel centre lies on an edge: see CoveredByUnitSquare).
///
/// @p dx shifts the view in x. AxisOrthoShift (1/8192) keeps every pixel
/// centre of a 1..4096-pixel square image off the planes x = y and x = y +- 1/2
/// (the interior faces of UnitBlock(2) parallel to the view direction), so no
/// ray lies exactly in a face.
constexpr double AxisOrthoShift = 1.0 / 8192.0;
inline void AxisOrthoCamera(vtkCamera* cam, double scale = 1.0, double dx = 0.0)
{
  cam->SetFocalPoint(0.5 + dx, 0.5, 0.5);
  cam->SetPosition(0.5 + dx, 0.5, 5.0);
  cam->SetViewUp(0, 1, 0);
  cam->ParallelProjectionOn();
  cam->SetParallelScale(scale);
  cam->SetClippingRange(1.0, 10.0);
}

/// World x (or y) of pixel centre i of an N-pixel axis under AxisOrthoCamera.
inline double OrthoPixelCoord(int i, int n, double scale = 1.0, double aspect = 1.0, double dx = 0.0)
{
  return 0.5 + dx + (2.0 * (i + 0.5) / n - 1.0) * scale * aspect;
}

//------------------------------------------------------------------------------
// Float images.
struct Image
{
  int W = 0, H = 0;
  std::vector<double> V; // 4 per pixel
  double At(int i, int j, int c) const { return this->V[4 * (static_cast<size_t>(j) * W + i) + c]; }
  double& At(int i, int j, int c) { return this->V[4 * (static_cast<size_t>(j) * W + i) + c]; }
  size_t Pixels() const { return static_cast<size_t>(W) * H; }
};

inline Image FloatImage(vtkHighOrderVolumeMapper* mapper)
{
  Image img;
  vtkImageData* id = mapper->GetFloatImage();
  int dims[3];
  id->GetDimensions(dims);
  img.W = dims[0];
  img.H = dims[1];
  vtkDataArray* a = id->GetPointData()->GetScalars();
  if (!a || a->GetNumberOfComponents() != 4 ||
    a->GetNumberOfTuples() != static_cast<vtkIdType>(img.W) * img.H)
  {
    std::cout << "  (float image missing or of the wrong size: " << img.W << "x" << img.H
              << ", tuples " << (a ? a->GetNumberOfTuples() : -1) << ")\n";
    img.W = img.H = 0;
    return img;
  }
  img.V.resize(img.Pixels() * 4);
  for (vtkIdType t = 0; t < a->GetNumberOfTuples(); ++t)
  {
    for (int c = 0; c < 4; ++c)
    {
      img.V[4 * t + c] = a->GetComponent(t, c);
    }
  }
  return img;
}

/// Sanity of a premultiplied image: finite, 0 <= a <= 1, 0 <= rgb <= a (+eps)
/// (colours of every test transfer function are in [0,1]).
struct Sanity
{
  size_t NonFinite = 0, AlphaOut = 0, ColorOut = 0, Covered = 0;
  double MinA = 0, MaxA = 0, MeanA = 0, MaxRGB = 0;
  bool Ok() const { return NonFinite == 0 && AlphaOut == 0 && ColorOut == 0; }
  std::string Str() const
  {
    std::ostringstream s;
    s << "nonfinite=" << NonFinite << " alphaOut=" << AlphaOut << " colorOut=" << ColorOut
      << " covered(a>0)=" << Covered << " alpha[min,max,mean]=[" << Fmt(MinA) << ","
      << Fmt(MaxA) << "," << Fmt(MeanA) << "] maxRGB=" << Fmt(MaxRGB);
    return s.str();
  }
};

inline Sanity CheckImage(const Image& img)
{
  Sanity s;
  s.MinA = std::numeric_limits<double>::infinity();
  s.MaxA = -s.MinA;
  double sum = 0;
  for (size_t p = 0; p < img.Pixels(); ++p)
  {
    const double* v = &img.V[4 * p];
    bool finite = true;
    for (int c = 0; c < 4; ++c)
    {
      finite = finite && std::isfinite(v[c]);
    }
    if (!finite)
    {
      ++s.NonFinite;
      continue;
    }
    const double a = v[3];
    if (!(a >= 0.0 && a <= 1.0))
    {
      ++s.AlphaOut;
    }
    for (int c = 0; c < 3; ++c)
    {
      if (!(v[c] >= 0.0 && v[c] <= a + 1e-6))
      {
        ++s.ColorOut;
        break;
      }
      s.MaxRGB = std::max(s.MaxRGB, v[c]);
    }
    s.Covered += a > 0.0;
    s.MinA = std::min(s.MinA, a);
    s.MaxA = std::max(s.MaxA, a);
    sum += a;
  }
  s.MeanA = img.Pixels() ? sum / img.Pixels() : 0.0;
  if (img.Pixels() == 0)
  {
    s.MinA = s.MaxA = 0;
  }
  return s;
}

struct DiffStats
{
  double Max = 0, Mean = 0, P99 = 0;
  size_t Count = 0;     // channel values compared
  size_t Above = 0;     // pixels with any channel difference above the threshold
  int MaxI = -1, MaxJ = -1, MaxC = -1;
  std::string Str() const
  {
    std::ostringstream s;
    s << "max=" << Fmt(Max) << " (at " << MaxI << "," << MaxJ << " ch " << MaxC
      << ") mean=" << Fmt(Mean) << " p99=" << Fmt(P99) << " pixelsAboveThr=" << Above;
    return s.str();
  }
};

/// Differences per channel of the channels [c0, c1) between two float images.
inline DiffStats Diff(const Image& a, const Image& b, int c0 = 0, int c1 = 4, double thr = 1e-6)
{
  DiffStats d;
  if (a.W != b.W || a.H != b.H)
  {
    d.Max = std::numeric_limits<double>::infinity();
    return d;
  }
  std::vector<double> all;
  all.reserve(a.Pixels() * (c1 - c0));
  double sum = 0;
  for (int j = 0; j < a.H; ++j)
  {
    for (int i = 0; i < a.W; ++i)
    {
      bool above = false;
      for (int c = c0; c < c1; ++c)
      {
        double e = std::abs(a.At(i, j, c) - b.At(i, j, c));
        if (std::isnan(e))
        {
          e = std::numeric_limits<double>::infinity();
        }
        all.push_back(e);
        sum += e;
        above = above || e > thr;
        if (e > d.Max || d.MaxI < 0)
        {
          d.Max = e;
          d.MaxI = i;
          d.MaxJ = j;
          d.MaxC = c;
        }
      }
      d.Above += above;
    }
  }
  d.Count = all.size();
  d.Mean = all.empty() ? 0 : sum / all.size();
  if (!all.empty())
  {
    const size_t k = std::min(all.size() - 1, static_cast<size_t>(0.99 * all.size()));
    std::nth_element(all.begin(), all.begin() + k, all.end());
    d.P99 = all[k];
  }
  return d;
}

/// Screen capture (RGBA or RGB) of a render window as doubles in [0,1].
inline Image Capture(vtkRenderWindow* win, bool rgba = false)
{
  vtkNew<vtkWindowToImageFilter> w2i;
  w2i->SetInput(win);
  if (rgba)
  {
    w2i->SetInputBufferTypeToRGBA();
  }
  else
  {
    w2i->SetInputBufferTypeToRGB();
  }
  w2i->ReadFrontBufferOff();
  w2i->ShouldRerenderOff();
  w2i->Update();
  vtkImageData* id = w2i->GetOutput();
  int dims[3];
  id->GetDimensions(dims);
  Image img;
  img.W = dims[0];
  img.H = dims[1];
  vtkDataArray* a = id->GetPointData()->GetScalars();
  const int nc = a->GetNumberOfComponents();
  img.V.assign(img.Pixels() * 4, 0.0);
  for (vtkIdType t = 0; t < a->GetNumberOfTuples(); ++t)
  {
    for (int c = 0; c < std::min(nc, 4); ++c)
    {
      img.V[4 * t + c] = a->GetComponent(t, c) / 255.0;
    }
    if (nc == 3)
    {
      img.V[4 * t + 3] = 1.0;
    }
  }
  return img;
}

/// Writes RGB (premultiplied values clamped to [0,1]) of @p img as an 8-bit PNG.
inline void WritePNG(const Image& img, const std::string& path)
{
  vtkNew<vtkImageData> id;
  id->SetDimensions(img.W, img.H, 1);
  vtkNew<vtkUnsignedCharArray> a;
  a->SetNumberOfComponents(3);
  a->SetNumberOfTuples(static_cast<vtkIdType>(img.Pixels()));
  for (size_t p = 0; p < img.Pixels(); ++p)
  {
    for (int c = 0; c < 3; ++c)
    {
      const double v = std::min(std::max(img.V[4 * p + c], 0.0), 1.0);
      a->SetValue(static_cast<vtkIdType>(3 * p + c), static_cast<unsigned char>(v * 255 + 0.5));
    }
  }
  id->GetPointData()->SetScalars(a);
  vtkNew<vtkPNGWriter> w;
  w->SetInputData(id);
  w->SetFileName(path.c_str());
  w->Write();
}

/// The argument following @p flag ("-D" data dir, "-T" temporary dir), or @p fallback.
inline std::string ArgAfter(int argc, char* argv[], const char* flag, const std::string& fallback)
{
  for (int i = 1; i + 1 < argc; ++i)
  {
    if (std::string(argv[i]) == flag)
    {
      return argv[i + 1];
    }
  }
  return fallback;
}

/// Sub-image [x0, x0+w) x [y0, y0+h).
inline Image Crop(const Image& img, int x0, int y0, int w, int h)
{
  Image out;
  out.W = w;
  out.H = h;
  out.V.resize(out.Pixels() * 4);
  for (int j = 0; j < h; ++j)
  {
    for (int i = 0; i < w; ++i)
    {
      for (int c = 0; c < 4; ++c)
      {
        out.At(i, j, c) = img.At(x0 + i, y0 + j, c);
      }
    }
  }
  return out;
}

inline double MeanChannel(const Image& img, int c)
{
  double s = 0;
  for (size_t p = 0; p < img.Pixels(); ++p)
  {
    s += img.V[4 * p + c];
  }
  return img.Pixels() ? s / img.Pixels() : 0.0;
}

/// Mean of (r+g+b)/3 over the image.
inline double MeanIntensity(const Image& img)
{
  return (MeanChannel(img, 0) + MeanChannel(img, 1) + MeanChannel(img, 2)) / 3.0;
}

/// An unlit box actor over @p b (xmin,xmax,ymin,ymax,zmin,zmax) of flat
/// colour @p rgb and opacity @p opacity.
inline vtkSmartPointer<vtkActor> BoxActor(const double b[6], const double rgb[3], double opacity = 1.0)
{
  // (Built by hand: vtkCubeSource's module is not linked into the tests.)
  vtkNew<vtkPoints> pts;
  for (int k = 0; k < 8; ++k)
  {
    pts->InsertNextPoint(b[(k & 1) ? 1 : 0], b[(k & 2) ? 3 : 2], b[(k & 4) ? 5 : 4]);
  }
  vtkNew<vtkCellArray> quads;
  const vtkIdType faces[6][4] = { { 0, 2, 3, 1 }, { 4, 5, 7, 6 }, { 0, 1, 5, 4 }, { 2, 6, 7, 3 },
    { 0, 4, 6, 2 }, { 1, 3, 7, 5 } };
  for (const auto& f : faces)
  {
    quads->InsertNextCell(4, f);
  }
  vtkNew<vtkPolyData> box;
  box->SetPoints(pts);
  box->SetPolys(quads);
  vtkNew<vtkPolyDataMapper> pm;
  pm->SetInputData(box);
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(pm);
  actor->GetProperty()->SetColor(rgb[0], rgb[1], rgb[2]);
  actor->GetProperty()->LightingOff();
  actor->GetProperty()->SetOpacity(opacity);
  return actor;
}

/// Renders @p w x @p h and returns the float image (also prints a warning if
/// RenderImage failed).
inline Image Render(vtkHighOrderVolumeMapper* mapper, vtkCamera* cam, vtkVolume* vol, int w, int h,
  int* status = nullptr)
{
  const int ok = mapper->RenderImage(cam, vol, w, h);
  if (status)
  {
    *status = ok;
  }
  return FloatImage(mapper);
}
}

#endif
