/**
 * @class   hov::Backend
 * @brief   One render mode of vtkHighOrderVolumeMapper: what the facade hands
 *          a frame to. One implementation per mode: hov::ProjectorBackend
 *          (CPU_ACCURATE, Mapper/Projector), hov::ProjectionBackend
 *          (OPENGL_PROJECTION, Mapper/OpenGL), hov::RayCastBackend (RAY_CAST,
 *          Mapper/RayCast); the facade chooses one in one place
 *          (vtkHighOrderVolumeMapper::SelectBackend).
 *
 * An image backend (DrawsIntoWindow() false) computes the frame's image in
 * double precision (RenderFrame::RGBA) and the facade publishes it as the
 * float image and, in a window, blits it over the scene. A window backend
 * (OPENGL_PROJECTION) draws into the renderer's window itself and writes the
 * float image it read back (the facade only checks it).
 *
 * Thread safety: rendering thread only.
 * @sa hov::RenderFrame, vtkHighOrderVolumeMapper
 */
#ifndef hovBackend_h
#define hovBackend_h

class vtkImageData;
class vtkWindow;

namespace hov
{
class RenderFrame;

/**
 * The most nodes the GPU-compatible refinement may add to the table of a
 * CPU_ACCURATE frame with non-tetrahedral cells, whose segments take each
 * table node they cross as a breakpoint to locate and integrate to (~1 us per
 * node against ~30 ns for a tetrahedron's closed form; RAY_CAST: below). Opacity 1
 * at a node is a log singularity of the extinction: GPUOpacityTolerance 1e-8
 * there asks for 10^5 nodes or more (hovRobustness case 22000865: 265,956
 * nodes, a 33x33 frame of 70 quadratic cells took 91 s). The table stops at
 * the budget and says so, with its worst error.
 */
constexpr int QuadratureTableBudget = 16384;

/**
 * The same budget for RAY_CAST, whose curved pieces cost several times more
 * per node crossed (the crossing is isolated on a degree-16 piece, polished
 * by Newton on the exact field, and each sub-piece fitted): hovRobustness case
 * 22002649 (48x48, 74 cells, a magnitude field crossing 9,500 of 16,384
 * nodes per segment) took over 120 s with 16,384 nodes and 40 s with 4,096.
 * The table's tolerance there is max(GPUOpacityTolerance, RayCastTolerance /
 * 10): only both set far below their defaults (1e-4, 1e-3), with a sharp
 * table, reach it.
 */
constexpr int RayCastTableBudget = 4096;

class Backend
{
public:
  virtual ~Backend() = default;

  /**
   * Render @p frame (see the class doc): 1 on success, also for an image that
   * is empty for a reason of the scene (RenderFrame::Drawn then tells whether
   * visible cells were drawn); 0 on error (reported through the frame).
   * @p floatImage: the window backend's float image (image backends leave it).
   */
  virtual int Render(RenderFrame& frame, vtkImageData* floatImage) = 0;

  /// True if the backend draws into the renderer's window itself.
  virtual bool DrawsIntoWindow() const { return false; }

  virtual void ReleaseGraphicsResources(vtkWindow*) {}
};
}

#endif
