/**
 * @file hovTransferFunction.h
 * @brief Piecewise-linear transfer function table: colour and extinction per
 * unit length as functions of the scalar s, with every breakpoint kept.
 *
 * Input: colour nodes (RGB, piecewise linear) and opacity nodes a(s)
 * (piecewise linear, in [0,1]) as a vtkVolumeProperty holds them, plus the
 * opacity semantics. Output: one table whose nodes are the union of the colour
 * nodes, the opacity nodes and (GPU-compatible semantics only) refinement
 * nodes; between consecutive nodes colour and extinction tau are both linear in
 * s, which is what the exact segment integral needs. (VTK's unstructured
 * integrators keep only the first opacity node of each colour interval; this
 * table keeps them all.)
 *
 * A jump is two nodes at the same s (left and right values); beyond the first
 * and last nodes every value is constant (clamping).
 *
 * Opacity semantics (u = unit distance of the vtkVolumeProperty):
 *  - GPUCompatible: tau(s) = -ln(1 - a(s)) / u, the limit of
 *    vtkGPUVolumeRayCastMapper's per-sample 1-(1-a)^(dt/u). tau is convex in
 *    s, not linear; opacity intervals are bisected (hovOpacityRefinement.h)
 *    until the chord of tau has relative error <= GPUTolerance everywhere. If the extinction used along the whole
 *    ray is within a factor (1 +- eps) of the true one, the ray's opacity is off
 *    by at most eps/e and its premultiplied colour by at most 2 eps max|c|
 *    (Williams-Max): the image error bound of this semantics is
 *    2 GPUTolerance (default 1e-4 gives 2e-4, 0.05/255).
 *    a = 1 on a whole interval is an opaque medium (tau = +infinity, handled
 *    by the segment integral without Inf/NaN); an interval that reaches a = 1
 *    at one end only has an integrable log singularity: 1 - a is clamped at
 *    OpaqueClamp = 1e-12 (tau <= 27.6/u), which changes the optical depth of a
 *    ray by at most 1e-12 / (|da/ds| |ds/dt| u).
 *  - VTKUnstructured: tau(s) = a(s) / u, what VTK's unstructured mappers use.
 *  - RawExtinction (HIAC): tau(s) = a(s), extinction per unit length (values
 *    above 1 are kept; opacities in the other semantics are clamped to [0,1]).
 *
 * Wilhelms-Van Gelder emission per unit length is g(s) = EmissionScale c(s) / u:
 * a non-absorbing layer of thickness u/EmissionScale glows with colour c(s).
 *
 * Thread safety: Build() is not thread safe; every const method is.
 * @sa hovRayIntegrator.h, vtkHighOrderTransferFunction (conversion from VTK)
 */
#ifndef hovTransferFunction_h
#define hovTransferFunction_h

#include "hovConfig.h"
#include "hovOpacityRefinement.h" // OpaqueClamp
#include "hovSegmentIntegral.h"   // SegmentEnd

#include <algorithm> // std::min, std::max, std::upper_bound (inline lookups)
#include <string>    // Build() messages
#include <vector>    // node storage

namespace hov
{
/// How the opacity function's values become extinction per unit length.
enum class OpacitySemantics
{
  GPUCompatible = 0,   ///< tau = -ln(1 - a)/u (vtkGPUVolumeRayCastMapper's limit)
  VTKUnstructured = 1, ///< tau = a/u (VTK's unstructured mappers)
  RawExtinction = 2    ///< tau = a (HIAC: the values are extinction per unit length)
};

struct ColorNode
{
  double X = 0.0;
  double R = 0.0, G = 0.0, B = 0.0;
};

struct OpacityNode
{
  double X = 0.0;
  double Opacity = 0.0;
};

/// Everything the table is built from.
struct TransferFunctionSpec
{
  std::vector<ColorNode> Color;     ///< sorted by X; two nodes at one X make a jump
  std::vector<OpacityNode> Opacity; ///< sorted by X; two nodes at one X make a jump
  OpacitySemantics Semantics = OpacitySemantics::GPUCompatible;
  double UnitDistance = 1.0;   ///< u of vtkVolumeProperty (> 0)
  double GPUTolerance = 1e-4;  ///< relative error bound of the linearised -ln(1-a)/u
  double EmissionScale = 1.0;  ///< Wilhelms-Van Gelder: g = EmissionScale c / u
  /// Most nodes the GPU-compatible refinement may add (a ray-cast segment pays
  /// for every node in its range; see vtkHighOrderVolumeMapper's RAY_CAST).
  int RefinementBudget = 1000000;
};

class HOV_EXPORT TransferFunction
{
public:
  /// 1 - a is never taken below this in GPU-compatible semantics (see file doc).
  static constexpr double OpaqueClamp = hov::OpaqueClamp;
  /// Refinement stops here even if the tolerance is not met (reported by Build()).
  static constexpr int MaxRefinementNodes = 1000000;

