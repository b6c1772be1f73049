/**
 * @class   vtkDeepGIEXRReader
 * @brief   reads an OpenEXR image (scanline or tiled; half, float or uint
 *          channels) into a vtkImageData of float point arrays
 *
 * Reads the first part of an OpenEXR file with the OpenEXR 3 library
 * (Debian libopenexr-dev): environment maps (lat-long radiance), G-buffer
 * layers and results saved by vtkDeepGIEXRWriter.
 *
 * Channels become vtkFloatArray point arrays, grouped by layer: the layer
 * of "Radiance_0.R" is "Radiance_0" (everything before the last dot), so
 * Radiance_0.R/G/B/A become the 4-component array "Radiance_0" and Depth_0.Y
 * the 1-component array "Depth_0". Components are ordered R, G, B, A first,
 * then the other channels of the layer in the file's (alphabetical) order,
 * names made only of digits numerically. Channels without a layer: those
 * among R, G, B, A form one array named by the letters present, in that
 * order ("RGBA", "RGB", ...); every other one is a 1-component array of its
 * own name. Half and float values are converted exactly; uint values are
 * rounded to float (exact up to 2^24). Subsampled channels (x or y sampling
 * other than 1) are skipped with a warning. The first array ("RGBA"/"RGB" if
 * present) is the active scalars.
 *
 * Geometry: rows are flipped into VTK's bottom-up order. The data window is
 * honoured: with display window [dx0, dx1] x [dy0, dy1] the file's pixel
 * (x, y) becomes the VTK point (x, dy0 + dy1 - y), so an image whose data
 * window equals its display window starts at the origin (0, 0, 0) and a
 * smaller data window keeps its place; spacing is 1.
 *
 * Header attributes written by vtkDeepGIEXRWriter for field data (names
 * starting with "vtkFieldData.") come back as field-data arrays: double
 * (vtkDoubleArray), int (vtkIntArray), string (vtkStringArray), 4x4 double
 * matrix (16-component vtkDoubleArray, row-major).
 *
 * Errors (missing file, not an OpenEXR file, deep data, a file the library
 * cannot decode) are reported with vtkErrorMacro and an empty output; the
 * reader never throws.
 *
 * @sa vtkDeepGIEXRWriter
 */

#ifndef vtkDeepGIEXRReader_h
#define vtkDeepGIEXRReader_h

#include "vtkDeepGIIOOpenEXRModule.h" // for export macro
#include "vtkImageAlgorithm.h"

#include <string> // for std::string

class VTKDEEPGIIOOPENEXR_EXPORT vtkDeepGIEXRReader : public vtkImageAlgorithm
{
public:
  static vtkDeepGIEXRReader* New();
  vtkTypeMacro(vtkDeepGIEXRReader, vtkImageAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The file to read. Default empty (Update() then fails with an error).
   * An OpenEXR file: scanline or tiled, half/float/uint channels; of a multi-part file the first
   * part is read. A missing, non-EXR, deep or undecodable file gives an error and an empty output.
   *
   * @default empty
   */
  vtkSetStdStringFromCharMacro(FileName);
  vtkGetCharFromStdStringMacro(FileName);
  ///@}

  /**
   * Whether `fileName` exists and starts with the OpenEXR magic number.
   */
  static bool CanReadFile(const char* fileName);

protected:
  vtkDeepGIEXRReader();
  ~vtkDeepGIEXRReader() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestInformation(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;
  int RequestData(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

  std::string FileName;

private:
  vtkDeepGIEXRReader(const vtkDeepGIEXRReader&) = delete;
  void operator=(const vtkDeepGIEXRReader&) = delete;
};

#endif
