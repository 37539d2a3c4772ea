"""Offscreen render windows that work with an X server and without one.

``offscreen_window(width, height)`` returns a vtkRenderWindow with offscreen rendering on,
made by the module's vtkHighOrderOffscreenWindow: VTK's X window if DISPLAY is set (a desktop
or Xvfb), a Mesa EGL window (vtkHighOrderEGLRenderWindow, no X server needed) if DISPLAY is
unset or empty, or what HOV_OFFSCREEN (auto, x11, egl) or ``backend`` asks for. Every module
tool and helper gets its windows here. Where no window can be made (a DISPLAY naming no X
server, no EGL driver, a size outside 1..16384) it raises OffscreenError with the reason;
Debian's VTK would abort the process instead.

    from highordervolume.offscreen import offscreen_window
    window = offscreen_window(640, 480)
    window.AddRenderer(renderer)
    window.Render()
"""
from .vtkRenderingHighOrderVolume import vtkHighOrderOffscreenWindow

BACKENDS = {"auto": vtkHighOrderOffscreenWindow.AUTOMATIC,
            "x11": vtkHighOrderOffscreenWindow.X11,
            "egl": vtkHighOrderOffscreenWindow.EGL}


class OffscreenError(RuntimeError):
    """No render window could be made (the message says why)."""


def offscreen_window(width, height, backend="auto"):
    """A new offscreen vtkRenderWindow of width x height; OffscreenError if there is none."""
    if backend not in BACKENDS:
        raise OffscreenError("backend '%s': expected one of %s" % (backend, ", ".join(BACKENDS)))
    factory = vtkHighOrderOffscreenWindow()
    factory.SetBackend(BACKENDS[backend])
    window = factory.NewRenderWindow(int(width), int(height))
    if window is None:
        raise OffscreenError("no render window: " + factory.GetErrorMessage())
    return window


def backend_name(window):
    """'egl' for the module's EGL window, 'x11' for VTK's X window, else VTK's class name."""
    name = window.GetClassName()
    return {"vtkHighOrderEGLRenderWindow": "egl", "vtkXOpenGLRenderWindow": "x11"}.get(name, name)
