#include "hovProjectionVertex.h"

#include "hovTransferFunction.h" // Evaluate

#include <algorithm> // std::min
#include <cmath>     // std::isfinite

unsigned int hov::ProjectionChunk::NumberOfVertices() const
{
  return static_cast<unsigned int>(
    this->Vertices.Size() / hov::ProjectionVertex::FloatsPerVertex);
}

float* hov::ProjectionChunk::AddVertices(int n, unsigned int& first)
{
  first = this->NumberOfVertices();
  return this->Vertices.Append(static_cast<size_t>(n) * hov::ProjectionVertex::FloatsPerVertex);
}

double hov::ProjectionVertex::Unproject(const hov::ProjectionFrame& f, double x,
  double y, double zFront, double zBack, glm::dvec3& front, glm::dvec3& back)
{
  const glm::dvec4 hf = f.Inverse * glm::dvec4(x, y, zFront, 1.0);
  const glm::dvec4 hb = f.Inverse * glm::dvec4(x, y, zBack, 1.0);
  front = glm::dvec3(hf) / hf.w;
  back = glm::dvec3(hb) / hb.w;
  return 1.0 / hf.w; // Inverse * clip = (X, 1), so the NDC point has w = 1 / w_clip
}

namespace
{
/**
 * GPU-compatible semantics: whether interval @p k of the linear-opacity table
 * is an opaque medium (a = 1 all over it; infinite extinction). Its vertices
 * carry the opacity 2 instead of 1 (the fragment shader's marker): in float,
 * an interpolated 1 cannot be told from the 1 - 6e-8 of an interval that
 * only reaches a = 1 at its end (a finite mean extinction).
 */
bool OpaqueInterval(const hov::TransferFunction& tf, int k)
{
  const int n = tf.GetNumberOfNodes();
  if (n == 0)
  {
    return false;
  }
  if (k < 0 || k >= n - 1)
  {
    return tf.GetNode(k < 0 ? 0 : n - 1).Tau >= 1.0;
  }
  const hov::TransferFunction::Node& node = tf.GetNode(k);
  const double width = tf.GetNodes()[k + 1] - tf.GetNodes()[k];
  return node.Tau >= 1.0 && node.Tau + node.DTau * width >= 1.0;
}
}

bool hov::ProjectionVertex::Write(const hov::ProjectionFrame& f, int k, double x,
  double y, double zFront, double w, const glm::dvec3& front, const glm::dvec3& back,
  double sFront, double sBack, float* out)
{
  const double length = glm::length(back - front);
  const bool wvg = f.Emission == hov::EmissionModel::WilhelmsVanGelder;
  hov::SegmentEnd ef, eb;
  f.Tf->Evaluate(k, sFront, wvg, ef);
  f.Tf->Evaluate(k, sBack, wvg, eb);
  hov::ProjectionVertexColor v;
  if (f.ExtinctionTf)
  {
    // ef.Tau, eb.Tau are opacities (the linear-opacity table).
    v = hov::ComputeProjectionVertexGPU(f.Method, f.Emission, length, ef, eb, sFront, sBack,
      *f.ExtinctionTf, f.InverseUnit, *f.Table);
    if (OpaqueInterval(*f.Tf, k))
    {
      ef.Tau = eb.Tau = 2.0;
    }
  }
  else
  {
    v = hov::ComputeProjectionVertex(f.Method, f.Emission, length, ef, eb, *f.Table);
  }
  out[0] = static_cast<float>(x * w);
  out[1] = static_cast<float>(y * w);
  out[2] = static_cast<float>(zFront * w);
  out[3] = static_cast<float>(w);
  // An opaque medium (infinite extinction) stays finite: alpha is 1 either way.
  // (GPU-compatible semantics: the opacities, in [0, 1].)
  const double tauFront = std::min(ef.Tau, 1e30), tauBack = std::min(eb.Tau, 1e30);
  double first = length, scale = 1.0;
  if (!f.Parallel)
  {
    // mu = |P| / |Q|: 1/mu is linear along the back face, mu tauBack too.
    const double p = glm::length(front - f.Eye), q = glm::length(back - f.Eye);
    first = scale = q > 0.0 ? p / q : 1.0;
  }
  out[4] = static_cast<float>(first);
  out[5] = static_cast<float>(tauFront);
  out[6] = static_cast<float>(tauBack * scale);
  out[7] = static_cast<float>(v.Color[0]);
  out[8] = static_cast<float>(v.Color[1]);
  out[9] = static_cast<float>(v.Color[2]);
  out[10] = static_cast<float>(v.Alpha);
  bool finite = true;
  for (int c = 0; c < FloatsPerVertex; ++c)
  {
    finite = finite && std::isfinite(out[c]);
  }
  return finite;
}

void hov::ProjectionVertex::WriteCorner(
  const hov::ProjectionFrame& f, int k, const glm::dvec4& clip, double s, float* out)
{
  hov::SegmentEnd e;
  f.Tf->Evaluate(k, s, f.Emission == hov::EmissionModel::WilhelmsVanGelder, e);
  if (f.ExtinctionTf && OpaqueInterval(*f.Tf, k))
  {
    e.Tau = 2.0; // the opaque-medium marker (see OpaqueInterval)
  }
  const double tau = std::min(e.Tau, 1e30);
  for (int c = 0; c < 4; ++c)
  {
    out[c] = static_cast<float>(clip[c]);
  }
  out[4] = f.Parallel ? 0.0f : 1.0f; // L = 0, mu = 1
  out[5] = out[6] = static_cast<float>(tau);
  out[7] = static_cast<float>(e.Color[0]);
  out[8] = static_cast<float>(e.Color[1]);
  out[9] = static_cast<float>(e.Color[2]);
  out[10] = 0.0f;
}
