/**
 * @class   hov::ViewRays
 * @brief   Primary rays through OpenGL pixel centres, in dataset coordinates.
 *
 * For a viewport of W x H pixels, pixel (i, j) (j = 0 at the bottom, as in
 * OpenGL window coordinates) has its centre at NDC
 * x = 2 (i + 1/2) / W - 1, y = 2 (j + 1/2) / H - 1, where OpenGL rasterizes
 * and where VTK's other mappers sample. Its ray runs from the near-plane point
 * (NDC z = -1) to the far-plane point (z = +1), both unprojected exactly
 * through the inverse of (camera composite projection) x (volume matrix), so
 * rays live in dataset coordinates and their parameter t is dataset length
 * (the length vtkGPUVolumeRayCastMapper and the Bunyk ray caster integrate
 * over). Orthographic and perspective cameras, off-axis projections and
 * any affine volume matrix are handled by the same unprojection.
 *
 * Clipping (SetClipPlanes): half-spaces a.x + d >= 0 in dataset coordinates
 * (the mapper's vtkPlaneCollection and its view-depth range, transformed
 * like vtkAbstractMapper3D::GetClippingPlaneInDataCoords); ClipRange()
 * narrows a ray's parameter range to the part inside all of them (convex:
 * one interval).
 *
 * Thread safety: after Setup(), every const method is thread safe.
 * @sa hov::CellProjector
 */
#ifndef hovViewRays_h
#define hovViewRays_h

#include <glm/glm.hpp> // dvec3, dvec4, dmat4

#include <vector> // clip planes

class vtkAbstractMapper3D;
class vtkCamera;
class vtkMatrix4x4;

namespace hov
{
class ViewRays
{
public:
  /// A ray: origin on the near plane, unit direction (dataset space), far limit.
  struct Ray
  {
    glm::dvec3 Origin;
    glm::dvec3 Direction;
    double TFar;
  };

  /**
   * Set up from a camera, the volume's data-to-world matrix (may be null) and
   * the viewport size. @p aspect is the projection's aspect (usually W/H, or
   * the renderer's tiled aspect ratio). Returns false if the matrices are
   * singular or the size is not positive.
   */
  bool Setup(vtkCamera* camera, vtkMatrix4x4* volumeMatrix, int width, int height, double aspect);

  int GetWidth() const { return this->Width; }
  int GetHeight() const { return this->Height; }

  /// The ray through the centre of pixel (i, j).
  Ray PixelRay(int i, int j) const;

  /// PixelRay() of the @p count pixels (i0 + k, j), k < count, into @p rays:
  /// four pixels per vector with PixelRay()'s operations, so bit-identical
  /// (this file is compiled without contraction into fused multiply-adds).
  void RowRays(int i0, int j, int count, Ray* rays) const;

  /**
   * Ray parameter of the point of pixel (i, j)'s ray at OpenGL window depth
   * @p windowDepth in [0,1] (a depth-buffer value).
   */
  double DepthToT(int i, int j, const Ray& ray, double windowDepth) const;

  /**
   * The ray of pixel (i, j) as the CPU tiles trace it: PixelRay(), ending at
   * TFar, at the opaque window depth @p windowDepth (1: nothing drawn) and at
   * the clipping; with clipping the origin moves to the clipped entry, so the
   * ray starts at t = 0 (same segments, shifted t). @p tMax receives its end
   * (0: nothing to trace).
   */
  Ray TracedPixelRay(int i, int j, double windowDepth, double& tMax) const;

  /**
   * Project a dataset point to window coordinates (pixels, centres at
   * half-integers). Returns false if the point is at or behind the eye plane
   * (its projection is then unbounded).
   */
  bool Project(const glm::dvec3& p, double& xWindow, double& yWindow) const;

  /// A length scale of the view (near-to-far distance along the central ray).
  double GetDepthScale() const { return this->DepthScale; }

  /**
   * Directions (dataset space) of +x and +y on the near plane. A ray that
   * lies exactly in a cell face is resolved by displacing it symbolically by
   * e PerturbX + e^2 PerturbY (e -> 0+): it then lies in exactly one of the
   * cells around that face or edge (simulation of simplicity).
   */
  const glm::dvec3& GetPerturbX() const { return this->PerturbX; }
  const glm::dvec3& GetPerturbY() const { return this->PerturbY; }

  /**
   * Planes (a, b, c, d) in dataset coordinates; a point x is kept where
   * a x + b y + c z + d >= 0. Empty: no clipping. Call after Setup().
   */
  void SetClipPlanes(const std::vector<glm::dvec4>& planes) { this->ClipPlanes = planes; }

  /**
   * SetClipPlanes() from @p mapper's clipping planes (world coordinates, the
   * normal's side kept) and, if @p viewDepthRange is given, the slab of view
   * depths [near, far] (world distance from @p camera's position along its
   * direction of projection), both transformed to dataset coordinates with
   * the volume matrix @p volumeMatrix as
   * vtkAbstractMapper3D::GetClippingPlaneInDataCoords does. A plane whose
   * normal is zero or whose coefficients are not finite defines no half-space:
   * it is left out; returns how many were.
   */
  int SetupClipping(vtkAbstractMapper3D* mapper, vtkCamera* camera, vtkMatrix4x4* volumeMatrix,
    const double* viewDepthRange);
  bool HasClipping() const { return !this->ClipPlanes.empty(); }

  /**
   * Narrow [@p tMin, @p tMax] of @p ray to where it is inside every clip
   * plane; the result may be empty (tMin >= tMax). A ray parallel to a plane
   * is kept or dropped whole.
   */
  void ClipRange(const Ray& ray, double& tMin, double& tMax) const;

private:
  std::vector<glm::dvec4> ClipPlanes;
  glm::dvec3 Unproject(double xNdc, double yNdc, double zNdc) const;

  glm::dmat4 DataToClip{ 1.0 };
  glm::dmat4 ClipToData{ 1.0 };
  int Width = 0;
  int Height = 0;
  double DepthScale = 1.0;
  glm::dvec3 PerturbX{ 1.0, 0.0, 0.0 };
  glm::dvec3 PerturbY{ 0.0, 1.0, 0.0 };
};
}

#endif
