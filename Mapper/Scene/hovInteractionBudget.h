/**
 * @class   hov::InteractionBudget
 * @brief   The level of detail of a window frame from the time VTK allocates
 *          to the volume (vtkProp::GetAllocatedRenderTime(): the renderer's
 *          share of 1 / the window's DesiredUpdateRate, 15 frames/s while a
 *          vtkRenderWindowInteractor interacts, 0.0001 for the still frame),
 *          as VTK's own volume mappers decide it
 *          (vtkFixedPointVolumeRayCastMapper::ComputeRequiredImageSampleDistance,
 *          vtkUnstructuredGridVolumeRayCastMapper's AutoAdjustSampleDistances).
 *
 * Each render mode's cost is measured on every completed frame as a fixed
 * part (what does not depend on the number of rays: the cells, the
 * visibility order, the regions of OPENGL_PROJECTION, the display) plus a
 * cost per pixel ray (from exact frames; a reduced frame updates the fixed
 * part, so the next factor follows what the last frame cost). A frame whose
 * estimated exact cost fits Headroom x budget is exact (f = 1, the image of a
 * non-interactive render bit for bit). Otherwise it is an interactive frame:
 * one ray per f x f block of pixels (hovReducedImage.h),
 * f = ceil(sqrt(cost per ray x pixels / (Headroom x budget - fixed))) in
 * [2, 16] (budget - fixed when the fixed part exceeds Headroom x budget; 16
 * when it exceeds the budget), or the fixed factor the user set.
 * Headroom = 0.85: the budget is the volume's, but the window's frame also
 * draws the image, swaps and serves the interactor; aimed at the whole
 * budget, the frames' median landed 3% over it (14.5 fps at DesiredUpdateRate
 * 15, hovBenchHighOrder, T-junction 256x256; 19-21 fps with the headroom).
 * Before any measurement a budget under 1 s gives f = 4 (VTK's "half the
 * maximum").
 *
 * Thread safety: rendering thread only.
 * @sa hovReducedImage.h, vtkHighOrderVolumeMapper (interaction)
 */
#ifndef hovInteractionBudget_h
#define hovInteractionBudget_h

namespace hov
{
class InteractionBudget
{
public:
  /// Largest pixels per ray of an interactive frame chosen from the budget.
  static constexpr int MaximumSubsampling = 16;
  /// The share of the budget an interactive frame's estimate aims at (see class doc).
  static constexpr double Headroom = 0.85;

  struct Choice
  {
    bool Interactive = false; ///< reduced (f > 1) because the exact frame does not fit
    int Subsampling = 1;      ///< pixels per ray in x and y
    double Estimate = -1.0;   ///< estimated seconds of the exact frame (-1: unknown)
  };

  /**
   * The level of a @p width x @p height frame of render mode @p mode in
   * @p budget seconds (<= 0: no budget, exact). @p autoAdjust false: always
   * exact. @p fixed > 0: the interactive frame's factor.
   */
  Choice Choose(int mode, double budget, int width, int height, int fixed, bool autoAdjust) const;

  /// Estimated seconds of the exact frame of @p mode at @p pixels (-1: unknown).
  double Estimate(int mode, double pixels) const;

  /// The measured fixed seconds of @p mode (-1: unknown).
  double FixedSeconds(int mode) const;

  /// A completed frame of @p mode: @p seconds in all, @p fixedSeconds of it
  /// independent of the pixels, @p rays pixel rays; @p reduced (f > 1): only
  /// the fixed part is updated once the cost per ray is known.
  void Measure(int mode, double seconds, double fixedSeconds, double rays, bool reduced);

private:
  struct Cost
  {
    bool Known = false;
    double Fixed = 0.0;
    double PerRay = 0.0;
  };
  Cost Costs[3];
};
}

#endif
