#include "vtkHighOrderTransferFunction.h"

#include "hovBlendModes.h" // BlendModeTableSpec

#include "hovOpacityRefinement.h" // the slab nodes of the linear-opacity table
#include "hovTransferFunction.h" // the kernel table built here

#include "vtkColorTransferFunction.h"
#include "vtkObjectFactory.h"
#include "vtkPiecewiseFunction.h"
#include "vtkVolumeProperty.h"

#include <algorithm> // std::max
#include <array>     // sampled values
#include <cmath>     // std::abs
#include <functional> // sampled evaluators

vtkStandardNewMacro(vtkHighOrderTransferFunction);

namespace
{
/// The kernel's semantics of the OpacitySemantics setting (0, 1, 2; clamped by its setter).
hov::OpacitySemantics SemanticsOf(int semantics)
{
  static_assert(static_cast<int>(hov::OpacitySemantics::GPUCompatible) == 0 &&
      static_cast<int>(hov::OpacitySemantics::VTKUnstructured) == 1 &&
      static_cast<int>(hov::OpacitySemantics::RawExtinction) == 2,
    "OpacitySemantics: 0 GPU-compatible, 1 VTK-unstructured, 2 raw extinction");
  constexpr hov::OpacitySemantics table[] = { hov::OpacitySemantics::GPUCompatible,
    hov::OpacitySemantics::VTKUnstructured, hov::OpacitySemantics::RawExtinction };
  return table[std::min(std::max(semantics, 0), 2)];
}

// Depth limit of the adaptive sampling of non-linear segments: 2^-20 of a
// segment, enough to resolve VTK's sharpness-1 steps to 1e-6 of the segment.
constexpr int MaxSamplingDepth = 20;

template <int N>
using Evaluator = std::function<std::array<double, N>(double)>;

/// Appends samples in (x0, x1] so that linear interpolation between them is
/// within tol of f at the quarter points of every piece.
template <int N>
void SampleAdaptively(const Evaluator<N>& f, double x0, const std::array<double, N>& v0, double x1,
  const std::array<double, N>& v1, double tol, int depth,
  std::vector<std::pair<double, std::array<double, N>>>& out)
{
  bool linear = true;
  for (double w : { 0.25, 0.5, 0.75 })
  {
    const std::array<double, N> v = f(x0 + (x1 - x0) * w);
    for (int c = 0; c < N && linear; ++c)
    {
      linear = std::abs(v[c] - (v0[c] + (v1[c] - v0[c]) * w)) <= tol;
    }
  }
  const double xm = 0.5 * (x0 + x1);
  if (!linear && depth < MaxSamplingDepth && xm > x0 && xm < x1)
  {
    const std::array<double, N> vm = f(xm);
    SampleAdaptively<N>(f, x0, v0, xm, vm, tol, depth + 1, out);
    SampleAdaptively<N>(f, xm, vm, x1, v1, tol, depth + 1, out);
    return;
  }
  out.emplace_back(x1, v1);
}

/// Nodes of a piecewise function with per-segment midpoint/sharpness.
template <int N>
struct NodeList
{
  std::vector<double> X, Mid, Sharp;
  std::vector<std::array<double, N>> V;
  void Add(double x, const std::array<double, N>& v, double mid, double sharp)
  {
    this->X.push_back(x);
    this->V.push_back(v);
    this->Mid.push_back(mid);
    this->Sharp.push_back(sharp);
  }
};

/// Exact copy where the segments are linear, adaptive sampling elsewhere.
template <int N>
std::vector<std::pair<double, std::array<double, N>>> Linearize(
  const NodeList<N>& nodes, const Evaluator<N>& f, bool nonlinearEverywhere, double tol)
{
  std::vector<std::pair<double, std::array<double, N>>> out;
  const size_t n = nodes.X.size();
  for (size_t i = 0; i < n; ++i)
  {
    out.emplace_back(nodes.X[i], nodes.V[i]);
    if (i + 1 == n || nodes.X[i + 1] == nodes.X[i])
    {
      continue;
    }
    const bool linear = !nonlinearEverywhere && nodes.Mid[i] == 0.5 && nodes.Sharp[i] == 0.0;
    if (!linear)
    {
      SampleAdaptively<N>(f, nodes.X[i], nodes.V[i], nodes.X[i + 1], nodes.V[i + 1], tol, 0, out);
      out.pop_back(); // the next node is appended by the loop
    }
  }
  return out;
}
/// Nodes of a VTK piecewise function (x, value, midpoint, sharpness),
/// its value replicated to N channels.
template <int N>
NodeList<N> ReadNodes(vtkPiecewiseFunction* f)
{
  NodeList<N> nodes;
  for (int i = 0; i < f->GetSize(); ++i)
  {
    double v[4];
    f->GetNodeValue(i, v);
    std::array<double, N> value;
    value.fill(v[1]);
    nodes.Add(v[0], value, v[2], v[3]);
  }
  return nodes;
}

/// Colour nodes (RGB or grey) as VTK evaluates them, with the values outside
/// the node range (clamped end colours, black, or below/above-range colours)
/// as jumps at the end nodes.
void ReadColor(vtkVolumeProperty* property, int comp, double tol, std::vector<hov::ColorNode>& out)
{
  NodeList<3> nodes;
  Evaluator<3> colorOf;
  bool nonlinear = false, clamp = true, useBelow = false, useAbove = false;
  std::array<double, 3> below{ 0, 0, 0 }, above{ 0, 0, 0 };
  if (property->GetColorChannels(comp) == 1)
  {
    vtkPiecewiseFunction* gray = property->GetGrayTransferFunction(comp);
    nodes = ReadNodes<3>(gray);
    colorOf = [gray](double x) {
      const double g = gray->GetValue(x);
      return std::array<double, 3>{ g, g, g };
    };
    clamp = gray->GetClamping() != 0;
  }
  else
  {
    vtkColorTransferFunction* ctf = property->GetRGBTransferFunction(comp);
    for (int i = 0; i < ctf->GetSize(); ++i)
    {
      double v[6];
      ctf->GetNodeValue(i, v);
      nodes.Add(v[0], { v[1], v[2], v[3] }, v[4], v[5]);
    }
    colorOf = [ctf](double x) {
      std::array<double, 3> c;
      ctf->GetColor(x, c.data());
      return c;
    };
    nonlinear = ctf->GetColorSpace() != VTK_CTF_RGB || ctf->GetScale() != VTK_CTF_LINEAR;
    clamp = ctf->GetClamping() != 0;
    useBelow = ctf->GetUseBelowRangeColor() != 0;
    useAbove = ctf->GetUseAboveRangeColor() != 0;
    ctf->GetBelowRangeColor(below.data());
    ctf->GetAboveRangeColor(above.data());
  }
  const auto samples = Linearize<3>(nodes, colorOf, nonlinear, tol);
  if (samples.empty())
  {
    return;
  }
  const std::array<double, 3> black{ 0, 0, 0 };
  below = useBelow ? below : (clamp ? samples.front().second : black);
  above = useAbove ? above : (clamp ? samples.back().second : black);
  out.push_back({ samples.front().first, below[0], below[1], below[2] });
  for (const auto& s : samples)
  {
    out.push_back({ s.first, s.second[0], s.second[1], s.second[2] });
  }
  out.push_back({ samples.back().first, above[0], above[1], above[2] });
}

/// Opacity nodes as VTK evaluates them; 0 outside the range without clamping.
void ReadOpacity(vtkPiecewiseFunction* opacity, double tol, std::vector<hov::OpacityNode>& out)
{
  const Evaluator<1> opacityOf = [opacity](double x) {
    return std::array<double, 1>{ opacity->GetValue(x) };
  };
  const auto samples = Linearize<1>(ReadNodes<1>(opacity), opacityOf, false, tol);
  if (samples.empty())
  {
    return;
  }
  const bool clamp = opacity->GetClamping() != 0;
  out.push_back({ samples.front().first, clamp ? samples.front().second[0] : 0.0 });
  for (const auto& s : samples)
  {
    out.push_back({ s.first, s.second[0] });
  }
  out.push_back({ samples.back().first, clamp ? samples.back().second[0] : 0.0 });
}
}

