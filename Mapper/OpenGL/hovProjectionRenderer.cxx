#include "hovProjectionRenderer.h"

#include "hovProjectionFS.h"      // encoded fragment shader
#include "hovProjectionVS.h"      // encoded vertex shader

#include "hovProjectionColor.h" // OpacityTexture

#include "vtkOpenGLBufferObject.h"
#include "vtkOpenGLError.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkOpenGLVertexArrayObject.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

#include <algorithm> // std::copy

hov::ProjectionRenderer::ProjectionRenderer() = default;

hov::ProjectionRenderer::~ProjectionRenderer() = default;

bool hov::ProjectionRenderer::PrepareTarget(
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
    // Bilinear between texel centres (hov::OpacityFromTexture).
    this->OpacityTable->SetMinificationFilter(vtkTextureObject::Linear);
    this->OpacityTable->SetMagnificationFilter(vtkTextureObject::Linear);
    this->OpacityTable->SetWrapS(vtkTextureObject::ClampToEdge);
    this->OpacityTable->SetWrapT(vtkTextureObject::ClampToEdge);
    constexpr int n = hov::OpacityTexture::Size;
    if (!this->OpacityTable->Create2DFromRaw(n, n, 1, VTK_FLOAT, const_cast<float*>(texels.data())))
    {
      return false;
    }
    this->HaveOpacityTable = true;
  }
  this->Framebuffer->SetContext(renWin);
  this->Framebuffer->Bind();
  this->Framebuffer->AddColorAttachment(0, this->ColorTexture);
  this->Framebuffer->ActivateDrawBuffer(0);
  this->Framebuffer->ActivateReadBuffer(0);
  if (sceneDepth && this->PrepareDepth(renWin, width, height, sceneDepth))
  {
    this->Framebuffer->AddDepthAttachment(this->DepthTexture);
  }
  else
  {
    this->Framebuffer->RemoveDepthAttachment();
    if (sceneDepth)
    {
      return false;
    }
  }
  return this->Framebuffer->CheckFrameBufferStatus(GL_FRAMEBUFFER) != 0;
}

bool hov::ProjectionRenderer::PrepareDepth(
  vtkOpenGLRenderWindow* renWin, int width, int height, const float* sceneDepth)
{
  this->DepthTexture->SetContext(renWin);
  if (this->DepthWidth != width || this->DepthHeight != height ||
    !this->DepthTexture->GetHandle())
  {
    this->DepthTexture->SetMinificationFilter(vtkTextureObject::Nearest);
    this->DepthTexture->SetMagnificationFilter(vtkTextureObject::Nearest);
    this->DepthTexture->SetWrapS(vtkTextureObject::ClampToEdge);
    this->DepthTexture->SetWrapT(vtkTextureObject::ClampToEdge);
    if (!this->DepthTexture->CreateDepthFromRaw(
          width, height, vtkTextureObject::Float32, VTK_FLOAT, const_cast<float*>(sceneDepth)))
    {
      return false;
    }
    this->DepthWidth = width;
    this->DepthHeight = height;
    return true;
  }
  // Same size: new contents into the same storage.
  vtkOpenGLState* ostate = renWin->GetState();
  vtkOpenGLState::ScopedglActiveTexture activeTextureSaver(ostate);
  this->DepthTexture->Activate();
  GLint alignment = 4;
  glGetIntegerv(GL_UNPACK_ALIGNMENT, &alignment);
  ostate->vtkglPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, width, height, GL_DEPTH_COMPONENT, GL_FLOAT, sceneDepth);
  ostate->vtkglPixelStorei(GL_UNPACK_ALIGNMENT, alignment);
  this->DepthTexture->Deactivate();
  return true;
}

namespace
{
constexpr int Floats = hov::ProjectionVertex::FloatsPerVertex;

/// @p source with the HOV_* switches of the variant for @p options.
std::string Variant(const char* source, const hov::ProjectionRenderer::Options& options)
{
  std::string defines = "#define HOV_PERSPECTIVE " + std::string(options.Parallel ? "0" : "1") +
    "\n#define HOV_TEXTURE_OPACITY " + (options.TextureOpacity && !options.AnalyticOpacity ? "1" : "0") +
    "\n#define HOV_ANALYTIC_OPACITY " + (options.TextureOpacity && options.AnalyticOpacity ? "1" : "0") +
    "\n#define HOV_GLOW " + (options.PremultipliedColor ? "1" : "0") +
    "\n#define HOV_GPU_OPACITY " + (options.GPUOpacity ? "1" : "0") + "\n";
  std::string out = source;
  const std::string tag = "//HOV::Variant::Dec";
  const size_t at = out.find(tag);
  if (at != std::string::npos)
  {
    out.replace(at, tag.size(), defines);
  }
  return out;
}

}

bool hov::ProjectionRenderer::BindAttributes()
{
  struct Attribute
  {
    const char* Name;
    int Offset, Components;
  };
  static const Attribute attributes[] = { { "vertexClip", 0, 4 }, { "segmentIn", 4, 3 },
    { "colorAlpha", 7, 4 } };
  bool ok = true;
  for (const Attribute& a : attributes)
  {
    // A variant may not read an attribute (M0 without glow: no segment).
    ok = ok &&
      (!this->Program->IsAttributeUsed(a.Name) ||
        this->VertexArray->AddAttributeArray(this->Program, this->Stream.GetVertexBuffer(), a.Name,
          a.Offset * sizeof(float), Floats * sizeof(float), VTK_FLOAT, a.Components, false));
  }
  return ok;
}

