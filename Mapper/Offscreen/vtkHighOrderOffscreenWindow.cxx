#include "vtkHighOrderOffscreenWindow.h"

#include "vtkObjectFactory.h" // vtkStandardNewMacro
#include "vtkRenderWindow.h" // VTK's default window (the X11 backend)

#include <cstdlib> // std::getenv, std::atof
#include <sstream> // messages

#ifdef HOV_HAVE_EGL
#include "vtkHighOrderEGLRenderWindow.h" // the no-X backend
#endif

#ifdef HOV_HAVE_X11
#include <X11/Xlib.h>   // XOpenDisplay in the probe
#include <csignal>      // kill
#include <sys/wait.h>   // waitpid
#include <time.h>       // nanosleep between polls
#include <unistd.h>     // fork, _exit
#endif

vtkStandardNewMacro(vtkHighOrderOffscreenWindow);

namespace
{
std::string Lower(const char* s)
{
  std::string out = s ? s : "";
  for (char& c : out)
  {
    c = static_cast<char>(c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c);
  }
  return out;
}

bool DisplaySet()
{
  const char* display = std::getenv("DISPLAY");
  return display && *display;
}
}

//------------------------------------------------------------------------------
vtkHighOrderOffscreenWindow::vtkHighOrderOffscreenWindow()
{
  const char* timeout = std::getenv("HOV_DISPLAY_TIMEOUT");
  if (timeout && *timeout)
  {
    this->SetDisplayTimeout(std::atof(timeout)); // clamped to 0.1..600
  }
}

int vtkHighOrderOffscreenWindow::ResolveBackend(int requested, std::string* error)
{
  if (requested == X11 || requested == EGL)
  {
    return requested;
  }
  const std::string env = Lower(std::getenv("HOV_OFFSCREEN"));
  if (env == "egl")
  {
    return EGL;
  }
  if (env == "x11" || env == "x" || env == "glx")
  {
    return X11;
  }
  if (!env.empty() && env != "auto")
  {
    if (error)
    {
      *error = "HOV_OFFSCREEN='" + env + "': expected auto, x11 or egl";
    }
    return -1;
  }
  return DisplaySet() ? X11 : EGL;
}

bool vtkHighOrderOffscreenWindow::CanOpenDisplay(
  const char* display, double timeoutSeconds, std::string* error)
{
#ifdef HOV_HAVE_X11
  // XOpenDisplay can block for minutes on an unreachable TCP display, and
  // VTK's X window aborts the process on one it cannot open: try it in a child
  // process and give up after the timeout.
  const pid_t child = fork();
  if (child < 0)
  {
    return true; // cannot probe: let VTK try
  }
  if (child == 0)
  {
    Display* d = XOpenDisplay(display);
    _exit(d ? 0 : 1); // no XCloseDisplay: the child ends here either way
  }
  const long stepNs = 5000000; // 5 ms between polls
  const long steps = static_cast<long>(timeoutSeconds * 1e9 / stepNs) + 1;
  int status = 0;
  for (long i = 0; i < steps; ++i)
  {
    const pid_t done = waitpid(child, &status, WNOHANG);
    if (done == child)
    {
      if (WIFEXITED(status) && WEXITSTATUS(status) == 0)
      {
        return true;
      }
      if (error)
      {
        *error = "cannot connect to the X server DISPLAY='" + std::string(display ? display : "") +
          "'";
      }
      return false;
    }
    if (done < 0)
    {
      return true; // the child was reaped elsewhere (a SIGCHLD handler): let VTK try
    }
    const timespec pause = { 0, stepNs };
    nanosleep(&pause, nullptr);
  }
  kill(child, SIGKILL);
  waitpid(child, &status, 0);
  if (error)
  {
    std::ostringstream s;
    s << "the X server DISPLAY='" << (display ? display : "") << "' did not answer within "
      << timeoutSeconds << " s";
    *error = s.str();
  }
  return false;
#else
  (void)display;
  (void)timeoutSeconds;
  (void)error;
  return true;
#endif
}

//------------------------------------------------------------------------------
vtkRenderWindow* vtkHighOrderOffscreenWindow::Fail(const std::string& message)
{
  this->ErrorMessage = message;
  this->BackendName.clear();
  return nullptr;
}

vtkRenderWindow* vtkHighOrderOffscreenWindow::NewRenderWindow(int width, int height)
{
  this->ErrorMessage.clear();
  this->BackendName.clear();
  if (width < 1 || height < 1 || width > GetMaximumSize() || height > GetMaximumSize())
  {
    std::ostringstream s;
    s << "window size " << width << " x " << height << ": each side must be 1.."
      << GetMaximumSize();
    return this->Fail(s.str());
  }
  std::string error;
  const int backend = ResolveBackend(this->Backend, &error);
  if (backend < 0)
  {
    return this->Fail(error);
  }

  // VTK built without X (EGL, OSMesa, Windows, macOS): its own window renders offscreen.
  vtkRenderWindow* probe = vtkRenderWindow::New();
  const bool vtkUsesX = probe->IsA("vtkXOpenGLRenderWindow") != 0;
  if (!vtkUsesX && backend != EGL)
  {
    probe->SetOffScreenRendering(1);
    probe->SetSize(width, height);
    this->BackendName = "vtk";
    return probe;
  }

  if (backend == X11)
  {
    probe->Delete();
    if (!DisplaySet())
    {
      return this->Fail("no X server: DISPLAY is not set (unset HOV_OFFSCREEN or set it to egl "
                        "to render with Mesa EGL)");
    }
    const char* display = std::getenv("DISPLAY");
    if (!CanOpenDisplay(display, this->DisplayTimeout, &error))
    {
      return this->Fail(error +
        "; unset DISPLAY (or set HOV_OFFSCREEN=egl) to render without an X server");
    }
    vtkRenderWindow* window = vtkRenderWindow::New();
    window->SetOffScreenRendering(1);
    window->SetSize(width, height);
    this->BackendName = "x11";
    return window;
  }

  probe->Delete();
#ifndef HOV_HAVE_EGL
  return this->Fail("no OpenGL without X: this module was built without EGL (Debian: libegl-dev)");
#else
  vtkHighOrderEGLRenderWindow* window = vtkHighOrderEGLRenderWindow::New();
  if (!window->InitializeEGL())
  {
    error = window->GetEGLErrorMessage();
    window->Delete();
    return this->Fail("no OpenGL without X: " + error +
      (DisplaySet() ? "" : " (and DISPLAY is not set, so no X server either)"));
  }
  if (width > window->GetMaximumSize() || height > window->GetMaximumSize())
  {
    std::ostringstream s;
    s << "window size " << width << " x " << height << ": this OpenGL context allows at most "
      << window->GetMaximumSize() << " per side";
    window->Delete();
    return this->Fail(s.str());
  }
  window->SetSize(width, height);
  this->BackendName = "egl";
  return window;
#endif
}

//------------------------------------------------------------------------------
void vtkHighOrderOffscreenWindow::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Backend: " << this->Backend << "\n";
  os << indent << "DisplayTimeout: " << this->DisplayTimeout << "\n";
  os << indent << "BackendName: " << this->BackendName << "\n";
  os << indent << "ErrorMessage: " << this->ErrorMessage << "\n";
}
