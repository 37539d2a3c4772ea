/**
 * @file hovTestReferencePeers.h
 * @brief The bundled-dataset comparisons of issue 4 (TestDataset*): our
 * mapper on the native cells (quadratic tetrahedra, hexahedra, wedges,
 * pyramids) beside VTK's vtkProjectedTetrahedraMapper (PT) and
 * vtkUnstructuredGridVolumeRayCastMapper (RC, Bunyk + linear ray integrator,
 * image sample distance 1) on the linear tetrahedra they need.
 *
 * All of them read the same vtkVolumeProperty; ours uses VTK_UNSTRUCTURED
 * semantics (extinction a/u, like VTK's unstructured mappers) so that, with a
 * transfer function whose opacity nodes are also colour nodes (where VTK's
 * linear integrator is exact), the images differ only by the tessellation,
 * the peers' 8-bit output and their pixel/sampling conventions. Our image is
 * the float image of RenderImage; the peers' images are screen captures of
 * offscreen windows (black background). RC casts its rays through pixel
 * corners: ours is also rendered with the rays shifted by half a pixel
 * (vtkCamera::SetWindowCenter) for that comparison, as in TestCompareVTK.
 */
#ifndef hovTestReferencePeers_h
#define hovTestReferencePeers_h

#include "hovTestImages.h"

#include <string>

class vtkCamera;
class vtkUnstructuredGrid;
class vtkVolumeProperty;

namespace hovTestRef
{
/// Images, times and messages of one comparison.
struct PeerRun
{
  hovTest::Image Ours;          ///< ours, native cells, pixel-centre rays
  hovTest::Image OursCorners;   ///< ours, native cells, rays through pixel corners
  hovTest::Image OursTessellated; ///< ours on the peers' tetrahedra
  hovTest::Image PT, RC;        ///< screen captures
  double OursSeconds = 0, OursTessellatedSeconds = 0, PTSeconds = 0, RCSeconds = 0;
  std::string OurWarnings, OurErrors, PeerMessages;
  long long WitnessViolations = 0;
  int OurStatus = 0;
};

/**
 * Renders @p native with ours (ordering @p cellOrdering) and @p tessellated
 * with ours, PT and RC, all @p size x @p size from @p cam with @p property;
 * writes PNGs <tmp>/<tag>_{ours,ours_tess,pt,rc}.png.
 */
PeerRun RenderWithPeers(vtkUnstructuredGrid* native, vtkUnstructuredGrid* tessellated,
  vtkVolumeProperty* property, vtkCamera* cam, int size, int cellOrdering, const std::string& tmp,
  const std::string& tag);

/// Largest of the R, G, B mean absolute differences (x 255).
double MeanDiff255(const hovTest::Image& a, const hovTest::Image& b);

/// Prints the comparison table of a run (mean / p99 / max x 255 per channel, times).
void PrintPeerTable(const PeerRun& run);
}

#endif
