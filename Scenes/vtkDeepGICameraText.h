/**
 * @class   vtkDeepGICameraText
 * @brief   A camera as one line of text, for command lines: read and written.
 *
 * The text is ten comma-separated numbers, PX,PY,PZ,FX,FY,FZ,UX,UY,UZ,A:
 * the position, the focal point, the view-up and the vertical view angle in
 * degrees. The angle may be left out; the camera keeps its own then (VTK's
 * default is 30). These are the values of ParaView's Adjust Camera dialog
 * and of pvpython's CameraPosition, CameraFocalPoint, CameraViewUp and
 * CameraViewAngle, so a view found interactively can be given to the
 * benchmarks and to deepgi-render (their --camera option), and the
 * benchmarks print each scene's camera in this form.
 *
 * Apply() rejects, with the reason and without changing the camera: a count
 * other than 9 or 10, a value that is not a finite number, a position at the
 * focal point, a view-up of length 0 or parallel to the direction of view,
 * and an angle outside (0, 179] degrees (179 is vtkCamera's own limit). A
 * view-up that is not perpendicular to the direction of view is made so
 * (vtkCamera::OrthogonalizeViewUp, as VTK's interaction does); a
 * perpendicular one is kept as given, so a written camera reads back to
 * the same doubles. Numbers are
 * read and written in the classic locale, whatever the user's.
 */

#ifndef vtkDeepGICameraText_h
#define vtkDeepGICameraText_h

#include "vtkDeepGIScenesModule.h" // for export macro
#include "vtkObject.h"

#include <string> // for std::string

class vtkCamera;

class VTKDEEPGISCENES_EXPORT vtkDeepGICameraText : public vtkObject
{
public:
  static vtkDeepGICameraText* New();
  vtkTypeMacro(vtkDeepGICameraText, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Sets `camera` from `text`. Returns an empty string when it did,
   * otherwise why not (then the camera is unchanged).
   */
  static std::string Apply(const char* text, vtkCamera* camera);

  /**
   * The text of `camera`, all ten numbers, each with as few digits as read
   * back the same double. Empty without a camera.
   */
  static std::string Write(vtkCamera* camera);

protected:
  vtkDeepGICameraText() = default;
  ~vtkDeepGICameraText() override = default;

private:
  vtkDeepGICameraText(const vtkDeepGICameraText&) = delete;
  void operator=(const vtkDeepGICameraText&) = delete;
};

#endif