  /**
   * Build the table. Returns false only if nothing usable remains (the table
   * is then fully transparent); @p messages receives one line per problem
   * found (NaN nodes dropped, opacity clamped to [0,1], bad unit distance...).
   */
  bool Build(const TransferFunctionSpec& spec, std::vector<std::string>* messages = nullptr);

  int GetNumberOfNodes() const { return static_cast<int>(this->X.size()); }
  const std::vector<double>& GetNodes() const { return this->X; }
  /// Number of nodes added by GPU-compatible refinement.
  int GetNumberOfRefinementNodes() const { return this->RefinementNodes; }
  /// True if some opacity is non-zero (else the volume is invisible).
  bool HasExtinction() const { return this->AnyExtinction; }
  /**
   * True if the extinction is exactly zero for every s in [@p lo, @p hi]
   * (finite, lo <= hi): every node from the last one below lo (or the first
   * node) to the first one above hi (or the last node) has tau = 0, so tau,
   * linear between them and clamped beyond, is zero there. A conservative
   * test (an end exactly on a node also reads the next node out); false for
   * NaN, infinite or reversed ends and for a table without nodes. Emission
   * aside (Wilhelms-Van Gelder), a segment whose exact scalars stay in such a
   * range adds nothing: alpha and colour are 0.
   */
  bool ZeroExtinctionOver(double lo, double hi) const;
  /// True if some node has tau = 0 (else ZeroExtinctionOver() is always false).
  bool HasZeroExtinctionNode() const
  {
    return !this->ExtinctionBefore.empty() &&
      this->ExtinctionBefore.back() < static_cast<int>(this->Nodes.size());
  }
  /**
   * True if nothing narrow can hide at node @p k (0 < k < n - 1): both
   * neighbouring intervals have width > 0 (no jump) and finite extinction,
   * the colour's slope is the same on both and the extinction's slope does
   * not decrease (convex there), each up to a change that moves the value by
   * 1e-15 of the table's largest finite value over the wider interval
   * (rounding; k such nodes move it by at most k^2 1e-15). Over a run of such
   * nodes tau is convex and the colour linear in s, so no band narrower than
   * a quadrature's sample spacing can hide between its samples: the nodes the
   * GPU-compatible refinement adds inside one interval of the user's function
   * qualify (-ln(1 - a)/u is convex for a linear in s). Adaptive quadratures
   * may step over them (hovShadedSegment.h); every other node is a breakpoint.
   */
  bool IsSmoothNode(int k) const
  {
    return k > 0 && k < static_cast<int>(this->SmoothNodes.size()) && this->SmoothNodes[k];
  }
  OpacitySemantics GetSemantics() const { return this->Semantics; }
  /// Factor from colour to Wilhelms-Van Gelder emission per unit length.
  double GetEmissionFactor() const { return this->EmissionFactor; }

  /**
   * Interval index for walking toward larger s: the largest k with
   * X[k] <= s, or -1 below the first node (k = n-1 is the clamped region above).
   */
  int FindIntervalUpward(double s) const;
  /// Interval index for walking toward smaller s: the largest k with X[k] < s, or -1.
  int FindIntervalDownward(double s) const;

