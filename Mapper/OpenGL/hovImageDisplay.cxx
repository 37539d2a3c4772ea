#include "hovImageDisplay.h"

#include "hovImageDisplayFS.h" // encoded fragment shader

#include "vtkInformation.h"
#include "vtkObject.h" // vtkOpenGLError.h uses vtkObject in builds without NDEBUG
#include "vtkOpenGLActor.h" // GLDepthMaskOverride
#include "vtkOpenGLError.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderUtilities.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkPropCollection.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtkVolume.h"
#include "vtk_glew.h"

#include <algorithm> // std::max, std::min

hov::ImageDisplay::ImageDisplay() = default;

hov::ImageDisplay::~ImageDisplay()
{
  delete this->Quad;
}

bool hov::ImageDisplay::Draw(
  vtkRenderer* ren, const float* rgba, int width, int height, const int* box)
{
  auto* renWin = vtkOpenGLRenderWindow::SafeDownCast(ren ? ren->GetRenderWindow() : nullptr);
  if (!renWin || !rgba || width <= 0 || height <= 0)
  {
    return false;
  }
  // Only the box of non-zero pixels: the rest would blend as nothing.
  const int x0 = box ? std::max(box[0], 0) : 0, x1 = box ? std::min(box[1], width) : width;
  const int y0 = box ? std::max(box[2], 0) : 0, y1 = box ? std::min(box[3], height) : height;
  if (x0 >= x1 || y0 >= y1)
  {
    return true;
  }
  vtkOpenGLState* ostate = renWin->GetState();
  vtkOpenGLClearErrorMacro();

  this->Texture->SetContext(renWin);
  this->Texture->SetMinificationFilter(vtkTextureObject::Nearest);
  this->Texture->SetMagnificationFilter(vtkTextureObject::Nearest);
  this->Texture->SetWrapS(vtkTextureObject::ClampToEdge);
  this->Texture->SetWrapT(vtkTextureObject::ClampToEdge);
  // The box's rows of the image, read in place (unpack row length: the
  // image's width); the unpack state is put back (Create2DFromRaw sets the
  // alignment to 1 and leaves it).
  GLint rowLength = 0, alignment = 4;
  glGetIntegerv(GL_UNPACK_ROW_LENGTH, &rowLength);
  glGetIntegerv(GL_UNPACK_ALIGNMENT, &alignment);
  ostate->vtkglPixelStorei(GL_UNPACK_ROW_LENGTH, width);
  const bool uploaded = this->Texture->Create2DFromRaw(x1 - x0, y1 - y0, 4, VTK_FLOAT,
    const_cast<float*>(rgba + 4 * (static_cast<size_t>(y0) * width + x0)));
  ostate->vtkglPixelStorei(GL_UNPACK_ROW_LENGTH, rowLength);
  ostate->vtkglPixelStorei(GL_UNPACK_ALIGNMENT, alignment);
  if (!uploaded)
  {
    return false;
  }

  // Save every state touched; the savers restore it when leaving this scope.
  vtkOpenGLState::ScopedglEnableDisable blendSaver(ostate, GL_BLEND);
  vtkOpenGLState::ScopedglEnableDisable depthTestSaver(ostate, GL_DEPTH_TEST);
  vtkOpenGLState::ScopedglBlendFuncSeparate blendFuncSaver(ostate);
  vtkOpenGLState::ScopedglDepthMask depthMaskSaver(ostate);
  vtkOpenGLState::ScopedglActiveTexture activeTextureSaver(ostate);

  ostate->vtkglEnable(GL_BLEND);
  ostate->vtkglBlendFuncSeparate(GL_ONE, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  ostate->vtkglDisable(GL_DEPTH_TEST);
  ostate->vtkglDepthMask(GL_FALSE);
  // The quad over the box: the renderer's viewport (width x height) moved
  // and shrunk to it, so texel (i, j) still lands on pixel (x0 + i, y0 + j).
  vtkOpenGLState::ScopedglViewport viewportSaver(ostate);
  int viewport[4];
  ostate->vtkglGetIntegerv(GL_VIEWPORT, viewport);
  ostate->vtkglViewport(viewport[0] + x0, viewport[1] + y0, x1 - x0, y1 - y0);

  if (!this->Blit(renWin, this->Texture))
  {
    return false;
  }
  // Not a vtkObject: the static form (vtkErrorMacro needs one in builds without NDEBUG).
  vtkOpenGLStaticCheckErrorMacro("failed after drawing the high-order volume image");
  return true;
}

bool hov::ImageDisplay::Blit(vtkOpenGLRenderWindow* renWin, vtkTextureObject* texture)
{
  if (!this->Quad)
  {
    this->Quad = new vtkOpenGLQuadHelper(renWin,
      vtkOpenGLRenderUtilities::GetFullScreenQuadVertexShader().c_str(), hovImageDisplayFS, "");
  }
  else
  {
    renWin->GetShaderCache()->ReadyShaderProgram(this->Quad->Program);
  }
  if (!this->Quad->Program || !this->Quad->Program->GetCompiled())
  {
    return false;
  }
  texture->Activate();
  this->Quad->Program->SetUniformi("image", texture->GetTextureUnit());
  this->Quad->Render();
  texture->Deactivate();
  return true;
}

void hov::ImageDisplay::ReleaseGraphicsResources(vtkWindow* win)
{
  this->Texture->ReleaseGraphicsResources(win);
  if (this->Quad)
  {
    this->Quad->ReleaseGraphicsResources(win);
    delete this->Quad;
    this->Quad = nullptr;
  }
}

bool hov::ImageDisplay::ReadDepth(
  vtkRenderer* ren, int width, int height, int x0, int y0, float* depth)
{
  auto* renWin = vtkOpenGLRenderWindow::SafeDownCast(ren ? ren->GetRenderWindow() : nullptr);
  if (!renWin || !depth || width <= 0 || height <= 0)
  {
    return false;
  }
  vtkOpenGLState* ostate = renWin->GetState();
  // vtkOpenGLRenderWindow::GetZbufferData disables the scissor test and sets
  // the pack alignment; put both back.
  vtkOpenGLState::ScopedglEnableDisable scissorSaver(ostate, GL_SCISSOR_TEST);
  GLint packAlignment = 4;
  glGetIntegerv(GL_PACK_ALIGNMENT, &packAlignment);
  const int ok = renWin->GetZbufferData(x0, y0, x0 + width - 1, y0 + height - 1, depth);
  ostate->vtkglPixelStorei(GL_PACK_ALIGNMENT, packAlignment);
  return ok == VTK_OK;
}

bool hov::ImageDisplay::MayHoldDepth(vtkRenderer* ren)
{
  // The camera clears the depth only if both erase flags are on and depth is
  // not preserved; a render pass (ParaView's, a composite) may draw or keep
  // depth that no view prop drew.
  vtkRenderWindow* renWin = ren ? ren->GetRenderWindow() : nullptr;
  if (!ren || !renWin || ren->GetPreserveDepthBuffer() || !ren->GetErase() ||
    !renWin->GetErase() || ren->GetPass())
  {
    return true;
  }
  vtkPropCollection* props = ren->GetViewProps();
  if (!props)
  {
    return true;
  }
  vtkCollectionSimpleIterator it;
  props->InitTraversal(it);
  while (vtkProp* prop = props->GetNextProp(it))
  {
    if (!prop->GetVisibility())
    {
      continue;
    }
    vtkInformation* keys = prop->GetPropertyKeys();
    if (!vtkVolume::SafeDownCast(prop) ||
      (keys && keys->Has(vtkOpenGLActor::GLDepthMaskOverride())))
    {
      return true; // geometry (or anything else, or a volume told to) may write depth
    }
  }
  return false;
}
