// hovBenchRender: the Markdown table of the results (see BenchRender.h).
#include "BenchRender.h"

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <sstream>

namespace hovBench
{
std::string Fmt(double v, int prec)
{
  char buf[64];
  std::snprintf(buf, sizeof(buf), "%.*f", prec, v);
  return buf;
}

std::string Ratio(double a, double b)
{
  if (!(b > 0.0) || !(a > 0.0))
  {
    return "-";
  }
  char buf[64];
  std::snprintf(buf, sizeof(buf), "%.2fx", a / b);
  return buf;
}

std::string PairedRatio(const Row& r, const Row* base)
{
  if (!base || r.RotatingTimes.size() != base->RotatingTimes.size() || r.RotatingTimes.empty())
  {
    return "-";
  }
  std::vector<double> ratios;
  for (size_t i = 0; i < r.RotatingTimes.size(); ++i)
  {
    if (!(base->RotatingTimes[i] > 0.0))
    {
      return "-";
    }
    ratios.push_back(r.RotatingTimes[i] / base->RotatingTimes[i]);
  }
  char buf[96];
  std::snprintf(buf, sizeof(buf), "%.2fx [%.2f, %.2f]", Median(ratios),
    *std::min_element(ratios.begin(), ratios.end()),
    *std::max_element(ratios.begin(), ratios.end()));
  return buf;
}

bool PrintTable(const Options& opt, const std::vector<Mesh>& meshes, const std::vector<Row>& rows)
{
  std::ostringstream t;
  t << "\n## hovBenchRender: " << opt.Size << "x" << opt.Size << ", N = " << opt.Frames
    << " frames per median, azimuth step " << opt.AzimuthStep
    << " deg; opacity semantics: VTK-unstructured (extinction a(s)/u) for every mapper\n\n";
  t << "Times in seconds, wall clock of renderWindow->Render() + WaitForCompletion(). "
       "First: first frame of a fresh mapper (window already created). Rotating: median of N "
       "frames, each after a camera azimuth step. Same view: median of N frames without a camera "
       "change. CPU image: our mapper's GetLastImageTime() (median, rotating). Ratios: this "
       "mapper's time / our mapper's time (>1: ours is faster); 'vis' = our visibility sort, "
       "'pix' = our per-pixel sort. Paired: the frames are interleaved (each round renders one "
       "frame with every mapper), so each rotating round gives a ratio under the same machine "
       "load; median [min, max] over the rounds.\n\n";
  t << "| mesh | tets | mapper | first | rotating median | same-view median | CPU image "
       "| first / vis | rotating / vis | paired rotating / vis | same-view / vis | rotating / pix "
       "| witness | covered px | status |\n";
  t << "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  bool allOk = true;
  for (const Mesh& mesh : meshes)
  {
    const Row* vis = nullptr;
    const Row* pix = nullptr;
    for (const Row& r : rows)
    {
      if (r.Mesh == mesh.Name && r.Key == "hov_vis" && r.Ran)
      {
        vis = &r;
      }
      if (r.Mesh == mesh.Name && r.Key == "hov_pix" && r.Ran)
      {
        pix = &r;
      }
    }
    for (const Row& r : rows)
    {
      if (r.Mesh != mesh.Name)
      {
        continue;
      }
      t << "| " << r.Mesh << " | " << mesh.Tetras << " | " << r.Mapper << " | ";
      if (!r.Ran)
      {
        t << "- | - | - | - | - | - | - | - | - | - | - | - | " << r.Problem << " |\n";
        continue;
      }
      allOk = allOk && r.Ok;
      t << Fmt(r.First) << " | " << Fmt(r.Rotating) << " | " << Fmt(r.Same) << " | "
        << (r.CpuRotating >= 0 ? Fmt(r.CpuRotating) : std::string("-")) << " | "
        << (vis ? Ratio(r.First, vis->First) : "-") << " | "
        << (vis ? Ratio(r.Rotating, vis->Rotating) : "-") << " | " << PairedRatio(r, vis)
        << " | "
        << (vis ? Ratio(r.Same, vis->Same) : "-") << " | "
        << (pix ? Ratio(r.Rotating, pix->Rotating) : "-") << " | "
        << (r.Witness >= 0 ? std::to_string(r.Witness) : std::string("-")) << " | "
        << Fmt(100.0 * r.Coverage, 1) << "% | " << (r.Ok ? "ok" : "FAILED: " + r.Problem)
        << " |\n";
    }
  }
  std::cout << t.str() << std::flush;
  return allOk;
}
}
