#include "vtkHighOrderProjectionRenderer.h"

#include "vtkHighOrderImageDisplayFS.h"    // composite: one texel per pixel
#include "vtkHighOrderProjectionFS.h"      // encoded fragment shader
#include "vtkHighOrderProjectionRegions.h" // FloatsPerVertex
#include "vtkHighOrderProjectionVS.h"      // encoded vertex shader

#include "hovProjectionColor.h" // OpacityTexture

#include "vtkOpenGLBufferObject.h"
#include "vtkOpenGLError.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderUtilities.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkOpenGLVertexArrayObject.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

vtkHighOrderProjectionRenderer::vtkHighOrderProjectionRenderer() = default;

vtkHighOrderProjectionRenderer::~vtkHighOrderProjectionRenderer()
{
  delete this->Quad;
}

bool vtkHighOrderProjectionRenderer::PrepareTarget(
  vtkRenderer* ren, int width, int height, const float* sceneDepth)
{
  auto* renWin = static_cast<vtkOpenGLRenderWindow*>(ren->GetRenderWindow());
  this->ColorTexture->SetContext(renWin);
  if (this->Width != width || this->Height != height || !this->ColorTexture->GetHandle())
  {
    this->ColorTexture->SetMinificationFilter(vtkTextureObject::Nearest);
    this->ColorTexture->SetMagnificationFilter(vtkTextureObject::Nearest);
    this->ColorTexture->SetWrapS(vtkTextureObject::ClampToEdge);
    this->ColorTexture->SetWrapT(vtkTextureObject::ClampToEdge);
    if (!this->ColorTexture->Allocate2D(width, height, 4, VTK_FLOAT))
    {
      return false;
    }
    this->Width = width;
    this->Height = height;
  }
  if (!this->HaveOpacityTable || !this->OpacityTable->GetHandle())
  {
    const std::vector<float> texels = hov::OpacityTexture::Texels();
    this->OpacityTable->SetContext(renWin);
    this->OpacityTable->SetMinificationFilter(vtkTextureObject::Nearest);
    this->OpacityTable->SetMagnificationFilter(vtkTextureObject::Nearest);
    constexpr int n = hov::OpacityTexture::Size;
    if (!this->OpacityTable->Create2DFromRaw(n, n, 1, VTK_FLOAT, const_cast<float*>(texels.data())))
    {
      return false;
    }
    this->HaveOpacityTable = true;
  }
  if (sceneDepth)
  {
    this->DepthTexture->SetContext(renWin);
    this->DepthTexture->SetMinificationFilter(vtkTextureObject::Nearest);
    this->DepthTexture->SetMagnificationFilter(vtkTextureObject::Nearest);
    if (!this->DepthTexture->Create2DFromRaw(
          width, height, 1, VTK_FLOAT, const_cast<float*>(sceneDepth)))
    {
      return false;
    }
  }
  this->Framebuffer->SetContext(renWin);
  this->Framebuffer->Bind();
  this->Framebuffer->AddColorAttachment(0, this->ColorTexture);
  this->Framebuffer->ActivateDrawBuffer(0);
  this->Framebuffer->ActivateReadBuffer(0);
  return this->Framebuffer->CheckFrameBufferStatus(GL_FRAMEBUFFER) != 0;
}

bool vtkHighOrderProjectionRenderer::DrawRegions(
  vtkRenderer* ren, const std::vector<float>& vertices, const Options& options, bool useDepth)
{
  auto* renWin = static_cast<vtkOpenGLRenderWindow*>(ren->GetRenderWindow());
  this->Program = renWin->GetShaderCache()->ReadyShaderProgram(
    vtkHighOrderProjectionVS, vtkHighOrderProjectionFS, "");
  if (!this->Program || !this->Program->GetCompiled())
  {
    return false;
  }
  constexpr int floats = vtkHighOrderProjectionRegions::FloatsPerVertex;
  const size_t count = vertices.size() / floats;
  if (count == 0)
  {
    return true;
  }
  this->Vertices->SetType(vtkOpenGLBufferObject::ArrayBuffer);
  if (!this->Vertices->Upload(vertices, vtkOpenGLBufferObject::ArrayBuffer))
  {
    return false;
  }
  this->VertexArray->Bind();
  const size_t stride = floats * sizeof(float);
  bool ok = this->VertexArray->AddAttributeArray(
    this->Program, this->Vertices, "vertexClip", 0, stride, VTK_FLOAT, 4, false);
  ok = ok &&
    this->VertexArray->AddAttributeArray(
      this->Program, this->Vertices, "rayIn", 4 * sizeof(float), stride, VTK_FLOAT, 4, false);
  ok = ok &&
    this->VertexArray->AddAttributeArray(
      this->Program, this->Vertices, "tauIn", 8 * sizeof(float), stride, VTK_FLOAT, 2, false);
  ok = ok &&
    this->VertexArray->AddAttributeArray(
      this->Program, this->Vertices, "colorAlpha", 10 * sizeof(float), stride, VTK_FLOAT, 4, false);
  if (!ok)
  {
    this->VertexArray->Release();
    return false;
  }
  this->OpacityTable->Activate();
  const int tableUnit = this->OpacityTable->GetTextureUnit();
  this->Program->SetUniformi("opacityTable", tableUnit);
  if (useDepth)
  {
    this->DepthTexture->Activate();
    this->Program->SetUniformi("sceneDepth", this->DepthTexture->GetTextureUnit());
  }
  else
  {
    this->Program->SetUniformi("sceneDepth", tableUnit); // never sampled
  }
  this->Program->SetUniformi("useDepth", useDepth ? 1 : 0);
  this->Program->SetUniformi("perspective", options.Parallel ? 0 : 1);
  this->Program->SetUniformi("textureOpacity", options.TextureOpacity ? 1 : 0);
  this->Program->SetUniformi("premultipliedColor", options.PremultipliedColor ? 1 : 0);
  this->Program->SetUniformf("lengthScale", static_cast<float>(options.LengthScale));
  this->Program->SetUniformf("logMin", static_cast<float>(hov::OpacityTexture::LogMin));
  this->Program->SetUniformf("logMax", static_cast<float>(hov::OpacityTexture::LogMax));
  glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(count));
  this->VertexArray->Release();
  this->Vertices->Release();
  if (useDepth)
  {
    this->DepthTexture->Deactivate();
  }
  this->OpacityTable->Deactivate();
  return true;
}