namespace
{
/**
 * The opacity nodes @p nodes (clamped to [0, 1]) plus, inside each interval,
 * the nodes of a coarse GPU-compatible refinement (relative chord error of
 * -ln(1 - a) at most @p tolerance), with the opacity's own (linear) values:
 * the same function a(s), cut where -ln(1 - a) bends, so that colours
 * interpolated over a slab's regions stay accurate (GetLinearOpacityTable).
 */
std::vector<hov::OpacityNode> SlabNodes(
  const std::vector<hov::OpacityNode>& nodes, double unit, double tolerance)
{
  std::vector<hov::OpacityInterval> intervals;
  std::vector<size_t> starts;
  for (size_t i = 0; i + 1 < nodes.size(); ++i)
  {
    const hov::OpacityNode &a = nodes[i], &b = nodes[i + 1];
    const bool finite = std::isfinite(a.X) && std::isfinite(b.X) && std::isfinite(a.Opacity) &&
      std::isfinite(b.Opacity);
    if (finite && b.X > a.X && a.Opacity != b.Opacity && std::min(a.Opacity, b.Opacity) < 1.0)
    {
      intervals.push_back({ a.X, a.Opacity, b.X, b.Opacity });
      starts.push_back(i);
    }
  }
  if (intervals.empty())
  {
    return nodes;
  }
  const hov::RefinementResult refined = hov::RefineGPUExtinction(intervals, unit, tolerance, 100000);
  std::vector<hov::OpacityNode> out;
  size_t next = 0;
  for (size_t i = 0; i < nodes.size(); ++i)
  {
    out.push_back(nodes[i]);
    if (next < starts.size() && starts[next] == i)
    {
      const hov::OpacityInterval& in = intervals[next];
      for (const auto& node : refined.Interior[next])
      {
        const double t = (node.first - in.S0) / (in.S1 - in.S0);
        out.push_back({ node.first, in.A0 + t * (in.A1 - in.A0) });
      }
      ++next;
    }
  }
  return out;
}
}

