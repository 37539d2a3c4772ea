/**
 * @file hovStreamPlacement.h
 * @brief Where the OpenGL projection streams a group of region triangles
 * (hov::ProjectionStream: one vertex and one index buffer, refilled group
 * after group while earlier groups are drawn): the storage rule, kept free of
 * OpenGL so that its bound is tested on its own (Testing/Kernels/TestStreamPlacement.cxx).
 *
 * A group of @p bytes goes after the @p used bytes already written this frame
 * if it fits in @p capacity; otherwise the buffer gets new storage (the groups
 * already drawn keep the old one) and the group starts at its beginning. The
 * new storage is larger (twice, at least the group plus 25%) only if the group
 * alone does not fit: growing at every refill made the storage converge to a
 * whole frame's geometry, gigabytes for a transfer function with many nodes
 * (GL_OUT_OF_MEMORY, or a crash in llvmpipe). So the storage stays within 2.5x
 * the largest group, however many groups and frames are streamed.
 *
 * Thread safety: a pure function.
 */
#ifndef hovStreamPlacement_h
#define hovStreamPlacement_h

#include <algorithm> // std::max
#include <cstddef>   // size_t

namespace hov
{
/**
 * Place a group of @p bytes (see the file doc): returns true if the buffer
 * needs new storage of (the updated) @p capacity bytes, @p used then 0; the
 * group goes at offset @p used either way (the caller adds @p bytes to it).
 */
inline bool PlaceInStream(size_t bytes, size_t& used, size_t& capacity)
{
  if (used + bytes <= capacity)
  {
    return false;
  }
  if (bytes > capacity)
  {
    capacity = std::max(2 * capacity, bytes + bytes / 4);
  }
  used = 0;
  return true;
}
}

#endif
