#include "hovProjectionBackend.h"

#include "hovCellScene.h"                 // cells, order, table
#include "hovFloatImage.h"                // the float image read back
#include "hovImageDisplay.h"              // ReadDepth
#include "hovProjectionVertex.h"          // FloatsPerVertex (group budget)
#include "hovReducedImage.h"              // interactive frames
#include "hovRenderFrame.h"               // the frame
#include "vtkHighOrderTransferFunction.h" // the table object

#include "hovTransferFunction.h" // the table

#include "vtkCamera.h"    // the view
#include "vtkMatrix4x4.h" // the volume matrix
#include "vtkVolume.h"    // the volume matrix

#include <algorithm> // std::reverse_copy, std::all_of
#include <cfloat>    // FLT_MAX
#include <chrono>    // the fixed part of the frame's cost
#include <cmath>     // std::abs
#include <sstream>   // messages

namespace
{
/// Cells per group at least (hov::ProjectionRenderer draws a group while the
/// next is built; at most MaxGroups groups). The buffers (ours and Mesa's)
/// grow with the group: 128 groups instead of 32 took a 2M-tetrahedron frame's
/// peak from 1390 to 1304 MB, at the same speed (RT 553k: 1.05 s either way).
constexpr vtkIdType CellsPerGroup = 8192;
constexpr vtkIdType MaxGroups = 128;
/// Vertex bytes per group at most, and the cells of the first group (before
/// the cost per cell is known): a transfer function with many nodes cuts every
/// cell into many slabs (ParaView's default colour map, 256 steps in a
/// non-linear colour space, gives thousands of nodes), and a group of
/// CellsPerGroup cells then needed gigabytes. Typical groups (a few hundred
/// bytes per cell) stay at CellsPerGroup.
constexpr double GroupVertexBudget = 64.0 * 1024 * 1024;
constexpr vtkIdType FirstGroupCells = 1024;
constexpr vtkIdType MinGroupCells = 64;

/// VTK's row-major matrix as glm's column-major one.
glm::dmat4 ToGlm(vtkMatrix4x4* m)
{
  glm::dmat4 g(1.0);
  for (int i = 0; i < 4; ++i)
  {
    for (int j = 0; j < 4; ++j)
    {
      g[j][i] = m->GetElement(i, j);
    }
  }
  return g;
}

/// The view in dataset coordinates: composite matrix, eye, direction of projection.
void ViewSettings(const hov::RenderFrame& frame, hov::ProjectionRegions::Settings& settings)
{
  vtkCamera* camera = frame.Camera;
  const glm::dmat4 model = ToGlm(frame.Volume->GetMatrix());
  settings.Composite =
    ToGlm(camera->GetCompositeProjectionTransformMatrix(frame.Aspect, -1.0, 1.0)) * model;
  const glm::dmat4 inverseModel = glm::inverse(model);
  double eye[3], dop[3];
  camera->GetPosition(eye);
  camera->GetDirectionOfProjection(dop);
  const glm::dvec4 e = inverseModel * glm::dvec4(eye[0], eye[1], eye[2], 1.0);
  settings.Eye = glm::dvec3(e) / e.w;
  settings.Direction = glm::dvec3(inverseModel * glm::dvec4(dop[0], dop[1], dop[2], 0.0));
  settings.Parallel = camera->GetParallelProjection() != 0;
  settings.Method = frame.Settings.ColorMethod;
  settings.Emission = frame.Settings.Emission;
}

/**
 * The scene depth of the viewport into @p depth; null if it cannot be read or
 * if it is the far plane everywhere (no opaque geometry in the viewport: the
 * depth test could reject nothing, so the projection skips it and its
 * per-fragment cost).
 */
const float* SceneDepth(const hov::RenderFrame& frame, std::vector<float>& depth)
{
  if (!hov::ImageDisplay::MayHoldDepth(frame.Renderer))
  {
    return nullptr; // only the far plane there
  }
  depth.resize(static_cast<size_t>(frame.Width) * frame.Height);
  if (!hov::ImageDisplay::ReadDepth(
        frame.Renderer, frame.Width, frame.Height, frame.X0, frame.Y0, depth.data()))
  {
    return nullptr;
  }
  const bool allFar = std::all_of(depth.begin(), depth.end(), [](float z) { return z >= 1.0f; });
  return allFar ? nullptr : depth.data();
}

/// The renderer's options for the region @p settings.
hov::ProjectionRenderer::Options RenderOptions(
  const hov::ProjectionRegions::Settings& settings, const hov::FrameSettings& frame)
{
  hov::ProjectionRenderer::Options options;
  options.TextureOpacity = settings.Method != hov::ProjectionColorMethod::InterpolatedOpacity;
  options.PremultipliedColor = settings.Emission == hov::EmissionModel::WilhelmsVanGelder;
  options.Parallel = settings.Parallel;
  options.ClipToData = glm::inverse(settings.Composite);
  options.Eye = settings.Eye;
  options.AnalyticOpacity = frame.Lookup == hov::OpacityLookup::Analytic;
  options.GPUOpacity = settings.ExtinctionTf != nullptr;
  options.InverseUnit = settings.InverseUnit;
  return options;
}
}

