/**
 * @class   hov::ImageDisplay
 * @brief   Puts a float premultiplied RGBA image over the renderer's viewport.
 *
 * The CPU paths compute their image in double precision; this class uploads it
 * once as a GL_RGBA32F texture and draws a quad over the viewport that fetches
 * one texel per pixel (no filtering, no resampling: pixel (i, j) of the image
 * is window pixel (x0 + i, y0 + j)); given the box of its non-zero pixels,
 * only that box is uploaded and drawn (a 1024x1024 image of a mesh that covers
 * a fifth of it: ~4 ms less per frame with Mesa llvmpipe). Blended with glBlendFuncSeparate(GL_ONE,
 * GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA) over what is already
 * drawn. Depth test and depth writes are off (the CPU path already clipped its
 * rays at the depth of opaque geometry). Every GL state it touches is saved
 * and restored by vtkOpenGLState's scoped savers.
 *
 * Blit() is the full-viewport quad alone (fragment shader hovImageDisplayFS.glsl:
 * one texel per viewport pixel), for a float texture already on the GPU with
 * the caller's GL state: the OpenGL projection composites its target with it
 * (hov::ProjectionRenderer). It is the module's one image blit.
 *
 * Thread safety: call from the rendering thread only.
 * @sa vtkHighOrderVolumeMapper, hov::ProjectionRenderer
 */
#ifndef hovImageDisplay_h
#define hovImageDisplay_h

#include "vtkNew.h" // For vtkNew

class vtkOpenGLQuadHelper;
class vtkOpenGLRenderWindow;
class vtkRenderer;
class vtkTextureObject;
class vtkWindow;

namespace hov
{
class ImageDisplay
{
public:
  ImageDisplay();
  ~ImageDisplay();

  /**
   * Draw @p rgba (width*height*4 floats, premultiplied, row 0 at the bottom)
   * over the current viewport of @p ren (which must be width x height).
   * With @p box ({x0, x1, y0, y1}: columns [x0, x1), rows [y0, y1); see
   * hov::ImageCheck::GetNonZeroBox()) only that part is uploaded and drawn:
   * the caller vouches that every other pixel is zero (it would blend as
   * nothing); an empty box draws nothing. Returns false if the OpenGL
   * resources could not be made.
   */
  bool Draw(vtkRenderer* ren, const float* rgba, int width, int height, const int* box = nullptr);

  /**
   * Draw @p texture (a float RGBA texture of the viewport's size) over the
   * current viewport of @p renWin, one texel per pixel, with the caller's
   * blending and depth state. Returns false if the shader could not be made.
   */
  bool Blit(vtkOpenGLRenderWindow* renWin, vtkTextureObject* texture);

  /// Free the texture and the shader program.
  void ReleaseGraphicsResources(vtkWindow* win);

  /**
   * Read the depth buffer of the viewport (window depth in [0,1], row 0 at the
   * bottom) into @p depth (width*height floats). Returns false on failure.
   */
  static bool ReadDepth(vtkRenderer* ren, int width, int height, int x0, int y0, float* depth);

  /**
   * False if the depth buffer of @p ren's viewport can only hold the far
   * plane: the camera clears it for this renderer (renderer and window erase
   * on, no preserved depth, no render pass of its own) and no visible prop
   * but volumes (which write no depth unless told to by
   * vtkOpenGLActor::GLDepthMaskOverride) is drawn in it; then reading it back
   * (a few milliseconds per frame at 1024x1024) is skipped. True in every
   * other case, and whenever unsure.
   */
  static bool MayHoldDepth(vtkRenderer* ren);

private:
  ImageDisplay(const hov::ImageDisplay&) = delete;
  void operator=(const ImageDisplay&) = delete;

  vtkNew<vtkTextureObject> Texture;
  vtkOpenGLQuadHelper* Quad = nullptr;
};
}

#endif
