#include "hovProjectionStream.h"

#include "vtkOpenGLBufferObject.h"
#include "vtkSMPTools.h"
#include "vtk_glew.h"

#include <algorithm> // std::copy, std::max

namespace
{
constexpr int Floats = vtkHighOrderProjectionVertex::FloatsPerVertex;

/**
 * Map @p bytes of the buffer bound to @p target after @p used bytes for
 * writing; when they do not fit after @p used, new storage and @p used
 * restarts at 0. The new storage is larger (twice, at least @p bytes plus 25%)
 * only if the group alone does not fit in @p capacity: growing at every refill
 * made the storage converge to a whole frame's geometry, gigabytes for a
 * transfer function with many nodes (GL_OUT_OF_MEMORY, or a crash in llvmpipe).
 */
void* MapRange(GLenum target, size_t bytes, size_t& used, size_t& capacity, bool synchronized)
{
  if (used + bytes > capacity)
  {
    if (bytes > capacity)
    {
      capacity = std::max(2 * capacity, bytes + bytes / 4);
    }
    glBufferData(target, static_cast<GLsizeiptr>(capacity), nullptr, GL_STREAM_DRAW);
    used = 0;
  }
  const GLbitfield access = GL_MAP_WRITE_BIT | (synchronized ? 0 : GL_MAP_UNSYNCHRONIZED_BIT);
  return glMapBufferRange(
    target, static_cast<GLintptr>(used), static_cast<GLsizeiptr>(bytes), access);
}

/// The chunks of @p geometry into @p vertices and @p indices (indices made group-relative).
void CopyGroup(
  const vtkHighOrderProjectionRegions::Geometry& geometry, float* vertices, unsigned int* indices)
{
  const vtkIdType numChunks = static_cast<vtkIdType>(geometry.VertexOffsets.size()) - 1;
  vtkSMPTools::For(0, numChunks, [&](vtkIdType first, vtkIdType last) {
    for (vtkIdType c = first; c < last; ++c)
    {
      const vtkHighOrderProjectionChunk& chunk = geometry.Chunks[c];
      std::copy(chunk.Vertices.Data(), chunk.Vertices.Data() + chunk.Vertices.Size(),
        vertices + geometry.VertexOffsets[c] * Floats);
      const unsigned int base = static_cast<unsigned int>(geometry.VertexOffsets[c]);
      const unsigned int* src = chunk.Indices.Data();
      unsigned int* dst = indices + geometry.IndexOffsets[c];
      for (size_t i = 0, n = chunk.Indices.Size(); i < n; ++i)
      {
        dst[i] = src[i] + base;
      }
    }
  });
}
}

vtkHighOrderProjectionStream::vtkHighOrderProjectionStream() = default;

vtkHighOrderProjectionStream::~vtkHighOrderProjectionStream() = default;

bool vtkHighOrderProjectionStream::Begin()
{
  this->VertexUsed = this->IndexUsed = 0;
  this->FirstOfFrame = true;
  return this->Vertices->GenerateBuffer(vtkOpenGLBufferObject::ArrayBuffer) &&
    this->Indices->GenerateBuffer(vtkOpenGLBufferObject::ElementArrayBuffer) &&
    this->Vertices->Bind() && this->Indices->Bind();
}

bool vtkHighOrderProjectionStream::Append(
  const vtkHighOrderProjectionRegions::Geometry& geometry, Range& range)
{
  range = Range();
  const size_t vertexBytes = geometry.GetNumberOfVertices() * Floats * sizeof(float);
  const size_t indexBytes = geometry.GetNumberOfIndices() * sizeof(unsigned int);
  if (indexBytes == 0)
  {
    return true;
  }
  // Previous frames may still be drawing from the first range: synchronized.
  const bool synchronized = this->FirstOfFrame;
  this->FirstOfFrame = false;
  this->Vertices->Bind();
  auto* vertices = static_cast<float*>(MapRange(
    GL_ARRAY_BUFFER, vertexBytes, this->VertexUsed, this->VertexCapacity, synchronized));
  auto* indices = static_cast<unsigned int*>(MapRange(
    GL_ELEMENT_ARRAY_BUFFER, indexBytes, this->IndexUsed, this->IndexCapacity, synchronized));
  if (vertices && indices)
  {
    CopyGroup(geometry, vertices, indices);
  }
  const bool unmappedVertices = !vertices || glUnmapBuffer(GL_ARRAY_BUFFER) == GL_TRUE;
  const bool unmappedIndices = !indices || glUnmapBuffer(GL_ELEMENT_ARRAY_BUFFER) == GL_TRUE;
  if (!vertices || !indices || !unmappedVertices || !unmappedIndices)
  {
    return false;
  }
  range.IndexOffset = this->IndexUsed;
  range.Count = geometry.GetNumberOfIndices();
  range.BaseVertex = static_cast<long long>(this->VertexUsed / (Floats * sizeof(float)));
  this->VertexUsed += vertexBytes;
  this->IndexUsed += indexBytes;
  return true;
}

void vtkHighOrderProjectionStream::End()
{
  this->Indices->Release();
  this->Vertices->Release();
}

void vtkHighOrderProjectionStream::ReleaseGraphicsResources()
{
  this->Vertices->ReleaseGraphicsResources();
  this->Indices->ReleaseGraphicsResources();
  this->VertexCapacity = this->IndexCapacity = 0;
  this->VertexUsed = this->IndexUsed = 0;
}
