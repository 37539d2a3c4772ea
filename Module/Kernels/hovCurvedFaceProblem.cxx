// The ray problem on one curved face: see hovCurvedFaceProblem.h.
#include "hovCurvedFaceProblem.h"

#include "hovCurvedFaceNets.h"     // RangeOf
#include "hovCurvedTriangleNets.h" // EvaluateTriangleNet

#include <algorithm> // std::copy, std::max
#include <cmath>     // std::abs, std::sqrt
#include <limits>    // epsilon

namespace hov
{
namespace detail
{
namespace
{
constexpr double Eps = std::numeric_limits<double>::epsilon();

/// The Bernstein basis of degree @p n at @p t and its derivatives.
void BernsteinBasis(int n, double t, double* b, double* db)
{
  const double s = 1.0 - t;
  b[0] = 1.0;
  for (int k = 1; k <= n; ++k)
  {
    if (k == n)
    {
      // Derivatives from the degree n - 1 values: n (B_{i-1} - B_i).
      for (int i = 0; i <= n; ++i)
      {
        db[i] = n * ((i > 0 ? b[i - 1] : 0.0) - (i < n ? b[i] : 0.0));
      }
    }
    b[k] = t * b[k - 1];
    for (int i = k - 1; i > 0; --i)
    {
      b[i] = s * b[i] + t * b[i - 1];
    }
    b[0] *= s;
  }
  if (n == 0)
  {
    db[0] = 0.0;
  }
}

/// x, x_u, x_v of a tensor net (row a along u, DegreeV + 1 points per row).
void EvaluateTensorNet(const CurvedFacePatch& f, double u, double v, double x[3], double xu[3],
  double xv[3])
{
  const int du = f.DegreeU, dv = f.DegreeV, nv = dv + 1;
  double bu[MaxFaceDegree + 1], dbu[MaxFaceDegree + 1], bv[MaxFaceDegree + 1],
    dbv[MaxFaceDegree + 1];
  BernsteinBasis(du, u, bu, dbu);
  BernsteinBasis(dv, v, bv, dbv);
  for (int i = 0; i < 3; ++i)
  {
    x[i] = xu[i] = xv[i] = 0.0;
  }
  const double* net = f.Net.data();
  for (int a = 0; a <= du; ++a)
  {
    double r[3] = { 0.0, 0.0, 0.0 }, rv[3] = { 0.0, 0.0, 0.0 };
    for (int b = 0; b <= dv; ++b)
    {
      const double* q = net + 3 * (nv * a + b);
      for (int i = 0; i < 3; ++i)
      {
        r[i] += bv[b] * q[i];
        rv[i] += dbv[b] * q[i];
      }
    }
    for (int i = 0; i < 3; ++i)
    {
      x[i] += bu[a] * r[i];
      xu[i] += dbu[a] * r[i];
      xv[i] += bu[a] * rv[i];
    }
  }
}
}

/// The ray's frame: unit e1, e2 perpendicular to d.
void RayFrame(const double d[3], double e1[3], double e2[3])
{
  const double len = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
  const double n[3] = { d[0] / len, d[1] / len, d[2] / len };
  // e1 perpendicular to n, built from the axis of n's smallest component.
  int k = 0;
  for (int i = 1; i < 3; ++i)
  {
    k = std::abs(n[i]) < std::abs(n[k]) ? i : k;
  }
  double a[3] = { 0.0, 0.0, 0.0 };
  a[k] = 1.0;
  e1[0] = a[1] * n[2] - a[2] * n[1];
  e1[1] = a[2] * n[0] - a[0] * n[2];
  e1[2] = a[0] * n[1] - a[1] * n[0];
  const double l1 = std::sqrt(e1[0] * e1[0] + e1[1] * e1[1] + e1[2] * e1[2]);
  for (int i = 0; i < 3; ++i)
  {
    e1[i] /= l1;
  }
  e2[0] = n[1] * e1[2] - n[2] * e1[1];
  e2[1] = n[2] * e1[0] - n[0] * e1[2];
  e2[2] = n[0] * e1[1] - n[1] * e1[0];
}

void FaceProblem::Evaluate(double u, double v, double h[2], double jac[4], double x[3],
  double pc[3], double* normal) const
{
  double pu[3], pv[3], J[9];
  FaceParametricPoint(*this->Face, u, v, pc, pu, pv);
  EvaluateLagrangePosition(*this->Cell, pc, x, J);
  double xu[3], xv[3], rel[3];
  for (int i = 0; i < 3; ++i)
  {
    xu[i] = J[3 * i] * pu[0] + J[3 * i + 1] * pu[1] + J[3 * i + 2] * pu[2];
    xv[i] = J[3 * i] * pv[0] + J[3 * i + 1] * pv[1] + J[3 * i + 2] * pv[2];
    rel[i] = x[i] - this->O[i];
  }
  this->Project(rel, xu, xv, h, jac);
  if (normal)
  {
    normal[0] = xu[1] * xv[2] - xu[2] * xv[1];
    normal[1] = xu[2] * xv[0] - xu[0] * xv[2];
    normal[2] = xu[0] * xv[1] - xu[1] * xv[0];
  }
}

void FaceProblem::EvaluateNet(double u, double v, double h[2], double jac[4]) const
{
  double x[3], xu[3], xv[3];
  if (this->Face->Triangle)
  {
    EvaluateTriangleNet(this->Face->Net.data(), this->Face->DegreeU, u, v, x, xu, xv);
  }
  else
  {
    EvaluateTensorNet(*this->Face, u, v, x, xu, xv);
  }
  const double rel[3] = { x[0] - this->O[0], x[1] - this->O[1], x[2] - this->O[2] };
  this->Project(rel, xu, xv, h, jac);
}

void FaceProblem::Project(
  const double rel[3], const double xu[3], const double xv[3], double h[2], double jac[4]) const
{
  h[0] = Dot(this->E1, rel);
  h[1] = Dot(this->E2, rel);
  jac[0] = Dot(this->E1, xu);
  jac[1] = Dot(this->E1, xv);
  jac[2] = Dot(this->E2, xu);
  jac[3] = Dot(this->E2, xv);
}

int FaceProblem::Side(const double n[3]) const
{
  const double dn = Dot(this->D, n);
  const double scale = std::sqrt(Dot(this->D, this->D) * Dot(n, n));
  if (this->Face->Orientation == 0 || !(std::abs(dn) > SideTolerance * scale))
  {
    return 0;
  }
  return (dn > 0.0) == (this->Face->Orientation > 0) ? 1 : -1;
}

bool FaceProblem::Newton(double& u, double& v, const double box[4]) const
{
  const double wu = 0.5 * (box[1] - box[0]), wv = 0.5 * (box[3] - box[2]);
  double h[2], jac[4];
  for (int iter = 0; iter < 40; ++iter)
  {
    this->EvaluateNet(u, v, h, jac);
    const double det = jac[0] * jac[3] - jac[1] * jac[2];
    if (!(std::abs(det) > 0.0))
    {
      return false;
    }
    const double du = -(jac[3] * h[0] - jac[1] * h[1]) / det;
    const double dv = -(-jac[2] * h[0] + jac[0] * h[1]) / det;
    u += du;
    v += dv;
    if (!(u >= box[0] - wu && u <= box[1] + wu && v >= box[2] - wv && v <= box[3] + wv))
    {
      return false;
    }
    const double step = std::max(std::abs(du), std::abs(dv));
    const bool floor = std::max(std::abs(h[0]), std::abs(h[1])) <= 16.0 * Eps * this->Extent;
    if (step <= 1e-15 || (floor && step <= 1e-9))
    {
      return true;
    }
  }
  return false;
}

void FaceProblem::Crossing(double u, double v, FaceCrossing& out) const
{
  double h[2], jac[4], x[3], normal[3];
  this->Evaluate(u, v, h, jac, x, out.PC, normal);
  out.Side = this->Side(normal);
  out.U = u;
  out.V = v;
  const double rel[3] = { x[0] - this->O[0], x[1] - this->O[1], x[2] - this->O[2] };
  out.T = Dot(this->D, rel) / Dot(this->D, this->D);
}

int FinishSubPatch(const FaceProblem& prob, bool accepted, bool small, double u, double v,
  double cu, double cv, const double* const net[2], int n, const FaceSearchSettings& settings,
  FaceCrossing& c, std::vector<FaceCrossing>& out)
{
  if (accepted)
  {
    prob.Crossing(u, v, c);
    c.Side = c.Grazing ? 0 : c.Side;
    out.push_back(c);
    return 1;
  }
  if (!small)
  {
    return 2;
  }
  // Resolution limit: a contact if the sub-patch's image hugs the ray.
  const Interval range[2] = { RangeOf(net[0], n), RangeOf(net[1], n) };
  if (std::max(range[0].Hi - range[0].Lo, range[1].Hi - range[1].Lo) <=
    settings.GrazeTolerance * prob.Extent)
  {
    prob.Crossing(cu, cv, c);
    c.Side = 0; // a contact: no side
    out.push_back(c);
  }
  return 1;
}
}
}
