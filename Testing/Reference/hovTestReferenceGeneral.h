/**
 * @file hovTestReferenceGeneral.h
 * @brief Independent reference for NON-linear scalars along a ray (quadratic
 * and trilinear cells, issue 4): the emission-absorption integral of a
 * general s(t) given as a callback, the cell fields that produce s(t)
 * through VTK's own shape functions, exact ray/convex-cell intersection,
 * and the 1 -> 8^k subdivision of quadratic tetrahedra into linear ones.
 *
 * Nothing here uses the module's code (no hov:: kernel).
 *
 * IntegrateRayGeneral(property, model, s, L): on [0, L]
 *  1. dense sampling of s at Samples + 1 equidistant points; where the sign
 *     of the differences changes (and in the first and last two intervals)
 *     an interior extremum of s is located by Brent's method
 *     (boost::math::tools::brent_find_minima, long double); the extrema
 *     split [0, L] into pieces on which s is monotone;
 *  2. on each monotone piece every colour or opacity node v with
 *     (s(a) - v)(s(b) - v) < 0 is crossed exactly once; the crossing is
 *     located by TOMS 748 (boost::math::tools::toms748_solve) to long double
 *     precision;
 *  3. between successive cuts a(s(t)) and c(s(t)) are smooth; the colour
 *     integral (Williams-Max c tau exp(-D), Wilhelms-Van Gelder
 *     EmissionScale c / u exp(-D)) is done by adaptive Gauss-Kronrod
 *     (31 points, relative tolerance 1e-9) in long double, where the optical
 *     depth D(t) = D(piece start) + int_{piece start}^t tau(s(t')) dt' is an
 *     inner adaptive Gauss-Kronrod (15 points, tolerance 1e-11) at every outer
 *     node (no ODE, no closed form: valid for any semantics and any s);
 *     measured agreement with the exact linear reference ~1e-16
 *     (TestQuadraticReference), i.e. far below the 1e-6 the tests ask;
 *  4. alpha = -expm1(-D(L)).
 * The only assumption on s: its extrema are separated by more than about
 * L / Samples (a polynomial of degree <= 3 along a chord of a cell has at
 * most 2; the tests use Samples = 64).
 *
 * Semantics / emission codes as in hovTestReference.h.
 */
#ifndef hovTestReferenceGeneral_h
#define hovTestReferenceGeneral_h

#include "hovTestReference.h"

#include <functional>
#include <utility>
#include <vector>

class vtkUnstructuredGrid;
class vtkVolumeProperty;

