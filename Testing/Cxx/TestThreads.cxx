// Determinism across threads: the real bracket mesh (56071 linear tetrahedra,
// point scalars "von_mises") rendered with RenderImage at 200x150 under 1, 2
// and 4 threads (vtkSMPTools::LocalScope) of the TBB and STDThread backends,
// a fresh mapper each time, for both cell orderings: every float image must be
// bit-identical (memcmp) to the first one and non-trivial (pixels with
// alpha > 0.05). Also: rendering twice in a row with one mapper, re-rendering
// under another thread count, and rendering after the camera moved away and
// back all give the identical image.
#include "hovTestReference.h"

#include "vtkHighOrderVolumeMapper.h"

#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkDataArray.h"
#include "vtkMath.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkSMPTools.h"
#include "vtkTestErrorObserver.h"
#include "vtkUnstructuredGrid.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"
#include "vtkXMLUnstructuredGridReader.h"

#include <chrono>
#include <cmath>
#include <cstring>
#include <iostream>
#include <mutex>
#include <set>
#include <thread>
#include <sstream>
#include <string>
#include <vector>

namespace
{
constexpr int Width = 200;
constexpr int Height = 150;

struct Render
{
  std::vector<float> Pixels;
  vtkIdType Witness = 0;
  std::string Backend;
  int Threads = 0;       ///< vtkSMPTools::GetEstimatedNumberOfThreads()
  int ActualThreads = 0; ///< distinct threads seen by a probe vtkSMPTools::For
  double Seconds = 0.0;
};

/// Distinct threads that run the pieces of a small vtkSMPTools::For whose
/// pieces sleep (so an idle worker always gets some).
int ProbeThreads()
{
  std::mutex mutex;
  std::set<std::thread::id> ids;
  for (int attempt = 0; attempt < 100 && ids.size() < 2; ++attempt) // a loaded machine may be slow to wake workers
  {
    vtkSMPTools::For(0, 16, 1, [&](vtkIdType, vtkIdType) {
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
      std::lock_guard<std::mutex> lock(mutex);
      ids.insert(std::this_thread::get_id());
    });
  }
  return static_cast<int>(ids.size());
}

/// Pixels with alpha > 0.05.
int VisiblePixels(const std::vector<float>& px)
{
  int n = 0;
  for (size_t p = 3; p < px.size(); p += 4)
  {
    n += px[p] > 0.05f;
  }
  return n;
}

/// Number of differing floats and the largest difference.
std::string Difference(const std::vector<float>& a, const std::vector<float>& b)
{
  if (a.size() != b.size())
  {
    return "sizes differ: " + std::to_string(a.size()) + " vs " + std::to_string(b.size());
  }
  size_t count = 0, first = a.size();
  double largest = 0.0;
  for (size_t k = 0; k < a.size(); ++k)
  {
    if (std::memcmp(&a[k], &b[k], sizeof(float)) != 0)
    {
      first = std::min(first, k);
      ++count;
      largest = std::max(largest, std::fabs(static_cast<double>(a[k]) - b[k]));
    }
  }
  std::ostringstream os;
  os << count << " of " << a.size() << " floats differ, largest difference " << largest;
  if (count)
  {
    os << ", first at pixel (" << (first / 4) % Width << ", " << (first / 4) / Width
       << ") channel " << first % 4;
  }
  return os.str();
}
}

