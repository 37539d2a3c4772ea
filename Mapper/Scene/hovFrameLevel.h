/**
 * @file    hovFrameLevel.h
 * @brief   The level of detail of one window frame of vtkHighOrderVolumeMapper
 *          (README, "Interaction"): interactive (the volume's allocated render
 *          time is shorter than the exact frame's measured cost,
 *          hov::InteractionBudget), a progressive level of a slow still frame
 *          (hov::ProgressiveStill), or exact.
 *
 * Reduced frames (f > 1) of CPU_ACCURATE composite per pixel (exact per ray,
 * no visibility sort); those of OPENGL_PROJECTION are drawn by the CPU path
 * when the projection's fixed part alone exceeds the level's budget; those of
 * RAY_CAST by the CPU path when every cell is linear, the ray caster skips
 * none of them and no CPU-only feature is set (its exact rays cost a fraction
 * of the ray caster's), by the ray caster otherwise (curved cells). A
 * progressive level drawn at another factor than it was scheduled at tells
 * hov::ProgressiveStill, whose next level is then finer than the one drawn.
 *
 * Thread safety: rendering thread only.
 * @sa hov::InteractionBudget, hov::ProgressiveStill, hovReducedImage.h
 */
#ifndef hovFrameLevel_h
#define hovFrameLevel_h

class vtkAbstractMapper;
class vtkRenderer;
class vtkVolume;

namespace hov
{
class InteractionBudget;
class ProgressiveStill;
class RenderFrame;

/// The mapper's interaction settings (vtkHighOrderVolumeMapper).
struct LevelSettings
{
  int Mode = 0;        ///< RenderMode (the hov::RenderMode value)
  int Fixed = 0;       ///< InteractiveSubsampling (0: from the budget)
  bool AutoAdjust = true;
  double ProgressiveTime = 0.5;
  /// The previous frame was interactive (only then may a refinement start).
  bool AfterInteraction = false;
  /// RAY_CAST: the ray caster renders every cell of the input (it has been
  /// built for it and skipped none), a condition for its reduced frames to be
  /// drawn by the CPU path.
  bool RayCastEveryCell = false;
};

/**
 * Sets frame.Interactive, frame.Subsampling and, for reduced frames, the
 * settings they change (see the file doc). Returns the render mode whose
 * backend draws the frame and whose cost it measures.
 */
int ChooseFrameLevel(RenderFrame& frame, const LevelSettings& settings,
  const InteractionBudget& budget, ProgressiveStill& progressive, vtkRenderer* renderer,
  vtkVolume* volume, vtkAbstractMapper* mapper);
}

#endif
