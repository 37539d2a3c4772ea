/**
 * @file hovLagrangeSpecial.h
 * @brief Internal (namespace hov::detail): the closed-form shape functions of
 * VTK 9.1's two non-tensor quadratic Lagrange cells, the 15-node tetrahedron
 * (vtkLagrangeTetra, FIFTEEN_POINT_TETRA: 10 quadratic nodes, 4 face centres,
 * 1 body centre) and the 21-node wedge (vtkHigherOrderInterpolation,
 * VTK_21_POINT_WEDGE: 6 corners, 9 mid-edges, 3 quadrilateral-face centres,
 * 2 triangle-face centres and the body centre, in VTK's order). Transcribed once as a
 * template and evaluated in double and in forward-mode dual numbers (exact
 * derivatives). Used by LagrangeBasis (hovLagrangeBasis.h).
 *
 * Thread safety: stateless, re-entrant.
 */
#ifndef hovLagrangeSpecial_h
#define hovLagrangeSpecial_h

#include "hovConfig.h"

namespace hov
{
namespace detail
{
/// Node counts of the two closed-form cells.
constexpr int Tetra15Nodes = 15;
constexpr int Wedge21Nodes = 21;

/// Shape functions @p w (may be null) and derivatives @p derivs (may be null;
/// derivs[d * n + i]) of the 15-node tetrahedron at @p pc.
HOV_EXPORT void Tetra15Functions(const double pc[3], double* w, double* derivs);

/// The same for the 21-node wedge.
HOV_EXPORT void Wedge21Functions(const double pc[3], double* w, double* derivs);

/// Parametric coordinates of node @p node of the 15-node tetrahedron / 21-node wedge.
HOV_EXPORT void Tetra15NodeCoords(int node, double pc[3]);
HOV_EXPORT void Wedge21NodeCoords(int node, double pc[3]);
}
}

#endif
