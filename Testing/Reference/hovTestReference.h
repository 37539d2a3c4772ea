/**
 * @file hovTestReference.h
 * @brief Independent reference for the analytic mapper tests: the
 * emission-absorption integral along one ray by adaptive high-precision
 * quadrature, exact pixel rays built from the camera's parameters, exact
 * ray/box and ray/tetrahedron intersection, and small mesh builders.
 *
 * Nothing here uses the module's code (no hov:: kernel, no
 * vtkHighOrderTransferFunction, no hov::ViewRays): the transfer
 * functions are read through vtkColorTransferFunction::GetColor and
 * vtkPiecewiseFunction::GetValue, rays are built from the camera's position,
 * focal point, view up, view angle / parallel scale and clipping range.
 *
 * Ray integral (IntegrateRay): the scalar is linear along the ray,
 * s(t) = s0 + (s1 - s0) t / L on [0, L]. The t-range is split wherever s(t)
 * crosses a colour or opacity node; on each piece a(s(t)) and c(s(t)) are
 * linear in t, so
 *  - the optical depth from the front D(t) is exact per piece: trapezoid for
 *    the linear semantics (tau = a/u, tau = a), and for GPU-compatible
 *    semantics (tau = -ln(1 - a)/u, p = 1 - a linear in t)
 *      int_0^x -ln p = x [1 - ln p0 - (1 + r) log1p(r)/r],  r = (p(x) - p0)/p0,
 *    (the p ln p closed form written without cancellation);
 *  - the colour integral (Williams-Max: c tau exp(-D); Wilhelms-Van Gelder:
 *    EmissionScale c / u exp(-D)) is done by adaptive Gauss-Kronrod (31
 *    points) in long double on each piece (relative tolerance 1e-12), whose integrand is analytic there;
 *  - alpha = 1 - exp(-D(L)) = -expm1(-D(L)).
 * IntegrateRayBruteForce is a second, cruder method (N uniform midpoint
 * steps, each with constant tau and colour) used to cross-check the first.
 *
 * Semantics / emission codes are the mapper's enum values
 * (0 GPU_COMPATIBLE, 1 VTK_UNSTRUCTURED, 2 RAW_EXTINCTION; 0 WILLIAMS_MAX,
 * 1 WILHELMS_VAN_GELDER). GPU-compatible semantics requires a(s) < 1.
 *
 * Sources: hovTestReference.cxx (the ray integral), hovTestReferenceGeometry.cxx
 * (cameras, rays, intersections), hovTestReferenceMeshes.cxx (meshes, float
 * image access); hovTestReferenceVector.h is their 3-vector arithmetic.
 */
#ifndef hovTestReference_h
#define hovTestReference_h

#include "vtkSmartPointer.h"

#include <array>
#include <string>

class vtkCamera;
class vtkImageData;
class vtkMatrix4x4;
class vtkUnstructuredGrid;
class vtkVolumeProperty;

namespace hovTestRef
{
using Real = long double;
using Vec3 = std::array<Real, 3>;

/// Premultiplied RGBA.
struct RGBA
{
  Real R = 0, G = 0, B = 0, A = 0;
  Real operator[](int c) const { return c == 0 ? R : c == 1 ? G : c == 2 ? B : A; }
};

/// Optical model (the mapper's enum values).
struct Model
{
  int Semantics = 0;        ///< 0 GPU, 1 VTK unstructured, 2 raw extinction
  int Emission = 0;         ///< 0 Williams-Max, 1 Wilhelms-Van Gelder
  double EmissionScale = 1.0;
};

const char* SemanticsName(int semantics);
const char* EmissionName(int emission);

/// Extinction per unit length of opacity @p a (long double).
Real Extinction(Real a, int semantics, Real unit);

/**
 * Premultiplied RGBA of a ray segment of length @p length along which the
 * scalar goes linearly from @p s0 (front) to @p s1 (back); colour and opacity
 * from component 0 of @p property.
 */
RGBA IntegrateRay(vtkVolumeProperty* property, const Model& model, double s0, double s1, Real length);

/// The same integral by @p steps uniform midpoint steps (error O(1/steps^2)).
RGBA IntegrateRayBruteForce(
  vtkVolumeProperty* property, const Model& model, double s0, double s1, Real length, long steps);

/// A ray: origin on the near plane, unit direction, far parameter.
struct Ray
{
  Vec3 Origin{};
  Vec3 Direction{};
  Real TFar = 0;
  Vec3 At(Real t) const
  {
    return { Origin[0] + t * Direction[0], Origin[1] + t * Direction[1], Origin[2] + t * Direction[2] };
  }
};

/// What the ray construction reads from a vtkCamera.
struct CameraSpec
{
  Vec3 Position{}, FocalPoint{}, ViewUp{};
  Real ViewAngle = 30; ///< degrees, vertical
  bool Parallel = false;
  Real ParallelScale = 1;
  Real Near = 0.1, Far = 1000;
  std::string ToString() const;
};

/// Read the parameters (position, focal point, view up, angle/scale, clipping range).
CameraSpec ReadCamera(vtkCamera* camera);

/**
 * World-space ray through the centre of pixel (i, j) of a W x H image
 * (NDC x = 2(i+.5)/W - 1, y = 2(j+.5)/H - 1; aspect W/H), from the near plane
 * to the far plane. Built from the camera frame: d = unit(focal - position),
 * right = unit(d x up), up' = right x d.
 */
Ray PixelRay(const CameraSpec& cam, int i, int j, int width, int height);

/// The ray in dataset coordinates of a volume with data-to-world matrix @p m (affine).
Ray ToDataCoordinates(const Ray& worldRay, vtkMatrix4x4* m);

/// Slab-method intersection with an axis-aligned box, clipped to [0, TFar].
bool IntersectBox(const Ray& ray, const double bounds[6], Real& tIn, Real& tOut);

/// Intersection with a tetrahedron (any orientation), clipped to [0, TFar].
bool IntersectTetra(const Ray& ray, const double pts[4][3], Real& tIn, Real& tOut);

/// Smallest distance between the ray (segment [0, TFar]) and an edge of the tetrahedron.
Real DistanceToTetraEdges(const Ray& ray, const double pts[4][3]);

/// Smallest distance between the ray (segment [0, TFar]) and an edge of the box.
Real DistanceToBoxEdges(const Ray& ray, const double bounds[6]);

/// One VTK_TETRA with point scalars "s" (active) at its four vertices.
vtkSmartPointer<vtkUnstructuredGrid> MakeTetra(const double pts[4][3], const double scalars[4]);

/**
 * An n x n x n block of cubes over [origin, origin + size]^3, each cube split
 * into @p tetsPerCube (5: alternating-parity split; 6: Kuhn split along the
 * main diagonal) positively oriented, conforming tetrahedra, with the active
 * point scalar "s" = a + g . x.
 */
vtkSmartPointer<vtkUnstructuredGrid> MakeCubeOfTetras(
  int n, const double origin[3], double size, int tetsPerCube, double a, const double g[3]);

/**
 * The float pixels of a mapper image if it is @p width x @p height x 1 with a
 * 4-component float "RGBA" point array, else null and @p why says what is wrong.
 */
const float* ImagePixels(vtkImageData* image, int width, int height, std::string& why);

/// Nodes of the property's colour and opacity functions, for failure messages.
std::string DescribeProperty(vtkVolumeProperty* property);
}

#endif
