// OPENGL_PROJECTION: the streaming buffers of vtkHighOrderProjectionStream stay
// within 2.5x the largest group, however many groups and frames are streamed.
// Regression: the storage doubled at every refill, so it grew to a whole
// frame's geometry; with a transfer function of thousands of nodes (ParaView's
// default colour map) that was gigabytes: GL_OUT_OF_MEMORY, then
// GL_INVALID_VALUE from the mapping and an empty image, or a crash in llvmpipe.
#include "vtkHighOrderProjectionStream.h"

#include "hovTestScenes.h" // OffscreenWindow

#include "vtkNew.h"
#include "vtkOpenGLVertexArrayObject.h" // the element buffer binds to a vertex array
#include "vtkRenderWindow.h"

#include <iostream>

int TestProjectionStream(int, char*[])
{
  auto window = hovTest::OffscreenWindow(nullptr, 8, 8); // X, or EGL headless
  window->Render(); // a current OpenGL context
  window->MakeCurrent();
  vtkNew<vtkOpenGLVertexArrayObject> vertexArray;

  // One group: 2 chunks of 3000 vertices and 9000 indices each.
  constexpr int Floats = vtkHighOrderProjectionVertex::FloatsPerVertex;
  vtkHighOrderProjectionRegions::Geometry group;
  group.Chunks.resize(2);
  group.VertexOffsets = { 0 };
  group.IndexOffsets = { 0 };
  for (auto& chunk : group.Chunks)
  {
    unsigned int first = 0;
    float* v = chunk.AddVertices(3000, first);
    std::fill(v, v + 3000 * Floats, 0.5f);
    unsigned int* idx = chunk.Indices.Append(9000);
    for (int i = 0; i < 9000; ++i)
    {
      idx[i] = static_cast<unsigned int>(i % 3000);
    }
    group.VertexOffsets.push_back(group.VertexOffsets.back() + 3000);
    group.IndexOffsets.push_back(group.IndexOffsets.back() + 9000);
  }
  const size_t vertexBytes = group.GetNumberOfVertices() * Floats * sizeof(float);
  const size_t indexBytes = group.GetNumberOfIndices() * sizeof(unsigned int);

  vtkHighOrderProjectionStream stream;
  int failures = 0;
  for (int frame = 0; frame < 12; ++frame)
  {
    vertexArray->Bind();
    if (!stream.Begin())
    {
      std::cerr << "frame " << frame << ": Begin failed\n";
      return 1;
    }
    for (int g = 0; g < 10; ++g)
    {
      vtkHighOrderProjectionStream::Range range;
      if (!stream.Append(group, range) || range.Count != group.GetNumberOfIndices())
      {
        std::cerr << "frame " << frame << " group " << g << ": Append failed\n";
        ++failures;
      }
    }
    stream.End();
    vertexArray->Release();
  }
  const double vertexRatio = static_cast<double>(stream.GetVertexCapacity()) / vertexBytes;
  const double indexRatio = static_cast<double>(stream.GetIndexCapacity()) / indexBytes;
  std::cout << "[measured] after 12 frames of 10 groups: vertex storage " << vertexRatio
            << " groups, index storage " << indexRatio << " groups (bound 2.5)\n";
  if (vertexRatio > 2.5 || indexRatio > 2.5 || vertexRatio < 1.0 || indexRatio < 1.0)
  {
    std::cerr << "storage not within [1, 2.5] groups\n";
    ++failures;
  }
  stream.ReleaseGraphicsResources();
  return failures == 0 ? 0 : 1;
}
