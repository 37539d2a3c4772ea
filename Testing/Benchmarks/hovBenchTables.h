/**
 * @file hovBenchTables.h
 * @brief The 10-node transfer-function table shared by the kernel benchmarks
 * (colour and opacity nodes at the same 10 scalars in [0, 1], random values,
 * fixed seed), so that their ns-per-segment numbers compare like with like.
 */
#ifndef hovBenchTables_h
#define hovBenchTables_h

#include "hovTransferFunction.h"

#include <random> // fixed-seed node values

namespace hovBench
{
inline hov::TransferFunctionSpec TenNodeSpec(hov::OpacitySemantics semantics)
{
  hov::TransferFunctionSpec spec;
  spec.Semantics = semantics;
  spec.UnitDistance = 0.5;
  std::mt19937_64 rng(777);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  for (int k = 0; k < 10; ++k)
  {
    const double x = k / 9.0;
    spec.Color.push_back({ x, u01(rng), u01(rng), u01(rng) });
    spec.Opacity.push_back({ x, 0.9 * u01(rng) });
  }
  return spec;
}

inline hov::TransferFunction TenNodeTable(hov::OpacitySemantics semantics)
{
  hov::TransferFunction tf;
  tf.Build(TenNodeSpec(semantics));
  return tf;
}
}

#endif
