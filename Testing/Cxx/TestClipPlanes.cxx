// Clipping per pixel on the ray (issue 4): the mapper's vtkPlaneCollection
// clipping planes (world coordinates, the normal's side kept) and the
// view-depth slab (SetViewDepthClipping/SetViewDepthRange: world distance
// from the camera along the direction of projection), for the linear
// tetrahedra and the general cells, in both cell orderings.
//
// Scene: a box [0,2]x[0,1]x[0,1] with a CONSTANT field, its left half as
// 12 tetrahedra (the fast path), its right half as a hexahedron below two
// wedges (general cells). The volume has a
// non-trivial matrix (scale, rotation, translation), so planes and depths are
// transformed to dataset coordinates, where lengths are measured. Closed form
// per pixel: alpha = 1 - exp(-tau L), rgb = c alpha, with L the length (in
// dataset units) of the part of the pixel ray inside the box and inside every
// clip half-space, computed independently in long double (world planes
// evaluated at world points of the data ray). Cases: two oblique planes; the
// view-depth slab; both together; orthographic and perspective views.
// Every pixel whose ray is farther than 1e-9 from the box edges must match to
// 1e-9 (double image), and the clipped image must differ from the unclipped
// one (the clipping is exercised); switched off again, the full box renders.
#include "hovTestAnalytic.h"
#include "hovTestMixed.h"
#include "hovTestReference.h"
#include "hovTestScenes.h"

#include "vtkCamera.h"
#include "vtkMatrix4x4.h"
#include "vtkPlane.h"
#include "vtkPlaneCollection.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>

using namespace hovTest;
using hovTestRef::Real;

namespace
{
constexpr int W = 64, H = 56;
constexpr double Tolerance = 1e-9;
const double Colour[3] = { 0.3, 0.8, 0.5 };
constexpr double Opacity = 0.7, Unit = 0.5; // tau = 1.4
const double Box[6] = { 0, 2, 0, 1, 0, 1 };

double Constant(double, double, double)
{
  return 2.0;
}

MeshBuilder ClipMesh()
{
  MeshBuilder m;
  const double o[3] = { 0, 0, 0 };
  const double a[3][3] = { { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 0.5 } };
  const std::vector<vtkIdType> ids = AddLattice(m, 2, 1, 2, o, a, Constant);
  AddCube(m, LatticeCube(ids, 2, 1, 0, 0, 0), CubeSplit::Tetras, Constant);
  AddCube(m, LatticeCube(ids, 2, 1, 0, 0, 1), CubeSplit::Tetras, Constant);
  AddCube(m, LatticeCube(ids, 2, 1, 1, 0, 0), CubeSplit::Hexahedron, Constant);
  AddCube(m, LatticeCube(ids, 2, 1, 1, 0, 1), CubeSplit::Wedges, Constant);
  return m;
}

/// A half-space n.x + d >= 0 (world coordinates).
struct HalfSpace
{
  Real N[3];
  Real D;
};

/// Narrows [t0, t1] of the data ray to where its world image satisfies @p h.
void Clip(const hovTestRef::Ray& ray, vtkMatrix4x4* m, const HalfSpace& h, Real& t0, Real& t1)
{
  // World point w(t) = M (O + t D) = W0 + t W1.
  Real value0 = h.D, slope = 0;
  for (int r = 0; r < 3; ++r)
  {
    Real w0 = m->GetElement(r, 3), w1 = 0;
    for (int c = 0; c < 3; ++c)
    {
      w0 += m->GetElement(r, c) * ray.Origin[c];
      w1 += m->GetElement(r, c) * ray.Direction[c];
    }
    value0 += h.N[r] * w0;
    slope += h.N[r] * w1;
  }
  if (slope > 0)
  {
    t0 = std::max(t0, -value0 / slope);
  }
  else if (slope < 0)
  {
    t1 = std::min(t1, -value0 / slope);
  }
  else if (value0 < 0)
  {
    t1 = t0;
  }
}
}

