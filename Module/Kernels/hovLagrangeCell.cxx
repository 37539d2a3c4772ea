// Geometry, field and Newton inversion of Lagrange cells: see hovLagrangeCell.h.
#include "hovLagrangeCell.h"

#include <algorithm> // std::max, std::swap
#include <cmath>     // std::abs, std::isfinite, std::sqrt
#include <limits>    // epsilon, infinity

namespace hov
{
namespace
{
constexpr double Eps = std::numeric_limits<double>::epsilon();
/// |F| at most this many eps x extent is the rounding floor of x(pc) - x.
constexpr double ResidualFloorUlps = 64.0;
/// Backtracking halvings per Newton step.
constexpr int MaxHalvings = 12;
/// Steps (max norm, parametric) short enough to try ending the run with a
/// chord step: quadratic convergence then leaves ~|step|^2 to correct, below
/// the step tolerance for well-shaped maps; otherwise the evaluation without
/// the Jacobian was spent for nothing (and the run goes on as Newton's).
constexpr double ChordRange = 1e-6;

double NormInf(const double v[3])
{
  return std::max(std::max(std::abs(v[0]), std::abs(v[1])), std::abs(v[2]));
}

double Norm2(const double v[3])
{
  return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
}

bool AllFinite(const double* v, int n)
{
  for (int i = 0; i < n; ++i)
  {
    if (!std::isfinite(v[i]))
    {
      return false;
    }
  }
  return true;
}

/// Residual F = x(pc) - target and its 2-norm.
double Residual(const LagrangeCellView& cell, const double pc[3], const double target[3],
  double F[3], double* J)
{
  double x[3];
  EvaluateLagrangePosition(cell, pc, x, J);
  for (int i = 0; i < 3; ++i)
  {
    F[i] = x[i] - target[i];
  }
  return Norm2(F);
}

/// One Newton run from @p pc; returns the status, @p pc the last iterate.
InversionStatus NewtonRun(const LagrangeCellView& cell, const double target[3], double extent,
  const LagrangeInversionSettings& s, double pc[3], LagrangeInversionResult& result)
{
  double F[3], J[9];
  double fNorm = Residual(cell, pc, target, F, J);
  const double floor = ResidualFloorUlps * Eps * extent;
  result.Residual = fNorm / extent;
  for (int iter = 0; iter < s.MaxIterations; ++iter)
  {
    ++result.Iterations;
    double step[3];
    const double minusF[3] = { -F[0], -F[1], -F[2] };
    if (!Solve3x3(J, minusF, step, s.SingularTolerance))
    {
      // A point where the map is singular (a collapsed vertex, such as a
      // pyramid's apex as a degenerate hexahedron) that already maps to the
      // target to rounding is a solution: no step can improve it.
      std::copy(J, J + 9, result.Jacobian);
      return fNorm <= floor && iter > 0 ? InversionStatus::Converged
                                        : InversionStatus::SingularJacobian;
    }
    const double length = NormInf(step);
    // Converged: the step from here is below the tolerance. It is taken
    // without evaluating the map at its end (the point is the one an
    // evaluated step would give; that evaluation could only confirm it).
    if (length <= s.StepTolerance || (fNorm <= floor && length <= s.FloorStepTolerance))
    {
      for (int k = 0; k < 3; ++k)
      {
        pc[k] += step[k];
      }
      result.LastStep = length;
      std::copy(J, J + 9, result.Jacobian);
      return AllFinite(pc, 3) && cell.Basis->DistanceOutside(pc) <= s.AbandonOutside
        ? InversionStatus::Converged
        : InversionStatus::NoConvergence;
    }
    if (!(length <= s.MaxStep))
    {
      const double scale = std::isfinite(length) ? s.MaxStep / length : 0.0;
      for (double& v : step)
      {
        v *= scale;
      }
    }
    // A short full step near the solution: the map alone at its end (no
    // Jacobian, a fraction of the cost) and the chord step with the current
    // Jacobian; if that is below the tolerance it is taken and the run has
    // converged (the chord step differs from Newton's by ~|step| times it).
    if (length <= ChordRange && AllFinite(step, 3))
    {
      double trial[3], Ft[3];
      for (int k = 0; k < 3; ++k)
      {
        trial[k] = pc[k] + step[k];
      }
      const double ftNorm = Residual(cell, trial, target, Ft, nullptr);
      double chord[3];
      const double minusFt[3] = { -Ft[0], -Ft[1], -Ft[2] };
      if ((ftNorm < fNorm || fNorm <= floor) && Solve3x3(J, minusFt, chord, s.SingularTolerance) &&
        NormInf(chord) <= s.StepTolerance)
      {
        for (int k = 0; k < 3; ++k)
        {
          pc[k] = trial[k] + chord[k];
        }
        result.LastStep = NormInf(chord);
        result.Residual = ftNorm / extent;
        std::copy(J, J + 9, result.Jacobian);
        return AllFinite(pc, 3) && cell.Basis->DistanceOutside(pc) <= s.AbandonOutside
          ? InversionStatus::Converged
          : InversionStatus::NoConvergence;
      }
    }
    // Backtracking: halve until |F| decreases (or give up and take the smallest).
    double lambda = 1.0, used = 1.0, trial[3], Ft[3], Jt[9], ftNorm = 0.0;
    for (int h = 0; h <= MaxHalvings; ++h, lambda *= 0.5)
    {
      used = lambda;
      for (int k = 0; k < 3; ++k)
      {
        trial[k] = pc[k] + lambda * step[k];
      }
      ftNorm = Residual(cell, trial, target, Ft, Jt);
      if (ftNorm < fNorm || fNorm <= floor)
      {
        break;
      }
    }
    if (!(ftNorm < fNorm) && !(fNorm <= floor))
    {
      return InversionStatus::NoConvergence; // a local minimum of |F|: hopeless start
    }
    const double taken = used * NormInf(step);
    std::copy(trial, trial + 3, pc);
    std::copy(Ft, Ft + 3, F);
    std::copy(Jt, Jt + 9, J);
    fNorm = ftNorm;
    result.LastStep = taken;
    result.Residual = fNorm / extent;
    if (!AllFinite(pc, 3) || !(cell.Basis->DistanceOutside(pc) <= s.AbandonOutside))
    {
      return InversionStatus::NoConvergence;
    }
    // A damped step may be short without being near a solution: only full
    // steps count for the step criterion.
    if ((used == 1.0 && taken <= s.StepTolerance) ||
      (fNorm <= floor && taken <= s.FloorStepTolerance))
    {
      std::copy(J, J + 9, result.Jacobian);
      return InversionStatus::Converged;
    }
  }
  return InversionStatus::NoConvergence;
}
}

namespace
{
/// The trilinear map of the hexahedron corners @p X (VTK order) and its Jacobian.
void TrilinearPosition(const double* X, const double pc[3], double x[3], double* jacobian)
{
  const double r = pc[0], s = pc[1], t = pc[2], r1 = 1.0 - r, s1 = 1.0 - s, t1 = 1.0 - t;
  const double w[8] = { r1 * s1 * t1, r * s1 * t1, r * s * t1, r1 * s * t1, r1 * s1 * t, r * s1 * t,
    r * s * t, r1 * s * t };
  for (int i = 0; i < 3; ++i)
  {
    double v = 0.0;
    for (int k = 0; k < 8; ++k)
    {
      v += w[k] * X[3 * k + i];
    }
    x[i] = v;
  }
  if (!jacobian)
  {
    return;
  }
  const double wr[8] = { -s1 * t1, s1 * t1, s * t1, -s * t1, -s1 * t, s1 * t, s * t, -s * t };
  const double ws[8] = { -r1 * t1, -r * t1, r * t1, r1 * t1, -r1 * t, -r * t, r * t, r1 * t };
  const double wt[8] = { -r1 * s1, -r * s1, -r * s, -r1 * s, r1 * s1, r * s1, r * s, r1 * s };
  for (int i = 0; i < 3; ++i)
  {
    double a = 0.0, b = 0.0, c = 0.0;
    for (int k = 0; k < 8; ++k)
    {
      a += wr[k] * X[3 * k + i];
      b += ws[k] * X[3 * k + i];
      c += wt[k] * X[3 * k + i];
    }
    jacobian[3 * i] = a;
    jacobian[3 * i + 1] = b;
    jacobian[3 * i + 2] = c;
  }
}
}

void EvaluateLagrangePosition(
  const LagrangeCellView& cell, const double pc[3], double x[3], double* jacobian)
{
  if (cell.Trilinear)
  {
    TrilinearPosition(cell.Points, pc, x, jacobian);
    return;
  }
  cell.Basis->Interpolate(pc, cell.Points, 3, x, jacobian);
}

bool IsLagrangeGeometryTrilinear(const LagrangeCellView& cell, double relativeTolerance)
{
  if (!cell.Basis || !cell.Basis->IsInitialized() || !cell.Points ||
    cell.Basis->GetShape() != LagrangeShape::Hexahedron || cell.Basis->GetNodeCount() < 8)
  {
    return false;
  }
  const double tol = relativeTolerance * LagrangeCellExtent(cell);
  if (!(tol > 0.0))
  {
    return false;
  }
  for (int n = 0; n < cell.Basis->GetNodeCount(); ++n)
  {
    double pc[3], x[3];
    cell.Basis->NodeParametricCoords(n, pc);
    TrilinearPosition(cell.Points, pc, x, nullptr);
    for (int i = 0; i < 3; ++i)
    {
      if (!(std::abs(x[i] - cell.Points[3 * n + i]) <= tol))
      {
        return false;
      }
    }
  }
  return true;
}

double EvaluateLagrangeScalar(const LagrangeCellView& cell, const double pc[3], double* gradient)
{
  double f = 0.0;
  cell.Basis->Interpolate(pc, cell.Scalars, 1, &f, gradient);
  return f;
}

double LagrangeCellExtent(const LagrangeCellView& cell)
{
  const int n = cell.Basis->GetNodeCount();
  double lo[3], hi[3];
  for (int k = 0; k < 3; ++k)
  {
    lo[k] = hi[k] = cell.Points[k];
  }
  for (int i = 1; i < n; ++i)
  {
    for (int k = 0; k < 3; ++k)
    {
      lo[k] = std::min(lo[k], cell.Points[3 * i + k]);
      hi[k] = std::max(hi[k], cell.Points[3 * i + k]);
    }
  }
  const double d[3] = { hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2] };
  return Norm2(d);
}

