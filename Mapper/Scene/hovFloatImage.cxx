#include "hovFloatImage.h"

#include "vtkFloatArray.h" // the pixels
#include "vtkImageData.h"  // the image
#include "vtkNew.h"        // a new array
#include "vtkPointData.h"  // its scalars

#include <algorithm> // std::max

float* hov::FloatImagePixels(
  vtkImageData* image, const char* name, int components, int width, int height, bool reuse)
{
  width = std::max(width, 0);
  height = std::max(height, 0);
  const vtkIdType n = static_cast<vtkIdType>(width) * height;
  image->SetDimensions(width, height, 1);
  auto* array = vtkFloatArray::SafeDownCast(image->GetPointData()->GetScalars());
  if (reuse && array && array->GetReferenceCount() <= 1 &&
    array->GetNumberOfComponents() == components && array->GetNumberOfTuples() == n)
  {
    array->Modified();
    image->Modified();
    return array->GetPointer(0);
  }
  vtkNew<vtkFloatArray> fresh;
  fresh->SetName(name);
  fresh->SetNumberOfComponents(components);
  fresh->SetNumberOfTuples(n);
  image->GetPointData()->SetScalars(fresh);
  if (reuse)
  {
    fresh->Modified();
    image->Modified();
  }
  return fresh->GetPointer(0);
}
