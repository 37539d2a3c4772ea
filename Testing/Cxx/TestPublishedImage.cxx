// The published float image (GetFloatImage) of CPU_ACCURATE, written with
// the pixel check in one parallel pass over blocks of rows (16384 pixels), on the
// bundled bracket at 257 x 203 (52,171 pixels: three blocks of 63 rows and a part):
// - every value is the double image's (GetDoubleImage) rounded to float, with
//   covered pixels in at least three blocks, also where the pass only writes
//   zeros: outside the tiles (TileSize, 32) that hold cells, whose pixels it
//   does not read (whole tile rows and columns are outside here);
// - the array is reused from frame to frame when nobody else holds it, and
//   left alone (a new one published) when somebody does;
// - pixels whose colour float cannot hold (Wilhelms-Van Gelder emission, red
//   1e37, EmissionScale 1e6) are zeroed in both images and counted exactly
//   once in the frame's warning.
#include "hovTestImages.h"
#include "hovTestScenes.h"

#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkPointData.h"
#include "vtkSmartPointer.h"

#include <algorithm>
#include <cctype>
#include <cfloat>
#include <cmath>
#include <set>
#include <string>
#include <vector>

using namespace hovTest;

namespace
{
constexpr int Width = 257, Height = 203;

vtkFloatArray* Published(vtkHighOrderVolumeMapper* mapper)
{
  return vtkFloatArray::SafeDownCast(mapper->GetFloatImage()->GetPointData()->GetScalars());
}

/// Values of the float image that are not the double image's rounded to
/// float (all of them if the sizes differ).
size_t Mismatches(vtkHighOrderVolumeMapper* mapper)
{
  vtkFloatArray* f = Published(mapper);
  const Image d = DoubleImage(mapper);
  if (!f || d.V.size() != 4u * Width * Height ||
    f->GetNumberOfValues() != static_cast<vtkIdType>(d.V.size()))
  {
    return static_cast<size_t>(-1);
  }
  size_t bad = 0;
  for (size_t i = 0; i < d.V.size(); ++i)
  {
    bad += f->GetValue(static_cast<vtkIdType>(i)) != static_cast<float>(d.V[i]);
  }
  return bad;
}

/// The N of "N of <pixels> pixels had a colour" in @p warning (0 if absent).
size_t OverflowCount(const std::string& warning)
{
  const std::string tail =
    " of " + std::to_string(Width * Height) + " pixels had a colour";
  const size_t at = warning.find(tail);
  size_t begin = at;
  while (at != std::string::npos && begin > 0 &&
    std::isdigit(static_cast<unsigned char>(warning[begin - 1])))
  {
    --begin;
  }
  return at == std::string::npos || begin == at ? 0 : std::stoul(warning.substr(begin, at - begin));
}
}