  /**
   * Values at @p s using interval @p k's linear pieces (k from the Find*
   * functions; -1 and n-1 are the clamped regions). @p emission selects
   * Wilhelms-Van Gelder emission instead of chromaticity in out.Color.
   */
  void Evaluate(int k, double s, bool emission, SegmentEnd& out) const;

  /// Values at a node and their slopes d/ds over the interval that starts there.
  struct Node
  {
    double Tau, R, G, B;
    double DTau, DR, DG, DB;
  };
  /// Node @p k (0 <= k < n) as Evaluate() reads it: for callers that evaluate
  /// many values of one interval with the same operations (hov::SegmentBatch).
  const Node& GetNode(int k) const { return this->Nodes[k]; }

private:
  /// The interval lookup grid and the slopes of every interval (end of Build()).
  void BuildLookup();
  std::vector<double> X;
  std::vector<Node> Nodes;
  /// O(1) interval search: bucket b of a uniform grid over [X0, Xn-1] holds
  /// the interval containing its left end.
  std::vector<int> Buckets;
  /// IsSmoothNode() per node.
  std::vector<unsigned char> SmoothNodes;
  /// ExtinctionBefore[k]: the number of nodes before node k with tau != 0.
  std::vector<int> ExtinctionBefore;
  double BucketScale = 0.0;
  OpacitySemantics Semantics = OpacitySemantics::GPUCompatible;
  double EmissionFactor = 1.0;
  int RefinementNodes = 0;
  bool AnyExtinction = false;
};

// Inline: these run once or twice per ray segment in every renderer.

inline int TransferFunction::FindIntervalUpward(double s) const
{
  const int n = static_cast<int>(this->X.size());
  if (n == 0 || s < this->X[0])
  {
    return -1;
  }
  if (s >= this->X[n - 1])
  {
    return n - 1;
  }
  int k = 0;
  if (!this->Buckets.empty())
  {
    // The bucket of s, up to rounding: its position and the buckets' starts
    // round differently, so s just below a node may land in the bucket that
    // starts with that node. Walk down, then up, to the last X[k] <= s.
    const double pos = (s - this->X[0]) * this->BucketScale;
    k = this->Buckets[std::min(static_cast<size_t>(pos), this->Buckets.size() - 1)];
    while (k > 0 && this->X[k] > s)
    {
      --k;
    }
  }
  // A few steps up; beyond them a binary search: where the nodes crowd into
  // a few buckets (a table spanning [-1, 1e300] puts every node but one into
  // bucket 0) a walk would cost one step per node and sample.
  for (int step = 0; step < 8 && k + 1 < n && this->X[k + 1] <= s; ++step)
  {
    ++k;
  }
  if (k + 1 < n && this->X[k + 1] <= s)
  {
    k = static_cast<int>(std::upper_bound(this->X.begin() + (k + 1), this->X.end(), s) -
          this->X.begin()) - 1;
  }
  return k;
}

inline int TransferFunction::FindIntervalDownward(double s) const
{
  int k = this->FindIntervalUpward(s); // then the largest k with X[k] < s
  while (k >= 0 && this->X[k] >= s)
  {
    --k;
  }
  return k;
}

inline void TransferFunction::Evaluate(int k, double s, bool emission, SegmentEnd& out) const
{
  const int n = static_cast<int>(this->X.size());
  const double scale = emission ? this->EmissionFactor : 1.0;
  if (k < 0 || k >= n - 1)
  {
    const Node& node = this->Nodes[k < 0 ? 0 : n - 1];
    out.Tau = node.Tau;
    out.Color[0] = scale * node.R;
    out.Color[1] = scale * node.G;
    out.Color[2] = scale * node.B;
    return;
  }
  const Node& node = this->Nodes[k];
  // Clamp to the interval: s may sit a rounding error outside it.
  const double ds = std::min(std::max(s - this->X[k], 0.0), this->X[k + 1] - this->X[k]);
  out.Tau = node.Tau + node.DTau * ds;
  out.Color[0] = scale * (node.R + node.DR * ds);
  out.Color[1] = scale * (node.G + node.DG * ds);
  out.Color[2] = scale * (node.B + node.DB * ds);
}
}

#endif