vtkHighOrderTransferFunction::vtkHighOrderTransferFunction()
  : Table(new hov::TransferFunction)
  , LinearOpacityTable(new hov::TransferFunction)
  , BlendTable(new hov::TransferFunction)
{
}

vtkHighOrderTransferFunction::~vtkHighOrderTransferFunction() = default;

bool vtkHighOrderTransferFunction::Update(vtkVolumeProperty* property)
{
  if (!property)
  {
    return false;
  }
  const vtkMTimeType propertyTime = property->GetMTime();
  if (property == this->LastProperty && propertyTime == this->LastPropertyTime &&
    this->GetMTime() == this->LastBuildSettingsTime && this->Table->GetNumberOfNodes() > 0)
  {
    return true;
  }
  this->LastProperty = property;
  this->LastPropertyTime = propertyTime;
  this->LastBuildSettingsTime = this->GetMTime();
  this->Messages.clear();
  ++this->BuildCount;

  const int comp = this->Component;
  hov::TransferFunctionSpec spec;
  spec.Semantics = SemanticsOf(this->OpacitySemantics);
  spec.UnitDistance = property->GetScalarOpacityUnitDistance(comp);
  spec.GPUTolerance = this->GPUTolerance;
  spec.RefinementBudget = this->RefinementBudget;
  spec.EmissionScale = this->EmissionScale;
  ReadColor(property, comp, this->SamplingTolerance, spec.Color);
  ReadOpacity(property->GetScalarOpacity(comp), this->SamplingTolerance, spec.Opacity);
  this->Table->Build(spec, &this->Messages);
  this->BlendTable->Build(hov::BlendModeTableSpec(spec), nullptr); // its problems: as above
  // As hov::TransferFunction::Build takes it (a bad value is reported there).
  this->UnitDistance =
    spec.UnitDistance > 0.0 && std::isfinite(spec.UnitDistance) ? spec.UnitDistance : 1.0;
  if (spec.Semantics == hov::OpacitySemantics::GPUCompatible)
  {
    // The same nodes, the opacity itself as the linear quantity (its
    // problems are those reported above).
    spec.Semantics = hov::OpacitySemantics::RawExtinction;
    for (hov::OpacityNode& node : spec.Opacity)
    {
      node.Opacity = std::min(std::max(node.Opacity, 0.0), 1.0);
    }
    spec.Opacity = SlabNodes(spec.Opacity, this->UnitDistance, this->SlabTolerance);
    this->LinearOpacityTable->Build(spec, nullptr);
  }
  return true;
}

int vtkHighOrderTransferFunction::GetNumberOfNodes()
{
  return this->Table->GetNumberOfNodes();
}

void vtkHighOrderTransferFunction::GetNode(int i, double node[5])
{
  const int n = this->Table->GetNumberOfNodes();
  if (i < 0 || i >= n)
  {
    vtkErrorMacro("node index " << i << " out of range [0," << n << ")");
    return;
  }
  hov::SegmentEnd end;
  const double x = this->Table->GetNodes()[i];
  // Interval i-1 ends at node i, interval i starts at it; use the one that has node i as an end.
  this->Table->Evaluate(i < n - 1 ? i : i - 1, x, false, end);
  node[0] = x;
  node[1] = end.Color[0];
  node[2] = end.Color[1];
  node[3] = end.Color[2];
  node[4] = end.Tau;
}

int vtkHighOrderTransferFunction::GetNumberOfRefinementNodes()
{
  return this->Table->GetNumberOfRefinementNodes();
}

const char* vtkHighOrderTransferFunction::GetMessage(int i)
{
  return (i >= 0 && i < static_cast<int>(this->Messages.size())) ? this->Messages[i].c_str() : "";
}

void vtkHighOrderTransferFunction::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "OpacitySemantics: " << this->OpacitySemantics << "\n";
  os << indent << "GPUTolerance: " << this->GPUTolerance << "\n";
  os << indent << "RefinementBudget: " << this->RefinementBudget << "\n";
  os << indent << "EmissionScale: " << this->EmissionScale << "\n";
  os << indent << "Component: " << this->Component << "\n";
  os << indent << "SamplingTolerance: " << this->SamplingTolerance << "\n";
  os << indent << "SlabTolerance: " << this->SlabTolerance << "\n";
  os << indent << "NumberOfNodes: " << this->Table->GetNumberOfNodes() << "\n";
}
