#include "hovTwoFieldSegment.h"

#include "hovBreakpointWalk.h"   // the intervals a monotone run crosses
#include "hovPieceQuadrature.h"  // IntegrateSmoothPiece
#include "hovSegmentIntegral.h"  // IntegrateSegment (exact pieces)
#include "hovTransferFunction.h" // the tables

#include <algorithm> // std::min, std::max
#include <cmath>     // isfinite

namespace hov
{
namespace
{
// Fields of higher degree have a depth of degree > MaxDegree.
constexpr int MaxFieldDegree = Polynomial::MaxDegree - 1;

/**
 * Walks one field over its monotone runs and its table's intervals (as
 * RunWalker in hovPolynomialSegment.cxx): the current piece of this field is
 * [TCur, TNext] in interval Walk.Interval(), values SCur -> SNext (SNext is the node value
 * exactly when the piece ends at a node).
 */
struct FieldWalker
{
  const TransferFunction* Table = nullptr;
  Polynomial Field;
  double Ends[Polynomial::MaxDegree + 2];
  int NEnds = 0;
  int Run = 0;
  double SRunEnd = 0.0;
  BreakpointWalk Walk; ///< the table's intervals along the current run
  bool Last = true, Done = false;
  double TCur = 0.0, SCur = 0.0, TNext = 0.0, SNext = 0.0;

  void Init(const TransferFunction& table, const Polynomial& field, double length)
  {
    this->Table = &table;
    this->Field = field;
    this->NEnds = 0;
    this->Ends[this->NEnds++] = 0.0;
    double crit[Polynomial::MaxDegree];
    const int nCrit = FindRoots(Derivative(field), 0.0, 0.0, length, crit);
    for (int i = 0; i < nCrit; ++i)
    {
      if (crit[i] > this->Ends[this->NEnds - 1] && crit[i] < length)
      {
        this->Ends[this->NEnds++] = crit[i];
      }
    }
    this->Ends[this->NEnds++] = length;
    this->Run = 0;
    this->StartRun(field.C[0]);
  }

  void StartRun(double sStart)
  {
    const double t1 = this->Ends[this->Run + 1];
    this->SRunEnd = EvaluateCompensated(this->Field, t1);
    this->Walk = BreakpointWalk::Of(*this->Table, sStart, this->SRunEnd);
    this->TCur = this->Ends[this->Run];
    this->SCur = sStart;
    this->FindNext();
  }

  void FindNext()
  {
    const double t1 = this->Ends[this->Run + 1];
    this->Last = !this->Walk.CrossesNode();
    this->SNext = this->SRunEnd;
    this->TNext = t1;
    if (!this->Last)
    {
      this->SNext = this->Walk.Node();
      this->TNext = std::min(
        std::max(SolveMonotone(this->Field, this->SNext, this->TCur, t1), this->TCur), t1);
    }
  }

  /// The piece ends at @p t (<= TNext): move to the next piece of this field.
  void AdvanceTo(double t)
  {
    if (t < this->TNext)
    {
      if (t > this->TCur) // inside this field's piece: the other field's breakpoint
      {
        this->TCur = t;
        this->SCur = EvaluateCompensated(this->Field, t);
      }
      return;
    }
    if (!this->Last)
    {
      this->TCur = this->TNext;
      this->SCur = this->SNext;
      this->Walk.Next();
      this->FindNext();
      return;
    }
    if (this->Run + 2 >= this->NEnds)
    {
      this->Done = true;
      return;
    }
    ++this->Run;
    this->StartRun(this->SRunEnd);
  }

  /// Value at the end @p t of the current merged piece.
  double ValueAt(double t) const
  {
    return t == this->TNext ? this->SNext : EvaluateCompensated(this->Field, t);
  }
};

/// u(y) = (s(tA + h y) - sA) / (sB - sA), or y if sA = sB (s constant).
Polynomial Normalised(const Polynomial& s, double tA, double h, double sA, double sB)
{
  if (sB == sA)
  {
    return Polynomial::FromCoefficients({ 0.0, 1.0 });
  }
  Polynomial u = ComposeAffine(s, tA, h);
  u.C[0] = 0.0; // u(0) = 0 exactly
  const double inv = 1.0 / (sB - sA);
  for (int i = 1; i <= u.Degree; ++i)
  {
    u.C[i] *= inv;
  }
  return u;
}

struct Merger
{
  FieldWalker E, C; // extinction field s1, colour field s2
  bool Emission = false;
  double BudgetPerLength = 0.0;
  int PanelsLeft = 1;
  RGBA Accum;
  PolynomialSegmentResult* Result = nullptr;

