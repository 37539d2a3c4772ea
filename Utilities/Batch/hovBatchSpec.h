/**
 * @file   hovBatchSpec.h
 * @brief  Image specification file (JSON) of the batch renderer, parsed and checked.
 *
 * The format is documented in README.md, section "Batch rendering"; the
 * Python twin is Utilities/python/batch.py (same fields, same messages, same
 * calls on the mapper, so both give bit-identical float images).
 * Every problem is reported as "<field>: <what is wrong>", e.g.
 * "camera.position: expected 3 numbers, got 2"; unknown fields are errors
 * (a misspelt field would otherwise be silently ignored), except keys starting
 * with "_" (comments).
 */
#ifndef hovBatchSpec_h
#define hovBatchSpec_h

#include <string> // paths, names, messages
#include <vector> // nodes, planes, messages

namespace hov
{
struct BatchSpec
{
  std::string Data;           ///< absolute or relative to the spec file's folder
  std::string ArrayName;
  int ArrayComponent = -1;    ///< -1: magnitude
  bool CellArray = false;     ///< association "cell" (default "point")

  int Width = 512, Height = 512;
  double Background[3] = { 0.0, 0.0, 0.0 }; ///< PNG only

  bool HasPosition = false, HasViewUp = false, HasViewAngle = false;
  double Position[3] = { 0, 0, 1 }, FocalPoint[3] = { 0, 0, 0 }, ViewUp[3] = { 0, 1, 0 };
  double ViewAngle = 30.0;
  bool HasAzimuth = false, HasElevation = false, HasRoll = false, HasZoom = false;
  double Azimuth = 0.0, Elevation = 0.0, Roll = 0.0, Zoom = 1.0;
  bool Orthographic = false;
  bool HasParallelScale = false;
  double ParallelScale = 1.0;

  std::vector<double> ColorNodes;   ///< s, r, g, b per node
  std::vector<double> OpacityNodes; ///< s, a per node
  double UnitDistance = 1.0;
  int OpacitySemantics = 0; ///< vtkHighOrderVolumeMapper::OpacitySemanticsType
  double GPUOpacityTolerance = 1e-4;
  int EmissionModel = 0;
  double EmissionScale = 1.0;

  std::vector<double> Isosurfaces; ///< value, r, g, b, opacity per surface
  std::vector<double> ClipPlanes;  ///< origin xyz, normal xyz per plane
  bool ViewDepthClipping = false;
  double ViewDepthRange[2] = { 0.0, 1.0 };

  int RenderMode = 0;   ///< vtkHighOrderVolumeMapper::RenderModeType
  double RayCastTolerance = 1e-3; ///< RAY_CAST: per-pixel, per-channel tolerance
  int Integration = 0;  ///< EXACT / APPROXIMATE
  int CellOrdering = 0; ///< VISIBILITY_SORT / PER_PIXEL_SORT

  std::string OutputVTI, OutputPNG; ///< absolute or relative to the current directory
};

/**
 * Read and check @p path. Returns true if there is no error; @p errors and
 * @p warnings get one line each. A relative data path is resolved against
 * the spec file's folder (outputs stay relative to the current directory).
 */
bool ReadBatchSpec(const std::string& path, BatchSpec& spec, std::vector<std::string>& errors,
  std::vector<std::string>& warnings);

/// The same from JSON text; relative paths resolved against @p baseDir.
bool ParseBatchSpec(const std::string& text, const std::string& baseDir, BatchSpec& spec,
  std::vector<std::string>& errors, std::vector<std::string>& warnings);
}

#endif
