/**
 * @class   vtkDeepGINrrdReader
 * @brief   Reads 3D NRRD volumes with raw encoding: attached, detached, slice series.
 *
 * Reads 3D NRRD volumes with raw encoding (http://teem.sourceforge.net/nrrd/format.html):
 * attached (.nrrd) or detached (.nhdr) headers naming one data file, a
 * `data file: PATTERN MIN MAX STEP` slice series or a LIST. This parser
 * stands in for VTK 9.1's vtkNrrdReader, which overflows the heap, writes
 * through NULL or loops forever on headers this parser refuses (and which
 * Debian's Python build overrides with an MPI reader that fails anyway).
 *
 * RequestInformation reads the header: the whole extent (0 to size - 1 on
 * each axis), the spacing (`spacings`, else the lengths of the `space
 * directions`, else 1) and the origin (`space origin`, else 0), and the
 * scalar type. RequestData reads the voxels (always the whole extent) into
 * one-component point scalars; a left-handed space is made right-handed by
 * flipping the rows, as vtkNrrdReader does.
 *
 * Refused with one vtkErrorMacro (ErrorCode set, an empty output): other
 * encodings (gzip, bzip2, ascii, hex), other dimensions, unknown scalar
 * types, malformed header lines, lines longer than 1 MiB, headers longer
 * than 64 MiB, data files that are not regular files or are shorter than
 * the sizes need, and volumes whose voxels need more than 4 GiB.
 */

#ifndef vtkDeepGINrrdReader_h
#define vtkDeepGINrrdReader_h

#include "vtkDeepGIScenesModule.h" // for export macro
#include "vtkImageAlgorithm.h"

#include <memory> // for std::unique_ptr

class VTKDEEPGISCENES_EXPORT vtkDeepGINrrdReader : public vtkImageAlgorithm
{
public:
  static vtkDeepGINrrdReader* New();
  vtkTypeMacro(vtkDeepGINrrdReader, vtkImageAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The .nhdr or .nrrd file to read.
   *
   * @default null
   */
  vtkSetStringMacro(FileName);
  vtkGetStringMacro(FileName);
  ///@}

protected:
  vtkDeepGINrrdReader();
  ~vtkDeepGINrrdReader() override;

  int RequestInformation(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;
  int RequestData(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

  char* FileName = nullptr;

private:
  vtkDeepGINrrdReader(const vtkDeepGINrrdReader&) = delete;
  void operator=(const vtkDeepGINrrdReader&) = delete;

  class vtkInternals;
  std::unique_ptr<vtkInternals> Internals;
};

#endif
