// Figures of deepgi-render: captured G-buffer and effect quantities turned
// into labelled 8-bit RGB panels, panels tiled into one image, and PNG files
// written so that a failed write never leaves a partial file.
#ifndef DeepGIRenderFigures_h
#define DeepGIRenderFigures_h

#include "vtkSmartPointer.h"

#include <string>
#include <vector>

class vtkImageData;
class vtkRenderWindow;

namespace DeepGIRenderFigures
{
/// The window's image as last rendered (RGB, 8 bits), read from the back
/// buffer without rendering again.
vtkSmartPointer<vtkImageData> GrabWindow(vtkRenderWindow* window);

/// How a float array of a capture becomes a panel.
enum class Mapping
{
  Colour,  ///< RGB(A) clamped to [0, 1]
  Grey,    ///< one component in [0, 1]
  Depth,   ///< near light, far dark, normalised over the valid pixels
  Normal,  ///< n * 0.5 + 0.5
  Exposure ///< RGB scaled so that the 99th percentile of the valid pixels is 1
};

/**
 * A panel (RGB, 8 bits) of `capture`'s point-data array `arrayName`, mapped
 * as `mapping`; pixels where the unsigned char array `validName` is 0 are
 * black. Null when the array is missing. With Mapping::Exposure, `scale`
 * receives the factor applied.
 */
vtkSmartPointer<vtkImageData> Panel(vtkImageData* capture, const char* arrayName,
  const char* validName, Mapping mapping, double* scale = nullptr);

/// A grey panel of the given size (for an effect that did not run).
vtkSmartPointer<vtkImageData> BlankPanel(int width, int height);

/// Writes `text` in white on a dark box at the top-left corner of `panel`.
void Label(vtkImageData* panel, const std::string& text);

/// Halves a panel's resolution (2 x 2 box average), for contact sheets.
vtkSmartPointer<vtkImageData> Half(vtkImageData* panel);

/// Tiles equally sized panels row by row, `columns` per row, first row on top.
vtkSmartPointer<vtkImageData> Tile(
  const std::vector<vtkSmartPointer<vtkImageData>>& panels, int columns);

/**
 * Writes `image` as a PNG file through DeepGIOutput::WritePNG (a temporary
 * file renamed onto `fileName` once complete; a symbolic link there is
 * replaced, not followed). Returns false with a message on stderr.
 */
bool WritePNG(vtkImageData* image, const std::string& fileName);
} // namespace DeepGIRenderFigures

#endif
