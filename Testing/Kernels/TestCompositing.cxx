// Tests of hovCompositing: premultiplied RGBA and the Porter-Duff "over".

#include "hovCompositing.h"

#include "hovKernelTestReference.h"
#include "hovKernelTestTolerances.h"
#include "hovKernelTestUtilities.h"

#include <gtest/gtest.h>

#include <random>

using hovtest::Tolerances;
using hovtest::Worst;

namespace
{
/// A random premultiplied colour: opacity in [0,1], colour in [0, opacity].
hov::RGBA RandomPremultiplied(std::mt19937_64& rng)
{
  hov::RGBA c;
  c.A = hovtest::Uniform(rng, 0, 1);
  c.R = c.A * hovtest::Uniform(rng, 0, 1);
  c.G = c.A * hovtest::Uniform(rng, 0, 1);
  c.B = c.A * hovtest::Uniform(rng, 0, 1);
  return c;
}
}

TEST(Compositing, OverFormula)
{
  // C = Cf + (1 - Af) Cb, per channel, alpha included.
  const hov::RGBA f{ 0.1, 0.2, 0.3, 0.4 };
  const hov::RGBA b{ 0.5, 0.25, 0.125, 0.75 };
  const hov::RGBA o = hov::Over(f, b);
  EXPECT_DOUBLE_EQ(o.R, 0.1 + 0.6 * 0.5);
  EXPECT_DOUBLE_EQ(o.G, 0.2 + 0.6 * 0.25);
  EXPECT_DOUBLE_EQ(o.B, 0.3 + 0.6 * 0.125);
  EXPECT_DOUBLE_EQ(o.A, 0.4 + 0.6 * 0.75);
  // Not commutative.
  const hov::RGBA r = hov::Over(b, f);
  EXPECT_GT(hovtest::MaxAbsDiff(o, r), 0.01);
}

TEST(Compositing, Identity)
{
  std::mt19937_64 rng(1);
  const hov::RGBA clear{};
  EXPECT_EQ(clear.R, 0.0);
  EXPECT_EQ(clear.A, 0.0);
  for (int i = 0; i < 1000; ++i)
  {
    const hov::RGBA x = RandomPremultiplied(rng);
    SCOPED_TRACE(hovtest::ToString(x));
    // Transparent black is a two-sided identity, exactly.
    const hov::RGBA l = hov::Over(clear, x);
    const hov::RGBA r = hov::Over(x, clear);
    EXPECT_EQ(hovtest::MaxAbsDiff(l, x), 0.0);
    EXPECT_EQ(hovtest::MaxAbsDiff(r, x), 0.0);
    // An opaque front hides the back entirely.
    hov::RGBA opaque = x;
    opaque.A = 1.0;
    const hov::RGBA h = hov::Over(opaque, RandomPremultiplied(rng));
    EXPECT_EQ(hovtest::MaxAbsDiff(h, opaque), 0.0);
  }
}

TEST(Compositing, Associativity)
{
  std::mt19937_64 rng(2);
  Worst worst;
  for (int i = 0; i < 100000; ++i)
  {
    const hov::RGBA a = RandomPremultiplied(rng), b = RandomPremultiplied(rng), c = RandomPremultiplied(rng);
    const hov::RGBA l = hov::Over(hov::Over(a, b), c);
    const hov::RGBA r = hov::Over(a, hov::Over(b, c));
    const double e = hovtest::MaxAbsDiff(l, r);
    if (e > worst.Value)
    {
      worst.Add(e, hovtest::ToString(a) + " " + hovtest::ToString(b) + " " + hovtest::ToString(c));
    }
    EXPECT_LE(e, Tolerances.OverAssocAbs) << hovtest::ToString(a) << " " << hovtest::ToString(b) << " "
                                          << hovtest::ToString(c);
  }
  hovtest::ReportMeasured("Over associativity (absolute)", worst);
}

TEST(Compositing, AccumulationOrders)
{
  // Front-to-back with CompositeBehind and back-to-front with CompositeInFront
  // give the same result, both equal to the explicit Over chain, and the
  // result stays a valid premultiplied colour.
  std::mt19937_64 rng(3);
  Worst worst;
  for (int trial = 0; trial < 2000; ++trial)
  {
    std::vector<hov::RGBA> layers(1 + trial % 20);
    for (auto& l : layers)
    {
      l = RandomPremultiplied(rng);
    }
    hov::RGBA f2b{}, b2f{};
    for (const auto& l : layers)
    {
      hov::CompositeBehind(f2b, l);
    }
    for (auto it = layers.rbegin(); it != layers.rend(); ++it)
    {
      hov::CompositeInFront(b2f, *it);
    }
    hov::RGBA chain = layers.back();
    for (int k = static_cast<int>(layers.size()) - 2; k >= 0; --k)
    {
      chain = hov::Over(layers[k], chain);
    }
    EXPECT_EQ(hovtest::MaxAbsDiff(b2f, chain), 0.0);
    const double e = hovtest::MaxAbsDiff(f2b, b2f);
    worst.Add(e, std::to_string(layers.size()) + " layers");
    EXPECT_LE(e, layers.size() * Tolerances.OverAssocAbs);
    // Transmittance of the stack is the product of the layers' transmittances.
    double t = 1.0;
    for (const auto& l : layers)
    {
      t *= 1.0 - l.A;
    }
    EXPECT_NEAR(1.0 - f2b.A, t, layers.size() * Tolerances.OverAssocAbs);
    EXPECT_LE(f2b.A, 1.0);
    EXPECT_LE(f2b.R, f2b.A + Tolerances.FewUlpAbs);
  }
  hovtest::ReportMeasured("front-to-back vs back-to-front (absolute)", worst);
}
