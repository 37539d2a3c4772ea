/**
 * @file BenchRender.h
 * @brief Pieces of hovBenchRender (see BenchRender.cxx for what it measures):
 * options, the meshes and their transfer function and camera
 * (BenchRenderScene.cxx), one timed run of a mapper (BenchRenderRun.cxx) and
 * the Markdown table of the results (BenchRenderTable.cxx).
 */
#ifndef BenchRender_h
#define BenchRender_h

#include "vtkCallbackCommand.h"
#include "vtkNew.h"
#include "vtkSmartPointer.h"
#include "vtkType.h"
#include "vtkUnstructuredGrid.h"

#include <functional>
#include <memory>
#include <string>
#include <vector>

#ifndef HOV_BENCH_DATA_DIR
#define HOV_BENCH_DATA_DIR "."
#endif

class vtkAbstractVolumeMapper;
class vtkCamera;
class vtkObject;
class vtkRenderWindow;
class vtkVolumeProperty;

namespace hovBench
{
struct Options
{
  std::string DataDir = HOV_BENCH_DATA_DIR;
  std::string OutDir; // empty: no images written
  std::string Meshes = "all";
  int Frames = 3;
  int Size = 512;
  int Extent = 24;
  double AzimuthStep = 7.0;
  bool SkipRayCastLarge = false;
  std::string Only; // comma-separated row keys to run (empty: all)
  /// > 0: no opacity over the lowest fraction of the scalar range (MakeProperty()).
  double TransparentBelow = 0.0;
};

struct Mesh
{
  std::string Name;
  vtkSmartPointer<vtkUnstructuredGrid> Grid;
  std::string Array;
  double Range[2] = { 0, 1 };
  double UnitDistance = 1.0;
  vtkIdType Tetras = 0;
};

struct Row
{
  std::string Mesh;
  std::string Mapper;
  std::string Key; // hov_vis, hov_pix, pt, rc
  bool Ran = false;
  bool Ok = true;
  std::string Problem;
  double First = 0, Rotating = 0, Same = 0;
  double CpuRotating = -1; // our mapper: median GetLastImageTime() of the rotating frames
  vtkIdType Witness = -1;  // our mapper: witness violations of the last rotating frame
  double Coverage = 0;     // fraction of non-black pixels of the last frame
  std::vector<double> RotatingTimes; // per rotating frame, in frame order (paired ratios)
};

/// A mapper set up for timing in its own offscreen window (see Prepare()).
struct Run
{
  Row Result;
  vtkSmartPointer<vtkAbstractVolumeMapper> Mapper;
  vtkSmartPointer<vtkRenderWindow> Window;
  vtkSmartPointer<vtkCamera> Camera;
  size_t ErrorsBefore = 0;
  std::vector<double> Same, Cpu;
};

/// Collects VTK errors of the objects it observes (the message is not printed twice).
class ErrorCounter
{
public:
  ErrorCounter();
  void Watch(vtkObject* obj);
  std::vector<std::string> Messages;

private:
  static void OnEvent(vtkObject* caller, unsigned long, void* clientData, void* callData);
  vtkNew<vtkCallbackCommand> Callback;
};

// --- BenchRenderScene.cxx ----------------------------------------------------

/// Number of VTK_TETRA cells of @p grid.
vtkIdType CountTetras(vtkUnstructuredGrid* grid);

/// The demo's transfer function (Utilities/hov_demo.py): 7 colour and opacity nodes at the
/// same scalars, low faint blue -> cyan -> green -> yellow -> orange -> red, opacity rising.
/// With @p transparentBelow = f in (0, 1): opacity 0 from the start of the range to the
/// fraction f of it (the nodes there set to 0, one added at f), the rest as before.
vtkSmartPointer<vtkVolumeProperty> MakeProperty(
  const double range[2], double unitDistance, double transparentBelow = 0.0);

/// Oblique view (azimuth 35, elevation 30 from +z) of the bounding box, fitted like
/// vtkRenderer::ResetCamera, with a fixed clipping range enclosing the bounding sphere.
void SetupCamera(vtkCamera* cam, const double b[6]);

/// The bundled bracket (point array von_mises) from opt.DataDir.
bool LoadBracket(const Options& opt, Mesh& mesh);

/// vtkRTAnalyticSource over [-E,E]^3 split into tetrahedra (E = opt.Extent).
bool MakeRTMesh(const Options& opt, Mesh& mesh);

// --- BenchRenderRun.cxx ------------------------------------------------------

double Median(std::vector<double> v);

/// Wall-clock seconds of @p f.
double Seconds(const std::function<void()>& f);

/// Fraction of non-black pixels in the window (RGB read back); written as PNG to @p png
/// unless it is empty.
double Coverage(vtkRenderWindow* win, const std::string& png);

/// @p s with every character that is not alphanumeric replaced by '_'.
std::string FileSafe(std::string s);

/// Sets @p mapper up on @p mesh in its own offscreen window (OpenGL context created by
/// rendering once without the volume, so the first timed frame measures the mapper).
std::unique_ptr<Run> Prepare(const Options& opt, const Mesh& mesh, const std::string& key,
  const std::string& label, vtkAbstractVolumeMapper* mapper, ErrorCounter& errors);

/// Wall-clock seconds of one frame of @p run: Render() + WaitForCompletion().
double TimeFrame(Run& run);

/// Times the runs of one mesh: each one's first frame, then opt.Frames rounds in which every
/// run renders the same view once, then opt.Frames rounds in which every run steps its camera
/// by the same azimuth and renders. Rounds interleave the mappers, so a change of machine
/// load hits all of them alike and the per-frame ratios are paired.
void TimeInterleaved(const Options& opt, std::vector<std::unique_ptr<Run>>& runs);

/// Medians, coverage (PNG into opt.OutDir), errors seen by @p errors since Prepare() and an
/// all-black image (both make the row fail); releases the window. Returns the row.
Row Finish(const Options& opt, const Mesh& mesh, Run& run, ErrorCounter& errors);

// --- BenchRenderTable.cxx ----------------------------------------------------

/// "%.<prec>f" of @p v.
std::string Fmt(double v, int prec = 3);

/// "a/b" as "%.2fx", or "-" unless both are positive.
std::string Ratio(double a, double b);

/// "median [min, max]" of the per-round ratios r / base of the rotating frames, or "-".
std::string PairedRatio(const Row& r, const Row* base);

/// Prints the Markdown table of @p rows; true if every run succeeded.
bool PrintTable(const Options& opt, const std::vector<Mesh>& meshes, const std::vector<Row>& rows);
}

#endif
