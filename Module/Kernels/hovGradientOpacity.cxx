#include "hovGradientOpacity.h"

#include <algorithm> // stable_sort, upper_bound, min, max
#include <cmath>     // fabs, sqrt, isfinite, isnan

namespace hov
{
namespace
{
void Note(std::vector<std::string>* messages, const std::string& text)
{
  if (messages)
  {
    messages->push_back(text);
  }
}
}

double VectorLength(const double v[3])
{
  const double m = std::max(std::fabs(v[0]), std::max(std::fabs(v[1]), std::fabs(v[2])));
  if (std::isnan(v[0]) || std::isnan(v[1]) || std::isnan(v[2]))
  {
    return std::numeric_limits<double>::quiet_NaN();
  }
  if (!(m > 0.0) || !std::isfinite(m))
  {
    return m; // 0 or +inf
  }
  // Scaled by the largest component: no overflow, no underflow of the squares.
  const double a = v[0] / m, b = v[1] / m, c = v[2] / m;
  return m * std::sqrt(a * a + b * b + c * c);
}

GradientOpacitySpec VTKGradientOpacitySpec(
  const std::vector<OpacityNode>& nodes, const double spacing[3], const double scalarRange[2])
{
  GradientOpacitySpec spec;
  spec.Nodes = nodes;
  spec.MagnitudeScale = (spacing[0] + spacing[1] + spacing[2]) / 3.0;
  const double range = scalarRange[1] - scalarRange[0];
  spec.MaxMagnitude = 0.25 * (range != 0.0 ? range : 1.0);
  return spec;
}

bool GradientOpacityFunction::Build(const GradientOpacitySpec& spec, std::vector<std::string>* messages)
{
  this->X.clear();
  this->V.clear();
  this->Kinks.clear();
  this->Scale = spec.MagnitudeScale;
  if (!(this->Scale > 0.0) || !std::isfinite(this->Scale))
  {
    Note(messages, "gradient magnitude scale must be positive and finite; using 1");
    this->Scale = 1.0;
  }
  this->MaxMagnitude = spec.MaxMagnitude;
  if (std::isnan(this->MaxMagnitude) || this->MaxMagnitude < 0.0)
  {
    Note(messages, "gradient magnitude clamp must be >= 0; using +inf");
    this->MaxMagnitude = std::numeric_limits<double>::infinity();
  }
  std::vector<OpacityNode> nodes;
  int dropped = 0;
  for (const OpacityNode& n : spec.Nodes)
  {
    if (std::isnan(n.X) || !std::isfinite(n.Opacity))
    {
      ++dropped;
      continue;
    }
    nodes.push_back(n);
  }
  if (dropped)
  {
    Note(messages, std::to_string(dropped) + " gradient-opacity node(s) with NaN/Inf dropped");
  }
  std::stable_sort(nodes.begin(), nodes.end(),
    [](const OpacityNode& p, const OpacityNode& q) { return p.X < q.X; });
  this->Identity = true;
  for (const OpacityNode& n : nodes)
  {
    this->X.push_back(n.X);
    this->V.push_back(n.Opacity);
    this->Identity = this->Identity && n.Opacity == 1.0;
  }
  // Kinks in world units: the nodes inside [0, MaxMagnitude], the zero
  // crossings of F between nodes (gamma = max(0, F) has a kink there), and
  // the clamp.
  auto addKink = [this](double x) {
    if (x > 0.0 && x < this->MaxMagnitude && std::isfinite(x))
    {
      const double m = x / this->Scale;
      if (this->Kinks.empty() || this->Kinks.back() < m)
      {
        this->Kinks.push_back(m);
      }
    }
  };
  for (size_t i = 0; i < this->X.size(); ++i)
  {
    if (i > 0 && this->X[i] > this->X[i - 1] &&
      ((this->V[i - 1] < 0.0 && this->V[i] > 0.0) || (this->V[i - 1] > 0.0 && this->V[i] < 0.0)))
    {
      const double w = this->V[i - 1] / (this->V[i - 1] - this->V[i]);
      addKink(this->X[i - 1] + (this->X[i] - this->X[i - 1]) * w);
    }
    addKink(this->X[i]);
  }
  if (!this->X.empty() && std::isfinite(this->MaxMagnitude) && this->MaxMagnitude > 0.0 &&
    this->MaxMagnitude < this->X.back())
  {
    this->Kinks.push_back(this->MaxMagnitude / this->Scale);
  }
  return true;
}

double GradientOpacityFunction::Evaluate(double magnitude) const
{
  if (this->Identity || this->X.empty())
  {
    return 1.0;
  }
  double m = std::isnan(magnitude) ? 0.0 : std::fabs(magnitude) * this->Scale;
  m = std::min(m, this->MaxMagnitude);
  const size_t n = this->X.size();
  double value;
  if (!(m >= this->X[0]))
  {
    value = this->V[0];
  }
  else if (m >= this->X[n - 1])
  {
    value = this->V[n - 1];
  }
  else
  {
    // Last node with X <= m: a jump takes its right value at its node.
    const size_t i = static_cast<size_t>(std::upper_bound(this->X.begin(), this->X.end(), m) - this->X.begin()) - 1;
    const double w = (m - this->X[i]) / (this->X[i + 1] - this->X[i]);
    value = this->V[i] + (this->V[i + 1] - this->V[i]) * w;
  }
  return std::max(value, 0.0);
}

double GradientOpacityFunction::EvaluateGradient(const double gradient[3]) const
{
  return this->Identity ? 1.0 : this->Evaluate(VectorLength(gradient));
}
}
