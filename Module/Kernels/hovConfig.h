/**
 * @file hovConfig.h
 * @brief Export macro and shared constants of the hov numeric kernels.
 *
 * The kernels (namespace hov) are plain C++ with no VTK and no OpenGL. They are
 * compiled once into an object library that is linked into the VTK module
 * vtkRenderingHighOrderVolume and into the GoogleTest kernel tests.
 */
#ifndef hovConfig_h
#define hovConfig_h

#if defined(_WIN32)
#if defined(HOV_BUILDING_KERNELS)
#define HOV_EXPORT __declspec(dllexport)
#else
#define HOV_EXPORT __declspec(dllimport)
#endif
#else
#define HOV_EXPORT __attribute__((visibility("default")))
#endif

#endif
