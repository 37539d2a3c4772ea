/**
 * @file hovTestImages.h
 * @brief RGBA images as doubles for the VTK-level tests: the mapper's float
 * image, screen captures, sanity statistics of premultiplied images,
 * per-channel differences, crops, means and PNG output.
 */
#ifndef hovTestImages_h
#define hovTestImages_h

#include <cstddef>
#include <string>
#include <vector>

class vtkCamera;
class vtkHighOrderVolumeMapper;
class vtkRenderWindow;
class vtkVolume;

namespace hovTest
{
/// "%.6g" of @p v.
std::string Fmt(double v);

/// A W x H image, 4 doubles (RGBA) per pixel, row by row from the bottom.
struct Image
{
  int W = 0, H = 0;
  std::vector<double> V; // 4 per pixel
  double At(int i, int j, int c) const { return this->V[4 * (static_cast<size_t>(j) * W + i) + c]; }
  double& At(int i, int j, int c) { return this->V[4 * (static_cast<size_t>(j) * W + i) + c]; }
  size_t Pixels() const { return static_cast<size_t>(W) * H; }
};

/// The mapper's float image (empty, with a note, if it is missing or malformed).
Image FloatImage(vtkHighOrderVolumeMapper* mapper);

/// The mapper's last CPU image in double precision (GetDoubleImage), with the
/// float image's size (empty, with a note, if the sizes disagree).
Image DoubleImage(vtkHighOrderVolumeMapper* mapper);

/// Largest value of the mapper's RAY_CAST error image (-1 if it has none).
double MaxRayCastError(vtkHighOrderVolumeMapper* mapper);

/// RenderImage of @p w x @p h and its float image; RenderImage's status in
/// @p status if given.
Image Render(vtkHighOrderVolumeMapper* mapper, vtkCamera* cam, vtkVolume* vol, int w, int h,
  int* status = nullptr);

/// Sanity of a premultiplied image: finite, 0 <= a <= 1, 0 <= rgb <= a (+eps)
/// (colours of every test transfer function are in [0,1]).
struct Sanity
{
  size_t NonFinite = 0, AlphaOut = 0, ColorOut = 0, Covered = 0;
  double MinA = 0, MaxA = 0, MeanA = 0, MaxRGB = 0;
  bool Ok() const { return NonFinite == 0 && AlphaOut == 0 && ColorOut == 0; }
  std::string Str() const;
};

Sanity CheckImage(const Image& img);

/// Pixels with colour but no opacity (glow: Wilhelms-Van Gelder emission).
size_t GlowPixels(const Image& img);

struct DiffStats
{
  double Max = 0, Mean = 0, P99 = 0;
  size_t Count = 0; // channel values compared
  size_t Above = 0; // pixels with any channel difference above the threshold
  int MaxI = -1, MaxJ = -1, MaxC = -1;
  std::string Str() const;
};

/// Differences per channel of the channels [c0, c1) between two float images.
DiffStats Diff(const Image& a, const Image& b, int c0 = 0, int c1 = 4, double thr = 1e-6);

/// Screen capture (RGBA or RGB) of a render window as doubles in [0,1].
Image Capture(vtkRenderWindow* win, bool rgba = false);

/// Writes RGB (premultiplied values clamped to [0,1]) of @p img as an 8-bit PNG.
void WritePNG(const Image& img, const std::string& path);

/// Sub-image [x0, x0+w) x [y0, y0+h).
Image Crop(const Image& img, int x0, int y0, int w, int h);

double MeanChannel(const Image& img, int c);

/// Mean of (r+g+b)/3 over the image.
double MeanIntensity(const Image& img);
}

#endif
