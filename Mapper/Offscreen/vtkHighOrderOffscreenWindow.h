/**
 * @class   vtkHighOrderOffscreenWindow
 * @brief   Makes an offscreen render window that works with or without an X server.
 *
 * The module's tools, tests and Python helpers get every render window here, so
 * that they render under Xvfb or a desktop (X) and on servers with no X at all
 * (Mesa EGL), and fail with a message instead of aborting.
 *
 * NewRenderWindow(width, height) chooses the backend:
 * - The backend set with SetBackend(), else the environment variable
 *   HOV_OFFSCREEN (`auto`, `x11` or `egl`), else AUTOMATIC.
 * - AUTOMATIC: VTK's own window (vtkRenderWindow::New()) if VTK was built
 *   without X (an EGL, OSMesa, Windows or macOS build of VTK renders offscreen
 *   by itself); with Debian's GLX-only VTK: an X window if DISPLAY is set,
 *   vtkHighOrderEGLRenderWindow if DISPLAY is unset or empty.
 * - X11 needs an X server that answers: DISPLAY is checked first (in a child
 *   process, at most DisplayTimeout seconds), because VTK's vtkXOpenGLRenderWindow
 *   aborts the process on a display it cannot open. A set but broken DISPLAY is
 *   an error (with the advice to unset it or ask for EGL), not a silent
 *   fallback: the user asked for that server.
 * - EGL: the window's context is created at once, so that "no EGL" is reported
 *   here rather than at the first render.
 *
 * The window has offscreen rendering on and the requested size; the size must
 * be 1..MaximumSize (16384, llvmpipe's framebuffer limit) per side. On failure
 * NewRenderWindow returns nullptr and GetErrorMessage() says why.
 *
 * C++: `auto win = vtkSmartPointer<vtkRenderWindow>::Take(factory->NewRenderWindow(w, h));`
 * Python: `win = vtkHighOrderOffscreenWindow().NewRenderWindow(w, h)` (None on
 * failure), or highordervolume.offscreen.offscreen_window(w, h), which raises.
 *
 * Thread safety: one factory per thread; the windows as any vtkRenderWindow.
 * @sa vtkHighOrderEGLRenderWindow
 */
#ifndef vtkHighOrderOffscreenWindow_h
#define vtkHighOrderOffscreenWindow_h

#include "vtkObject.h"
#include "vtkRenderingHighOrderVolumeModule.h" // For export macro
#include "vtkWrappingHints.h"                  // For VTK_NEWINSTANCE

#include <string> // For the messages

class vtkRenderWindow;

class VTKRENDERINGHIGHORDERVOLUME_EXPORT vtkHighOrderOffscreenWindow : public vtkObject
{
public:
  static vtkHighOrderOffscreenWindow* New();
  vtkTypeMacro(vtkHighOrderOffscreenWindow, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum Backends
  {
    AUTOMATIC = 0, ///< HOV_OFFSCREEN, then VTK's build and DISPLAY decide
    X11 = 1,       ///< VTK's default window (GLX with Debian's VTK); needs an X server
    EGL = 2        ///< vtkHighOrderEGLRenderWindow (Mesa EGL, no X server)
  };

  ///@{
  /// The backend asked for (default AUTOMATIC).
  vtkSetClampMacro(Backend, int, AUTOMATIC, EGL);
  vtkGetMacro(Backend, int);
  void SetBackendToAutomatic() { this->SetBackend(AUTOMATIC); }
  void SetBackendToX11() { this->SetBackend(X11); }
  void SetBackendToEGL() { this->SetBackend(EGL); }
  ///@}

  ///@{
  /// Seconds to wait for the X server named by DISPLAY to accept a connection
  /// (default 10, or the environment variable HOV_DISPLAY_TIMEOUT).
  vtkSetClampMacro(DisplayTimeout, double, 0.1, 600.0);
  vtkGetMacro(DisplayTimeout, double);
  ///@}

  /// Largest width or height NewRenderWindow accepts.
  static int GetMaximumSize() { return 16384; }

  /**
   * A new offscreen render window of @p width x @p height, or nullptr with
   * GetErrorMessage() set. The caller owns the returned reference.
   */
  VTK_NEWINSTANCE
  vtkRenderWindow* NewRenderWindow(int width, int height);

  /// Why the last NewRenderWindow() failed ("" if it did not).
  const char* GetErrorMessage() { return this->ErrorMessage.c_str(); }

  /// The backend the last NewRenderWindow() chose: "x11", "egl", "vtk" (VTK's own
  /// non-X window) or "" (none: it failed).
  const char* GetBackendName() { return this->BackendName.c_str(); }

  /**
   * The backend AUTOMATIC resolves to now (X11 or EGL), from HOV_OFFSCREEN and
   * DISPLAY, without creating anything; -1 with @p error if HOV_OFFSCREEN is
   * not one of auto, x11, egl.
   */
  static int ResolveBackend(int requested, std::string* error = nullptr);

  /**
   * True if an X server accepts a connection to @p display (as XOpenDisplay),
   * tried in a child process that is killed after @p timeoutSeconds; false with
   * @p error otherwise. Always true if the module was built without X11.
   */
  static bool CanOpenDisplay(const char* display, double timeoutSeconds, std::string* error);

protected:
  vtkHighOrderOffscreenWindow();
  ~vtkHighOrderOffscreenWindow() override = default;

private:
  vtkHighOrderOffscreenWindow(const vtkHighOrderOffscreenWindow&) = delete;
  void operator=(const vtkHighOrderOffscreenWindow&) = delete;

  vtkRenderWindow* Fail(const std::string& message);

  int Backend = AUTOMATIC;
  double DisplayTimeout = 10.0;
  std::string ErrorMessage;
  std::string BackendName;
};

#endif