int hov::ProjectionBackend::Render(RenderFrame& frame, vtkImageData* floatImage)
{
  const auto begin = std::chrono::steady_clock::now();
  // An interactive frame: the approximate order, into a target of one pixel
  // per f x f block, blitted over the viewport (hovReducedImage.h).
  if (frame.Interactive)
  {
    frame.Settings.Order = ProjectionOrder::Approximate;
  }
  const FrameSettings& s = frame.Settings;
  frame.Stats.ProjectedTriangles = frame.Stats.ProjectedSlabs = 0;
  if (!this->WarnedFeatures &&
    (s.NumberOfIsosurfaces() > 0 || s.Splatting || s.ViewDepthClipping || !s.ColorArray.empty() ||
      s.HasClippingPlanes))
  {
    this->WarnedFeatures = true;
    frame.Warning("OPENGL_PROJECTION ignores isosurfaces, separate fields, splatting, clipping "
                  "planes and view-depth clipping; use CPU_ACCURATE for them.");
  }
  const float* depth = s.UseDepthBuffer ? SceneDepth(frame, this->Depth) : nullptr;
  ProjectionRegions::Settings settings;
  ViewSettings(frame, settings);
  this->BackToFront.clear();
  frame.Drawn = this->PrepareFrame(frame);
  if (frame.Drawn)
  {
    const CellScene& scene = this->Scene;
    if (s.Order == ProjectionOrder::Exact)
    {
      const std::vector<vtkIdType>& frontToBack = scene.GetFrontToBack();
      this->BackToFront.resize(frontToBack.size());
      std::reverse_copy(frontToBack.begin(), frontToBack.end(), this->BackToFront.begin());
    }
    else
    {
      this->Regions.CentroidOrder(scene.GetCells(), settings, this->BackToFront);
    }
    vtkHighOrderTransferFunction* tf = this->Scene.GetTransferFunction();
    this->CheckColorRange(frame, tf);
    if (s.Semantics == OpacitySemantics::GPUCompatible)
    {
      // Slabs at the property's nodes only; the opacity per fragment is exact
      // (hov::GPUAverageExtinction), M3 integrates the refined table.
      settings.ExtinctionTf = &tf->GetTable();
      settings.InverseUnit = 1.0 / tf->GetUnitDistance();
    }
  }
  float* pixels = FloatImagePixels(floatImage, "RGBA", 4, frame.Width, frame.Height, true);
  const int f = std::max(frame.Subsampling, 1);
  const int rw = ReducedSize(frame.Width, f), rh = ReducedSize(frame.Height, f);
  if (f > 1)
  {
    if (depth)
    {
      ReduceDepth(depth, frame.Width, frame.Height, rw, rh, this->ReducedDepth);
      depth = this->ReducedDepth.data();
    }
    this->Reduced.resize(static_cast<size_t>(rw) * rh * 4);
  }
  this->BuildSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
  if (!this->Draw(frame, settings, depth, f > 1 ? this->Reduced.data() : pixels, rw, rh))
  {
    frame.Error("Could not draw the cell projection with OpenGL.");
    std::fill(pixels, pixels + static_cast<size_t>(frame.Width) * frame.Height * 4, 0.0f);
  }
  else if (frame.Stats.Aborted)
  {
    // Nothing was read back or shown (the mapper shows the last completed
    // progressive level, if any).
    std::fill(pixels, pixels + static_cast<size_t>(frame.Width) * frame.Height * 4, 0.0f);
  }
  else if (f > 1)
  {
    ExpandImage(this->Reduced.data(), rw, rh, 4, pixels, frame.Width, frame.Height);
  }
  frame.Stats.FixedSeconds = this->BuildSeconds;
  frame.Stats.Rays = static_cast<vtkIdType>(rw) * rh;
  frame.Stats.ProjectedTriangles = this->Statistics.Triangles;
  frame.Stats.ProjectedSlabs = this->Statistics.Slabs;
  return 1;
}

