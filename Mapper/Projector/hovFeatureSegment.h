/**
 * @class   hov::FeatureSegment
 * @brief   One ray interval of one cell (linear tetrahedron or general cell)
 *          with the features of hov::Features: up to three fields
 *          (extinction, colour, isosurfaces) and embedded shaded isosurfaces.
 *
 * Restriction: the fields along the ray as polynomial pieces in the local
 * parameter tau = t - T0. Tetrahedra: every field is linear (its gradient
 * over the cell), one exact piece. General cells: hov::RestrictCellScalar
 * per field (exact for affine cells, Chebyshev with its relative bound
 * otherwise); the pieces of several fields are merged at the union of their
 * breakpoints (each re-expanded on the common sub-interval by
 * hov::ComposeAffine).
 *
 * Surfaces: hov::SurfaceCrossings of the isosurface field on each piece;
 * @p includeFront applies to the interval's first piece only (inner piece
 * boundaries belong to the piece in front). The hit's normal is the gradient
 * of the isosurface field at the hit: constant in a tetrahedron; in a
 * general cell dS/dpc (hov::CellShapeDerivatives) times the inverse Jacobian
 * at the hit's parametric point (precomputed for affine cells, else Newton:
 * hov::InvertGeometry), so surfaces inside quadratic and trilinear cells are
 * curved and smooth. Gradient and point go to world coordinates for
 * hov::IsosurfaceHitColor (Blinn-Phong, edge-on opacity).
 *
 * Integration per piece: hov::IntegratePolynomialScalar (one field, no
 * surface), hov::IntegrateTwoFields (separate colour field),
 * hov::IntegrateWithSurfaces (one- or three-field overload) otherwise; pieces
 * composited front to back. With the volume's own shading or gradient
 * opacity (hov::Features::VolumeActive) and neither surfaces nor a separate
 * colour field, each piece goes to hov::ShadedCellSegment instead.
 *
 * Thread safety: one object per thread; the frame data is read-only.
 * @sa hov::FeatureTile, hovIsosurface.h, hovTwoFieldSegment.h
 */
#ifndef hovFeatureSegment_h
#define hovFeatureSegment_h

#include "hovFeatures.h"          // settings
#include "hovShadedCellSegment.h" // the volume's own shading
#include "hovViewRays.h" // Ray

#include "hovCellRestriction.h"   // RestrictedPiece
#include "hovCompositing.h"       // RGBA
#include "hovPolynomialSegment.h" // settings, IsovalueCrossing

#include "vtkType.h" // vtkIdType

#include <vector> // scratch

namespace hov
{
class CellSetup;
}
namespace hov
{
class TransferFunction;
}

namespace hov
{
class FeatureSegment
{
public:
  /// A linear field over a tetrahedron: s(x) = RefScalar + Gradient . (x - x0), x0 its vertex 0.
  struct LinearField
  {
    glm::dvec3 Gradient{ 0.0 };
    double RefScalar = 0.0;
  };

  struct FrameData
  {
    const hov::CellSetup* Setup = nullptr;
    const hov::Features* Features = nullptr;
    const hov::TransferFunction* TF = nullptr;
    hov::PolynomialSegmentSettings Segment;
    hov::CellRestrictionSettings Restriction;
    /// Per tetrahedron: the colour / isosurface field (empty if not separate).
    const std::vector<LinearField>* TetColor = nullptr;
    const std::vector<LinearField>* TetIso = nullptr;
  };

  /**
   * Premultiplied RGBA of rendered cell @p cell over [@p t0, @p t1] of
   * @p ray; @p includeFront: a surface exactly at t0 is drawn (the ray
   * enters the mesh there). @p pieces is incremented by the pieces integrated.
   */
  hov::RGBA Integrate(const FrameData& frame, vtkIdType cell, const hov::ViewRays::Ray& ray,
    double t0, double t1, bool includeFront, vtkIdType& pieces);

  /// Worst error estimate of the shaded quadrature segments so far (hov::ShadedCellSegment).
  double GetShadingErrorEstimate() const { return this->Shaded.GetWorstErrorEstimate(); }
  void ResetShadingErrorEstimate() { this->Shaded.ResetWorstErrorEstimate(); }

  /// Linear fields of per-point @p values over every tetrahedron of @p setup.
  static void TetraFields(
    const hov::CellSetup& setup, const std::vector<double>& values, std::vector<LinearField>& out);

private:
  struct Piece
  {
    double T0, T1;
    hov::Polynomial S[3]; ///< extinction, colour, isosurface field (tau = t - T0)
  };
  void RestrictTetra(const FrameData& frame, vtkIdType tet, const hov::ViewRays::Ray& ray,
    double t0, double t1);
  void RestrictGeneral(const FrameData& frame, int g, const hov::ViewRays::Ray& ray,
    double t0, double t1);
  void RestrictField(const FrameData& frame, int g, const double* scalars,
    const hov::ViewRays::Ray& ray, double t0, double t1,
    std::vector<hov::RestrictedPiece>& out);
  /// Isosurface-field gradient (dataset coordinates) of cell at point x.
  void IsoGradient(const FrameData& frame, vtkIdType cell, const double x[3], double g[3]);
  hov::RGBA Shade(const FrameData& frame, vtkIdType cell, const hov::ViewRays::Ray& ray,
    double t, int surface);

  std::vector<Piece> Pieces;
  std::vector<hov::RestrictedPiece> Restricted[3];
  std::vector<double> Breaks;
  std::vector<double> NodeValues[3];
  std::vector<hov::IsovalueCrossing> Crossings;
  hov::ShadedCellSegment Shaded;
};
}

#endif