int TestClipPlanes(int, char*[])
{
  Checker ck;
  const double tau = Opacity / Unit;
  VolumeScene scene(ClipMesh().Grid());
  ConstantTF(scene.Tf, Colour, Opacity, Unit);
  scene.Mapper->SetOpacitySemanticsToVTKUnstructured();
  // Data -> world: scale, rotation about z, translation.
  scene.Volume->SetScale(1.3, 0.9, 1.1);
  scene.Volume->SetOrientation(0, 0, 20);
  scene.Volume->SetPosition(0.4, -0.3, 0.2);
  vtkMatrix4x4* matrix = scene.Volume->GetMatrix();

  // World planes through the box (normal side kept).
  const double planeOrigin[2][3] = { { 1.2, 0.3, 0.6 }, { 1.0, 0.5, 0.5 } };
  const double planeNormal[2][3] = { { -0.6, 0.3, 0.74 }, { 0.8, 0.5, -0.2 } };
  vtkNew<vtkPlaneCollection> planes;
  for (int p = 0; p < 2; ++p)
  {
    vtkNew<vtkPlane> plane;
    plane->SetOrigin(planeOrigin[p][0], planeOrigin[p][1], planeOrigin[p][2]);
    plane->SetNormal(planeNormal[p][0], planeNormal[p][1], planeNormal[p][2]);
    planes->AddItem(plane);
  }
  struct View
  {
    const char* Name;
    double Direction[3];
    bool Parallel;
    double AngleOrScale;
  };
  const View views[2] = { { "ortho", { 0.3, -0.5, 0.8 }, true, 1.6 },
    { "perspective", { -0.5, -0.6, 0.6 }, false, 35.0 } };
  for (const View& v : views)
  {
    vtkNew<vtkCamera> cam;
    const double focal[3] = { 1.35, 0.35, 0.75 };
    const double up[3] = { 0, 0, 1 };
    PlaceCamera(cam, focal, v.Direction, 6.0, up, v.Parallel, v.AngleOrScale);
    cam->SetClippingRange(1.0, 20.0);
    const hovTestRef::CameraSpec spec = hovTestRef::ReadCamera(cam);
    double eye[3], dop[3];
    cam->GetPosition(eye);
    cam->GetDirectionOfProjection(dop);
    const double depthRange[2] = { 5.6, 6.3 }; // the box's centre is 6 from the eye
    // Modes: planes, slab, both, and clipping switched off again (full chords).
    for (int mode = 0; mode < 4; ++mode)
    {
      const bool usePlanes = mode == 0 || mode == 2, useDepth = mode == 1 || mode == 2;
      const char* modeName = mode == 0 ? "2 planes"
        : mode == 1                    ? "view-depth slab"
        : mode == 2                    ? "planes + slab"
                                       : "clipping off";
      scene.Mapper->SetClippingPlanes(usePlanes ? planes.Get() : static_cast<vtkPlaneCollection*>(nullptr));
      scene.Mapper->SetViewDepthClipping(useDepth);
      scene.Mapper->SetViewDepthRange(depthRange[0], depthRange[1]);
      std::vector<HalfSpace> halves;
      if (usePlanes)
      {
        for (int p = 0; p < 2; ++p)
        {
          const double* n = planeNormal[p];
          const double* o = planeOrigin[p];
          halves.push_back({ { n[0], n[1], n[2] }, -(Real(n[0]) * o[0] + Real(n[1]) * o[1] + Real(n[2]) * o[2]) });
        }
      }
      if (useDepth)
      {
        const Real de = Real(dop[0]) * eye[0] + Real(dop[1]) * eye[1] + Real(dop[2]) * eye[2];
        halves.push_back({ { dop[0], dop[1], dop[2] }, -(de + depthRange[0]) });
        halves.push_back({ { -dop[0], -dop[1], -dop[2] }, de + depthRange[1] });
      }
      for (int order : { vtkHighOrderVolumeMapper::VISIBILITY_SORT,
             vtkHighOrderVolumeMapper::PER_PIXEL_SORT })
      {
        scene.Mapper->SetCellOrdering(order);
        scene.Observer->Clear();
        int status = 0;
        const Image img = RenderDouble(scene.Mapper, cam, scene.Volume, W, H, &status);
        const std::string label = std::string(v.Name) + ", " + modeName + ", " +
          (order ? "PER_PIXEL_SORT" : "VISIBILITY_SORT");
        double maxErr = 0.0;
        int clipped = 0, covered = 0, bad = 0;
        for (int j = 0; j < H && img.W == W; ++j)
        {
          for (int i = 0; i < W; ++i)
          {
            const hovTestRef::Ray ray =
              hovTestRef::ToDataCoordinates(hovTestRef::PixelRay(spec, i, j, W, H), matrix);
            if (hovTestRef::DistanceToBoxEdges(ray, Box) < GrazeDistance)
            {
              continue;
            }
            Real t0 = 0, t1 = 0;
            Real chord = 0, full = 0;
            if (hovTestRef::IntersectBox(ray, Box, t0, t1))
            {
              full = t1 - t0;
              for (const HalfSpace& h : halves)
              {
                Clip(ray, matrix, h, t0, t1);
              }
              chord = std::max(Real(0), t1 - t0);
            }
            clipped += chord < full - 1e-6;
            covered += chord > 0;
            const double alpha = -std::expm1(-tau * static_cast<double>(chord));
            double err = std::abs(img.At(i, j, 3) - alpha);
            for (int c = 0; c < 3; ++c)
            {
              err = std::max(err, std::abs(img.At(i, j, c) - Colour[c] * alpha));
            }
            if (!(err <= Tolerance) && bad++ < 3)
            {
              std::cout << "  pixel (" << i << "," << j << "): chord " << static_cast<double>(chord)
                        << " of " << static_cast<double>(full) << ", alpha " << img.At(i, j, 3)
                        << " expected " << alpha << "\n";
            }
            maxErr = std::max(maxErr, err);
          }
        }
        std::cout << "== " << label << ": " << covered << " covered, " << clipped
                  << " clipped pixels, max error " << Fmt(maxErr) << ", segments "
                  << scene.Mapper->GetNumberOfSegments() << "\n";
        ck.Check(status == 1 && scene.NoMessages(), label + ": renders without messages");
        ck.Check(covered > 100 && (mode == 3 ? clipped == 0 : clipped > 100),
          label + (mode == 3 ? ": > 100 covered pixels" : ": > 100 covered pixels, > 100 clipped"));
        ck.Check(bad == 0, label + ": every pixel equals 1-exp(-tau L_clipped) within " +
            Fmt(Tolerance) + " (max " + Fmt(maxErr) + ")");
      }
    }
  }
  return ck.Result();
}
