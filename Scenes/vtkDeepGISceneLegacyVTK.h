/**
 * @file   vtkDeepGISceneLegacyVTK.h
 * @brief  The legacy .vtk polydata reader of vtkDeepGISceneLoader
 *         (private to DeepGI::Scenes).
 *
 * VTK 9.1's vtkPolyDataReader trusts every count a file declares: a cell
 * list whose point counts run past its size makes
 * vtkCellArray::AppendLegacyFormat read and write out of bounds, truncated
 * binary data loads "successfully". Fuzzing found these within seconds, so
 * the loader reads legacy files with this parser of its own instead, which
 * checks every count against the bytes left before allocating.
 *
 * Read: the header (versions up to 5.1, ASCII or BINARY), DATASET
 * POLYDATA, POINTS, POLYGONS and TRIANGLE_STRIPS (legacy cell lists and
 * the OFFSETS / CONNECTIVITY of version 5), and the point NORMALS.
 * Checked and skipped: VERTICES, LINES, METADATA, and the point and cell
 * attributes (SCALARS with their LOOKUP_TABLE, COLOR_SCALARS, LOOKUP_TABLE,
 * VECTORS, TEXTURE_COORDINATES, TENSORS, TENSORS6, GLOBAL_IDS,
 * PEDIGREE_IDS, FIELD). Reading stops, keeping what was read, at what it
 * cannot skip after the geometry (string or bit arrays, unknown keywords).
 */

#ifndef vtkDeepGISceneLegacyVTK_h
#define vtkDeepGISceneLegacyVTK_h

#include <string>

class vtkPolyData;

namespace vtkDeepGISceneLegacyVTK
{
/**
 * Reads the legacy VTK polydata file `path` into `output`. Returns an empty
 * string on success, else one sentence saying why it cannot be read.
 */
std::string Read(const std::string& path, vtkPolyData* output);
}

#endif
// VTK-HeaderTest-Exclude: vtkDeepGISceneLegacyVTK.h
