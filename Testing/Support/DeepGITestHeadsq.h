// The headsq volume of the project's test data (Testing/Data/volumes/headsq,
// see its MANIFEST.md): 93 slices of 64 x 64 16-bit little-endian samples,
// spacing 3.2 / 3.2 / 1.5, read the way VTK's own examples read it.
#ifndef DeepGITestHeadsq_h
#define DeepGITestHeadsq_h

#include "vtkImageData.h"
#include "vtkSmartPointer.h"
#include "vtkVolume16Reader.h"

#include <cstdio>
#include <string>

namespace DeepGITestData
{
/**
 * A vtkVolume16Reader set up for headsq under `folder` (Testing/Data), not
 * yet updated.
 */
inline vtkSmartPointer<vtkVolume16Reader> HeadsqReader(const std::string& folder)
{
  auto reader = vtkSmartPointer<vtkVolume16Reader>::New();
  reader->SetFilePrefix((folder + "/volumes/headsq/quarter").c_str());
  reader->SetDataDimensions(64, 64);
  reader->SetImageRange(1, 93);
  reader->SetDataByteOrderToLittleEndian();
  reader->SetDataSpacing(3.2, 3.2, 1.5);
  return reader;
}

/**
 * HeadsqReader, updated; nullptr (with one line naming the files) when it
 * read nothing.
 */
inline vtkSmartPointer<vtkVolume16Reader> ReadHeadsq(const std::string& folder)
{
  auto reader = HeadsqReader(folder);
  reader->Update();
  if (reader->GetOutput()->GetNumberOfPoints() == 0)
  {
    std::printf("could not read %s/volumes/headsq/quarter\n", folder.c_str());
    return nullptr;
  }
  return reader;
}
} // namespace DeepGITestData

#endif
