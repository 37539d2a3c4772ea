/**
 * @class   vtkHighOrderImageDisplay
 * @brief   Puts a float premultiplied RGBA image over the renderer's viewport.
 *
 * The CPU paths compute their image in double precision; this class uploads it
 * once as a GL_RGBA32F texture and draws a full-viewport quad that fetches one
 * texel per pixel (no filtering, no resampling: pixel (i, j) of the image is
 * window pixel (x0 + i, y0 + j)), blended with glBlendFuncSeparate(GL_ONE,
 * GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA) over what is already
 * drawn. Depth test and depth writes are off (the CPU path already clipped its
 * rays at the depth of opaque geometry). Every GL state it touches is saved
 * and restored by vtkOpenGLState's scoped savers.
 *
 * Thread safety: call from the rendering thread only.
 * @sa vtkHighOrderVolumeMapper
 */
#ifndef vtkHighOrderImageDisplay_h
#define vtkHighOrderImageDisplay_h

#include "vtkNew.h" // For vtkNew

class vtkOpenGLQuadHelper;
class vtkRenderer;
class vtkTextureObject;
class vtkWindow;

class vtkHighOrderImageDisplay
{
public:
  vtkHighOrderImageDisplay();
  ~vtkHighOrderImageDisplay();

  /**
   * Draw @p rgba (width*height*4 floats, premultiplied, row 0 at the bottom)
   * over the current viewport of @p ren (which must be width x height).
   * Returns false if the OpenGL resources could not be made.
   */
  bool Draw(vtkRenderer* ren, const float* rgba, int width, int height);

  /// Free the texture and the shader program.
  void ReleaseGraphicsResources(vtkWindow* win);

  /**
   * Read the depth buffer of the viewport (window depth in [0,1], row 0 at the
   * bottom) into @p depth (width*height floats). Returns false on failure.
   */
  static bool ReadDepth(vtkRenderer* ren, int width, int height, int x0, int y0, float* depth);

private:
  vtkHighOrderImageDisplay(const vtkHighOrderImageDisplay&) = delete;
  void operator=(const vtkHighOrderImageDisplay&) = delete;

  vtkNew<vtkTextureObject> Texture;
  vtkOpenGLQuadHelper* Quad = nullptr;
};

#endif
