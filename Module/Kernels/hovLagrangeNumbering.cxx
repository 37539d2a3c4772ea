// VTK 9.1's Lagrange node numbering, ported: see hovLagrangeNumbering.h.
#include "hovLagrangeNumbering.h"

#include <algorithm> // std::min

namespace hov
{
namespace detail
{
/// vtkHigherOrderHexahedron::PointIndexFromIJK.
int LagrangeHexIndex(int i, int j, int k, const int* order)
{
  const bool ibdy = (i == 0 || i == order[0]);
  const bool jbdy = (j == 0 || j == order[1]);
  const bool kbdy = (k == 0 || k == order[2]);
  const int nbdy = (ibdy ? 1 : 0) + (jbdy ? 1 : 0) + (kbdy ? 1 : 0);
  if (nbdy == 3)
  {
    return (i ? (j ? 2 : 1) : (j ? 3 : 0)) + (k ? 4 : 0);
  }
  int offset = 8;
  if (nbdy == 2)
  {
    if (!ibdy)
    {
      return (i - 1) + (j ? order[0] + order[1] - 2 : 0) +
        (k ? 2 * (order[0] + order[1] - 2) : 0) + offset;
    }
    if (!jbdy)
    {
      return (j - 1) + (i ? order[0] - 1 : 2 * (order[0] - 1) + order[1] - 1) +
        (k ? 2 * (order[0] + order[1] - 2) : 0) + offset;
    }
    offset += 4 * (order[0] - 1) + 4 * (order[1] - 1);
    return (k - 1) + (order[2] - 1) * (i ? (j ? 2 : 1) : (j ? 3 : 0)) + offset;
  }
  offset += 4 * (order[0] + order[1] + order[2] - 3);
  if (nbdy == 1)
  {
    if (ibdy)
    {
      return (j - 1) + ((order[1] - 1) * (k - 1)) + (i ? (order[1] - 1) * (order[2] - 1) : 0) +
        offset;
    }
    offset += 2 * (order[1] - 1) * (order[2] - 1);
    if (jbdy)
    {
      return (i - 1) + ((order[0] - 1) * (k - 1)) + (j ? (order[2] - 1) * (order[0] - 1) : 0) +
        offset;
    }
    offset += 2 * (order[2] - 1) * (order[0] - 1);
    return (i - 1) + ((order[0] - 1) * (j - 1)) + (k ? (order[0] - 1) * (order[1] - 1) : 0) +
      offset;
  }
  offset += 2 *
    ((order[1] - 1) * (order[2] - 1) + (order[2] - 1) * (order[0] - 1) +
      (order[0] - 1) * (order[1] - 1));
  return offset + (i - 1) + (order[0] - 1) * ((j - 1) + (order[1] - 1) * (k - 1));
}

namespace
{
/// vtkHigherOrderWedge's triangleDOFOffset.
int TriangleDofOffset(int order, int i, int j)
{
  return i + order * (j - 1) - (j * (j + 1)) / 2;
}

}

/// vtkHigherOrderWedge::PointIndexFromIJK (general, not the 21-node layout).
int LagrangeWedgeIndex(int i, int j, int k, const int* order)
{
  const int rsOrder = order[0], rm1 = rsOrder - 1, tOrder = order[2], tm1 = tOrder - 1;
  const bool ibdy = (i == 0), jbdy = (j == 0), ijbdy = (i + j == rsOrder);
  const bool kbdy = (k == 0 || k == tOrder);
  const int nbdy = (ibdy ? 1 : 0) + (jbdy ? 1 : 0) + (ijbdy ? 1 : 0) + (kbdy ? 1 : 0);
  if (i < 0 || i > rsOrder || j < 0 || j > rsOrder || i + j > rsOrder || k < 0 || k > tOrder)
  {
    return -1;
  }
  if (nbdy == 3)
  {
    return (ibdy && jbdy ? 0 : (jbdy && ijbdy ? 1 : 2)) + (k ? 3 : 0);
  }
  int offset = 6;
  if (nbdy == 2)
  {
    if (!kbdy)
    {
      offset += rm1 * 6;
      return offset + (k - 1) + ((ibdy && jbdy) ? 0 : (jbdy && ijbdy ? 1 : 2)) * tm1;
    }
    offset += (k == tOrder ? 3 * rm1 : 0);
    if (jbdy)
    {
      return offset + i - 1;
    }
    offset += rm1;
    if (ijbdy)
    {
      return offset + j - 1;
    }
    offset += rm1;
    return offset + (rsOrder - j - 1);
  }
  offset += 6 * rm1 + 3 * tm1;
  const int ntfdof = (rm1 - 1) * rm1 / 2, nqfdof = rm1 * tm1;
  if (nbdy == 1)
  {
    if (kbdy)
    {
      return offset + (k > 0 ? ntfdof : 0) + TriangleDofOffset(rsOrder, i, j);
    }
    offset += 2 * ntfdof;
    if (jbdy)
    {
      return offset + (i - 1) + rm1 * (k - 1);
    }
    offset += nqfdof;
    if (ijbdy)
    {
      return offset + (j - 1) + rm1 * (k - 1);
    }
    offset += nqfdof;
    return offset + (rsOrder - j - 1) + rm1 * (k - 1);
  }
  offset += 2 * ntfdof + 3 * nqfdof;
  return offset + TriangleDofOffset(rsOrder, i, j) + ntfdof * (k - 1);
}

/// vtkHigherOrderTriangle::Index.
int LagrangeTriangleIndex(const int* bindex, int order)
{
  int index = 0, max = order, min = 0;
  const int bmin = std::min(std::min(bindex[0], bindex[1]), bindex[2]);
  while (bmin > min)
  {
    index += 3 * order;
    max -= 2;
    ++min;
    order -= 3;
  }
  for (int dim = 0; dim < 3; ++dim)
  {
    if (bindex[(dim + 2) % 3] == max)
    {
      return index;
    }
    ++index;
  }
  for (int dim = 0; dim < 3; ++dim)
  {
    if (bindex[(dim + 1) % 3] == min)
    {
      return index + bindex[dim] - (min + 1);
    }
    index += max - (min + 1);
  }
  return index;
}

/// vtkHigherOrderTetra::Index (its private tables copied).
int LagrangeTetraIndex(const int* bindex, int order)
{
  static constexpr int VertexMaxCoords[4] = { 3, 0, 1, 2 };
  static constexpr int EdgeMinCoords[6][2] = { { 1, 2 }, { 2, 3 }, { 0, 2 }, { 0, 1 }, { 1, 3 },
    { 0, 3 } };
  static constexpr int EdgeCountingCoord[6] = { 0, 1, 3, 2, 2, 2 };
  static constexpr int FaceBCoords[4][3] = { { 0, 2, 3 }, { 2, 0, 1 }, { 2, 1, 3 },
    { 1, 0, 3 } };
  static constexpr int FaceMinCoord[4] = { 1, 3, 0, 2 };
  int index = 0, max = order, min = 0;
  const int bmin = std::min(std::min(std::min(bindex[0], bindex[1]), bindex[2]), bindex[3]);
  while (bmin > min)
  {
    index += 2 * (order * order + 1);
    max -= 3;
    ++min;
    order -= 4;
  }
  for (int vertex = 0; vertex < 4; ++vertex)
  {
    if (bindex[VertexMaxCoords[vertex]] == max)
    {
      return index;
    }
    ++index;
  }
  for (int edge = 0; edge < 6; ++edge)
  {
    if (bindex[EdgeMinCoords[edge][0]] == min && bindex[EdgeMinCoords[edge][1]] == min)
    {
      return index + bindex[EdgeCountingCoord[edge]] - (min + 1);
    }
    index += max - (min + 1);
  }
  for (int face = 0; face < 4; ++face)
  {
    if (bindex[FaceMinCoord[face]] == min)
    {
      int projected[3];
      for (int i = 0; i < 3; ++i)
      {
        projected[i] = bindex[FaceBCoords[face][i]] - min;
      }
      return index + LagrangeTriangleIndex(projected, order) - 3 * order;
    }
    index += (order + 1) * (order + 2) / 2 - 3 * order;
  }
  return index;
}

}
}
