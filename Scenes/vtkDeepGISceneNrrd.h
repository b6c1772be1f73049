/**
 * @file   vtkDeepGISceneNrrd.h
 * @brief  The NRRD reader of vtkDeepGBufferSceneLoader (private to DeepGI::Scenes).
 *
 * Reads 3D NRRD volumes with raw encoding (http://teem.sourceforge.net/nrrd/format.html):
 * attached (.nrrd) or detached (.nhdr) headers naming one data file, a
 * `data file: PATTERN MIN MAX STEP` slice series or a LIST. Every file goes
 * through this parser and nothing else: VTK 9.1's vtkNrrdReader overflows
 * the heap, writes through NULL or loops forever on headers this parser
 * refuses, so it is never given a file (and Debian's Python build overrides
 * it with an MPI reader that fails anyway).
 *
 * Refused with a reason: other encodings (gzip, bzip2, ascii, hex), other
 * dimensions, unknown scalar types, malformed header lines, lines longer
 * than 1 MiB, headers longer than 64 MiB, data files that are not regular
 * files or are shorter than the sizes need, and volumes whose voxels need
 * more than MaximumBytes.
 */

#ifndef vtkDeepGISceneNrrd_h
#define vtkDeepGISceneNrrd_h

#include <cstdint>
#include <string>

class vtkImageData;

namespace vtkDeepGISceneNrrd
{
/// The largest volume read (bytes of voxel data): 4 GiB.
constexpr std::uint64_t MaximumBytes = std::uint64_t(4) << 30;

/**
 * Reads the NRRD file `path` into `output`. Returns an empty string on
 * success, else one sentence saying why the file cannot be read.
 */
std::string Read(const std::string& path, vtkImageData* output);
}

#endif
// VTK-HeaderTest-Exclude: vtkDeepGISceneNrrd.h
