#include "vtkHighOrderEGLRenderWindow.h"

#include "vtkObjectFactory.h" // vtkStandardNewMacro
#include "vtk_glew.h" // glewInit, GLEW_VERSION_3_2, glGet* of the limits

#include <EGL/egl.h>    // the EGL 1.5 API
#include <EGL/eglext.h> // EGL_PLATFORM_SURFACELESS_MESA

#include <algorithm> // std::min
#include <cstring>   // std::strstr on the extension string
#include <mutex>     // the shared display's reference count
#include <sstream>   // messages

vtkStandardNewMacro(vtkHighOrderEGLRenderWindow);

struct vtkHighOrderEGLRenderWindow::Handles
{
  EGLDisplay Display = EGL_NO_DISPLAY;
  EGLContext Context = EGL_NO_CONTEXT;
  EGLSurface Surface = EGL_NO_SURFACE;
};

namespace
{
/**
 * eglGetPlatformDisplay returns the same handle to every caller and
 * eglTerminate ends every context on it, so the display is initialised by the
 * first window and terminated after the last one (as VTK's vtkEGLRenderWindow
 * does).
 */
std::mutex DisplayMutex;
int DisplayUsers = 0;

std::string EGLErrorName(EGLint code)
{
  switch (code)
  {
    case EGL_NOT_INITIALIZED: return "EGL_NOT_INITIALIZED";
    case EGL_BAD_ACCESS: return "EGL_BAD_ACCESS";
    case EGL_BAD_ALLOC: return "EGL_BAD_ALLOC";
    case EGL_BAD_ATTRIBUTE: return "EGL_BAD_ATTRIBUTE";
    case EGL_BAD_CONFIG: return "EGL_BAD_CONFIG";
    case EGL_BAD_CONTEXT: return "EGL_BAD_CONTEXT";
    case EGL_BAD_DISPLAY: return "EGL_BAD_DISPLAY";
    case EGL_BAD_MATCH: return "EGL_BAD_MATCH";
    case EGL_BAD_PARAMETER: return "EGL_BAD_PARAMETER";
    case EGL_BAD_SURFACE: return "EGL_BAD_SURFACE";
    default:
    {
      std::ostringstream s;
      s << "EGL error 0x" << std::hex << code;
      return s.str();
    }
  }
}

/// The surfaceless display, initialised; EGL_NO_DISPLAY and @p error if none.
EGLDisplay AcquireDisplay(std::string& error)
{
  std::lock_guard<std::mutex> lock(DisplayMutex);
  const char* clientExtensions = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  if (!clientExtensions || !std::strstr(clientExtensions, "EGL_MESA_platform_surfaceless"))
  {
    error = "EGL has no surfaceless platform (EGL_MESA_platform_surfaceless): no Mesa EGL "
            "driver was found (Debian: libegl1 and libegl-mesa0)";
    return EGL_NO_DISPLAY;
  }
  EGLDisplay display =
    eglGetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
  if (display == EGL_NO_DISPLAY)
  {
    error = "eglGetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA) failed: " +
      EGLErrorName(eglGetError());
    return EGL_NO_DISPLAY;
  }
  EGLint major = 0, minor = 0;
  if (!eglInitialize(display, &major, &minor))
  {
    error = "eglInitialize failed on the surfaceless display: " + EGLErrorName(eglGetError());
    return EGL_NO_DISPLAY;
  }
  ++DisplayUsers;
  return display;
}

void ReleaseDisplay(EGLDisplay display)
{
  std::lock_guard<std::mutex> lock(DisplayMutex);
  if (--DisplayUsers == 0)
  {
    eglTerminate(display);
  }
}

std::string GLString(GLenum name)
{
  const GLubyte* s = glGetString(name);
  return s ? reinterpret_cast<const char*>(s) : "?";
}
}

//------------------------------------------------------------------------------
vtkHighOrderEGLRenderWindow::vtkHighOrderEGLRenderWindow()
  : EGL(new Handles)
{
  this->SetOwnContext(1);
  this->ShowWindow = false;
  this->UseOffScreenBuffers = true;
  this->FrameBlitMode = vtkGenericOpenGLRenderWindow::NoBlit;
  this->ReadyForRendering = true;
  this->SupportsOpenGLStatus = 0;
  this->SetWindowName("vtkHighOrderEGLRenderWindow");
}

vtkHighOrderEGLRenderWindow::~vtkHighOrderEGLRenderWindow()
{
  // The superclass destructor calls its own Finalize(), which cannot reach the
  // context any more: release everything here, while the context exists.
  this->Finalize();
}

