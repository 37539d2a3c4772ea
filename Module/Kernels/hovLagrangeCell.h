/**
 * @file hovLagrangeCell.h
 * @brief A Lagrange cell bound to its node data: the geometry map x(pc) with
 * its Jacobian, the interpolated scalar f(pc) with its gradient, and the
 * inverse map pc(x) by safeguarded Newton (our own: VTK's EvaluatePosition
 * is approximate for curved cells, ~1e-2 for a cubic hexahedron).
 *
 * Geometry (isoparametric, issue 6): x(pc) = sum_i w_i(pc) X_i over ALL
 * nodes (curved edges and faces), w from LagrangeBasis. Field: f(pc) =
 * sum_i w_i(pc) f_i.
 *
 * Inversion (InvertLagrangeGeometry): Newton on F(pc) = x(pc) - x with
 *  - the step solved by Gaussian elimination with partial pivoting; a
 *    Jacobian with |det| <= SingularTolerance |J_0| |J_1| |J_2| (columns) is
 *    singular (the start is abandoned);
 *  - the step limited to MaxStep = 1 parametric unit (max norm) and damped
 *    by halving (up to 12 times) until |F| decreases (backtracking line
 *    search), so iterates far from the solution cannot run away; a start
 *    is abandoned when no halving decreases |F| (a local minimum of |F|)
 *    or an iterate lies more than AbandonOutside (1) outside the domain;
 *  - convergence when the step from the current iterate is below
 *    StepTolerance (1e-13, max norm; it is taken without evaluating the map
 *    at its end), or when |F| is at its rounding floor (<= 64 eps x extent,
 *    the extent being the nodes' bounding-box diagonal) and the step is
 *    below FloorStepTolerance (1e-9: the map's conditioning then limits the
 *    accuracy and LastStep reports it); a full step of at most 1e-6 is first
 *    checked with the map alone at its end and a chord step (the current
 *    Jacobian): below StepTolerance, that step ends the run;
 *  - starts, in turn, until one converges: the caller's guess, the domain's
 *    centre, and the 27 points {0.2, 0.5, 0.8}^3 that lie in the domain.
 * A point outside the cell converges to parametric coordinates outside the
 * domain (the polynomial map extends); DistanceOutside tells. Points more
 * than ~AbandonOutside outside report NoConvergence.
 * Measured (TestLagrangeInversion, TestLagrangeVTKShapes; GCC 12 Release):
 * round trips x(pc) -> pc on curved cells (bent maps + perturbed nodes) of
 * every type and order 1..8: max error 7.0e-15 in parametric space, <= 6
 * iterations; on a curved cubic hexahedron VTK 9.1's EvaluatePosition is
 * off by 6.1e-3, this inversion by 6.7e-16.
 *
 * Domain: Basis initialised, Points finite (3 per node, VTK order). Bad
 * input gives InversionStatus::InvalidInput, never NaN in pc.
 *
 * Thread safety: re-entrant; no allocation.
 * @sa hovLagrangeBasis.h, hovCurvedRayCell.h, hovEnclosure.h
 */
#ifndef hovLagrangeCell_h
#define hovLagrangeCell_h

#include "hovConfig.h"
#include "hovLagrangeBasis.h"

