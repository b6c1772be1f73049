/**
 * @class   vtkDeepGIEXRWriter
 * @brief   writes the point arrays of a 2D vtkImageData as one multi-channel
 *          OpenEXR file
 *
 * Saves HDR results and G-buffer captures (vtkDeepGBufferPass::CaptureLayers)
 * with the OpenEXR 3 library (Debian libopenexr-dev): one scanline file,
 * ZIP compression (lossless), channels of PixelType HALF or FLOAT (default).
 *
 * Channel names: an array "Name" with 1 component becomes the channel
 * "Name.Y"; with 2 to 4 components "Name.R", "Name.G", "Name.B", "Name.A"
 * (as many as it has); with more than 4 "Name.0", "Name.1", ... Arrays named
 * exactly "RGB" or "RGBA" (3 or 4 components) are written as the file's
 * default layer R, G, B(, A), which image viewers show. vtkDeepGIEXRReader
 * reads all of them back under the same names.
 *
 * Values: float arrays are written exactly with FLOAT; double arrays are
 * rounded to float; other numeric arrays (e.g. the captures' unsigned char
 * "Valid_j") are converted to float values (exact for integers up to 2^24).
 * With HALF every value is rounded to half precision (11 significant bits,
 * relative error <= 2^-11; magnitudes above 65504 become infinity).
 * Non-numeric point arrays are skipped with a warning.
 *
 * Rows are flipped from VTK's bottom-up order to OpenEXR's top-down order.
 * The data and display windows are [x0, x0 + w - 1] x [y0, y0 + h - 1] with
 * (x0, y0) the image's first point in index space (origin / spacing, rounded,
 * plus the extent's start), so that vtkDeepGIEXRReader restores the origin;
 * the spacing itself is not stored.
 *
 * Field data: arrays with one tuple become header attributes named
 * "vtkFieldData.<name>": one float/double component as a double attribute,
 * one integer component as an int attribute, 16 numeric components as a 4x4
 * double matrix (row-major: how the captures store ViewMatrix and
 * ProjectionMatrix), one string as a string attribute. Others are skipped with
 * a warning.
 *
 * The file is encoded in memory and written under a temporary name in the
 * same directory ("FileName.partial-XXXXXX", every write checked), then
 * renamed onto FileName: a failed write (a full disk, a read-only
 * directory) removes the temporary file and leaves no partial file (an
 * older file of that name stays as it was), and a symbolic link at
 * FileName is replaced by the new file, its target never written.
 *
 * Errors (no input, not 2D, no points, no numeric point array, no file name,
 * a path that cannot be written, a full disk: OutOfDiskSpaceError) are
 * reported with vtkErrorMacro and an error code (vtkErrorCode); Write()
 * then returns 0 and never throws.
 *
 * @sa vtkDeepGIEXRReader
 */

#ifndef vtkDeepGIEXRWriter_h
#define vtkDeepGIEXRWriter_h

#include "vtkDeepGIIOOpenEXRModule.h" // for export macro
#include "vtkWriter.h"

#include <string> // for std::string

class vtkImageData;

class VTKDEEPGIIOOPENEXR_EXPORT vtkDeepGIEXRWriter : public vtkWriter
{
public:
  static vtkDeepGIEXRWriter* New();
  vtkTypeMacro(vtkDeepGIEXRWriter, vtkWriter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Channel pixel types (the values of OpenEXR's HALF and FLOAT).
  enum PixelTypes
  {
    HALF = 1,
    FLOAT = 2
  };

  ///@{
  /**
   * The file to write. Default empty (Write() then fails with an error).
   * The file is a ZIP-compressed scanline OpenEXR.
   *
   * @default empty
   */
  vtkSetStdStringFromCharMacro(FileName);
  vtkGetCharFromStdStringMacro(FileName);
  ///@}

  ///@{
  /**
   * Pixel type of every channel: HALF (2 bytes, about 3 significant decimal
   * digits) or FLOAT (4 bytes, exact for float arrays). Default FLOAT.
   * FLOAT writes float arrays exactly; HALF rounds to 11 significant bits.
   *
   * @range HALF 1, FLOAT 2; clamped
   * @default FLOAT
   */
  vtkSetClampMacro(PixelType, int, HALF, FLOAT);
  vtkGetMacro(PixelType, int);
  void SetPixelTypeToHalf() { this->SetPixelType(HALF); }
  void SetPixelTypeToFloat() { this->SetPixelType(FLOAT); }
  ///@}

  /// The input image.
  vtkImageData* GetInput();

protected:
  vtkDeepGIEXRWriter();
  ~vtkDeepGIEXRWriter() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  void WriteData() override;

  std::string FileName;
  int PixelType = FLOAT;

private:
  vtkDeepGIEXRWriter(const vtkDeepGIEXRWriter&) = delete;
  void operator=(const vtkDeepGIEXRWriter&) = delete;
};

#endif
