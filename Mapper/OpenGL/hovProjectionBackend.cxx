// vtkHighOrderVolumeMapper: the OPENGL_PROJECTION render mode (HIAC section 7).
// Builds the region triangles on the CPU (hov::ProjectionRegions),
// draws them with OpenGL (hov::ProjectionRenderer) and publishes the
// float image.
#include "vtkHighOrderVolumeMapper.h"

#include "hovImageDisplay.h" // ReadDepth
#include "hovProjectionBackend.h"   // mode state
#include "hovProjectionVertex.h" // FloatsPerVertex (group budget)
#include "hovCellSetup.h"   // cells
#include "vtkHighOrderTransferFunction.h"

#include "hovTransferFunction.h" // the table

#include "vtkCamera.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkMatrix4x4.h"
#include "vtkPlaneCollection.h"
#include "vtkPointData.h"
#include "vtkRenderer.h"
#include "vtkTimerLog.h"
#include "vtkVolume.h"

#include <algorithm> // std::reverse_copy, std::all_of
#include <cfloat>    // FLT_MAX
#include <cmath>     // std::abs
#include <cstring>   // std::memcpy

namespace
{
/// Cells per group at least (hov::ProjectionRenderer draws a group
/// while the next is built; at most MaxGroups groups).
constexpr vtkIdType CellsPerGroup = 8192;
constexpr vtkIdType MaxGroups = 32;
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
void ViewSettings(vtkCamera* camera, vtkVolume* volume, double aspect,
  hov::ProjectionRegions::Settings& settings)
{
  const glm::dmat4 model = ToGlm(volume->GetMatrix());
  settings.Composite =
    ToGlm(camera->GetCompositeProjectionTransformMatrix(aspect, -1.0, 1.0)) * model;
  const glm::dmat4 inverseModel = glm::inverse(model);
  double eye[3], dop[3];
  camera->GetPosition(eye);
  camera->GetDirectionOfProjection(dop);
  const glm::dvec4 e = inverseModel * glm::dvec4(eye[0], eye[1], eye[2], 1.0);
  settings.Eye = glm::dvec3(e) / e.w;
  settings.Direction = glm::dvec3(inverseModel * glm::dvec4(dop[0], dop[1], dop[2], 0.0));
  settings.Parallel = camera->GetParallelProjection() != 0;
}

/**
 * The scene depth of the viewport into @p depth; null if it cannot be read or
 * if it is the far plane everywhere (no opaque geometry in the viewport: the
 * depth test could reject nothing, so the projection skips it and its
 * per-fragment cost).
 */
const float* SceneDepth(
  vtkRenderer* ren, int width, int height, int x0, int y0, std::vector<float>& depth)
{
  depth.resize(static_cast<size_t>(width) * height);
  if (!hov::ImageDisplay::ReadDepth(ren, width, height, x0, y0, depth.data()))
  {
    return nullptr;
  }
  const bool allFar =
    std::all_of(depth.begin(), depth.end(), [](float z) { return z >= 1.0f; });
  return allFar ? nullptr : depth.data();
}

/// proj.BackToFront: @p frontToBack reversed (exact order) or, if null, the centroid order.
void BackToFront(hov::ProjectionState& proj, const hov::CellSetup& setup,
  const std::vector<vtkIdType>* frontToBack, const hov::ProjectionRegions::Settings& settings)
{
  if (frontToBack)
  {
    proj.BackToFront.resize(frontToBack->size());
    std::reverse_copy(frontToBack->begin(), frontToBack->end(), proj.BackToFront.begin());
  }
  else
  {
    proj.Regions.CentroidOrder(setup, settings, proj.BackToFront);
  }
}

/// The renderer's options for the region @p settings.
hov::ProjectionRenderer::Options RenderOptions(
  const hov::ProjectionRegions::Settings& settings)
{
  hov::ProjectionRenderer::Options options;
  options.TextureOpacity = settings.Method != hov::ProjectionColorMethod::InterpolatedOpacity;
  options.PremultipliedColor = settings.Emission == hov::EmissionModel::WilhelmsVanGelder;
  options.Parallel = settings.Parallel;
  options.ClipToData = glm::inverse(settings.Composite);
  options.Eye = settings.Eye;
  return options;
}

/**
 * The RGBA float array of @p image resized to @p width x @p height (reused
 * when nobody else holds it, so the frame's read-back goes straight into it);
 * marked modified.
 */
float* FloatImagePixels(vtkImageData* image, int width, int height)
{
  const vtkIdType n = static_cast<vtkIdType>(width) * height;
  image->SetDimensions(width, height, 1);
  auto* array = vtkFloatArray::SafeDownCast(image->GetPointData()->GetScalars());
  if (!array || array->GetReferenceCount() > 1 || array->GetNumberOfComponents() != 4 ||
    array->GetNumberOfTuples() != n)
  {
    vtkNew<vtkFloatArray> fresh;
    fresh->SetName("RGBA");
    fresh->SetNumberOfComponents(4);
    fresh->SetNumberOfTuples(n);
    image->GetPointData()->SetScalars(fresh);
    array = fresh;
  }
  array->Modified();
  image->Modified();
  return array->GetPointer(0);
}
}

