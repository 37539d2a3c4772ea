/**
 * @class   hov::ShadedCellSegment
 * @brief   One restricted piece of a ray segment through one cell, with the
 *          volume's own shading and gradient opacity (vtkVolumeProperty Shade,
 *          Ambient/Diffuse/Specular/SpecularPower, the gradient-opacity
 *          function; hov::Features::VolumeShading / GradientOpacity).
 *
 * The CPU_ACCURATE side of hovVolumeShading.h, hovGradientOpacity.h and
 * hovShadedSegment.h (their file docs define the model: VTK's GPU ray
 * caster's per-sample colour clamp(ka A + kd D c + ks S) and extinction
 * GO(|grad s|) tau(s), in the continuum limit):
 *  - linear tetrahedra: the gradient is constant over the cell, so under
 *    directional lights the shading transform and the gradient-opacity factor
 *    are one per segment and the integral is the closed form
 *    hov::IntegrateLinearScalarShaded (exact; no error estimate);
 *  - affine general cells (voxels, parallelepipeds, prismatic wedges,
 *    straight-sided quadratic tetrahedra, ...): s(t) and grad s(t) are
 *    polynomials along the ray (hov::AffineGradientAlongLine, from the inverse
 *    Jacobian kept by hov::GeneralCells):
 *    hov::IntegrateShadedPolynomial (closed form when s is linear and the
 *    lights directional, adaptive quadrature with an error estimate otherwise);
 *  - other cells (distorted hexahedra, general wedges, pyramids): the
 *    gradient restricted to the piece as polynomials too
 *    (hov::RestrictCellGradient: Chebyshev, to 1e-10 of its scale on the
 *    piece, at most 8 sub-pieces), each sub-piece then as an affine cell's
 *    (hov::IntegrateShadedPolynomial with the scalar shifted to it, its
 *    share of the tolerance and of the panels): one Newton inversion per
 *    fitted point (17 per sub-piece) instead of one per quadrature sample.
 *    The fit's error is not in the error estimate (hovGradientRestriction.h
 *    discusses its effect on the normal). Where that fit needs more pieces
 *    (chords near a pyramid's apex) or Newton fails: the field and gradient
 *    sampled pointwise (hov::CellFieldAndGradient) for
 *    hov::IntegrateShadedSegment, cut at the transfer-function node
 *    crossings of the restricted scalar.
 * Positional lights make the transform vary along every ray: the quadrature
 * path, also on tetrahedra.
 *
 * Frames: rays, points and gradients in dataset coordinates; shading in world
 * coordinates (points by DataToWorld, gradients by NormalToWorld, the view
 * vector the normalised world ray direction). The quadrature's positions
 * along the ray use the dataset parameter (exact for rigid volume matrices;
 * with a scaled matrix positional lights see slightly moved points).
 *
 * The worst error estimate of the quadrature segments is kept
 * (GetWorstErrorEstimate) and reported as a frame diagnostic.
 *
 * Thread safety: one object per thread; the frame data is read only.
 * @sa hov::FeatureSegment, hovVolumeShading.h, hovShadedSegment.h
 */
#ifndef hovShadedCellSegment_h
#define hovShadedCellSegment_h

#include "hovViewRays.h" // Ray

#include "hovCompositing.h"     // RGBA
#include "hovGeneralCells.h"    // Cell
#include "hovGradientRestriction.h" // GradientPiece
#include "hovShadedSegment.h"   // ShadedSegmentSettings, ShadedSegmentResult
#include "hovPolynomial.h"      // Polynomial
#include "hovSegmentIntegral.h" // EmissionModel

#include "vtkType.h" // vtkIdType

#include <vector> // breakpoints

namespace hov
{
class CellSetup;
class TransferFunction;
struct Features;

class ShadedCellSegment
{
public:
  /// What every piece of a frame reads.
  struct FrameData
  {
    const hov::CellSetup* Setup = nullptr;
    const hov::Features* Features = nullptr;
    const hov::TransferFunction* TF = nullptr;
    hov::EmissionModel Emission = hov::EmissionModel::WilliamsMax;
    double Tolerance = 1e-9; ///< absolute per channel, per segment (quadrature)
  };

  /**
   * Premultiplied RGBA of rendered cell @p cell over [@p t0, @p t1] of
   * @p ray, where the cell's scalar is @p s (in tau = t - t0). @p pieces is
   * incremented by the pieces or panels integrated.
   */
  hov::RGBA Integrate(const FrameData& frame, vtkIdType cell, const hov::ViewRays::Ray& ray,
    double t0, double t1, const hov::Polynomial& s, vtkIdType& pieces);

  double GetWorstErrorEstimate() const { return this->WorstError; }
  void ResetWorstErrorEstimate() { this->WorstError = 0.0; }

private:
  /// Non-affine cells: grad s fitted by polynomials, each piece integrated as
  /// an affine cell's with its share of the tolerance and of the panels;
  /// false (the pointwise route then) if the fit did not converge within 8
  /// pieces or a Newton inversion failed.
  bool IntegrateFitted(const FrameData& frame, const hov::GeneralCells::Cell& cell,
    const hov::ViewRays::Ray& ray, double t0, double t1, const hov::Polynomial& s,
    const hov::ShadedSegmentSettings& settings, hov::ShadedSegmentResult& out);

  /// The affine gradient coefficients (hov::AffineGradientCoefficients) of
  /// the last cell: a tile visits a cell's pixels one after the other. Keyed
  /// by the shape and the scalars' values, so never stale.
  struct CoefficientCache
  {
    /// The coefficients of @p scalars, or null if the cell has none.
    const double (*Get(hov::CellShape shape, const double* scalars))[hov::AffineFieldTerms];

    bool Valid = false;
    bool Usable = false;
    hov::CellShape Shape = hov::CellShape::Tetra;
    double Scalars[hov::MaxCellNodes];
    double C[3][hov::AffineFieldTerms];
  };
  CoefficientCache Coefficients;

  std::vector<hov::GradientPiece> GradientPieces;
  std::vector<double> Breaks;
  std::vector<unsigned char> Smooth; ///< per breakpoint: mergeable (hovShadedSegment.h)
  double WorstError = 0.0;
};
}

#endif