void hov::ProjectionRenderer::SetUniforms(const Options& options)
{
  if (options.TextureOpacity && !options.AnalyticOpacity)
  {
    this->OpacityTable->Activate();
    this->Program->SetUniformi("opacityTable", this->OpacityTable->GetTextureUnit());
    constexpr double n = hov::OpacityTexture::Size;
    this->Program->SetUniformf(
      "opacityScale", static_cast<float>((n - 1.0) / (hov::OpacityTexture::UMax * n)));
    this->Program->SetUniformf("opacityOffset", static_cast<float>(0.5 / n));
    this->Program->SetUniformf("opacityLast", static_cast<float>((n - 0.5) / n));
  }
  if (options.GPUOpacity)
  {
    this->Program->SetUniformf("inverseUnit", static_cast<float>(options.InverseUnit));
  }
  if (!options.Parallel)
  {
    float matrix[16]; // column-major, as GL expects
    for (int c = 0; c < 4; ++c)
    {
      for (int r = 0; r < 4; ++r)
      {
        matrix[4 * c + r] = static_cast<float>(options.ClipToData[c][r]);
      }
    }
    const float eye[3] = { static_cast<float>(options.Eye.x), static_cast<float>(options.Eye.y),
      static_cast<float>(options.Eye.z) };
    this->Program->SetUniformMatrix4x4("clipToData", matrix);
    this->Program->SetUniform3f("eye", eye);
  }
}

bool hov::ProjectionRenderer::DrawRegions(vtkRenderer* ren, const Producer& produce,
  hov::ProjectionRegions::Geometry& geometry, const Options& options)
{
  auto* renWin = static_cast<vtkOpenGLRenderWindow*>(ren->GetRenderWindow());
  const std::string vs = Variant(hovProjectionVS, options);
  const std::string fs = Variant(hovProjectionFS, options);
  this->Program = renWin->GetShaderCache()->ReadyShaderProgram(vs.c_str(), fs.c_str(), "");
  if (!this->Program || !this->Program->GetCompiled())
  {
    return false;
  }
  this->VertexArray->ShaderProgramChanged(); // the variant may differ from the last frame's
  this->VertexArray->Bind();
  bool ok = this->Stream.Begin() && this->BindAttributes();
  if (ok)
  {
    this->SetUniforms(options);
    // Group after group, a flush after each: a software rasterizer (llvmpipe)
    // rasterizes a group while the next one is built and its vertices processed.
    while (ok && !this->StopRequested && produce(geometry))
    {
      // The producer reports progress: an observer may have made another
      // context current (this one's bindings are kept with it).
      renWin->MakeCurrent();
      hov::ProjectionStream::Range range;
      ok = this->Stream.Append(geometry, range);
      if (ok && range.Count > 0)
      {
        glDrawElementsBaseVertex(GL_TRIANGLES, static_cast<GLsizei>(range.Count),
          GL_UNSIGNED_INT, reinterpret_cast<const void*>(range.IndexOffset),
          static_cast<GLint>(range.BaseVertex));
        glFlush();
      }
    }
    if (options.TextureOpacity && !options.AnalyticOpacity)
    {
      this->OpacityTable->Deactivate();
    }
  }
  this->Stream.End();
  this->VertexArray->Release();
  return ok;
}

bool hov::ProjectionRenderer::Render(vtkRenderer* ren, const Producer& produce,
  hov::ProjectionRegions::Geometry& geometry, const Options& options,
  const float* sceneDepth, int width, int height, float* image)
{
  auto* renWin = vtkOpenGLRenderWindow::SafeDownCast(ren ? ren->GetRenderWindow() : nullptr);
  this->StopRequested = false;
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
  vtkOpenGLState::ScopedglDepthFunc depthFuncSaver(ostate);
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
      ostate->vtkglClear(GL_COLOR_BUFFER_BIT); // the depth attachment keeps the scene depth
      if (sceneDepth)
      {
        // Fragments behind the opaque geometry fail the depth test (no writes).
        ostate->vtkglEnable(GL_DEPTH_TEST);
        ostate->vtkglDepthFunc(GL_LEQUAL);
      }
      ok = this->DrawRegions(ren, produce, geometry, options);
      ostate->vtkglDisable(GL_DEPTH_TEST);
      if (ok && image && !this->StopRequested)
      {
        GLint packAlignment = 4;
        glGetIntegerv(GL_PACK_ALIGNMENT, &packAlignment);
        ostate->vtkglPixelStorei(GL_PACK_ALIGNMENT, 4);
        glReadPixels(0, 0, width, height, GL_RGBA, GL_FLOAT, image);
        ostate->vtkglPixelStorei(GL_PACK_ALIGNMENT, packAlignment);
      }
    }
    this->Framebuffer->UnBind();
    ostate->PopFramebufferBindings();
  }
  // The float image over the scene: the one image blit.
  ok = ok && (this->StopRequested || this->Display.Blit(renWin, this->ColorTexture));
  // Not a vtkObject: the static form (vtkErrorMacro needs one in builds without NDEBUG).
  vtkOpenGLStaticCheckErrorMacro("failed after the high-order cell projection");
  return ok;
}

void hov::ProjectionRenderer::ReleaseGraphicsResources(vtkWindow* win)
{
  this->Framebuffer->ReleaseGraphicsResources(win);
  this->ColorTexture->ReleaseGraphicsResources(win);
  this->DepthTexture->ReleaseGraphicsResources(win);
  this->OpacityTable->ReleaseGraphicsResources(win);
  this->Stream.ReleaseGraphicsResources();
  this->VertexArray->ReleaseGraphicsResources();
  this->Display.ReleaseGraphicsResources(win);
  if (this->Program)
  {
    this->Program->ReleaseGraphicsResources(win);
    this->Program = nullptr;
  }
  this->Width = this->Height = 0;
  this->DepthWidth = this->DepthHeight = 0;
  this->HaveOpacityTable = false;
}
