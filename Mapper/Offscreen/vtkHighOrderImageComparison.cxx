#include "vtkHighOrderImageComparison.h"

#include "vtkImageData.h" // the images compared and the difference image
#include "vtkNew.h"           // the difference array
#include "vtkObjectFactory.h" // vtkStandardNewMacro
#include "vtkPointData.h"         // the images' scalars
#include "vtkUnsignedCharArray.h" // 8-bit pixels

#include <algorithm> // std::max, std::min
#include <cstdlib>   // std::abs
#include <sstream>   // the message

vtkStandardNewMacro(vtkHighOrderImageComparison);

namespace
{
/// The 8-bit scalars of @p image with 3 or 4 components, or null and @p why.
vtkUnsignedCharArray* Pixels(vtkImageData* image, const char* which, std::string& why)
{
  if (!image)
  {
    why = std::string("no ") + which + " image";
    return nullptr;
  }
  vtkUnsignedCharArray* pixels =
    vtkUnsignedCharArray::SafeDownCast(image->GetPointData()->GetScalars());
  if (!pixels)
  {
    why = std::string("the ") + which + " image has no 8-bit scalars";
    return nullptr;
  }
  const int nc = pixels->GetNumberOfComponents();
  if (nc != 3 && nc != 4)
  {
    std::ostringstream s;
    s << "the " << which << " image has " << nc << " components (3 or 4 expected)";
    why = s.str();
    return nullptr;
  }
  return pixels;
}
}

vtkHighOrderImageComparison::vtkHighOrderImageComparison() = default;
vtkHighOrderImageComparison::~vtkHighOrderImageComparison() = default;

bool vtkHighOrderImageComparison::Refuse(const std::string& why)
{
  this->Message = "images not compared: " + why;
  this->MaximumDifference = -1;
  this->Difference = nullptr;
  return false;
}

bool vtkHighOrderImageComparison::Compare(vtkImageData* baseline, vtkImageData* candidate)
{
  this->PixelsAboveTolerance = 0;
  this->PixelsDifferent = 0;
  this->WorstI = this->WorstJ = -1;
  std::string why;
  vtkUnsignedCharArray* b = Pixels(baseline, "baseline", why);
  vtkUnsignedCharArray* c = b ? Pixels(candidate, "candidate", why) : nullptr;
  if (!b || !c)
  {
    return this->Refuse(why);
  }
  int db[3], dc[3];
  baseline->GetDimensions(db);
  candidate->GetDimensions(dc);
  if (db[0] != dc[0] || db[1] != dc[1] || db[2] != dc[2])
  {
    std::ostringstream s;
    s << "the baseline is " << db[0] << " x " << db[1] << " pixels, the candidate " << dc[0]
      << " x " << dc[1];
    return this->Refuse(s.str());
  }
  const int nb = b->GetNumberOfComponents(), nc = c->GetNumberOfComponents();
  const vtkIdType n = static_cast<vtkIdType>(db[0]) * db[1] * db[2];
  this->Difference = vtkSmartPointer<vtkImageData>::New();
  this->Difference->SetDimensions(db);
  vtkNew<vtkUnsignedCharArray> diff;
  diff->SetName("Difference");
  diff->SetNumberOfComponents(3);
  diff->SetNumberOfTuples(n);
  this->Difference->GetPointData()->SetScalars(diff);
  const unsigned char* pb = b->GetPointer(0);
  const unsigned char* pc = c->GetPointer(0);
  unsigned char* pd = diff->GetPointer(0);
  int worst = 0;
  for (vtkIdType p = 0; p < n; ++p)
  {
    int d = 0;
    for (int k = 0; k < 3; ++k)
    {
      d = std::max(d, std::abs(int(pb[nb * p + k]) - int(pc[nc * p + k])));
    }
    const unsigned char shown =
      static_cast<unsigned char>(std::min(255, d * this->DifferenceScale));
    pd[3 * p] = shown;
    pd[3 * p + 1] = d > this->Tolerance ? 0 : shown;
    pd[3 * p + 2] = d > this->Tolerance ? 0 : shown;
    this->PixelsDifferent += d > 0 ? 1 : 0;
    this->PixelsAboveTolerance += d > this->Tolerance ? 1 : 0;
    if (d > worst)
    {
      worst = d;
      this->WorstI = static_cast<int>(p % db[0]);
      this->WorstJ = static_cast<int>((p / db[0]) % db[1]);
    }
  }
  this->MaximumDifference = worst;
  const bool passed = worst <= this->Tolerance && this->PixelsDifferent <= this->AllowedPixels;
  std::ostringstream s;
  s << (passed ? "passed" : "FAILED") << ": max difference " << worst << "/255";
  if (worst > 0)
  {
    s << " at pixel (" << this->WorstI << ", " << this->WorstJ << ")";
  }
  s << " (allowed " << this->Tolerance << "/255), " << this->PixelsDifferent << " of " << n
    << " pixels differ (allowed " << this->AllowedPixels << "), " << this->PixelsAboveTolerance
    << " by more than the tolerance";
  this->Message = s.str();
  return passed;
}

vtkImageData* vtkHighOrderImageComparison::GetDifferenceImage()
{
  return this->Difference;
}

void vtkHighOrderImageComparison::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Tolerance: " << this->Tolerance << "\n";
  os << indent << "AllowedPixels: " << this->AllowedPixels << "\n";
  os << indent << "DifferenceScale: " << this->DifferenceScale << "\n";
  os << indent << "MaximumDifference: " << this->MaximumDifference << "\n";
  os << indent << "PixelsAboveTolerance: " << this->PixelsAboveTolerance << "\n";
  os << indent << "Message: " << this->Message << "\n";
}