bool vtkHighOrderProjectionRenderer::Composite(vtkRenderer* ren)
{
  auto* renWin = static_cast<vtkOpenGLRenderWindow*>(ren->GetRenderWindow());
  if (!this->Quad)
  {
    this->Quad = new vtkOpenGLQuadHelper(renWin,
      vtkOpenGLRenderUtilities::GetFullScreenQuadVertexShader().c_str(),
      vtkHighOrderImageDisplayFS, "");
  }
  else
  {
    renWin->GetShaderCache()->ReadyShaderProgram(this->Quad->Program);
  }
  if (!this->Quad->Program || !this->Quad->Program->GetCompiled())
  {
    return false;
  }
  this->ColorTexture->Activate();
  this->Quad->Program->SetUniformi("image", this->ColorTexture->GetTextureUnit());
  this->Quad->Render();
  this->ColorTexture->Deactivate();
  return true;
}

bool vtkHighOrderProjectionRenderer::Render(vtkRenderer* ren, const std::vector<float>& vertices,
  const Options& options, const float* sceneDepth, int width, int height, std::vector<float>* image)
{
  auto* renWin = vtkOpenGLRenderWindow::SafeDownCast(ren ? ren->GetRenderWindow() : nullptr);
  if (!renWin || width <= 0 || height <= 0)
  {
    return false;
  }
  vtkOpenGLState* ostate = renWin->GetState();
  vtkOpenGLClearErrorMacro();
  // Every state touched is restored when these savers leave scope.
  vtkOpenGLState::ScopedglEnableDisable blendSaver(ostate, GL_BLEND);
  vtkOpenGLState::ScopedglEnableDisable depthTestSaver(ostate, GL_DEPTH_TEST);
  vtkOpenGLState::ScopedglEnableDisable cullSaver(ostate, GL_CULL_FACE);
  vtkOpenGLState::ScopedglBlendFuncSeparate blendFuncSaver(ostate);
  vtkOpenGLState::ScopedglDepthMask depthMaskSaver(ostate);
  vtkOpenGLState::ScopedglActiveTexture activeTextureSaver(ostate);
  ostate->vtkglEnable(GL_BLEND);
  ostate->vtkglBlendFuncSeparate(GL_ONE, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  ostate->vtkglDisable(GL_DEPTH_TEST);
  ostate->vtkglDisable(GL_CULL_FACE);
  ostate->vtkglDepthMask(GL_FALSE);

  bool ok = true;
  {
    // The float target: its own viewport, no scissor, cleared to 0.
    vtkOpenGLState::ScopedglViewport viewportSaver(ostate);
    vtkOpenGLState::ScopedglEnableDisable scissorSaver(ostate, GL_SCISSOR_TEST);
    vtkOpenGLState::ScopedglClearColor clearColorSaver(ostate);
    ostate->PushFramebufferBindings();
    ok = this->PrepareTarget(ren, width, height, sceneDepth);
    if (ok)
    {
      ostate->vtkglViewport(0, 0, width, height);
      ostate->vtkglDisable(GL_SCISSOR_TEST);
      ostate->vtkglClearColor(0.0, 0.0, 0.0, 0.0);
      ostate->vtkglClear(GL_COLOR_BUFFER_BIT);
      ok = this->DrawRegions(ren, vertices, options, sceneDepth != nullptr);
      if (ok && image)
      {
        image->resize(static_cast<size_t>(width) * height * 4);
        GLint packAlignment = 4;
        glGetIntegerv(GL_PACK_ALIGNMENT, &packAlignment);
        ostate->vtkglPixelStorei(GL_PACK_ALIGNMENT, 4);
        glReadPixels(0, 0, width, height, GL_RGBA, GL_FLOAT, image->data());
        ostate->vtkglPixelStorei(GL_PACK_ALIGNMENT, packAlignment);
      }
    }
    this->Framebuffer->UnBind();
    ostate->PopFramebufferBindings();
  }
  ok = ok && this->Composite(ren);
  vtkOpenGLCheckErrorMacro("failed after the high-order cell projection");
  return ok;
}

void vtkHighOrderProjectionRenderer::ReleaseGraphicsResources(vtkWindow* win)
{
  this->Framebuffer->ReleaseGraphicsResources(win);
  this->ColorTexture->ReleaseGraphicsResources(win);
  this->DepthTexture->ReleaseGraphicsResources(win);
  this->OpacityTable->ReleaseGraphicsResources(win);
  this->Vertices->ReleaseGraphicsResources();
  this->VertexArray->ReleaseGraphicsResources();
  if (this->Quad)
  {
    this->Quad->ReleaseGraphicsResources(win);
    delete this->Quad;
    this->Quad = nullptr;
  }
  if (this->Program)
  {
    this->Program->ReleaseGraphicsResources(win);
    this->Program = nullptr;
  }
  this->Width = this->Height = 0;
  this->HaveOpacityTable = false;
}
