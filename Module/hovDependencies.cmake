# Third-party dependencies of the module, found the same way in both builds
# (standalone, and as a module directory inside another project's
# vtk_module_build, e.g. VTK's Remote/ modules). Cache variables and targets
# used by Module/Kernels and Module.

# libcerf (Dawson, erfcx) for the exact segment integral.
find_path(CERF_INCLUDE_DIR cerf.h REQUIRED)
find_library(CERF_LIBRARY cerf REQUIRED)
if (NOT TARGET hov_cerf)
  add_library(hov_cerf INTERFACE)
  target_include_directories(hov_cerf INTERFACE "${CERF_INCLUDE_DIR}")
  target_link_libraries(hov_cerf INTERFACE "${CERF_LIBRARY}")
endif ()

# GLM (header only) for small vector math in the renderers.
find_path(GLM_INCLUDE_DIR glm/glm.hpp REQUIRED)

# EGL (Debian: libegl-dev) for vtkHighOrderEGLRenderWindow, the render window
# that needs no X server; Xlib for the DISPLAY check of
# vtkHighOrderOffscreenWindow. Both optional: without EGL the module has no
# X-less window (vtkHighOrderOffscreenWindow then says so), without X11 DISPLAY
# is not checked (VTK builds without X need neither).
find_package(OpenGL COMPONENTS EGL)
find_package(X11)
