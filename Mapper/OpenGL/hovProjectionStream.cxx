#include "hovProjectionStream.h"

#include "hovStreamPlacement.h" // where a group goes

#include "vtkOpenGLBufferObject.h"
#include "vtkSMPTools.h"
#include "vtk_glew.h"

#include <algorithm> // std::copy, std::max

namespace
{
constexpr int Floats = hov::ProjectionVertex::FloatsPerVertex;

/**
 * Map @p bytes of the buffer bound to @p target for writing, where
 * hov::PlaceInStream puts them (after the @p used bytes of this frame, or at
 * the beginning of new storage: hovStreamPlacement.h).
 */
void* MapRange(GLenum target, size_t bytes, size_t& used, size_t& capacity, bool synchronized)
{
  if (hov::PlaceInStream(bytes, used, capacity))
  {
    glBufferData(target, static_cast<GLsizeiptr>(capacity), nullptr, GL_STREAM_DRAW);
  }
  const GLbitfield access = GL_MAP_WRITE_BIT | (synchronized ? 0 : GL_MAP_UNSYNCHRONIZED_BIT);
  return glMapBufferRange(
    target, static_cast<GLintptr>(used), static_cast<GLsizeiptr>(bytes), access);
}

/// The chunks of @p geometry into @p vertices and @p indices (indices made group-relative).
void CopyGroup(
  const hov::ProjectionRegions::Geometry& geometry, float* vertices, unsigned int* indices)
{
  const vtkIdType numChunks = static_cast<vtkIdType>(geometry.VertexOffsets.size()) - 1;
  vtkSMPTools::For(0, numChunks, [&](vtkIdType first, vtkIdType last) {
    for (vtkIdType c = first; c < last; ++c)
    {
      const hov::ProjectionChunk& chunk = geometry.Chunks[c];
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

hov::ProjectionStream::ProjectionStream() = default;

hov::ProjectionStream::~ProjectionStream() = default;

bool hov::ProjectionStream::Begin()
{
  this->VertexUsed = this->IndexUsed = 0;
  this->FirstOfFrame = true;
  return this->Vertices->GenerateBuffer(vtkOpenGLBufferObject::ArrayBuffer) &&
    this->Indices->GenerateBuffer(vtkOpenGLBufferObject::ElementArrayBuffer) &&
    this->Vertices->Bind() && this->Indices->Bind();
}

bool hov::ProjectionStream::Append(
  const hov::ProjectionRegions::Geometry& geometry, Range& range)
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

void hov::ProjectionStream::End()
{
  this->Indices->Release();
  this->Vertices->Release();
}

void hov::ProjectionStream::ReleaseGraphicsResources()
{
  this->Vertices->ReleaseGraphicsResources();
  this->Indices->ReleaseGraphicsResources();
  this->VertexCapacity = this->IndexCapacity = 0;
  this->VertexUsed = this->IndexUsed = 0;
}
