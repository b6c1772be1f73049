/**
 * @class   vtkDeepGIOBJReader
 * @brief   Reads a Wavefront OBJ file and the Kd and Ke of its MTL materials.
 *
 * OBJ files are read by this parser rather than by vtkOBJImporter, whose
 * VTK 9.1 parser resolves relative (negative) vertex indices against a
 * function-static vertex count that is never reset: from the second OBJ
 * file a process imports on, "f -4 -3 -2 -1" points past the vertices
 * (out-of-bounds reads, garbage or empty parts). Neither the importer nor
 * vtkOBJReader checks indices against the vertex count at all.
 *
 * Read: `v`, `vn`, `f` (corners v, v/t, v/t/n or v//n), `usemtl` and
 * `mtllib`; the materials' Kd and Ke from the MTL file (the OBJ's `mtllib`,
 * else NAME.obj.mtl or NAME.mtl next to it). Backslash continuations are
 * joined (a lone `\` joins nothing). Faces indexing vertices the file does
 * not define are skipped with a warning (an error if none is left). Lines
 * longer than 1 MiB are refused; an MTL file is read only if it is a
 * regular file of at most 64 MiB (else a warning, and no materials).
 *
 * The output holds the polygons as the file gives them, material after
 * material in the order of first `usemtl` (the faces before any `usemtl`,
 * or all faces when there is no MTL file, form the material ""), each
 * material with its own points (one per vertex and normal pair, never
 * merged: coincident vertices and faces stay as they are in the file):
 * - point data "Normals" (normalized) when every corner of every face has
 *   a finite, non-zero normal;
 * - cell data "MaterialId" (int): the index of the face's material in the
 *   field data below;
 * - field data, one tuple per material: "MaterialName" (string),
 *   "MaterialKd" (double RGB, 0 where "MaterialHasKd" is 0), "MaterialHasKd"
 *   (unsigned char, 1 when the MTL file gives the material a Kd),
 *   "MaterialKe" (double RGB, the emitted radiance, negative components
 *   clamped to 0), "MaterialDefined" (unsigned char, 0 for a material the
 *   MTL file does not define), and "MaterialFile" (one string, the MTL file
 *   read; empty when there is none).
 *
 * A file that cannot be read (missing, malformed, no faces) gives one
 * vtkErrorMacro, ErrorCode set and an empty output.
 */

#ifndef vtkDeepGIOBJReader_h
#define vtkDeepGIOBJReader_h

#include "vtkDeepGIScenesModule.h" // for export macro
#include "vtkPolyDataAlgorithm.h"

class VTKDEEPGISCENES_EXPORT vtkDeepGIOBJReader : public vtkPolyDataAlgorithm
{
public:
  static vtkDeepGIOBJReader* New();
  vtkTypeMacro(vtkDeepGIOBJReader, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The OBJ file to read.
   *
   * @default null
   */
  vtkSetStringMacro(FileName);
  vtkGetStringMacro(FileName);
  ///@}

protected:
  vtkDeepGIOBJReader();
  ~vtkDeepGIOBJReader() override;

  int RequestData(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

  char* FileName = nullptr;

private:
  vtkDeepGIOBJReader(const vtkDeepGIOBJReader&) = delete;
  void operator=(const vtkDeepGIOBJReader&) = delete;
};

#endif