bool IsLagrangeGeometryAffine(
  const LagrangeCellView& cell, double relativeTolerance, double* affine)
{
  const LagrangeBasis& basis = *cell.Basis;
  // Corners at pc = e_r, e_s, e_t.
  const int axes[3] = { 1, basis.GetShape() == LagrangeShape::Hexahedron ? 3 : 2,
    basis.GetShape() == LagrangeShape::Hexahedron ? 4 : 3 };
  double map[12];
  for (int i = 0; i < 3; ++i)
  {
    map[i] = cell.Points[i];
    for (int j = 0; j < 3; ++j)
    {
      map[3 + 3 * j + i] = cell.Points[3 * axes[j] + i] - cell.Points[i];
    }
  }
  if (affine)
  {
    std::copy(map, map + 12, affine);
  }
  const double tol = relativeTolerance * LagrangeCellExtent(cell);
  for (int n = 0; n < basis.GetNodeCount(); ++n)
  {
    double pc[3];
    basis.NodeParametricCoords(n, pc);
    for (int i = 0; i < 3; ++i)
    {
      const double x = map[i] + map[3 + i] * pc[0] + map[6 + i] * pc[1] + map[9 + i] * pc[2];
      if (!(std::abs(x - cell.Points[3 * n + i]) <= tol))
      {
        return false;
      }
    }
  }
  return true;
}

