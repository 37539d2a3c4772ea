// Issue 4, acceptance 2: the bundled CalculiX mixed-cell zoo
// (Testing/Data/zoo_mixed_ccx.vtu: 55968 tetrahedra, 2000 hexahedra, 10346
// wedges, 400 pyramids; steady heat conduction, point array "temperature").
// The mesh contains one cluster of three overlapping tetrahedra left by the
// mesher: the visibility relation then has cycles and rays cross overlapping
// cells. Our mapper reports it (a captured cycle warning, or the per-pixel
// witness count of rays crossing overlapping cells: asserted, printed); its
// warnings never reach ctest's error filter.
//
// Ours (VTK_UNSTRUCTURED semantics, native cells, default visibility-sort
// ordering) beside vtkProjectedTetrahedraMapper and
// vtkUnstructuredGridVolumeRayCastMapper on vtkDataSetTriangleFilter's
// tetrahedra (timed separately), and ours on the same tetrahedra. The
// transfer function's opacity nodes are also colour nodes. Asserted: small
// mean absolute differences per channel (x255); thresholds are the measured
// values (printed) with margin. See hovTestReferencePeers.h.
#include "hovTestReferenceDatasets.h"
#include "hovTestPeers.h"
#include "hovTestScenes.h"

#include "vtkCamera.h"
#include "vtkCellType.h"
#include "vtkPointData.h"
#include "vtkUnstructuredGrid.h"

#include <iostream>

using namespace hovTest;

int TestDatasetZoo(int argc, char* argv[])
{
  Checker ck;
  const std::string data = ArgAfter(argc, argv, "-D", ".");
  const std::string tmp = ArgAfter(argc, argv, "-T", ".");
  vtkSmartPointer<vtkUnstructuredGrid> grid =
    hovTestRef::LoadDataset(data, "zoo_mixed_ccx.vtu", "temperature");
  auto counts = hovTestRef::CellTypeCounts(grid);
  std::cout << "zoo: " << grid->GetNumberOfCells() << " cells ("
            << hovTestRef::DescribeCellTypes(grid) << "), " << grid->GetNumberOfPoints()
            << " points\n";
  if (!ck.Check(counts[VTK_TETRA] == 55968 && counts[VTK_HEXAHEDRON] == 2000 &&
          counts[VTK_WEDGE] == 10346 && counts[VTK_PYRAMID] == 400 &&
          grid->GetPointData()->GetScalars(),
        "zoo loaded: 55968 tets, 2000 hexahedra, 10346 wedges, 400 pyramids, 'temperature'"))
  {
    return ck.Result();
  }
  double tessSeconds = 0;
  vtkSmartPointer<vtkUnstructuredGrid> tess = hovTestRef::TetrahedralizeLinear(grid, tessSeconds);
  std::cout << "tessellation (vtkDataSetTriangleFilter): " << tess->GetNumberOfCells()
            << " tets, " << tessSeconds << " s\n";
  ck.Check(hovTestRef::CellTypeCounts(tess).size() == 1 &&
      hovTestRef::CellTypeCounts(tess)[VTK_TETRA] > grid->GetNumberOfCells(),
    "tessellation: tetrahedra only, more of them than cells");

  TF tf;
  hovTestRef::DatasetTF(tf.Property, 15.0, 120.0, 0.8);
  vtkNew<vtkCamera> cam;
  hovTestRef::ZooCamera(cam);
  const int size = 200;
  const hovTestRef::PeerRun run = hovTestRef::RenderWithPeers(grid, tess, tf.Property, cam, size,
    vtkHighOrderVolumeMapper::VISIBILITY_SORT, tmp, "TestDatasetZoo");
  hovTestRef::PrintPeerTable(run);
  std::cout << "  our warnings (captured): " << (run.OurWarnings.empty() ? "(none)" : run.OurWarnings)
            << "\n  witness violations (rays crossing overlapping cells): " << run.WitnessViolations
            << "\n  peers' messages (captured): "
            << (run.PeerMessages.empty() ? "(none)" : run.PeerMessages) << "\n";

  const Sanity s = CheckImage(run.Ours);
  ck.Check(run.OurStatus == 1 && run.OurErrors.empty(), "ours: RenderImage 1, no error");
  ck.Check(s.Ok() && s.Covered > size * size / 10, "ours: image sane, covers > 10%: " + s.Str());
  // The overlap is reported either as a visibility-cycle warning (if the
  // view's order has a cycle) or by the per-pixel witness (rays on which
  // cells overlap); in this view: no cycle, 22 witness pixels (measured).
  ck.Check(run.OurWarnings.find("cycle") != std::string::npos || run.WitnessViolations > 0,
    "ours: the overlapping tetrahedra are reported (cycle warning captured or witness " +
      std::to_string(run.WitnessViolations) + " > 0)");
  const double tessDiff = hovTestRef::MeanDiff255(run.Ours, run.OursTessellated);
  const double rcDiff = hovTestRef::MeanDiff255(run.RC, run.OursCorners);
  const double ptDiff = hovTestRef::MeanDiff255(run.PT, run.Ours);
  ck.Check(tessDiff <= 0.1,
    "ours native vs ours on the tetrahedra: mean <= 0.1/255 (measured " + Fmt(tessDiff) + ")");
  ck.Check(rcDiff <= 1.0,
    "RC (tetrahedra) vs ours native, corner rays: mean <= 1/255 (measured " + Fmt(rcDiff) + ")");
  ck.Check(ptDiff <= 1.0,
    "PT (tetrahedra) vs ours native: mean <= 1/255 (measured " + Fmt(ptDiff) + ")");
  return ck.Result();
}