  /// Piece [t0, t1] with both walkers' current intervals.
  void Piece(double t0, double t1)
  {
    const double h = t1 - t0;
    const double s1A = this->E.SCur, s1B = this->E.ValueAt(t1);
    const double s2A = this->C.SCur, s2B = this->C.ValueAt(t1);
    SegmentEnd fA, fB, cA, cB;
    this->E.Table->Evaluate(this->E.Walk.Interval(), s1A, false, fA);
    this->E.Table->Evaluate(this->E.Walk.Interval(), s1B, false, fB);
    this->C.Table->Evaluate(this->C.Walk.Interval(), s2A, this->Emission, cA);
    this->C.Table->Evaluate(this->C.Walk.Interval(), s2B, this->Emission, cB);
    for (int c = 0; c < 3; ++c)
    {
      fA.Color[c] = cA.Color[c];
      fB.Color[c] = cB.Color[c];
    }
    const bool tauLinear = fA.Tau == fB.Tau || EffectiveDegree(this->E.Field) <= 1;
    const bool colorLinear = (cA.Color[0] == cB.Color[0] && cA.Color[1] == cB.Color[1] &&
                               cA.Color[2] == cB.Color[2]) ||
      EffectiveDegree(this->C.Field) <= 1;
    const double transmit = 1.0 - this->Accum.A;
    detail::PieceOutput piece;
    if ((tauLinear && colorLinear) || !std::isfinite(fA.Tau) || !std::isfinite(fB.Tau))
    {
      piece.Color = IntegrateSegment(h, fA, fB,
        this->Emission ? EmissionModel::WilhelmsVanGelder : EmissionModel::WilliamsMax,
        SegmentMethod::Exact);
    }
    else
    {
      piece = detail::IntegrateSmoothPiece(fA, fB, Normalised(this->E.Field, t0, h, s1A, s1B),
        Normalised(this->C.Field, t0, h, s2A, s2B), h, transmit, this->BudgetPerLength,
        this->Emission, this->PanelsLeft);
    }
    this->Result->ErrorEstimate += transmit * piece.Error;
    this->Result->Panels += piece.Panels;
    this->Result->Converged = this->Result->Converged && piece.Converged;
    ++this->Result->Pieces;
    CompositeBehind(this->Accum, piece.Color);
  }

  void Run()
  {
    while (!this->E.Done && !this->C.Done && this->Accum.A < 1.0)
    {
      const double t0 = std::max(this->E.TCur, this->C.TCur);
      const double t1 = std::min(this->E.TNext, this->C.TNext);
      if (t1 > t0)
      {
        this->Piece(t0, t1);
      }
      // The field(s) whose piece ends at t1 move to their next piece; the
      // other one continues from t1 within its piece.
      const double tEnd = std::max(t0, t1);
      this->E.AdvanceTo(tEnd);
      this->C.AdvanceTo(tEnd);
    }
  }
};

bool FiniteCoefficients(const Polynomial& s)
{
  for (int i = 0; i <= std::min(s.Degree, Polynomial::MaxDegree); ++i)
  {
    if (!std::isfinite(s.C[i]))
    {
      return false;
    }
  }
  return true;
}

bool SameCoefficients(const Polynomial& a, const Polynomial& b)
{
  const int n = std::max(EffectiveDegree(a), EffectiveDegree(b));
  for (int i = 0; i <= n; ++i)
  {
    if ((i <= a.Degree ? a.C[i] : 0.0) != (i <= b.Degree ? b.C[i] : 0.0))
    {
      return false;
    }
  }
  return true;
}
}

PolynomialSegmentResult IntegrateTwoFields(const TransferFunction& extinction, const Polynomial& s1,
  const TransferFunction& color, const Polynomial& s2, double length,
  const PolynomialSegmentSettings& settings)
{
  PolynomialSegmentResult result;
  if (!(length > 0.0) || !std::isfinite(length) || extinction.GetNumberOfNodes() == 0 ||
    color.GetNumberOfNodes() == 0 || !FiniteCoefficients(s1) || !FiniteCoefficients(s2))
  {
    return result;
  }
  if (&extinction == &color && SameCoefficients(s1, s2))
  {
    return IntegratePolynomialScalar(extinction, s1, length, settings);
  }
  const int d1 = EffectiveDegree(s1), d2 = EffectiveDegree(s2);
  if (d1 > MaxFieldDegree || d2 > MaxFieldDegree)
  {
    result.Converged = false;
    return result;
  }
  Polynomial f1 = s1, f2 = s2;
  f1.Degree = d1;
  f2.Degree = d2;
  Merger m;
  m.E.Init(extinction, f1, length);
  m.C.Init(color, f2, length);
  m.Emission = settings.Emission == EmissionModel::WilhelmsVanGelder;
  m.BudgetPerLength = std::max(settings.Tolerance, 0.0) / length;
  m.PanelsLeft = std::max(settings.MaxPanels, 1);
  m.Result = &result;
  m.Run();
  result.Color = m.Accum;
  return result;
}
}
