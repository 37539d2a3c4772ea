/**
 * @class   vtkHighOrderEGLRenderWindow
 * @brief   An offscreen render window on a Mesa EGL surfaceless context: renders with no X server.
 *
 * Debian's VTK 9.1 is built for GLX only: every vtkRenderWindow it creates is a
 * vtkXOpenGLRenderWindow, which aborts the process (SIGABRT, "bad X server
 * connection") when DISPLAY is unset or names no server. This window makes its
 * own OpenGL (>= 3.2 core) context through EGL on Mesa's surfaceless platform
 * (EGL_MESA_platform_surfaceless: llvmpipe without a GPU, or the GPU's render
 * node), current on a small pbuffer, and renders, like every VTK 9.1 window
 * rendering offscreen, into VTK's own framebuffer objects: the images are the
 * ones a vtkXOpenGLRenderWindow gives offscreen on the same Mesa driver
 * (measured bit-identical for every render mode of vtkHighOrderVolumeMapper, see
 * the README, "Rendering without an X server").
 *
 * It is a vtkGenericOpenGLRenderWindow that owns its context: MakeCurrent,
 * IsCurrent, SupportsOpenGL, Initialize and Finalize act on the EGL context
 * directly (no observers needed). Offscreen rendering is always on (nothing is
 * ever blitted to the pbuffer: FrameBlitMode NoBlit).
 *
 * GLEW: VTK's OpenGLInitContext() calls glewInit(). Debian's GLEW is a GLX
 * build: glewInit() loads the OpenGL entry points and version flags
 * (glewContextInit), then fails in glxewInit() because no GLX display is
 * current; VTK then logs "ERR| GLEW could not be initialized" on every render
 * and never marks the context initialised. OpenGLInitContext() is overridden
 * here: it accepts exactly the glxewInit() failures (GLEW_ERROR_NO_GLX_DISPLAY,
 * GLEW_ERROR_GLX_VERSION_11_ONLY: returned only after the OpenGL part
 * succeeded), checks OpenGL >= 3.2 itself and completes VTK's initialisation,
 * so nothing is logged.
 *
 * Failure is never an abort: if EGL, the surfaceless platform or an OpenGL 3.2
 * context is not available, InitializeEGL() returns false with
 * GetEGLErrorMessage(), SupportsOpenGL() returns 0, and Render() reports one
 * error and draws nothing. A size beyond the context's framebuffer limit is an
 * error too (nothing drawn).
 *
 * Several windows may exist at once (one context each, one EGL display shared
 * and reference counted). Limitation (libglvnd): a thread cannot have a GLX
 * context and an EGL context current at the same time, so do not mix these
 * windows with vtkXOpenGLRenderWindows in one thread; vtkHighOrderOffscreenWindow
 * chooses one kind per process.
 *
 * Thread safety: as any vtkRenderWindow (one thread at a time).
 * @sa vtkHighOrderOffscreenWindow, vtkGenericOpenGLRenderWindow
 */
#ifndef vtkHighOrderEGLRenderWindow_h
#define vtkHighOrderEGLRenderWindow_h

#include "vtkGenericOpenGLRenderWindow.h"
#include "vtkRenderingHighOrderVolumeModule.h" // For export macro

#include <memory> // For std::unique_ptr (the EGL handles)
#include <string> // For the error and driver strings

class VTKRENDERINGHIGHORDERVOLUME_EXPORT vtkHighOrderEGLRenderWindow
  : public vtkGenericOpenGLRenderWindow
{
public:
  static vtkHighOrderEGLRenderWindow* New();
  vtkTypeMacro(vtkHighOrderEGLRenderWindow, vtkGenericOpenGLRenderWindow);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Creates the EGL display connection and context now (otherwise the first
   * render does). Returns false, with GetEGLErrorMessage(), if that is not
   * possible; a failure is remembered (not retried).
   */
  bool InitializeEGL();

  /// Why InitializeEGL() failed ("" if it did not, or was not called).
  const char* GetEGLErrorMessage() { return this->EGLError.c_str(); }

  /// "GL_VENDOR / GL_RENDERER / GL_VERSION" of the context ("" before InitializeEGL()).
  const char* GetContextDescription() { return this->ContextDescription.c_str(); }

  /// The largest width and height this context can render (GL_MAX_RENDERBUFFER_SIZE and
  /// viewport limits; 0 before InitializeEGL()).
  int GetMaximumSize() const { return this->MaximumSize; }

  ///@{
  /// The context: made current, queried, tested directly (no observers needed).
  void MakeCurrent() override;
  void ReleaseCurrent() override;
  bool IsCurrent() override;
  int SupportsOpenGL() override;
  vtkTypeBool IsDirect() override;
  ///@}

  /// Creates the context (InitializeEGL) and initialises VTK's OpenGL state.
  void Initialize() override;

  /// Releases every graphics resource of the window, then the EGL context.
  void Finalize() override;

  /// Renders if the context exists (made on demand) and the size fits; else one error.
  void Render() override;

  ///@{
  /// The EGL context and display handles (EGLContext, EGLDisplay), null before InitializeEGL().
  void* GetGenericContext() override;
  void* GetGenericDisplayId() override;
  ///@}

protected:
  vtkHighOrderEGLRenderWindow();
  ~vtkHighOrderEGLRenderWindow() override;

  /// GLEW and VTK's context initialisation without GLX (see the class documentation).
  void OpenGLInitContext() override;

private:
  vtkHighOrderEGLRenderWindow(const vtkHighOrderEGLRenderWindow&) = delete;
  void operator=(const vtkHighOrderEGLRenderWindow&) = delete;

  /// Destroys the context and releases the display (no GL resources are touched).
  void DestroyContext();

  struct Handles;
  std::unique_ptr<Handles> EGL;
  std::string EGLError;
  std::string ContextDescription;
  int MaximumSize = 0;
  bool EGLFailed = false;
  bool ReportedFailure = false;
};

#endif
