/**
 * @file hovLagrangeFactors.h
 * @brief Internal (namespace hov::detail): the one-dimensional factors of the
 * Lagrange shape functions of hovLagrangeBasis.h, at one coordinate: the 1D
 * Lagrange polynomials on equispaced nodes (hexahedra, the wedge's t) and
 * Silvester's Eta polynomials (simplices), with derivatives.
 */
#ifndef hovLagrangeFactors_h
#define hovLagrangeFactors_h

#include "hovLagrangeBasis.h" // MaxLagrangeOrder

namespace hov
{
namespace detail
{
/// 1 / prod_{k != j} (j - k) for the 1D Lagrange polynomials of order p
/// (Inverse[p][j]): integer products, one rounding each (compile time).
struct LagrangeDenominators
{
  double Inverse[MaxLagrangeOrder + 1][MaxLagrangeOrder + 1] = {};
  constexpr LagrangeDenominators()
  {
    for (int p = 1; p <= MaxLagrangeOrder; ++p)
    {
      for (int j = 0; j <= p; ++j)
      {
        double denom = 1.0;
        for (int k = 0; k <= p; ++k)
        {
          denom *= k == j ? 1.0 : static_cast<double>(j - k);
        }
        this->Inverse[p][j] = 1.0 / denom;
      }
    }
  }
};
inline constexpr LagrangeDenominators LagrangeInverseDenominators{};

/// 1D Lagrange polynomials of order p on the nodes m/p at x, and derivatives
/// (vtkLagrangeInterpolation::EvaluateShapeAndGradient's values, to rounding:
/// the denominators are applied as precomputed inverses).
struct Lagrange1D
{
  double L[MaxLagrangeOrder + 1];
  double D[MaxLagrangeOrder + 1];
  /// L_j = prod_{k != j} (v - k) / (j - k), v = p x, and (derivatives) L_j' =
  /// p sum_{k != j} prod_{q != j, k} (v - q) / prod_{q != j} (j - q), the inner
  /// products from prefix / suffix products: O(p^2) per direction.
  void Compute(int p, double x, bool derivatives)
  {
    const double v = p * x;
    const double* inverse = LagrangeInverseDenominators.Inverse[p];
    double num[MaxLagrangeOrder + 1], prefix[MaxLagrangeOrder + 2];
    for (int k = 0; k <= p; ++k)
    {
      num[k] = v - k;
    }
    for (int j = 0; j <= p; ++j)
    {
      prefix[0] = 1.0;
      for (int k = 0; k <= p; ++k)
      {
        prefix[k + 1] = prefix[k] * (k == j ? 1.0 : num[k]);
      }
      this->L[j] = prefix[p + 1] * inverse[j];
      double d = 0.0;
      if (derivatives)
      {
        double suffix = 1.0;
        for (int k = p; k >= 0; --k)
        {
          if (k != j)
          {
            d += prefix[k] * suffix;
            suffix *= num[k];
          }
        }
        d *= p * inverse[j];
      }
      this->D[j] = d;
    }
  }
};

/// Silvester's Eta(n, c, x) for c = 0..n and d/dx (vtkHigherOrderTriangle::Eta/Deta,
/// to rounding).
struct Eta1D
{
  double E[MaxLagrangeOrder + 1];
  double D[MaxLagrangeOrder + 1];
  void Compute(int n, double x)
  {
    // 1 / c (c = 1..10) as constants: multiplications instead of divisions
    // (VTK's values to rounding).
    static constexpr double inverse[MaxLagrangeOrder + 1] = { 0.0, 1.0, 1.0 / 2, 1.0 / 3,
      1.0 / 4, 1.0 / 5, 1.0 / 6, 1.0 / 7, 1.0 / 8, 1.0 / 9, 1.0 / 10 };
    this->E[0] = 1.0;
    this->D[0] = 0.0;
    const double v = n * x;
    for (int c = 1; c <= n; ++c)
    {
      const double factor = (v - c + 1.0) * inverse[c];
      this->E[c] = this->E[c - 1] * factor;
      this->D[c] = this->D[c - 1] * factor + this->E[c - 1] * (n * inverse[c]);
    }
  }
};
}
}

#endif