void vtkHighOrderVolumeMapper::RenderProjection(vtkRenderer* ren, vtkVolume* vol)
{
  vtkNew<vtkTimerLog> timer;
  timer->StartTimer();
  hov::ProjectionState& proj = *this->ProjectionImpl;
  int width = 0, height = 0, x0 = 0, y0 = 0;
  ren->GetTiledSizeAndOrigin(&width, &height, &x0, &y0);
  if (width <= 0 || height <= 0)
  {
    return;
  }
  this->WitnessViolations = this->NumberOfSegments = this->NumberOfPieces = 0;
  this->NumberOfRays = 0;
  this->NumberOfSplattedCells = 0;
  this->NumberOfProjectedTriangles = this->NumberOfProjectedSlabs = 0;
  this->LastRenderAborted = false; // a projection frame is never aborted
  if (!proj.WarnedFeatures &&
    (this->GetNumberOfIsosurfaces() > 0 || this->Splatting || this->ViewDepthClipping ||
      (this->ColorArrayName && *this->ColorArrayName) ||
      (this->ClippingPlanes && this->ClippingPlanes->GetNumberOfItems() > 0)))
  {
    proj.WarnedFeatures = true;
    vtkWarningMacro("OPENGL_PROJECTION ignores isosurfaces, separate fields, splatting, clipping "
                    "planes and view-depth clipping; use CPU_ACCURATE for them.");
  }
  const float* depth =
    this->UseDepthBuffer ? SceneDepth(ren, width, height, x0, y0, proj.Depth) : nullptr;
  vtkCamera* camera = ren->GetActiveCamera();
  const bool exactOrder = this->ProjectionOrder == EXACT_ORDER;
  const hov::CellSetup* setup = nullptr;
  const std::vector<vtkIdType>* frontToBack = nullptr;
  vtkHighOrderTransferFunction* tf = nullptr;
  hov::ProjectionRegions::Settings settings;
  ViewSettings(camera, vol, ren->GetTiledAspectRatio(), settings);
  settings.Method = static_cast<hov::ProjectionColorMethod>(this->ProjectionColorMethod);
  settings.Emission = static_cast<hov::EmissionModel>(this->EmissionModel);
  proj.BackToFront.clear();
  const bool drawn = this->PrepareProjectionFrame(
    camera, vol, ren->GetTiledAspectRatio(), exactOrder, &setup, &frontToBack, &tf);
  if (drawn)
  {
    BackToFront(proj, *setup, exactOrder ? frontToBack : nullptr, settings);
    this->CheckProjectionColorRange(tf);
    if (this->OpacitySemantics == GPU_COMPATIBLE)
    {
      // Slabs at the property's nodes only; the opacity per fragment is exact
      // (hov::GPUAverageExtinction), M3 integrates the refined table.
      settings.ExtinctionTf = &tf->GetTable();
      settings.InverseUnit = 1.0 / tf->GetUnitDistance();
    }
  }
  // The cells in groups, built while the previous group is drawn.
  const vtkIdType total = static_cast<vtkIdType>(proj.BackToFront.size());
  const vtkIdType largestGroup =
    std::max<vtkIdType>(CellsPerGroup, (total + MaxGroups - 1) / MaxGroups);
  vtkIdType group = std::min(largestGroup, FirstGroupCells);
  vtkIdType next = 0;
  proj.Statistics = hov::ProjectionRegions::Statistics();
  auto produce = [&](hov::ProjectionRegions::Geometry& geometry) {
    if (next >= total)
    {
      return false;
    }
    const vtkIdType last = std::min(total, next + group);
    proj.Statistics.Add(proj.Regions.Build(*setup, proj.BackToFront, next, last,
      settings.ExtinctionTf ? tf->GetLinearOpacityTable() : tf->GetTable(), settings, geometry));
    // The next group within the vertex budget at this group's cost per cell.
    const double bytesPerCell = static_cast<double>(geometry.GetNumberOfVertices()) *
      hov::ProjectionVertex::FloatsPerVertex * sizeof(float) / (last - next);
    group = bytesPerCell * largestGroup <= GroupVertexBudget
      ? largestGroup
      : std::max(MinGroupCells, static_cast<vtkIdType>(GroupVertexBudget / bytesPerCell));
    next = last;
    return true;
  };
  hov::ProjectionRenderer::Options options = RenderOptions(settings);
  options.AnalyticOpacity = this->ProjectionOpacityLookup == OPACITY_ANALYTIC;
  options.GPUOpacity = settings.ExtinctionTf != nullptr;
  options.InverseUnit = settings.InverseUnit;
  float* pixels = FloatImagePixels(this->GetFloatImage(), width, height);
  if (!proj.Renderer.Render(ren, produce, proj.Geometry, options, depth, width, height, pixels))
  {
    vtkErrorMacro("Could not draw the cell projection with OpenGL.");
    std::fill(pixels, pixels + static_cast<size_t>(width) * height * 4, 0.0f);
  }
  this->CheckFrameImage(pixels, static_cast<size_t>(width) * height, drawn);
  this->NumberOfProjectedTriangles = proj.Statistics.Triangles;
  this->NumberOfProjectedSlabs = proj.Statistics.Slabs;
  timer->StopTimer();
  this->LastImageTime = this->TimeToDraw = timer->GetElapsedTime();
}

