/**
 * @file hovRoundingScope.h
 * @brief For the kernel tests: the thin series' rounding (hovThinSeries.h:
 * FusedSeries, SetFusedSeries) set for a scope and restored after it.
 */
#ifndef hovRoundingScope_h
#define hovRoundingScope_h

#include "hovThinSeries.h" // FusedSeries, SetFusedSeries

namespace hovtest
{
/// Rounds the kernels' thin series as asked (hov::detail::SetFusedSeries)
/// while in scope, then restores the process's setting. Active: whether the
/// requested rounding is in force (fused needs the CPU's FMA).
class RoundingScope
{
public:
  explicit RoundingScope(bool fused)
    : Saved(hov::detail::FusedSeries())
    , Active(hov::detail::SetFusedSeries(fused) == fused)
  {
  }
  ~RoundingScope() { hov::detail::SetFusedSeries(this->Saved); }
  RoundingScope(const RoundingScope&) = delete;
  RoundingScope& operator=(const RoundingScope&) = delete;

private:
  const bool Saved;

public:
  const bool Active;
};

}

#endif