int TestPublishedImage(int argc, char* argv[])
{
  Checker ck;
  std::unique_ptr<VolumeScene> scene = BracketScene(ck, argc, argv);
  if (!scene)
  {
    return ck.Result();
  }
  vtkHighOrderVolumeMapper* mapper = scene->Mapper;
  mapper->SetRenderModeToCPUAccurate();
  vtkNew<vtkCamera> camera;
  BracketCamera(camera);
  auto render = [&](const std::string& what) {
    int status = 0;
    Render(mapper, camera, scene->Volume, Width, Height, &status);
    ck.Check(status == 1, what + ": rendered");
  };

  // 1. The float image is the double image rounded, in every block.
  render("first frame");
  ck.Check(Mismatches(mapper) == 0, "float image == double image rounded to float, every value");
  {
    const Image d = DoubleImage(mapper);
    std::set<size_t> blocks;
    size_t covered = 0;
    for (size_t p = 0; p < d.Pixels(); ++p)
    {
      if (d.V[4 * p + 3] > 0.0)
      {
        blocks.insert(p / 16384);
        ++covered;
      }
    }
    ck.Check(blocks.size() >= 3 && covered > 5000,
      "the covered pixels (" + std::to_string(covered) + ") lie in " +
        std::to_string(blocks.size()) + " blocks of 16384 pixels (at least 3)");
    // Every cell of the bracket is visible (the transfer function is
    // non-zero over its scalar range), so tiles beyond the covered pixels'
    // extent (and a pixel of slack) hold no cell: a whole tile row or column
    // of them lies outside the content box.
    int box[4] = { Width, -1, Height, -1 };
    for (int y = 0; y < Height; ++y)
    {
      for (int x = 0; x < Width; ++x)
      {
        if (d.V[4 * (static_cast<size_t>(y) * Width + x) + 3] > 0.0)
        {
          box[0] = std::min(box[0], x);
          box[1] = std::max(box[1], x);
          box[2] = std::min(box[2], y);
          box[3] = std::max(box[3], y);
        }
      }
    }
    const int tile = mapper->GetTileSize();
    const bool freeTiles = (box[0] - 1) / tile > 0 || (box[2] - 1) / tile > 0 ||
      (box[1] + 1) / tile < (Width - 1) / tile || (box[3] + 1) / tile < (Height - 1) / tile;
    ck.Check(freeTiles, "a whole row or column of tiles lies outside the covered pixels");
  }

  // 2. Not held: the next frame writes into the same array.
  vtkFloatArray* first = Published(mapper);
  camera->Azimuth(20.0);
  render("second frame");
  ck.Check(Published(mapper) == first, "the array nobody else holds is reused");
  ck.Check(Mismatches(mapper) == 0, "second frame: float image == double image rounded");

  // 3. Held: left as it was, a new array published.
  vtkSmartPointer<vtkFloatArray> held = Published(mapper);
  const float* h = held->GetPointer(0);
  const std::vector<float> before(h, h + held->GetNumberOfValues());
  camera->Azimuth(20.0);
  render("third frame");
  ck.Check(Published(mapper) != held.Get(), "a held array is not written: a new one is published");
  ck.Check(std::vector<float>(h, h + held->GetNumberOfValues()) == before,
    "the held array keeps the previous frame");
  ck.Check(Mismatches(mapper) == 0, "third frame: float image == double image rounded");
  ck.Check(scene->NoMessages(), "no messages so far");

  // 4. Colours beyond float's range. The expected count comes from the same
  // frame at scale 1 (the scale multiplies the colour; pixels within 1e-6 of
  // the threshold may go either way).
  mapper->SetEmissionModelToWilhelmsVanGelder();
  scene->Tf.Color->RemoveAllPoints();
  scene->Tf.Color->AddRGBPoint(0.0, 1e37, 0.9, 0.8);
  scene->Tf.Color->AddRGBPoint(170.0, 1e37, 1.0, 1.0);
  render("red 1e37");
  const Image plain = DoubleImage(mapper);
  size_t surely = 0, maybe = 0;
  for (size_t p = 0; p < plain.Pixels(); ++p)
  {
    surely += plain.V[4 * p] * 1e6 > FLT_MAX * (1 + 1e-6) ? 1 : 0;
    maybe += plain.V[4 * p] * 1e6 > FLT_MAX * (1 - 1e-6) ? 1 : 0;
  }
  scene->Observer->Clear();
  mapper->SetEmissionScale(1e6);
  render("EmissionScale 1e6");
  const std::string warning = Msg(scene->Observer->GetWarningMessage());
  const size_t reported = OverflowCount(warning);
  ck.Check(surely > 5000 && surely <= reported && reported <= maybe,
    "one warning counting every overflowing pixel: " + std::to_string(reported) + " in [" +
      std::to_string(surely) + ", " + std::to_string(maybe) + "]: '" + warning + "'");
  ck.Check(warning.find("image is empty") == std::string::npos,
    "an image emptied by the overflow is not also called empty");
  ck.Check(Mismatches(mapper) == 0, "overflow frame: float image == double image rounded");
  const Image glowing = DoubleImage(mapper);
  const Sanity sane = CheckImage(FloatImage(mapper));
  size_t zeroed = 0;
  for (size_t p = 0; p < glowing.Pixels() && glowing.V.size() == plain.V.size(); ++p)
  {
    bool allZero = true;
    for (int c = 0; c < 4; ++c)
    {
      allZero = allZero && glowing.V[4 * p + c] == 0.0;
    }
    zeroed += allZero && plain.V[4 * p] * 1e6 > FLT_MAX * (1 + 1e-6) ? 1 : 0;
  }
  ck.Check(sane.NonFinite == 0, "no non-finite value in the float image");
  ck.Check(zeroed == surely,
    "every overflowing pixel is transparent (" + std::to_string(zeroed) + " of " +
      std::to_string(surely) + ")");
  return ck.Result();
}