int TestThreads(int argc, char* argv[])
{
  std::string dataDir;
  for (int i = 1; i + 1 < argc; ++i)
  {
    if (std::string(argv[i]) == "-D")
    {
      dataDir = argv[i + 1];
    }
  }
  if (dataDir.empty())
  {
    std::cerr << "FAILED: no -D <data directory> argument\n";
    return EXIT_FAILURE;
  }
  const std::string fileName = dataDir + "/bracket_tet4_ccx.vtu";
  vtkNew<vtkXMLUnstructuredGridReader> reader;
  reader->SetFileName(fileName.c_str());
  reader->Update();
  vtkUnstructuredGrid* grid = reader->GetOutput();
  vtkDataArray* scalars = grid->GetPointData()->GetScalars();
  if (!scalars || std::string(scalars->GetName() ? scalars->GetName() : "") != "von_mises" ||
    grid->GetNumberOfCells() == 0)
  {
    std::cerr << "FAILED: " << fileName << " has no cells or its active point scalars are not "
              << "von_mises\n";
    return EXIT_FAILURE;
  }
  double range[2];
  scalars->GetRange(range);
  double bounds[6];
  grid->GetBounds(bounds);
  std::cout << fileName << ": " << grid->GetNumberOfCells() << " cells, von_mises in [" << range[0]
            << ", " << range[1] << "]\n";

  vtkNew<vtkColorTransferFunction> ctf;
  ctf->AddRGBPoint(0.0, 0.1, 0.1, 0.6);
  ctf->AddRGBPoint(40.0, 0.1, 0.8, 0.8);
  ctf->AddRGBPoint(90.0, 0.9, 0.9, 0.1);
  ctf->AddRGBPoint(166.0, 0.9, 0.1, 0.1);
  vtkNew<vtkPiecewiseFunction> otf;
  otf->AddPoint(0.0, 0.04);
  otf->AddPoint(15.0, 0.1);
  otf->AddPoint(55.0, 0.4);
  otf->AddPoint(100.0, 0.2);
  otf->AddPoint(166.0, 0.8);
  vtkNew<vtkVolumeProperty> property;
  property->SetColor(ctf);
  property->SetScalarOpacity(otf);
  property->SetScalarOpacityUnitDistance(2.0);

  // Oblique perspective view of the whole part.
  const double centre[3] = { 0.5 * (bounds[0] + bounds[1]), 0.5 * (bounds[2] + bounds[3]),
    0.5 * (bounds[4] + bounds[5]) };
  const double radius = 0.5 *
    std::sqrt((bounds[1] - bounds[0]) * (bounds[1] - bounds[0]) +
      (bounds[3] - bounds[2]) * (bounds[3] - bounds[2]) +
      (bounds[5] - bounds[4]) * (bounds[5] - bounds[4]));
  const double dir[3] = { 0.62, -0.7, 0.35 };
  const double dn = std::sqrt(dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2]);
  const double distance = 0.8 * radius / std::sin(vtkMath::RadiansFromDegrees(15.0));
  vtkNew<vtkCamera> camera;
  camera->SetFocalPoint(centre[0], centre[1], centre[2]);
  camera->SetPosition(centre[0] + distance * dir[0] / dn, centre[1] + distance * dir[1] / dn,
    centre[2] + distance * dir[2] / dn);
  camera->SetViewUp(0.0, 0.0, 1.0);
  camera->SetViewAngle(30.0);
  camera->SetClippingRange(distance - 1.2 * radius, distance + 1.2 * radius);
  const std::string inputs = hovTestRef::ReadCamera(camera).ToString() + "\n  " +
    hovTestRef::DescribeProperty(property) + "\n  image " + std::to_string(Width) + "x" +
    std::to_string(Height) + ", GPU_COMPATIBLE semantics, WILLIAMS_MAX emission";

  int failures = 0;
  auto fail = [&](const std::string& what) {
    std::cerr << "FAILED: " << what << "\n  inputs: " << inputs << "\n";
    ++failures;
  };

  using Clock = std::chrono::steady_clock;
  // One render with the given mapper under a given backend and thread count.
  auto render = [&](vtkHighOrderVolumeMapper* mapper, const std::string& backend, int threads,
                  const std::string& label) {
    Render out;
    vtkNew<vtkVolume> volume;
    volume->SetMapper(mapper);
    volume->SetProperty(property);
    vtkNew<vtkTest::ErrorObserver> observer;
    mapper->AddObserver(vtkCommand::ErrorEvent, observer);
    mapper->AddObserver(vtkCommand::WarningEvent, observer);
    vtkSMPTools::LocalScope(vtkSMPTools::Config{ threads, backend, false }, [&]() {
      out.Backend = vtkSMPTools::GetBackend();
      out.Threads = vtkSMPTools::GetEstimatedNumberOfThreads();
      out.ActualThreads = ProbeThreads();
      const Clock::time_point start = Clock::now();
      if (mapper->RenderImage(camera, volume, Width, Height) != 1)
      {
        fail(label + ": RenderImage did not return 1");
      }
      out.Seconds = std::chrono::duration<double>(Clock::now() - start).count();
    });
    mapper->RemoveObserver(observer);
    if (observer->GetError() || observer->GetWarning())
    {
      fail(label + ": unexpected VTK message: " + observer->GetErrorMessage() +
        observer->GetWarningMessage());
    }
    std::string why;
    const float* px = hovTestRef::ImagePixels(mapper->GetFloatImage(), Width, Height, why);
    if (!px)
    {
      fail(label + ": " + why);
      out.Pixels.assign(static_cast<size_t>(Width) * Height * 4, -1.0f);
      return out;
    }
    out.Pixels.assign(px, px + static_cast<size_t>(Width) * Height * 4);
    out.Witness = mapper->GetWitnessViolations();
    return out;
  };

  const char* backends[] = { "TBB", "STDThread" };
  const unsigned hardwareThreads = std::thread::hardware_concurrency();
  std::cout << "hardware threads: " << hardwareThreads << "\n";
  std::vector<float> orderingImages[2];
  for (int ordering = 0; ordering < 2; ++ordering)
  {
    const std::string orderingName = ordering ? "PER_PIXEL_SORT" : "VISIBILITY_SORT";
    std::vector<Render> renders;
    for (const char* backend : backends)
    {
      for (int threads : { 1, 2, 4 })
      {
        const std::string label =
          orderingName + " " + backend + " " + std::to_string(threads) + " thread(s)";
        vtkNew<vtkHighOrderVolumeMapper> mapper;
        mapper->SetInputData(grid);
        mapper->SetCellOrdering(ordering);
        renders.push_back(render(mapper, backend, threads, label));
        const Render& r = renders.back();
        std::cout << label << ": backend " << r.Backend << ", " << r.Threads
                  << " threads estimated, " << r.ActualThreads << " seen, " << r.Seconds << " s, "
                  << VisiblePixels(r.Pixels) << " pixels with alpha > 0.05, witness " << r.Witness
                  << "\n";
        // The machine may have fewer cores than requested: ask for at least 2
        // threads really running whenever 2 or more were requested.
        if (r.Backend != backend || (threads == 1 && r.ActualThreads != 1) ||
          (threads > 1 && hardwareThreads > 1 && r.ActualThreads < 2))
        {
          fail(label + ": LocalScope gave backend " + r.Backend + " running " +
            std::to_string(r.ActualThreads) + " threads");
        }
        if (renders.size() > 1 &&
          std::memcmp(r.Pixels.data(), renders[0].Pixels.data(), r.Pixels.size() * sizeof(float)) != 0)
        {
          fail(label + ": image differs from " + orderingName + " " + backends[0] +
            " 1 thread: " + Difference(renders[0].Pixels, r.Pixels));
        }
        if (r.Witness != renders[0].Witness)
        {
          fail(label + ": witness " + std::to_string(r.Witness) + " differs from " +
            std::to_string(renders[0].Witness));
        }
      }
    }
    orderingImages[ordering] = renders[0].Pixels;
    const int visible = VisiblePixels(renders[0].Pixels);
    if (visible < Width * Height / 10)
    {
      fail(orderingName + ": trivial image, only " + std::to_string(visible) +
        " pixels with alpha > 0.05");
    }
    if (ordering == 1 && renders[0].Witness != 0)
    {
      fail("PER_PIXEL_SORT: witness " + std::to_string(renders[0].Witness) +
        " (overlapping cells in a conforming mesh?)");
    }

    // One mapper: twice in a row, then under 4 STDThread threads, then after
    // the camera moved away and back (the order is recomputed).
    vtkNew<vtkHighOrderVolumeMapper> mapper;
    mapper->SetInputData(grid);
    mapper->SetCellOrdering(ordering);
    const Render first = render(mapper, "TBB", 2, orderingName + " repeat #1");
    const Render second = render(mapper, "TBB", 2, orderingName + " repeat #2");
    const Render third = render(mapper, "STDThread", 4, orderingName + " repeat #3 (4 threads)");
    double position[3];
    camera->GetPosition(position);
    camera->SetPosition(position[0] + 40.0, position[1] - 25.0, position[2] + 30.0);
    render(mapper, "TBB", 2, orderingName + " other view");
    camera->SetPosition(position);
    const Render fourth = render(mapper, "TBB", 2, orderingName + " repeat #4 (view restored)");
    const Render* again[] = { &second, &third, &fourth };
    const char* againNames[] = { "second render in a row", "re-render under 4 threads",
      "render after the camera moved away and back" };
    for (int k = 0; k < 3; ++k)
    {
      if (std::memcmp(first.Pixels.data(), again[k]->Pixels.data(),
            first.Pixels.size() * sizeof(float)) != 0)
      {
        fail(orderingName + ": " + againNames[k] + " differs from the first: " +
          Difference(first.Pixels, again[k]->Pixels));
      }
    }
    if (std::memcmp(first.Pixels.data(), renders[0].Pixels.data(),
          first.Pixels.size() * sizeof(float)) != 0)
    {
      fail(orderingName + ": the reused mapper's image differs from a fresh mapper's: " +
        Difference(renders[0].Pixels, first.Pixels));
    }
  }
  // For information: how far the default visibility order is from the exact per-pixel order.
  double largest = 0.0;
  int differing = 0;
  for (size_t p = 0; p + 3 < orderingImages[0].size(); p += 4)
  {
    double d = 0.0;
    for (int c = 0; c < 4; ++c)
    {
      d = std::max(d, std::fabs(static_cast<double>(orderingImages[0][p + c]) - orderingImages[1][p + c]));
    }
    largest = std::max(largest, d);
    differing += d > 1e-6;
  }
  std::cout << "VISIBILITY_SORT vs PER_PIXEL_SORT: " << differing
            << " pixels differ by more than 1e-6, largest difference " << largest << "\n";
  std::cout << failures << " failures\n";
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
