// Shared by the blend-mode kernel tests (TestBlendModes*.cxx): a random
// transfer-function spec and the raw blend-mode table built from it.
#ifndef hovBlendTestTables_h
#define hovBlendTestTables_h

#include "hovBlendModes.h"
#include "hovTransferFunction.h"

#include <random>

namespace hovtest
{
inline hov::TransferFunctionSpec RandomSpec(std::mt19937_64& rng, int colorNodes, int opacityNodes)
{
  hov::TransferFunctionSpec spec;
  std::vector<double> xc, xo;
  for (int i = 0; i < colorNodes; ++i)
  {
    xc.push_back(hovtest::Uniform(rng, -0.2, 1.2));
  }
  for (int i = 0; i < opacityNodes; ++i)
  {
    xo.push_back(hovtest::Uniform(rng, -0.2, 1.2));
  }
  std::sort(xc.begin(), xc.end());
  std::sort(xo.begin(), xo.end());
  for (double x : xc)
  {
    spec.Color.push_back({ x, hovtest::Uniform(rng, 0, 1), hovtest::Uniform(rng, 0, 1),
      hovtest::Uniform(rng, 0, 1) });
  }
  for (double x : xo)
  {
    spec.Opacity.push_back({ x, hovtest::Uniform(rng, 0, 1) });
  }
  // The blend modes ignore these (BlendModeTableSpec): set to something else.
  spec.Semantics = hov::OpacitySemantics::GPUCompatible;
  spec.UnitDistance = 0.37;
  return spec;
}

inline hov::TransferFunction RawTable(const hov::TransferFunctionSpec& spec)
{
  hov::TransferFunction tf;
  tf.Build(hov::BlendModeTableSpec(spec));
  return tf;
}
}

#endif