namespace hovTestRef
{
/// A scalar along a ray segment: s(t) for t in [0, L].
using ScalarFunction = std::function<Real(Real)>;

/// Parameters and counters of IntegrateRayGeneral.
struct GeneralOptions
{
  int Samples = 64;             ///< dense samples of s on [0, L] (extrema search)
  /// Relative tolerances of the outer (colour) and inner (optical depth)
  /// quadratures. They must stay well above the noise of s, which the cell
  /// fields evaluate through VTK's shape functions in double (~1e-16
  /// relative): Boost's adaptive Gauss-Kronrod keeps bisecting while its
  /// error estimate |K - G| exceeds the tolerance, and on noise it never
  /// stops before the depth limit (measured: 1e-15 inner made a 64 x 48
  /// reference image take minutes). Gauss-Kronrod's |K - G| grossly
  /// overestimates the error of its Kronrod result on smooth pieces: with
  /// 1e-9 / 1e-11 a ray with 16 pieces needs ~1e4 evaluations of s and gives
  /// the same RGBA to 17 digits as 1e-12 / 1e-15 (1e5 evaluations).
  Real Tolerance = 1e-9;
  Real InnerTolerance = 1e-11;
  int OuterDepth = 8; ///< bisection limits of the two quadratures
  int InnerDepth = 6;
};
struct GeneralStats
{
  int Pieces = 0;    ///< smooth pieces integrated
  int Extrema = 0;   ///< interior extrema of s found
  int Crossings = 0; ///< transfer-function node crossings found
};

/// The colour and opacity node positions of component 0 of @p property (sorted, unique).
std::vector<double> TransferFunctionNodes(vtkVolumeProperty* property);

/**
 * The cut times of [0, L] (steps 1-2 above): 0, every interior extremum of
 * @p s, every crossing of a value of @p nodes, L; sorted.
 */
std::vector<Real> BreakTimes(const ScalarFunction& s, Real length, const std::vector<double>& nodes,
  int samples, GeneralStats* stats = nullptr);

/// Premultiplied RGBA of the segment [0, @p length] with scalar @p s(t).
RGBA IntegrateRayGeneral(vtkVolumeProperty* property, const Model& model, const ScalarFunction& s,
  Real length, const GeneralOptions& options = GeneralOptions(), GeneralStats* stats = nullptr);

/// Crude cross-check: @p steps uniform midpoint steps (constant tau and colour each).
RGBA IntegrateRayGeneralBruteForce(vtkVolumeProperty* property, const Model& model,
  const ScalarFunction& s, Real length, long steps);

//------------------------------------------------------------------------------
// Cell fields (the value at a world point inside the cell).

/**
 * A straight-edged quadratic tetrahedron (VTK_QUADRATIC_TETRA node order:
 * corners 0-3, mid-edges (0,1),(1,2),(2,0),(0,3),(1,3),(2,3)): parametric
 * coordinates by solving the affine map in long double, the value by
 * vtkQuadraticTetra::InterpolationFunctions.
 */
struct QuadraticTetraField
{
  QuadraticTetraField(const double corners[4][3], const double nodeScalars[10]);
  Real operator()(const Vec3& x) const;
  Vec3 Origin{};
  Real Inverse[3][3]{}; ///< inverse of the edge matrix [x1-x0, x2-x0, x3-x0]
  double S[10]{};
};

/**
 * A trilinear hexahedron (VTK_HEXAHEDRON node order): parametric coordinates
 * by Newton's method on vtkHexahedron::InterpolationFunctions /
 * InterpolationDerivs (to 1e-15), warm-started from the previous call (not
 * thread safe), the value by the same shape functions.
 */
struct HexahedronField
{
  HexahedronField(const double corners[8][3], const double nodeScalars[8]);
  Real operator()(const Vec3& x) const;
  /// Parametric coordinates of @p x; false if Newton did not converge.
  bool Invert(const Vec3& x, double pcoords[3]) const;
  double X[8][3]{};
  double S[8]{};
  mutable double Guess[3] = { 0.5, 0.5, 0.5 };
};

//------------------------------------------------------------------------------
// Geometry of convex cells with planar faces.

/// A convex polyhedron: its faces as corner lists (any orientation).
struct ConvexCell
{
  std::vector<Vec3> Corners;
  std::vector<std::vector<int>> Faces;
  /// The hexahedron with VTK_HEXAHEDRON corners @p x (its faces must be planar).
  static ConvexCell Hexahedron(const double x[8][3]);
  /// Largest distance of a face corner from its face's plane (planarity check).
  Real MaxFaceNonPlanarity() const;
};

/// Half-space clipping of @p ray by the planes of @p cell's faces, within [0, TFar].
bool IntersectConvex(const Ray& ray, const ConvexCell& cell, Real& tIn, Real& tOut);

/// Smallest distance between the ray (segment [0, TFar]) and an edge of @p cell's faces.
Real DistanceToCellEdges(const Ray& ray, const ConvexCell& cell);

//------------------------------------------------------------------------------
// Quadratic tetrahedral meshes and their linear subdivision.

/**
 * Every VTK_QUADRATIC_TETRA of @p grid split into 8^@p levels linear
 * tetrahedra by @p levels rounds of the regular 1 -> 8 (red) split in the
 * parametric domain (straight-edged geometry from the 4 corners); the point
 * scalar is the quadratic interpolant (vtkQuadraticTetra::
 * InterpolationFunctions) of the active point scalars at the new nodes. Nodes
 * are merged by their barycentric key over the corners' global ids, so
 * neighbouring cells share their face nodes (conforming output). Other cell
 * types are ignored. The output's active point scalars keep the input name.
 */
vtkSmartPointer<vtkUnstructuredGrid> SubdivideQuadraticTetras(vtkUnstructuredGrid* grid, int levels);

/**
 * A mesh of quadratic tetrahedra: an n^3 block of cubes over
 * [origin, origin + size]^3, each split into 6 (Kuhn) tetrahedra, straight
 * edges, with point scalar "s" = @p f at every corner and mid-edge node.
 */
vtkSmartPointer<vtkUnstructuredGrid> MakeQuadraticTetraBlock(
  int n, const double origin[3], double size, const std::function<double(const double*)>& f);

//------------------------------------------------------------------------------
// Reference images of one cell (hovTestReferenceImage.cxx).

/**
 * One cell seen by a camera: its intersection with a ray (dataset =
 * world coordinates), the distance of a ray to its edges (grazing rays) and
 * its field. The callbacks are copied once per worker thread, so a stateful
 * field (HexahedronField's warm start) must be captured BY VALUE.
 */
struct CellScene
{
  std::function<bool(const Ray&, Real&, Real&)> Intersect;
  std::function<Real(const Ray&)> EdgeDistance;
  std::function<Real(const Vec3&)> Field;
};

/// Per-pixel reference of a W x H image (rows from the bottom).
struct ReferenceImage
{
  int W = 0, H = 0;
  std::vector<RGBA> Pixels;
  std::vector<Real> Length;          ///< chord length (0 if not covered)
  std::vector<char> Covered, Grazing; ///< grazing: within @p grazeDistance of an edge
  int ExpectedCovered = 0;            ///< covered and not grazing
};

/// IntegrateRayGeneral along every pixel ray (PixelRay) of @p cam (vtkSMPTools over rows).
ReferenceImage RenderReference(const CellScene& scene, const CameraSpec& cam,
  vtkVolumeProperty* property, const Model& model, int width, int height, Real grazeDistance);

/// A float image against a reference image.
struct ImageComparison
{
  double MaxError = 0;    ///< over every channel of every pixel (uncovered: reference 0)
  double MeanError = 0;   ///< over every channel of the covered pixels
  int GotCovered = 0;     ///< non-zero pixels among the non-grazing ones
  int CoverageMismatches = 0;
  int Above = 0;          ///< pixels with a channel error above the tolerance
  std::string Worst;      ///< the worst pixel, its values and chord length
};
ImageComparison CompareImage(const ReferenceImage& ref, const float* pixels, double tolerance);
}

#endif
