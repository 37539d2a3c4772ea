/**
 * @class   hov::ProjectionVertex
 * @brief   The region vertex record of the OpenGL cell projection (HIAC
 *          section 7), the per-frame constants it is computed from and the
 *          indexed triangle chunks the CPU side fills in parallel.
 *
 * A region vertex is the front point of a ray segment through one convex
 * cell (or transfer-function slab) at a vertex of a homogeneous region of
 * its projection. FloatsPerVertex = 11 floats:
 *  - 0-3: clip coordinates of the front point (x, y, z, w);
 *  - 4-6: parallel projection: (L, tauFront, tauBack); perspective:
 *    (mu, tauFront, tauBack mu) with mu = |P| / |Q| (P, Q the front and back
 *    points relative to the eye). These are linear over the region on the
 *    front face, so perspective-correct interpolation is exact for them; the
 *    vertex shader recovers P from the clip position (clip -> dataset matrix)
 *    and the fragment shader L = |P| (1/mu - 1), tau_avg = (tauFront +
 *    (tauBack mu)/mu)/2 (hovProjectionFS.glsl);
 *  - 7-9: colour by method M0-M3 (hov::ComputeProjectionVertex);
 *  - 10: the vertex opacity 1 - exp(-L tau_avg) (method M0 only).
 * GPU-compatible semantics (Frame::ExtinctionTf set): tau = -ln(1 - a)/u is
 * not linear in s, but the opacity a is (between the property's nodes, the
 * only slab boundaries then), so 5-6 carry aFront and aBack (x mu) instead
 * and the fragment shader takes tau_avg = hov::GPUAverageExtinction(aFront,
 * aBack)/u, exact on the segment; M3's colour integrates the refined
 * extinction table over the segment (hov::IntegrateLinearScalar), M0's
 * vertex opacity uses the exact tau_avg.
 * A vertex at a cell corner has L = 0: its colour is the transfer function's
 * colour there (the L -> 0 limit of every method), its opacity 0.
 *
 * Thread safety: the functions are re-entrant; a Chunk belongs to one thread.
 * @sa hov::ProjectionRegions, hov::ProjectionTetra, hovProjectionColor.h
 */
#ifndef hovProjectionVertex_h
#define hovProjectionVertex_h

#include "hovProjectionColor.h" // methods, colour table

#include <glm/glm.hpp> // dvec, dmat4

#include <algorithm> // std::max, std::copy
#include <cstddef>   // size_t
#include <memory>    // unique_ptr

namespace hov
{
class TransferFunction;
}

/// Per-frame constants of the region vertices.
namespace hov
{
struct ProjectionFrame
{
  glm::dmat4 Composite{ 1.0 }; ///< dataset -> clip
  glm::dmat4 Inverse{ 1.0 };   ///< clip -> dataset (homogeneous)
  const hov::SegmentColorTable* Table = nullptr;
  const hov::TransferFunction* Tf = nullptr;
  hov::ProjectionColorMethod Method = hov::ProjectionColorMethod::ExactColor;
  hov::EmissionModel Emission = hov::EmissionModel::WilliamsMax;
  bool Parallel = false;
  glm::dvec3 Eye{ 0.0 }; ///< perspective: camera position (dataset coordinates)
  /// GPU-compatible semantics: Tf is the linear-opacity table (its "tau" is
  /// the opacity a), this the refined extinction table (M3's integral), and
  /// the vertex carries opacities instead of extinctions (see the class doc).
  const hov::TransferFunction* ExtinctionTf = nullptr;
  double InverseUnit = 1.0; ///< 1 / unit distance (GPU-compatible semantics)
};
}

/// A growable array of plain values that never zero-fills and keeps its
/// storage across frames (Clear() only resets the size).
namespace hov
{
template <typename T>
class ProjectionArray
{
public:
  size_t Size() const { return this->Count; }
  const T* Data() const { return this->Storage.get(); }
  void Clear() { this->Count = 0; }
  /// Room for @p n more values at the end; returns a pointer to the first.
  T* Append(size_t n)
  {
    if (this->Count + n > this->Capacity)
    {
      const size_t capacity = std::max(this->Count + n, 2 * this->Capacity + 1024);
      std::unique_ptr<T[]> grown(new T[capacity]);
      std::copy(this->Storage.get(), this->Storage.get() + this->Count, grown.get());
      this->Storage = std::move(grown);
      this->Capacity = capacity;
    }
    T* out = this->Storage.get() + this->Count;
    this->Count += n;
    return out;
  }
  /// Drop the last @p n values.
  void Shrink(size_t n) { this->Count -= std::min(n, this->Count); }

private:
  std::unique_ptr<T[]> Storage;
  size_t Count = 0, Capacity = 0;
};
}

/// Indexed triangles of a run of consecutive cells (indices local to the chunk).
namespace hov
{
struct ProjectionChunk
{
  hov::ProjectionArray<float> Vertices;
  hov::ProjectionArray<unsigned int> Indices;

  unsigned int NumberOfVertices() const;
  /// Room for @p n vertices; @p first receives the local index of the first.
  float* AddVertices(int n, unsigned int& first);
  void Clear()
  {
    this->Vertices.Clear();
    this->Indices.Clear();
  }
};
}

namespace hov
{
class ProjectionVertex
{
public:
  static constexpr int FloatsPerVertex = 11;

  /**
   * Unproject the NDC points (x, y, zFront) and (x, y, zBack) to dataset
   * coordinates @p front and @p back; returns the clip w of the front point.
   */
  static double Unproject(const hov::ProjectionFrame& f, double x, double y, double zFront,
    double zBack, glm::dvec3& front, glm::dvec3& back);

  /**
   * The vertex of the segment @p front -> @p back (dataset coordinates, from
   * Unproject) seen at NDC (x, y, zFront), front clip w @p w, with scalars
   * @p sFront, @p sBack on transfer-function interval @p k. False if a value
   * is not finite (nothing useful to draw).
   */
  static bool Write(const hov::ProjectionFrame& f, int k, double x, double y, double zFront,
    double w, const glm::dvec3& front, const glm::dvec3& back, double sFront, double sBack,
    float* out);

  /// A zero-length vertex at clip position @p clip with scalar @p s (interval @p k).
  static void WriteCorner(
    const hov::ProjectionFrame& f, int k, const glm::dvec4& clip, double s, float* out);
};
}

#endif