namespace hov
{
/// A Lagrange cell: its basis and its node data (not owned).
struct LagrangeCellView
{
  const LagrangeBasis* Basis = nullptr;
  const double* Points = nullptr;  ///< 3 per node, VTK order
  const double* Scalars = nullptr; ///< 1 per node (may be null: no field)
  /// LagrangeCellExtent(*this) if the caller knows it (> 0 also vouches that
  /// the points are finite: InvertLagrangeGeometry then checks neither); 0:
  /// computed (and the points checked) on every inversion.
  double Extent = 0.0;
  /// A hexahedron whose every node lies on the trilinear map of its eight
  /// corners (Points[0..23], VTK order; see IsLagrangeGeometryTrilinear): the
  /// geometry is evaluated as that map (8 points instead of every node).
  bool Trilinear = false;
};

/// x(pc) and, if @p jacobian is given, J[3 i + j] = dx_i / dpc_j.
HOV_EXPORT void EvaluateLagrangePosition(
  const LagrangeCellView& cell, const double pc[3], double x[3], double* jacobian = nullptr);

/// f(pc) and, if @p gradient is given, df/dpc (parametric gradient).
HOV_EXPORT double EvaluateLagrangeScalar(
  const LagrangeCellView& cell, const double pc[3], double* gradient = nullptr);

/// Diagonal of the nodes' bounding box (the length scale of tolerances).
HOV_EXPORT double LagrangeCellExtent(const LagrangeCellView& cell);

/**
 * True if every node lies within @p relativeTolerance x extent of the affine
 * map through the corners (tetrahedron 0-1-2-3, hexahedron 0-1-3-4, wedge
 * 0-1-2-3): Lagrange interpolation reproduces affine maps, so the geometry
 * is then affine. @p affine (if given) receives that map: affine[0..2] the
 * origin, affine[3 + 3 j + i] = dx_i / dpc_j.
 */
/**
 * True if @p cell is a hexahedron whose every node lies within
 * @p relativeTolerance x LagrangeCellExtent of the trilinear map of its eight
 * corners (straight-edged hexahedra of any order, as meshers write them away
 * from curved boundaries): the interpolant then IS that map to this tolerance.
 */
HOV_EXPORT bool IsLagrangeGeometryTrilinear(
  const LagrangeCellView& cell, double relativeTolerance = 1e-12);

HOV_EXPORT bool IsLagrangeGeometryAffine(
  const LagrangeCellView& cell, double relativeTolerance = 1e-12, double* affine = nullptr);

enum class InversionStatus
{
  Converged = 0,
  NoConvergence = 1,    ///< no start converged within MaxIterations
  SingularJacobian = 2, ///< every start met a singular Jacobian
  InvalidInput = 3      ///< no basis, non-finite points or target
};

/// A short English description of @p status (for error messages).
HOV_EXPORT const char* InversionStatusName(InversionStatus status);

struct LagrangeInversionSettings
{
  double StepTolerance = 1e-13;      ///< converged below this step (max norm)
  double FloorStepTolerance = 1e-9;  ///< converged below this step at the residual floor
  double SingularTolerance = 1e-12;  ///< relative |det J| below which J is singular
  double MaxStep = 1.0;              ///< longest parametric step (max norm)
  int MaxIterations = 50;            ///< per start
  /// A start is abandoned when an iterate lies farther outside the domain
  /// (parametric units): far outside, the polynomial map's extension has
  /// spurious preimages and Newton wanders.
  double AbandonOutside = 1.0;
  bool UseStartGrid = true;          ///< try the 27-point grid after guess and centre
};

struct LagrangeInversionResult
{
  InversionStatus Status = InversionStatus::InvalidInput;
  int Iterations = 0;      ///< Newton iterations, all starts together
  int Starts = 0;          ///< starts tried
  double Residual = 0.0;   ///< |x(pc) - x| / extent at the result
  double LastStep = 0.0;   ///< last accepted step (max norm, parametric)
  /// Converged: the Jacobian dx/dpc (row-major) of the last evaluation, at
  /// the result to within the last step (<= StepTolerance, or
  /// FloorStepTolerance at the residual floor).
  double Jacobian[9] = {};
  bool Converged() const { return this->Status == InversionStatus::Converged; }
};

/**
 * Parametric coordinates of @p x (see file doc): @p pc is the guess on
 * input (ignored if not finite) and the result on output (the best iterate
 * if nothing converged; the centre for invalid input).
 */
HOV_EXPORT LagrangeInversionResult InvertLagrangeGeometry(const LagrangeCellView& cell,
  const double x[3], double pc[3],
  const LagrangeInversionSettings& settings = LagrangeInversionSettings());

/// Solve the 3x3 system J d = b (row-major J) by Gaussian elimination with
/// partial pivoting; false if |det| <= relTol x (product of column norms).
HOV_EXPORT bool Solve3x3(const double J[9], const double b[3], double d[3], double relTol);
}

#endif
