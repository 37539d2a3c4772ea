/**
 * @file    hovFloatImage.h
 * @brief   The float images vtkHighOrderVolumeMapper publishes (GetFloatImage:
 *          array "RGBA", 4 per pixel; GetRayCastErrorImage: array "Error", 1
 *          per pixel), written in one place for every mode.
 *
 * Thread safety: rendering thread only.
 * @sa vtkHighOrderVolumeMapper
 */
#ifndef hovFloatImage_h
#define hovFloatImage_h

class vtkImageData;

namespace hov
{
/**
 * Give @p image @p width x @p height pixels (negative sizes as 0) and a float
 * array @p name of @p components per pixel as its scalars; returns its first
 * value for the caller to fill. A new array, or with @p reuse the current one
 * when nobody else holds it and its shape fits (a read-back then goes straight
 * into it; it and the image are marked modified).
 */
float* FloatImagePixels(
  vtkImageData* image, const char* name, int components, int width, int height, bool reuse);

/// FloatImagePixels() filled from @p values (width x height x components), converted to float.
template <typename T>
void PublishFloatImage(vtkImageData* image, const char* name, int components, int width,
  int height, const T* values)
{
  float* out = FloatImagePixels(image, name, components, width, height, false);
  const long long n = static_cast<long long>(width > 0 ? width : 0) * (height > 0 ? height : 0) *
    components;
  for (long long i = 0; i < n; ++i)
  {
    out[i] = static_cast<float>(values[i]);
  }
}
}

#endif