//------------------------------------------------------------------------------
bool vtkHighOrderEGLRenderWindow::InitializeEGL()
{
  if (this->EGL->Context != EGL_NO_CONTEXT)
  {
    return true;
  }
  if (this->EGLFailed)
  {
    return false;
  }
  this->EGLFailed = true; // until every step below succeeds
  Handles& h = *this->EGL;
  h.Display = AcquireDisplay(this->EGLError);
  if (h.Display == EGL_NO_DISPLAY)
  {
    return false;
  }
  const EGLint configAttribs[] = { EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RED_SIZE, 8,
    EGL_GREEN_SIZE, 8, EGL_BLUE_SIZE, 8, EGL_ALPHA_SIZE, 8, EGL_DEPTH_SIZE, 24,
    EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE };
  EGLConfig config = nullptr;
  EGLint configs = 0;
  std::string failure;
  if (!eglChooseConfig(h.Display, configAttribs, &config, 1, &configs) || configs < 1)
  {
    failure = "no EGL configuration with a pbuffer and desktop OpenGL";
  }
  else if (!eglBindAPI(EGL_OPENGL_API))
  {
    failure = "eglBindAPI(EGL_OPENGL_API) failed: " + EGLErrorName(eglGetError());
  }
  else
  {
    // VTK draws into its own framebuffer objects; the pbuffer only makes the
    // context current (its size does not limit the window's).
    const EGLint pbufferAttribs[] = { EGL_WIDTH, 16, EGL_HEIGHT, 16, EGL_NONE };
    h.Surface = eglCreatePbufferSurface(h.Display, config, pbufferAttribs);
    const EGLint contextAttribs[] = { EGL_CONTEXT_MAJOR_VERSION, 3, EGL_CONTEXT_MINOR_VERSION, 2,
      EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE };
    if (h.Surface == EGL_NO_SURFACE)
    {
      failure = "eglCreatePbufferSurface failed: " + EGLErrorName(eglGetError());
    }
    else if ((h.Context = eglCreateContext(h.Display, config, EGL_NO_CONTEXT, contextAttribs)) ==
      EGL_NO_CONTEXT)
    {
      failure = "no OpenGL 3.2 core context (eglCreateContext: " + EGLErrorName(eglGetError()) +
        ")";
    }
    else if (!eglMakeCurrent(h.Display, h.Surface, h.Surface, h.Context))
    {
      failure = "eglMakeCurrent failed: " + EGLErrorName(eglGetError()) +
        " (libglvnd refuses an EGL context while a GLX context is current in this thread)";
    }
  }
  if (!failure.empty())
  {
    this->EGLError = failure;
    this->DestroyContext();
    return false;
  }
  // The framebuffer limit: VTK's framebuffers are renderbuffers/textures of the window size.
  GLint renderbuffer = 0, texture = 0, viewport[2] = { 0, 0 };
  glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &renderbuffer);
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &texture);
  glGetIntegerv(GL_MAX_VIEWPORT_DIMS, viewport);
  this->MaximumSize = std::min(std::min(renderbuffer, texture), std::min(viewport[0], viewport[1]));
  this->ContextDescription =
    GLString(GL_VENDOR) + " / " + GLString(GL_RENDERER) + " / " + GLString(GL_VERSION);
  this->EGLFailed = false;
  this->EGLError.clear();
  return true;
}

