#include "hovInteractionBudget.h"

#include <algorithm> // std::min, std::max
#include <cmath>     // std::ceil, std::sqrt, std::isfinite

namespace
{
int Clamped(int mode)
{
  return std::min(std::max(mode, 0), 2);
}
}

double hov::InteractionBudget::Estimate(int mode, double pixels) const
{
  const Cost& c = this->Costs[Clamped(mode)];
  return c.Known ? c.Fixed + c.PerRay * pixels : -1.0;
}

double hov::InteractionBudget::FixedSeconds(int mode) const
{
  const Cost& c = this->Costs[Clamped(mode)];
  return c.Known ? c.Fixed : -1.0;
}

hov::InteractionBudget::Choice hov::InteractionBudget::Choose(
  int mode, double budget, int width, int height, int fixed, bool autoAdjust) const
{
  Choice choice;
  const double pixels = static_cast<double>(width) * height;
  choice.Estimate = this->Estimate(mode, pixels);
  if (!autoAdjust || !(budget > 0.0) || !std::isfinite(budget) || pixels <= 1.0)
  {
    return choice;
  }
  const Cost& c = this->Costs[Clamped(mode)];
  if (!c.Known)
  {
    if (budget >= 1.0)
    {
      return choice;
    }
    choice.Interactive = true;
    choice.Subsampling = fixed > 0 ? fixed : 4;
    return choice;
  }
  if (choice.Estimate <= Headroom * budget)
  {
    return choice;
  }
  choice.Interactive = true;
  if (fixed > 0)
  {
    choice.Subsampling = fixed;
    return choice;
  }
  // The headroom's share of the budget, or the whole of it when the fixed
  // part alone exceeds the share (the rays must then fit in what is left).
  const double available =
    Headroom * budget > c.Fixed ? Headroom * budget - c.Fixed : budget - c.Fixed;
  int f = MaximumSubsampling;
  if (available > 0.0)
  {
    const double ratio = std::sqrt(c.PerRay * pixels / available);
    f = ratio < MaximumSubsampling ? static_cast<int>(std::ceil(ratio)) : MaximumSubsampling;
  }
  choice.Subsampling = std::min(std::max(f, 2), MaximumSubsampling);
  return choice;
}

void hov::InteractionBudget::Measure(
  int mode, double seconds, double fixedSeconds, double rays, bool reduced)
{
  if (!(seconds > 0.0) || !std::isfinite(seconds) || !(rays > 0.0))
  {
    return;
  }
  Cost& c = this->Costs[Clamped(mode)];
  if (reduced && c.Known)
  {
    // A few rays say little about the cost per ray (per-cell work of the tile
    // loop dominates): keep the exact frame's, and let the fixed part absorb
    // the difference, so that the next factor adapts to what was measured.
    // Averaged with the previous value: the cost of a few rays varies with
    // the factor, and an undamped fixed part makes f oscillate.
    c.Fixed = 0.5 * (c.Fixed + std::max(0.0, seconds - c.PerRay * rays));
    return;
  }
  c.Fixed = std::min(std::max(fixedSeconds, 0.0), seconds);
  c.PerRay = (seconds - c.Fixed) / rays;
  c.Known = true;
}
