/**
 * @file hovLagrangeNumbering.h
 * @brief Internal (namespace hov::detail): VTK 9.1's node numbering of
 * Lagrange cells, ported verbatim from vtkHigherOrderHexahedron,
 * vtkHigherOrderWedge, vtkHigherOrderTetra and vtkHigherOrderTriangle (the
 * VTK cross-check test TestLagrangeVTKShapes compares every index with VTK's
 * own functions). Used by LagrangeBasis to build its node tables.
 *
 * Thread safety: stateless, re-entrant.
 */
#ifndef hovLagrangeNumbering_h
#define hovLagrangeNumbering_h

#include "hovConfig.h"

namespace hov
{
namespace detail
{
/// vtkHigherOrderHexahedron::PointIndexFromIJK(i, j, k, order).
HOV_EXPORT int LagrangeHexIndex(int i, int j, int k, const int* order);
/// vtkHigherOrderWedge::PointIndexFromIJK(i, j, k, order) (not the 21-node layout).
HOV_EXPORT int LagrangeWedgeIndex(int i, int j, int k, const int* order);
/// vtkHigherOrderTriangle::Index(bindex, order) (barycentric index of 3).
HOV_EXPORT int LagrangeTriangleIndex(const int* bindex, int order);
/// vtkHigherOrderTetra::Index(bindex, order) (barycentric index of 4).
HOV_EXPORT int LagrangeTetraIndex(const int* bindex, int order);
}
}

#endif