void vtkHighOrderEGLRenderWindow::DestroyContext()
{
  Handles& h = *this->EGL;
  if (h.Display == EGL_NO_DISPLAY)
  {
    return;
  }
  if (h.Context != EGL_NO_CONTEXT && eglGetCurrentContext() == h.Context)
  {
    eglMakeCurrent(h.Display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  }
  if (h.Context != EGL_NO_CONTEXT)
  {
    eglDestroyContext(h.Display, h.Context);
  }
  if (h.Surface != EGL_NO_SURFACE)
  {
    eglDestroySurface(h.Display, h.Surface);
  }
  ReleaseDisplay(h.Display);
  h = Handles();
}

//------------------------------------------------------------------------------
void vtkHighOrderEGLRenderWindow::OpenGLInitContext()
{
  if (!this->Initialized && this->IsCurrent())
  {
    const GLenum status = glewInit();
    // GLEW's GLX build: glewInit() = glewContextInit() (OpenGL entry points and
    // version flags), then glxewInit(). The two glxewInit() failures below are
    // returned only after the OpenGL part succeeded; with no GLX context
    // current (always so on EGL) GLEW_ERROR_NO_GLX_DISPLAY is expected.
    if (status != GLEW_OK && status != GLEW_ERROR_NO_GLX_DISPLAY &&
      status != GLEW_ERROR_GLX_VERSION_11_ONLY)
    {
      vtkErrorMacro("GLEW could not load OpenGL on the EGL context: "
        << reinterpret_cast<const char*>(glewGetErrorString(status)));
      return;
    }
    if (!GLEW_VERSION_3_2)
    {
      vtkErrorMacro("the EGL context has no OpenGL 3.2: " << this->ContextDescription);
      return;
    }
    this->GlewInitValid = true;
    // As vtkOpenGLRenderWindow::OpenGLInitContext after a successful glewInit;
    // Initialized = true makes the superclass skip its own glewInit().
    this->Initialized = true;
    GLfloat lineWidthRange[2] = { 1.0f, 1.0f };
    this->MaximumHardwareLineWidth = 1.0f;
    glGetFloatv(this->LineSmoothing ? GL_SMOOTH_LINE_WIDTH_RANGE : GL_ALIASED_LINE_WIDTH_RANGE,
      lineWidthRange);
    if (glGetError() == GL_NO_ERROR)
    {
      this->MaximumHardwareLineWidth = lineWidthRange[1];
    }
  }
  this->Superclass::OpenGLInitContext();
}

void vtkHighOrderEGLRenderWindow::Initialize()
{
  if (this->InitializeEGL() && !this->Initialized)
  {
    this->MakeCurrent();
    this->OpenGLInit();
  }
}

void vtkHighOrderEGLRenderWindow::Finalize()
{
  if (this->EGL->Context != EGL_NO_CONTEXT)
  {
    this->MakeCurrent();
    this->ReleaseGraphicsResources(this);
  }
  this->DestroyContext();
  this->Initialized = false;
}

void vtkHighOrderEGLRenderWindow::Render()
{
  if (!this->InitializeEGL())
  {
    if (!this->ReportedFailure)
    {
      vtkErrorMacro("cannot render: " << this->EGLError);
      this->ReportedFailure = true;
    }
    return;
  }
  if (this->Size[0] > this->MaximumSize || this->Size[1] > this->MaximumSize)
  {
    vtkErrorMacro("cannot render " << this->Size[0] << " x " << this->Size[1]
                                   << " pixels: this OpenGL context allows at most "
                                   << this->MaximumSize << " per side");
    return;
  }
  this->MakeCurrent();
  this->Superclass::Render();
}

//------------------------------------------------------------------------------
void vtkHighOrderEGLRenderWindow::MakeCurrent()
{
  Handles& h = *this->EGL;
  if (h.Context == EGL_NO_CONTEXT || eglGetCurrentContext() == h.Context)
  {
    return;
  }
  eglBindAPI(EGL_OPENGL_API);
  if (!eglMakeCurrent(h.Display, h.Surface, h.Surface, h.Context))
  {
    vtkErrorMacro("eglMakeCurrent failed: " << EGLErrorName(eglGetError()));
  }
}

void vtkHighOrderEGLRenderWindow::ReleaseCurrent()
{
  Handles& h = *this->EGL;
  if (h.Context != EGL_NO_CONTEXT && eglGetCurrentContext() == h.Context)
  {
    eglMakeCurrent(h.Display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  }
}

bool vtkHighOrderEGLRenderWindow::IsCurrent()
{
  return this->EGL->Context != EGL_NO_CONTEXT && eglGetCurrentContext() == this->EGL->Context;
}

int vtkHighOrderEGLRenderWindow::SupportsOpenGL()
{
  if (!this->InitializeEGL())
  {
    return 0;
  }
  this->MakeCurrent();
  if (!this->Initialized)
  {
    this->OpenGLInit();
  }
  return this->Initialized ? 1 : 0;
}

vtkTypeBool vtkHighOrderEGLRenderWindow::IsDirect()
{
  return this->EGL->Context != EGL_NO_CONTEXT ? 1 : 0;
}

void* vtkHighOrderEGLRenderWindow::GetGenericContext()
{
  return this->EGL->Context;
}

void* vtkHighOrderEGLRenderWindow::GetGenericDisplayId()
{
  return this->EGL->Display;
}

//------------------------------------------------------------------------------
void vtkHighOrderEGLRenderWindow::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Context: "
     << (this->ContextDescription.empty() ? "(none)" : this->ContextDescription) << "\n";
  os << indent << "MaximumSize: " << this->MaximumSize << "\n";
  os << indent << "EGLError: " << (this->EGLError.empty() ? "(none)" : this->EGLError) << "\n";
}
