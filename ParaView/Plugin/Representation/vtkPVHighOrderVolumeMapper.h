/**
 * @class   vtkPVHighOrderVolumeMapper
 * @brief   vtkHighOrderVolumeMapper as ParaView's representation uses it.
 *
 * The mapper of the "Accurate Volume" representation
 * (vtkHighOrderVolumeRepresentation). It renders exactly like
 * vtkHighOrderVolumeMapper (every render mode, the same images) and adds what
 * a ParaView rank needs around a frame:
 *  - a rank whose piece is empty (ParaView's redistribution gave it no cells)
 *    draws nothing, without the mapper's generic warning (the representation
 *    names the rank once per piece): the other ranks' layers composite as usual;
 *    its float image is the zero image of the viewport and its counts are 0
 *    (also written to the file below, so no earlier frame's file is left);
 *  - after every frame the float image can be written to a file
 *    (SetFloatImageFileName; on rank r > 0 of an MPI run "_rank<r>" is added
 *    before the extension: each rank holds only its own piece's layer);
 *  - the frame's wall-clock time including the display of the image
 *    (GetLastFrameTime), beside the mapper's GetLastImageTime.
 *
 * Thread safety: as vtkHighOrderVolumeMapper (rendering thread only).
 * @sa vtkHighOrderVolumeMapper, vtkHighOrderVolumeRepresentation
 */
#ifndef vtkPVHighOrderVolumeMapper_h
#define vtkPVHighOrderVolumeMapper_h

#include "vtkHighOrderVolumeMapper.h"
#include "vtkParaViewHighOrderVolumeModule.h" // For export macro

#include <string> // For FloatImageFileName

class VTKPARAVIEWHIGHORDERVOLUME_EXPORT vtkPVHighOrderVolumeMapper : public vtkHighOrderVolumeMapper
{
public:
  static vtkPVHighOrderVolumeMapper* New();
  vtkTypeMacro(vtkPVHighOrderVolumeMapper, vtkHighOrderVolumeMapper);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// Write the float image (.vti, array "RGBA") here after every frame; empty: never (default).
  void SetFloatImageFileName(const std::string& name) { this->FloatImageFileName = name; }
  const std::string& GetFloatImageFileName() const { return this->FloatImageFileName; }
  ///@}

  /// Wall-clock seconds of the last Render() (image and its display).
  double GetLastFrameTime() const { return this->LastFrameTime; }

  /// Render() calls so far (diagnostics: one per frame and rank is expected).
  vtkIdType GetNumberOfRenderCalls() const { return this->NumberOfRenderCalls; }

  /// Largest per-pixel error estimate of the last RAY_CAST frame; -1 after other modes.
  double GetRayCastErrorEstimate();

  void Render(vtkRenderer* ren, vtkVolume* vol) override;

protected:
  vtkPVHighOrderVolumeMapper();
  ~vtkPVHighOrderVolumeMapper() override;

private:
  vtkPVHighOrderVolumeMapper(const vtkPVHighOrderVolumeMapper&) = delete;
  void operator=(const vtkPVHighOrderVolumeMapper&) = delete;

  /// The file name of this rank's float image.
  std::string RankFileName() const;
  /// An empty piece's frame: the zero float image of @p ren's viewport, counts 0.
  void PublishEmptyLayer(vtkRenderer* ren);
  void WriteFloatImage();

  std::string FloatImageFileName;
  double LastFrameTime = 0.0;
  vtkIdType NumberOfRenderCalls = 0;
};

#endif
