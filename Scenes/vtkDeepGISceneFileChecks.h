/**
 * @file   vtkDeepGISceneFileChecks.h
 * @brief  Checks vtkDeepGISceneLoader runs on a file before a reader of
 *         VTK 9.1 sees it (private to DeepGI::Scenes).
 *
 * VTK 9.1's vtkPLYReader and vtkSTLReader trust the counts a file
 * declares: a truncated PLY frees invalid pointers or reads through NULL, a
 * truncated binary STL loads "successfully" with the missing triangles
 * silently lost. The functions here
 * validate what those readers would read and return an empty string when the
 * file is sound, else one sentence saying what is wrong.
 */

#ifndef vtkDeepGISceneFileChecks_h
#define vtkDeepGISceneFileChecks_h

#include "vtkSmartPointer.h"

#include <cstdint>
#include <istream>
#include <string>

class vtkAlgorithm;

namespace vtkDeepGISceneFileChecks
{
/// The longest text line the loader's own parsers accept (bytes).
constexpr std::size_t MaximumLineBytes = 1 << 20;

/// The largest MTL file or NRRD header the loader reads (bytes).
constexpr std::uint64_t MaximumTextFileBytes = std::uint64_t(64) << 20;

/// True for an existing regular file (not a directory, device, FIFO or socket).
bool IsRegularFile(const std::string& path);

/// Size of a regular file in bytes; false if it is none.
bool RegularFileSize(const std::string& path, std::uint64_t& bytes);

/**
 * std::getline with a bound: reads up to the next '\n' (dropped) into
 * `line`. Returns false at the end of the stream with nothing read, and when
 * the line is longer than `maxBytes` (then `tooLong` is set).
 */
bool ReadLine(std::istream& in, std::string& line, std::size_t maxBytes, bool& tooLong);

/**
 * A PLY file as VTK 9.1's vtkPLYReader reads it: header syntax (no control
 * characters), the properties it reads (vertex x, y, z; a face
 * vertex_indices list; its optional ones as the lists or scalars it takes
 * them for), vertices before faces, and a walk over every element (list
 * counts included) that proves the data is there and that every face index
 * names a vertex. ASCII: one line per element with at least the values its
 * properties need; binary: enough bytes.
 */
std::string CheckPLY(const std::string& path);

/**
 * An STL file as vtkSTLReader reads it: a binary one (vtksys'
 * DetectFileType, as VTK decides) must hold the 84-byte header and the
 * 50 bytes of each triangle its header declares.
 */
std::string CheckSTL(const std::string& path);

/**
 * VTK's reader of the mesh file `path` by its `extension` (".ply",
 * ".stl", ".vtp"; nullptr for others), and in `invalid` why the file is
 * refused before the reader sees it (CheckPLY, CheckSTL; "" when sound).
 */
vtkSmartPointer<vtkAlgorithm> MakeMeshReader(
  const std::string& path, const std::string& extension, std::string& invalid);
}

#endif
// VTK-HeaderTest-Exclude: vtkDeepGISceneFileChecks.h
