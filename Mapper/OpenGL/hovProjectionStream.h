/**
 * @class   hov::ProjectionStream
 * @brief   Streams the region triangles of the OpenGL cell projection into
 *          one vertex and one index buffer, group after group, so that a
 *          group can be drawn while the next one is built.
 *
 * Each Append copies a group of chunks (hov::ProjectionRegions::
 * Geometry) in parallel (vtkSMPTools) into the next free ranges of the two
 * buffers (mapped for writing; ranges after the first of a frame unsynchronized:
 * nothing drawn earlier reads them) and returns where the group lies, for
 * glDrawElementsBaseVertex. The storage is kept across frames; when a group
 * does not fit after the groups already written, the buffer gets new storage
 * (the groups already drawn keep the old one) and the group starts at its
 * beginning; the new storage is larger only if the group alone does not fit,
 * so it stays within 2.5x the largest group (TestProjectionStream).
 *
 * Thread safety: rendering thread only (the copy itself runs in parallel).
 * @sa hov::ProjectionRenderer
 */
#ifndef hovProjectionStream_h
#define hovProjectionStream_h

#include "hovProjectionRegions.h" // Geometry
#include "vtkNew.h"                        // For vtkNew

#include <cstddef> // size_t

class vtkOpenGLBufferObject;

namespace hov
{
class ProjectionStream
{
public:
  /// Where an appended group lies.
  struct Range
  {
    size_t IndexOffset = 0; ///< in bytes, into the index buffer
    size_t Count = 0;       ///< indices
    long long BaseVertex = 0;
  };

  ProjectionStream();
  ~ProjectionStream();

  /// Start a frame: both buffers exist and are bound (the index buffer to the
  /// bound vertex array). False if a buffer could not be made.
  bool Begin();
  /// Copy @p geometry after the groups of this frame; false on a GL failure.
  bool Append(const hov::ProjectionRegions::Geometry& geometry, Range& range);
  /// Unbind the buffers.
  void End();

  vtkOpenGLBufferObject* GetVertexBuffer() { return this->Vertices; }
  /// Bytes of storage of the vertex and index buffers (kept across frames).
  size_t GetVertexCapacity() const { return this->VertexCapacity; }
  size_t GetIndexCapacity() const { return this->IndexCapacity; }
  void ReleaseGraphicsResources();

private:
  ProjectionStream(const hov::ProjectionStream&) = delete;
  void operator=(const ProjectionStream&) = delete;

  vtkNew<vtkOpenGLBufferObject> Vertices;
  vtkNew<vtkOpenGLBufferObject> Indices;
  size_t VertexCapacity = 0, IndexCapacity = 0; ///< bytes of storage
  size_t VertexUsed = 0, IndexUsed = 0;         ///< bytes written this frame
  bool FirstOfFrame = true;
};
}

#endif