bool hov::ProjectionBackend::PrepareFrame(RenderFrame& frame)
{
  CellScene& scene = this->Scene;
  if (!frame.ValidateView() || !scene.Prepare(frame))
  {
    return false;
  }
  if (scene.GetCells().GetNumberOfRenderedCells() == 0)
  {
    frame.NoRenderedCell(frame.Stats.RenderedCells + frame.Stats.SkippedCells);
    return false;
  }
  bool rebuilt = false;
  if (!frame.UpdateTransferFunction(
        scene.GetTransferFunction(), frame.Settings.GPUOpacityTolerance, rebuilt))
  {
    frame.NoVisibleVolume(rebuilt);
    return false;
  }
  return frame.Settings.Order != ProjectionOrder::Exact || scene.PrepareOrder(frame, true);
}

bool hov::ProjectionBackend::Draw(RenderFrame& frame, ProjectionRegions::Settings& settings,
  const float* depth, float* pixels, int width, int height)
{
  // The cells in groups, built while the previous group is drawn.
  const CellSetup& cells = this->Scene.GetCells();
  vtkHighOrderTransferFunction* tf = this->Scene.GetTransferFunction();
  const vtkIdType total = static_cast<vtkIdType>(this->BackToFront.size());
  const vtkIdType largestGroup =
    std::max<vtkIdType>(CellsPerGroup, (total + MaxGroups - 1) / MaxGroups);
  vtkIdType group = std::min(largestGroup, FirstGroupCells);
  vtkIdType next = 0;
  this->Statistics = ProjectionRegions::Statistics();
  auto produce = [&](ProjectionRegions::Geometry& geometry) {
    if (next >= total)
    {
      return false;
    }
    // Progress and abort before each group (a group holds about 1/MaxGroups
    // of the cells, at least CellsPerGroup): an aborted frame draws nothing
    // over the scene.
    if (frame.Progress && frame.Progress(static_cast<double>(next) / total))
    {
      frame.Stats.Aborted = true;
      this->Renderer.Stop();
      return false;
    }
    const auto start = std::chrono::steady_clock::now();
    const vtkIdType last = std::min(total, next + group);
    this->Statistics.Add(this->Regions.Build(cells, this->BackToFront, next, last,
      settings.ExtinctionTf ? tf->GetLinearOpacityTable() : tf->GetTable(), settings, geometry));
    // The next group within the vertex budget at this group's cost per cell.
    const double bytesPerCell = static_cast<double>(geometry.GetNumberOfVertices()) *
      ProjectionVertex::FloatsPerVertex * sizeof(float) / (last - next);
    group = bytesPerCell * largestGroup <= GroupVertexBudget
      ? largestGroup
      : std::max(MinGroupCells, static_cast<vtkIdType>(GroupVertexBudget / bytesPerCell));
    next = last;
    this->BuildSeconds +=
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return true;
  };
  const ProjectionRenderer::Options options = RenderOptions(settings, frame.Settings);
  return this->Renderer.Render(
    frame.Renderer, produce, this->Geometry, options, depth, width, height, pixels);
}

void hov::ProjectionBackend::CheckColorRange(
  const RenderFrame& frame, vtkHighOrderTransferFunction* tf)
{
  // The vertex colours go to OpenGL as floats: a colour (times the
  // Wilhelms-Van Gelder emission factor) beyond float's range becomes Inf and
  // the fragments that carry it are lost. Warned once per table build.
  const int model = static_cast<int>(frame.Settings.Emission);
  if (this->ColorRangeCheckedBuild == tf->GetBuildCount() && this->ColorRangeCheckedModel == model)
  {
    return;
  }
  this->ColorRangeCheckedBuild = tf->GetBuildCount();
  this->ColorRangeCheckedModel = model;
  const TransferFunction& table = tf->GetTable();
  const double factor =
    frame.Settings.Emission == EmissionModel::WilhelmsVanGelder ? table.GetEmissionFactor() : 1.0;
  double largest = 0.0;
  for (int k = 0; k < table.GetNumberOfNodes(); ++k)
  {
    const TransferFunction::Node& n = table.GetNode(k);
    largest = std::max(largest, std::max(std::abs(n.R), std::max(std::abs(n.G), std::abs(n.B))));
  }
  if (!(largest * factor < 0.01 * FLT_MAX))
  {
    std::ostringstream text;
    text << "OPENGL_PROJECTION computes in float: colours up to " << largest * factor
         << " (colour" << (factor != 1.0 ? " x EmissionScale / unit distance" : "")
         << ") exceed its range; cells carrying them are not drawn. CPU_ACCURATE and RAY_CAST "
         << "compute in double.";
    frame.Warning(text.str());
  }
}

void hov::ProjectionBackend::ReleaseGraphicsResources(vtkWindow* win)
{
  this->Renderer.ReleaseGraphicsResources(win);
}