const char* InversionStatusName(InversionStatus status)
{
  switch (status)
  {
    case InversionStatus::Converged:
      return "converged";
    case InversionStatus::NoConvergence:
      return "Newton did not converge from any start";
    case InversionStatus::SingularJacobian:
      return "the geometry map's Jacobian is singular (degenerate or inverted cell)";
    default:
      return "invalid input (no basis, or non-finite coordinates)";
  }
}

bool Solve3x3(const double J[9], const double b[3], double d[3], double relTol)
{
  double a[3][4];
  double colNorm[3] = { 0.0, 0.0, 0.0 };
  for (int i = 0; i < 3; ++i)
  {
    for (int j = 0; j < 3; ++j)
    {
      a[i][j] = J[3 * i + j];
      colNorm[j] += a[i][j] * a[i][j];
    }
    a[i][3] = b[i];
  }
  double det = 1.0;
  for (int c = 0; c < 3; ++c)
  {
    int pivot = c;
    for (int r = c + 1; r < 3; ++r)
    {
      pivot = std::abs(a[r][c]) > std::abs(a[pivot][c]) ? r : pivot;
    }
    if (pivot != c)
    {
      std::swap(a[pivot], a[c]);
      det = -det;
    }
    det *= a[c][c];
    if (a[c][c] == 0.0)
    {
      return false;
    }
    for (int r = c + 1; r < 3; ++r)
    {
      const double f = a[r][c] / a[c][c];
      for (int k = c; k < 4; ++k)
      {
        a[r][k] -= f * a[c][k];
      }
    }
  }
  const double scale = std::sqrt(colNorm[0] * colNorm[1] * colNorm[2]);
  if (!(std::abs(det) > relTol * scale))
  {
    return false;
  }
  for (int r = 2; r >= 0; --r)
  {
    double s = a[r][3];
    for (int k = r + 1; k < 3; ++k)
    {
      s -= a[r][k] * d[k];
    }
    d[r] = s / a[r][r];
  }
  return AllFinite(d, 3);
}

