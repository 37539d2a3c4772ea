// The warnings about vtkVolumeProperty features the mapper does not honour
// (hov::PropertyAudit) and PrintSelf.
//
// For each unhonoured feature: switched on, three frames give exactly one
// warning, naming the feature; switched off, no warning; switched on again,
// exactly one warning again. Features read by the mapper (Shade and gradient
// opacity of component 0 in CPU_ACCURATE) give none. Then PrintSelf names
// every setting and diagnostic.
#include "hovTestReference.h"
#include "hovTestScenes.h"

#include "vtkCamera.h"
#include "vtkCommand.h"
#include "vtkFloatArray.h"
#include "vtkPlane.h"
#include "vtkPointData.h"
#include "vtkUnstructuredGrid.h"

#include <functional>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace
{
struct Feature
{
  const char* Name; ///< what the warning must contain
  std::function<void(vtkVolumeProperty*, vtkHighOrderVolumeMapper*)> On, Off;
  int Expected; ///< warnings when switched on (0: honoured)
};
}

int TestPropertyAudit(int, char*[])
{
  int failures = 0;
  const double origin[3] = { -1.0, -1.0, -1.0 }, g[3] = { 0.3, -0.2, 0.25 };
  vtkSmartPointer<vtkUnstructuredGrid> grid = hovTestRef::MakeCubeOfTetras(2, origin, 2.0, 6, 0.5, g);
  // A second, 3-component array for the component features.
  vtkNew<vtkFloatArray> vectors;
  vectors->SetName("v");
  vectors->SetNumberOfComponents(3);
  vectors->SetNumberOfTuples(grid->GetNumberOfPoints());
  for (vtkIdType i = 0; i < grid->GetNumberOfPoints(); ++i)
  {
    double x[3];
    grid->GetPoint(i, x);
    vectors->SetTuple3(i, 0.5 + 0.2 * x[0], 0.4 + 0.1 * x[1], 0.3);
  }
  grid->GetPointData()->AddArray(vectors);
  hovTest::VolumeScene scene(grid);
  hovTest::DefaultTF(scene.Tf);
  vtkHighOrderVolumeMapper* mapper = scene.Mapper;
  vtkVolumeProperty* p = scene.Tf.Property;
  vtkNew<hovTest::MessageCounter> counter;
  mapper->AddObserver(vtkCommand::WarningEvent, counter);
  mapper->AddObserver(vtkCommand::ErrorEvent, counter);
  vtkNew<vtkCamera> camera;
  hovTest::ObliqueCamera(camera);

  vtkNew<vtkPiecewiseFunction> go;
  go->AddPoint(0.0, 0.5);
  go->AddPoint(1.0, 1.0);
  vtkNew<vtkPiecewiseFunction> shapedGO;
  shapedGO->AddPoint(0.0, 0.5, 0.3, 0.0);
  shapedGO->AddPoint(1.0, 1.0);
  vtkNew<vtkColorTransferFunction> label;
  label->AddRGBPoint(0.0, 1.0, 0.0, 0.0);
  vtkNew<vtkPlane> plane;
  vtkNew<vtkVolumeProperty> labelled;
  labelled->DeepCopy(p);
  labelled->SetLabelColor(1, label);

  using P = vtkVolumeProperty*;
  using M = vtkHighOrderVolumeMapper*;
  const std::vector<Feature> features = {
    { "IndependentComponents off",
      [](P q, M m) {
        q->IndependentComponentsOff();
        m->SelectScalarArray("v");
        m->SetScalarMode(VTK_SCALAR_MODE_USE_POINT_FIELD_DATA);
      },
      [](P q, M m) {
        q->IndependentComponentsOn();
        m->SetScalarMode(VTK_SCALAR_MODE_DEFAULT);
      },
      1 },
    { "ComponentWeight of component 1", [](P q, M) { q->SetComponentWeight(1, 0.5); },
      [](P q, M) { q->SetComponentWeight(1, 1.0); }, 1 },
    { "Shade of component 2", [](P q, M) { q->SetShade(2, 1); }, [](P q, M) { q->SetShade(2, 0); },
      1 },
    { "gradient opacity of component 1", [&](P q, M) { q->SetGradientOpacity(1, go); },
      [](P q, M) { q->SetGradientOpacity(1, nullptr); }, 1 },
    { "midpoints and sharpness", [&](P q, M) { q->SetGradientOpacity(shapedGO); },
      [](P q, M) { q->SetGradientOpacity(nullptr); }, 1 },
    { "TF_2D", [](P q, M) { q->SetTransferFunctionMode(vtkVolumeProperty::TF_2D); },
      [](P q, M) { q->SetTransferFunctionMode(vtkVolumeProperty::TF_1D); }, 1 },
    // vtkVolumeProperty cannot remove a label: another property has it.
    { "label-map", [&](P, M) { scene.Volume->SetProperty(labelled); },
      [&](P q, M) { scene.Volume->SetProperty(q); }, 1 },
    { "SliceFunction", [&](P q, M) { q->SetSliceFunction(plane); },
      [](P q, M) { q->SetSliceFunction(nullptr); }, 1 },
    { "UseClippedVoxelIntensity", [](P q, M) { q->UseClippedVoxelIntensityOn(); },
      [](P q, M) { q->UseClippedVoxelIntensityOff(); }, 1 },
    { "Shade (volume shading) is not applied in CPU_ACCURATE mode with isosurfaces",
      [](P q, M m) {
        q->ShadeOn();
        m->AddIsosurface(0.5, 1.0, 1.0, 1.0, 0.5);
      },
      [](P q, M m) {
        q->ShadeOff();
        m->RemoveAllIsosurfaces();
      },
      1 },
    // Honoured: no warning (NEAREST as VTK's unstructured mappers: ignored).
    { "", [](P q, M) { q->SetInterpolationTypeToNearest(); },
      [](P q, M) { q->SetInterpolationTypeToLinear(); }, 0 },
    { "", [](P q, M) { q->ShadeOn(); }, [](P q, M) { q->ShadeOff(); }, 0 },
    { "", [&](P q, M) { q->SetGradientOpacity(go); }, [](P q, M) { q->SetGradientOpacity(nullptr); },
      0 },
  };

  auto frames = [&](int n) {
    for (int i = 0; i < n; ++i)
    {
      mapper->RenderImage(camera, scene.Volume, 24, 20);
    }
  };
  counter->Clear();
  frames(1);
  if (counter->Warnings || counter->Errors)
  {
    std::cerr << "FAILED: messages with the default property: " << counter->Text << "\n";
    ++failures;
  }
  for (const Feature& f : features)
  {
    for (int round = 0; round < 2; ++round)
    {
      counter->Clear();
      f.On(p, mapper);
      frames(3);
      const bool named = counter->Text.find(f.Name) != std::string::npos;
      std::cout << "'" << f.Name << "' round " << round << ": " << counter->Warnings
                << " warnings over 3 frames\n";
      if (counter->Warnings != f.Expected || counter->Errors || !named)
      {
        std::cerr << "FAILED: '" << f.Name << "' on (round " << round << "): want " << f.Expected
                  << " warning naming it, got " << counter->Warnings << " warnings, "
                  << counter->Errors << " errors: " << counter->Text << "\n";
        ++failures;
      }
      counter->Clear();
      f.Off(p, mapper);
      frames(2);
      if (counter->Warnings || counter->Errors)
      {
        std::cerr << "FAILED: '" << f.Name << "' off: " << counter->Text << "\n";
        ++failures;
      }
    }
  }

  // PrintSelf names every setting and diagnostic.
  p->ShadeOn();
  frames(1);
  std::ostringstream os;
  mapper->Print(os);
  const char* names[] = { "RenderMode", "RayCastTolerance", "InteractiveSubsampling",
    "OpacitySemantics", "CellOrdering", "GPUOpacityTolerance", "EmissionModel", "EmissionScale",
    "IntegrationMethod", "VectorMode", "VectorComponent", "TerminationTransmittance",
    "UseDepthBuffer", "TileSize", "ViewDepthClipping", "VisibilitySort", "Isosurfaces",
    "ColorArrayName", "IsosurfaceArrayName", "Splatting", "ProjectionColorMethod",
    "ProjectionOrder", "ProjectionOpacityLookup", "BlendMode", "LastImageTime",
    "LastRenderAborted", "LastRenderWasInteractive", "LastSubsampling", "LastDrawingMode",
    "AutoAdjustImageSampleDistance", "ProgressiveTime", "AverageIPScalarRange",
    "WitnessViolations", "NumberOfRenderedCells", "NumberOfSkippedCells", "NumberOfSegments",
    "NumberOfPieces", "NumberOfRays", "NumberOfSplattedCells", "NumberOfProjectedTriangles",
    "NumberOfProjectedSlabs", "ShadingErrorEstimate", "Shading (last frame): Shade 1",
    "GradientOpacity (last frame)", "UnhonouredFeatures", "TransferFunction",
    "NumberOfNodes" };
  for (const char* name : names)
  {
    if (os.str().find(name) == std::string::npos)
    {
      std::cerr << "FAILED: PrintSelf does not name " << name << "\n";
      ++failures;
    }
  }
  if (failures)
  {
    std::cerr << os.str();
  }
  return failures ? 1 : 0;
}
