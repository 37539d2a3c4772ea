/**
 * @class   hov::ProjectionRenderer
 * @brief   OpenGL side of the cell projection (HIAC section 7): draws the
 *          region triangles of hov::ProjectionRegions into a float
 *          target and puts it over the scene.
 *
 * Per frame: groups of cells, in the order given (back to front), are built
 * by a producer (hov::ProjectionRegions) and streamed into one vertex
 * and one index buffer (hov::ProjectionStream); each group is drawn
 * with one glDrawElementsBaseVertex call and flushed, so that the rasterizer
 * works on a group while the next one is built. The target is a framebuffer
 * object of the viewport's size with one GL_RGBA32F colour texture cleared to
 * 0, premultiplied blending glBlendFuncSeparate(ONE, ONE_MINUS_SRC_ALPHA,
 * ONE, ONE_MINUS_SRC_ALPHA) ("over", no 8-bit rounding between cells). The
 * fragment shader (hovProjectionFS.glsl, one compiled variant per
 * projection / opacity / emission combination, so no run-time branches per
 * fragment) takes the opacity from the float texture of hov::OpacityTexture
 * (methods M1-M3) or the interpolated vertex opacity (M0). Fragments behind
 * the opaque geometry already drawn fail the depth test (GL_LEQUAL, no depth
 * writes) against the scene depth, read by the caller and uploaded into a
 * GL_DEPTH_COMPONENT32F texture attached to the framebuffer object (no depth
 * format matching with the window needed). The float image is then
 * composited over the renderer's viewport by a full-viewport quad (the
 * fragment shader of hov::ImageDisplay) and, on request, read back
 * (premultiplied RGBA floats, row 0 at the bottom).
 *
 * Every GL state touched is saved and restored with vtkOpenGLState's scoped
 * savers and framebuffer binding stack; ReleaseGraphicsResources frees the
 * framebuffer, the textures, the buffers, the vertex array and the programs.
 *
 * Thread safety: call from the rendering thread only.
 * @sa hov::ProjectionRegions, hov::ImageDisplay, vtkHighOrderVolumeMapper
 */
#ifndef hovProjectionRenderer_h
#define hovProjectionRenderer_h

#include "hovProjectionRegions.h" // Geometry
#include "hovImageDisplay.h"       // Blit
#include "hovProjectionStream.h"  // buffers
#include "vtkNew.h"                        // For vtkNew

#include <functional> // Producer
#include <string>     // shader variants

class vtkOpenGLFramebufferObject;
class vtkOpenGLRenderWindow;
class vtkOpenGLVertexArrayObject;
class vtkRenderer;
class vtkShaderProgram;
class vtkTextureObject;
class vtkWindow;

namespace hov
{
class ProjectionRenderer
{
public:
  struct Options
  {
    bool TextureOpacity = true;      ///< false: M0 (interpolated vertex opacity)
    bool AnalyticOpacity = false;    ///< with TextureOpacity: 1 - exp(-d) in the shader, no texture
    bool PremultipliedColor = false; ///< true: the vertex colour is an effective glow (Wilhelms-Van Gelder)
    bool Parallel = false;           ///< the vertex layout of hov::ProjectionVertex
    bool GPUOpacity = false;         ///< GPU-compatible semantics: the vertices carry opacities
    double InverseUnit = 1.0;        ///< with GPUOpacity: 1 / unit distance
    glm::dmat4 ClipToData{ 1.0 };    ///< perspective: clip -> dataset coordinates
    glm::dvec3 Eye{ 0.0 };           ///< perspective: camera position (dataset coordinates)
  };

  ProjectionRenderer();
  ~ProjectionRenderer();

  /// Fills the geometry with the next group of cells; false when none is left.
  using Producer = std::function<bool(hov::ProjectionRegions::Geometry&)>;

  /**
   * Draw the groups @p produce makes (into @p geometry, reused) for the
   * viewport of @p ren (@p width x @p height); @p sceneDepth (width*height
   * window depths) or null. If @p image is given, the float image is read
   * back into it (width*height*4 floats). Returns false if OpenGL resources
   * could not be made. A producer that calls Stop() (an abort between
   * groups) ends the frame with nothing read back and nothing drawn over the
   * scene (Stopped() says so).
   */
  bool Render(vtkRenderer* ren, const Producer& produce,
    hov::ProjectionRegions::Geometry& geometry, const Options& options,
    const float* sceneDepth, int width, int height, float* image);

  void ReleaseGraphicsResources(vtkWindow* win);

  /// From the producer: no more groups, and the frame is not shown.
  void Stop() { this->StopRequested = true; }
  /// Whether the last Render() was stopped.
  bool Stopped() const { return this->StopRequested; }

private:
  ProjectionRenderer(const hov::ProjectionRenderer&) = delete;
  void operator=(const ProjectionRenderer&) = delete;

  bool PrepareTarget(vtkRenderer* ren, int width, int height, const float* sceneDepth);
  /// The scene depth into the depth texture (storage kept while the size is).
  bool PrepareDepth(vtkOpenGLRenderWindow* renWin, int width, int height, const float* sceneDepth);
  bool DrawRegions(vtkRenderer* ren, const Producer& produce,
    hov::ProjectionRegions::Geometry& geometry, const Options& options);
  bool BindAttributes();
  void SetUniforms(const Options& options);

  vtkNew<vtkOpenGLFramebufferObject> Framebuffer;
  vtkNew<vtkTextureObject> ColorTexture;
  vtkNew<vtkTextureObject> DepthTexture;
  vtkNew<vtkTextureObject> OpacityTable;
  hov::ProjectionStream Stream;
  vtkNew<vtkOpenGLVertexArrayObject> VertexArray;
  vtkShaderProgram* Program = nullptr; ///< owned by the window's shader cache
  hov::ImageDisplay Display; ///< the blit of the float target over the scene
  int Width = 0, Height = 0;
  int DepthWidth = 0, DepthHeight = 0;
  bool StopRequested = false;
  bool HaveOpacityTable = false;
};
}

#endif