LagrangeInversionResult InvertLagrangeGeometry(const LagrangeCellView& cell, const double x[3],
  double pc[3], const LagrangeInversionSettings& settings)
{
  LagrangeInversionResult result;
  const bool known = cell.Extent > 0.0; // the caller vouches for finite points
  if (!cell.Basis || !cell.Basis->IsInitialized() || !cell.Points || !AllFinite(x, 3) ||
    (!known && !AllFinite(cell.Points, 3 * cell.Basis->GetNodeCount())))
  {
    double c[3] = { 0.5, 0.5, 0.5 };
    if (cell.Basis)
    {
      cell.Basis->ParametricCenter(c);
    }
    std::copy(c, c + 3, pc);
    return result; // InvalidInput
  }
  const double extent = known ? cell.Extent
                              : std::max(LagrangeCellExtent(cell), std::numeric_limits<double>::min());
  // Starts, in turn until one converges: the guess, the centre, then the grid
  // points inside the domain (made only if the first two fail: a warm start
  // almost always converges).
  static constexpr double grid[3] = { 0.2, 0.5, 0.8 };
  const bool guess = AllFinite(pc, 3);
  const int count = (guess ? 1 : 0) + 1 + (settings.UseStartGrid ? 27 : 0);
  InversionStatus status = InversionStatus::NoConvergence;
  double best[3] = { 0.0, 0.0, 0.0 };
  double bestResidual = std::numeric_limits<double>::infinity();
  bool allSingular = true, haveBest = false;
  const double initial[3] = { pc[0], pc[1], pc[2] };
  for (int k = 0; k < count; ++k)
  {
    double p[3];
    const int g = k - (guess ? 2 : 1); // grid index
    if (guess && k == 0)
    {
      std::copy(initial, initial + 3, p);
    }
    else if (g < 0)
    {
      cell.Basis->ParametricCenter(p);
    }
    else
    {
      p[0] = grid[g % 3];
      p[1] = grid[(g / 3) % 3];
      p[2] = grid[g / 9];
      if (!(cell.Basis->DistanceOutside(p) <= 0.0))
      {
        continue;
      }
    }
    if (!haveBest)
    {
      std::copy(p, p + 3, best); // the first start, if nothing better is found
      haveBest = true;
    }
    ++result.Starts;
    status = NewtonRun(cell, x, extent, settings, p, result);
    if (status == InversionStatus::Converged)
    {
      std::copy(p, p + 3, pc);
      result.Status = status;
      return result;
    }
    allSingular = allSingular && status == InversionStatus::SingularJacobian;
    if (result.Residual < bestResidual && AllFinite(p, 3))
    {
      bestResidual = result.Residual;
      std::copy(p, p + 3, best);
    }
  }
  std::copy(best, best + 3, pc);
  result.Residual = bestResidual;
  result.Status = allSingular ? InversionStatus::SingularJacobian : InversionStatus::NoConvergence;
  return result;
}
}
