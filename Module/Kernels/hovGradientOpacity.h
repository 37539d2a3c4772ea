/**
 * @file hovGradientOpacity.h
 * @brief vtkVolumeProperty's gradient opacity: the factor gamma(|grad s|)
 * that scales the extinction, as VTK 9.1's GPU ray caster defines it.
 *
 * VTK (vtkVolumeShaderComposer.h: ComputeGradientDeclaration,
 * ComputeLightingDeclaration; vtkOpenGLVolumeGradientOpacityTable.cxx;
 * vtkVolumeInputHelper.cxx): per sample the opacity is
 * GO(m) (1 - (1 - a)^(dt/u)), GO the gradient-opacity vtkPiecewiseFunction
 * sampled into a table over [0, 0.25 (r1 - r0)] ([r0, r1] the data scalar
 * range; clamped beyond its end nodes), looked up at
 *     m = min(|grad s| * avgSpacing, 0.25 (r1 - r0))
 * where |grad s| is in scalar units per world unit (central differences
 * scaled by the voxel spacing) and avgSpacing is the mean of the image's
 * three spacings. In the limit dt -> 0 this is an emission-absorption medium
 * whose extinction is gamma tau(s): the colour (chromaticity) is unchanged,
 * the extinction scaled (Williams-Max emission c gamma tau follows).
 * Applied in COMPOSITE blending only when vtkVolumeProperty::HasGradientOpacity()
 * (a gradient-opacity function was set or requested; DisableGradientOpacity
 * replaces it by the constant 1).
 *
 * Here, for an unstructured mesh (there is no voxel spacing):
 *     gamma(g) = max(0, F(min(|g| MagnitudeScale, MaxMagnitude)))
 * with F piecewise linear through the nodes (sorted, stable; a jump is two
 * nodes at one X and takes its right value at X; constant beyond the end
 * nodes, as vtkPiecewiseFunction with Clamping on). MagnitudeScale = 1 and
 * MaxMagnitude = +inf read the function in world units (the natural
 * definition); VTKGradientOpacitySpec sets MagnitudeScale = the average
 * spacing and MaxMagnitude = 0.25 (r1 - r0) (r1 = r0: 0.25) of a resampled
 * image, reproducing the GPU mapper on that image. Values above 1 are kept
 * (the continuum limit of VTK's per-sample clamp); negative values give 0.
 * A NaN gradient (magnitude) reads F(0); an infinite one F(MaxMagnitude)
 * (F's last value if MaxMagnitude is infinite).
 *
 * On a linear tetrahedron grad s is constant: gamma is one number per cell
 * and the exact segment integral is kept with tau scaled by it
 * (IntegrateLinearScalarShaded, hovVolumeShading.h). Elsewhere gamma varies
 * along the ray: hovShadedSegment.h. Kinks of gamma along a ray are where
 * |g| crosses GetKinks() (world units): the nodes, the zero crossings of F
 * between nodes of opposite sign (max(0, F)) and the magnitude clamp; gamma
 * is linear in |g| between consecutive kinks (TestGradientOpacity).
 *
 * Thread safety: Build() is not thread safe; the const methods are.
 * @sa hovVolumeShading.h, hovShadedSegment.h, hovFieldGradient.h
 */
#ifndef hovGradientOpacity_h
#define hovGradientOpacity_h

#include "hovConfig.h"
#include "hovTransferFunction.h" // OpacityNode

#include <limits> // infinity default
#include <string> // Build() messages
#include <vector> // nodes

namespace hov
{
struct GradientOpacitySpec
{
  /// Nodes (X = gradient magnitude after scaling, value = factor), any order.
  std::vector<OpacityNode> Nodes;
  /// Multiplies |grad s| before the lookup (VTK's GPU mapper: the average voxel spacing).
  double MagnitudeScale = 1.0;
  /// Upper clamp of the scaled magnitude (VTK's GPU mapper: 0.25 of the data range).
  double MaxMagnitude = std::numeric_limits<double>::infinity();
};

/// The parameters that reproduce vtkGPUVolumeRayCastMapper on an image with
/// spacing @p spacing and data scalar range @p scalarRange (see file doc).
HOV_EXPORT GradientOpacitySpec VTKGradientOpacitySpec(const std::vector<OpacityNode>& nodes,
  const double spacing[3], const double scalarRange[2]);

class HOV_EXPORT GradientOpacityFunction
{
public:
  /**
   * Build from @p spec: NaN nodes dropped, MagnitudeScale <= 0 or not
   * finite replaced by 1, MaxMagnitude NaN or < 0 by +inf; one message per
   * problem. No node: gamma = 1. Returns false if nothing usable remained.
   */
  bool Build(const GradientOpacitySpec& spec, std::vector<std::string>* messages = nullptr);

  /// True if gamma is 1 for every gradient (no node, or all node values 1).
  bool IsIdentity() const { return this->Identity; }

  /// gamma at gradient magnitude @p magnitude (world units; file doc).
  double Evaluate(double magnitude) const;

  /// gamma of the gradient vector @p gradient (its length without overflow).
  double EvaluateGradient(const double gradient[3]) const;

  /// Gradient magnitudes (world units, increasing) where gamma has a kink or a jump.
  const std::vector<double>& GetKinks() const { return this->Kinks; }

private:
  std::vector<double> X, V;
  std::vector<double> Kinks;
  double Scale = 1.0;
  double MaxMagnitude = std::numeric_limits<double>::infinity();
  bool Identity = true;
};

/// Euclidean length of @p v without overflow or underflow (NaN if any is NaN).
HOV_EXPORT double VectorLength(const double v[3]);
}

#endif