void vtkHighOrderVolumeMapper::CheckProjectionColorRange(vtkHighOrderTransferFunction* tf)
{
  // The vertex colours go to OpenGL as floats: a colour (times the
  // Wilhelms-Van Gelder emission factor) beyond float's range becomes Inf and
  // the fragments that carry it are lost. Warned once per table build.
  hov::ProjectionState& proj = *this->ProjectionImpl;
  if (proj.ColorRangeCheckedBuild == tf->GetBuildCount() &&
    proj.ColorRangeCheckedModel == this->EmissionModel)
  {
    return;
  }
  proj.ColorRangeCheckedBuild = tf->GetBuildCount();
  proj.ColorRangeCheckedModel = this->EmissionModel;
  const hov::TransferFunction& table = tf->GetTable();
  const double factor = this->EmissionModel == WILHELMS_VAN_GELDER ? table.GetEmissionFactor() : 1.0;
  double largest = 0.0;
  for (int k = 0; k < table.GetNumberOfNodes(); ++k)
  {
    const hov::TransferFunction::Node& n = table.GetNode(k);
    largest = std::max(largest, std::max(std::abs(n.R), std::max(std::abs(n.G), std::abs(n.B))));
  }
  if (!(largest * factor < 0.01 * FLT_MAX))
  {
    vtkWarningMacro("OPENGL_PROJECTION computes in float: colours up to "
      << largest * factor << " (colour" << (factor != 1.0 ? " x EmissionScale / unit distance" : "")
      << ") exceed its range; cells carrying them are not drawn. CPU_ACCURATE and RAY_CAST "
      << "compute in double.");
  }
}
