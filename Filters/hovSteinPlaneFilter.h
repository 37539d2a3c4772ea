/**
 * @file hovSteinPlaneFilter.h
 * @brief A precomputed floating-point filter for the exact side of the eye with
 *        respect to a fixed triangle plane (vtkSteinVisibilitySort, per view and
 *        exact boundary face).
 *
 * hov::Orient3d(a, b, c, e) is the sign of det[a-e; b-e; c-e] = n.(a - e) with
 * n = (b - a) x (c - a) exactly, and hov::Orient3dDirection(a, b, c, w) is the
 * sign of -n.w. The triangle is fixed and only the eye moves, so n and
 * D = n.a are rounded once (FilteredPlane::Set) and a view needs
 * S = N.e - D (perspective) or S = N.w (parallel): Side() returns -sign(S),
 * the predicate's value, when |S| exceeds a bound on its rounding error, and 0
 * ("not decided": call the exact predicate) otherwise.
 *
 * Error bound (u = 2^-53, standard model; FMA contraction only lowers the
 * errors): each component of the rounded normal N differs from n by at most
 * 4.1 u P_k, P_k = |(b-a)_y (c-a)_z| + |(b-a)_z (c-a)_y| (cyclically); the
 * dot products and D add at most 3.1 u sum |N_k| (|e_k| + |a_k|). So with
 * Q_k = P_k + |N_k| and R = sum Q_k |a_k| (both rounded up to float),
 * |S - n.(e - a)| <= 4.1 u (sum Q_k |e_k| + R) + u |S|. Side() decides when
 * |S| (1 - 4u) > 8 u (sum Q_k |e_k| + R) (twice the bound, for the rounding of
 * the bound itself) and |S| > 1e-280 (no underflow), else it returns 0; NaN and
 * infinities also give 0. Parallel projection: w instead of e, no D and R.
 *
 * Thread safety: plain data; Side() is pure.
 */
#ifndef hovSteinPlaneFilter_h
#define hovSteinPlaneFilter_h

#include "hovSteinRounding.h" // FloatUp

#include <cmath> // std::fabs

namespace hovStein
{
struct FilteredPlane
{
  double N[3]; ///< rounded (b - a) x (c - a)
  double D;    ///< rounded N.a
  float Q[3];  ///< error weights per axis (rounded up)
  float R;     ///< sum Q_k |a_k| (rounded up)

  /// The plane of the triangle (a, b, c).
  void Set(const double* a, const double* b, const double* c)
  {
    const double u[3] = { b[0] - a[0], b[1] - a[1], b[2] - a[2] };
    const double v[3] = { c[0] - a[0], c[1] - a[1], c[2] - a[2] };
    double r = 0;
    for (int k = 0; k < 3; ++k)
    {
      const int i = (k + 1) % 3, j = (k + 2) % 3;
      const double p1 = u[i] * v[j], p2 = u[j] * v[i];
      this->N[k] = p1 - p2;
      const double q = std::fabs(p1) + std::fabs(p2) + std::fabs(this->N[k]);
      this->Q[k] = FloatUp(q * (1 + 1e-12));
      r += static_cast<double>(this->Q[k]) * std::fabs(a[k]);
    }
    this->D = this->N[0] * a[0] + this->N[1] * a[1] + this->N[2] * a[2];
    this->R = FloatUp(r * (1 + 1e-12));
  }

  /**
   * hov::Orient3d(a, b, c, eye) (perspective) or
   * hov::Orient3dDirection(a, b, c, -dop) (parallel; @p x = -dop) when the
   * filter decides, else 0.
   */
  int Side(const double* x, bool parallel) const
  {
    constexpr double u = 1.1102230246251565e-16; // 2^-53
    const double s = this->N[0] * x[0] + this->N[1] * x[1] + this->N[2] * x[2] - (parallel ? 0.0 : this->D);
    const double weight = this->Q[0] * std::fabs(x[0]) + this->Q[1] * std::fabs(x[1]) +
      this->Q[2] * std::fabs(x[2]) + (parallel ? 0.0 : static_cast<double>(this->R));
    const double magnitude = std::fabs(s);
    const bool decided = magnitude * (1 - 4 * u) > 8 * u * weight && magnitude > 1e-280;
    // -sign(s) without a branch (the sign is a coin flip); 0 when not decided
    // (also for NaN and infinities).
    return decided ? static_cast<int>(s < 0) - static_cast<int>(s > 0) : 0;
  }
};
}

#endif
