#include "hovTestImages.h"

#include "vtkHighOrderVolumeMapper.h"

#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPNGWriter.h"
#include "vtkPointData.h"
#include "vtkRenderWindow.h"
#include "vtkUnsignedCharArray.h"
#include "vtkWindowToImageFilter.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <limits>
#include <sstream>

namespace hovTest
{
std::string Fmt(double v)
{
  char buf[64];
  std::snprintf(buf, sizeof(buf), "%.6g", v);
  return buf;
}

Image DoubleImage(vtkHighOrderVolumeMapper* mapper)
{
  Image img;
  int dims[3];
  mapper->GetFloatImage()->GetDimensions(dims);
  vtkNew<vtkDoubleArray> rgba;
  mapper->GetDoubleImage(rgba);
  if (rgba->GetNumberOfTuples() != static_cast<vtkIdType>(dims[0]) * dims[1])
  {
    std::cout << "  (double image of " << rgba->GetNumberOfTuples() << " pixels for "
              << dims[0] << "x" << dims[1] << ")\n";
    return img;
  }
  img.W = dims[0];
  img.H = dims[1];
  img.V.assign(rgba->GetPointer(0), rgba->GetPointer(0) + 4 * img.Pixels());
  return img;
}

double MaxRayCastError(vtkHighOrderVolumeMapper* mapper)
{
  vtkDataArray* e = mapper->GetRayCastErrorImage()->GetPointData()->GetScalars();
  double m = e ? 0.0 : -1.0;
  for (vtkIdType i = 0; e && i < e->GetNumberOfTuples(); ++i)
  {
    m = std::max(m, e->GetComponent(i, 0));
  }
  return m;
}

Image FloatImage(vtkHighOrderVolumeMapper* mapper)
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

Image Render(
  vtkHighOrderVolumeMapper* mapper, vtkCamera* cam, vtkVolume* vol, int w, int h, int* status)
{
  const int ok = mapper->RenderImage(cam, vol, w, h);
  if (status)
  {
    *status = ok;
  }
  return FloatImage(mapper);
}

std::string Sanity::Str() const
{
  std::ostringstream s;
  s << "nonfinite=" << NonFinite << " alphaOut=" << AlphaOut << " colorOut=" << ColorOut
    << " covered(a>0)=" << Covered << " alpha[min,max,mean]=[" << Fmt(MinA) << "," << Fmt(MaxA)
    << "," << Fmt(MeanA) << "] maxRGB=" << Fmt(MaxRGB);
  return s.str();
}

size_t GlowPixels(const Image& img)
{
  size_t glow = 0;
  for (size_t i = 0; i + 3 < img.V.size(); i += 4)
  {
    glow += img.V[i + 3] == 0 && img.V[i] + img.V[i + 1] + img.V[i + 2] > 0;
  }
  return glow;
}

Sanity CheckImage(const Image& img)
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

std::string DiffStats::Str() const
{
  std::ostringstream s;
  s << "max=" << Fmt(Max) << " (at " << MaxI << "," << MaxJ << " ch " << MaxC
    << ") mean=" << Fmt(Mean) << " p99=" << Fmt(P99) << " pixelsAboveThr=" << Above;
  return s.str();
}

DiffStats Diff(const Image& a, const Image& b, int c0, int c1, double thr)
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

Image Capture(vtkRenderWindow* win, bool rgba)
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

void WritePNG(const Image& img, const std::string& path)
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

Image Crop(const Image& img, int x0, int y0, int w, int h)
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

double MeanChannel(const Image& img, int c)
{
  double s = 0;
  for (size_t p = 0; p < img.Pixels(); ++p)
  {
    s += img.V[4 * p + c];
  }
  return img.Pixels() ? s / img.Pixels() : 0.0;
}

double MeanIntensity(const Image& img)
{
  return (MeanChannel(img, 0) + MeanChannel(img, 1) + MeanChannel(img, 2)) / 3.0;
}
}
