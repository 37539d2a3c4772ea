// The oracle (hovSortOracle) judged against an order known to be exact: a
// Delaunay tetrahedralization (vtkDelaunay3D of jittered points) sorted by
// power distance from the eye (|E - c|^2 - r^2 of each circumsphere,
// decreasing back to front) is a visibility order for every perspective view
// from outside (Edelsbrunner 1989; Max, Hanrahan & Crawfis 1990). The oracle
// must report 0 violations and 0 overlaps for it (no false positives), and
// must catch a swap of two cells sharing a visible face, a reversed order
// and a broken permutation (no false negatives). vtkSteinVisibilitySort is
// also checked on this mesh.
#include "hovSortCases.h"
#include "hovTestScenes.h"

#include "vtkCamera.h"
#include "vtkDelaunay3D.h"
#include "vtkIdList.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkTetra.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <iostream>
#include <numeric>
#include <string>

using namespace hovTest;

namespace
{
vtkSmartPointer<vtkUnstructuredGrid> DelaunayMesh()
{
  SortRandom rng(77);
  vtkNew<vtkPoints> pts;
  pts->SetDataTypeToDouble();
  for (int k = 0; k < 600; ++k)
  {
    pts->InsertNextPoint(rng.Uniform(), rng.Uniform(), rng.Uniform());
  }
  vtkNew<vtkPolyData> pd;
  pd->SetPoints(pts);
  vtkNew<vtkDelaunay3D> del;
  del->SetInputData(pd);
  del->Update();
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  grid->DeepCopy(del->GetOutput());
  return grid;
}

std::vector<vtkIdType> PowerOrder(vtkUnstructuredGrid* g, const double eye[3])
{
  const vtkIdType n = g->GetNumberOfCells();
  std::vector<double> key(n);
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < n; ++c)
  {
    g->GetCellPoints(c, ids);
    double p[4][3], ctr[3];
    for (int k = 0; k < 4; ++k)
    {
      g->GetPoint(ids->GetId(k), p[k]);
    }
    const double r2 = vtkTetra::Circumsphere(p[0], p[1], p[2], p[3], ctr);
    key[c] = (eye[0] - ctr[0]) * (eye[0] - ctr[0]) + (eye[1] - ctr[1]) * (eye[1] - ctr[1]) +
      (eye[2] - ctr[2]) * (eye[2] - ctr[2]) - r2;
  }
  std::vector<vtkIdType> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](vtkIdType a, vtkIdType b) { return key[a] > key[b]; });
  return order;
}
}

int TestSortOracle(int, char*[])
{
  Checker ck;
  int swapRayCatches = 0; // the rays are samples: a small swapped face may be missed
  vtkSmartPointer<vtkUnstructuredGrid> mesh = DelaunayMesh();
  std::cout << "Delaunay mesh: " << mesh->GetNumberOfCells() << " tets\n";
  ck.Check(mesh->GetNumberOfCells() > 2000, "Delaunay mesh built");
  double b[6];
  mesh->GetBounds(b);
  std::vector<SortView> views = RandomViews(b, 4, 5); // 2 perspective views
  PrintSortHeader();
  for (const SortView& v : views)
  {
    if (v.Parallel)
    {
      continue; // power distance is for a finite eye
    }
    vtkNew<vtkCamera> cam;
    v.Apply(cam);
    std::vector<vtkIdType> order = PowerOrder(mesh, v.Position);
    const OracleResult exact = CheckVisibilityOrder(mesh, cam, nullptr, order);
    std::cout << "  " << v.Name << ", power order: " << exact.Str() << "\n";
    ck.Check(exact.EveryCellOnce() && exact.RayViolations == 0 && exact.FaceViolations == 0 &&
        exact.OverlappingPairs == 0 && exact.FacesChecked > 1000 && exact.PairsChecked > 10000,
      v.Name + ": the oracle accepts the power-distance order (no false positive)");

    std::vector<vtkIdType> reversed(order.rbegin(), order.rend());
    const OracleResult rev = CheckVisibilityOrder(mesh, cam, nullptr, reversed);
    ck.Check(rev.FaceViolations == rev.FacesChecked && rev.RayViolations > 1000,
      v.Name + ": reversed order: every face wrong (" + std::to_string(rev.FaceViolations) +
        "/" + std::to_string(rev.FacesChecked) + "), " + std::to_string(rev.RayViolations) +
        " ray pairs");

    // Swap one back/front pair across an interior face: find two cells with 3 common points.
    vtkIdType a = -1, bcell = -1;
    for (size_t i = order.size() / 2; i + 1 < order.size() && a < 0; ++i)
    {
      vtkNew<vtkIdList> p, q, common;
      mesh->GetCellPoints(order[i], p);
      for (size_t j = i + 1; j < std::min(order.size(), i + 40) && a < 0; ++j)
      {
        mesh->GetCellPoints(order[j], q);
        common->DeepCopy(p);
        common->IntersectWith(q);
        if (common->GetNumberOfIds() == 3)
        {
          a = static_cast<vtkIdType>(i);
          bcell = static_cast<vtkIdType>(j);
        }
      }
    }
    std::vector<vtkIdType> swapped = order;
    std::swap(swapped[a], swapped[bcell]);
    const OracleResult sw = CheckVisibilityOrder(mesh, cam, nullptr, swapped);
    swapRayCatches += sw.RayViolations > 0;
    ck.Check(a >= 0 && sw.FaceViolations >= 1,
      v.Name + ": a swap of two face neighbours is caught (" + std::to_string(sw.FaceViolations) +
        " faces, " + std::to_string(sw.RayViolations) + " ray pairs)");

    std::vector<vtkIdType> broken = order;
    broken[3] = broken[4];
    const OracleResult br = CheckVisibilityOrder(mesh, cam, nullptr, broken);
    ck.Check(br.Duplicates == 1 && br.Missing == 1 && !br.EveryCellOnce(),
      v.Name + ": a duplicate/missing cell is caught");

    const SortCase c = RunSortCase("Delaunay", mesh, v, nullptr);
    PrintSortCase(c);
    CheckExactCase(ck, c);
  }
  ck.Check(swapRayCatches >= 1, "the rays also catch the swap in " +
      std::to_string(swapRayCatches) + " of 2 views");
  return ck.Result();
}
