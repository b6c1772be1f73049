#include "vtkDeepGICameraText.h"

#include "vtkCamera.h"
#include "vtkMath.h"
#include "vtkObjectFactory.h"

#include <algorithm>
#include <cmath>
#include <locale>
#include <sstream>
#include <vector>

vtkStandardNewMacro(vtkDeepGICameraText);

namespace
{
// vtkCamera::SetViewAngle clamps to this.
constexpr double MaximumViewAngle = 179.0;

// The numbers of `text`, or false with the reason in `error`.
bool ReadNumbers(const std::string& text, std::vector<double>& numbers, std::string& error)
{
  std::istringstream fields(text + ",");
  std::string field;
  while (std::getline(fields, field, ','))
  {
    const std::string position = "value " + std::to_string(numbers.size() + 1);
    std::istringstream number(field);
    number.imbue(std::locale::classic());
    double value = 0.0;
    if (!(number >> std::ws).good())
    {
      error = position + " is missing";
      return false;
    }
    number >> value;
    if (number.fail() || !(number >> std::ws).eof() || !std::isfinite(value))
    {
      error = position + " ('" + field + "') is not a finite number";
      return false;
    }
    numbers.push_back(value);
  }
  if (numbers.size() != 9 && numbers.size() != 10)
  {
    error = "it needs 9 or 10 numbers (position, focal point, view-up, optional view angle), got " +
      std::to_string(numbers.size());
    return false;
  }
  return true;
}

// Why the position, focal point, view-up and angle make no camera, or "".
std::string CheckGeometry(const std::vector<double>& v)
{
  const double direction[3] = { v[3] - v[0], v[4] - v[1], v[5] - v[2] };
  const double up[3] = { v[6], v[7], v[8] };
  const double scale = std::max({ 1e-300, std::abs(v[0]), std::abs(v[1]), std::abs(v[2]),
    std::abs(v[3]), std::abs(v[4]), std::abs(v[5]) });
  if (!(vtkMath::Norm(direction) > 1e-12 * scale))
  {
    return "the position is at the focal point";
  }
  if (!(vtkMath::Norm(up) > 0.0))
  {
    return "the view-up has length 0";
  }
  double across[3];
  vtkMath::Cross(direction, up, across);
  if (!(vtkMath::Norm(across) > 1e-6 * vtkMath::Norm(direction) * vtkMath::Norm(up)))
  {
    return "the view-up is parallel to the direction of view";
  }
  if (v.size() == 10 && !(v[9] > 0.0 && v[9] <= MaximumViewAngle))
  {
    return "the view angle must be in (0, 179] degrees";
  }
  return std::string();
}

// `value` with as few significant digits as read back the same double.
std::string Shortest(double value)
{
  std::string text;
  for (int digits = 6; digits <= 17; ++digits)
  {
    std::ostringstream out;
    out.imbue(std::locale::classic());
    out.precision(digits);
    out << value;
    text = out.str();
    std::istringstream in(text);
    in.imbue(std::locale::classic());
    double back = 0.0;
    in >> back;
    if (back == value)
    {
      break;
    }
  }
  return text;
}
}

//------------------------------------------------------------------------------
std::string vtkDeepGICameraText::Apply(const char* text, vtkCamera* camera)
{
  if (!camera)
  {
    return "no camera";
  }
  if (!text || !*text)
  {
    return "the camera text is empty";
  }
  std::vector<double> v;
  std::string error;
  if (!ReadNumbers(text, v, error))
  {
    return error;
  }
  error = CheckGeometry(v);
  if (!error.empty())
  {
    return error;
  }
  camera->SetPosition(v[0], v[1], v[2]);
  camera->SetFocalPoint(v[3], v[4], v[5]);
  camera->SetViewUp(v[6], v[7], v[8]);
  // A perpendicular view-up is kept as given, so that a written camera
  // reads back to the same doubles.
  const double direction[3] = { v[3] - v[0], v[4] - v[1], v[5] - v[2] };
  if (std::abs(vtkMath::Dot(direction, v.data() + 6)) >
    1e-12 * vtkMath::Norm(direction) * vtkMath::Norm(v.data() + 6))
  {
    camera->OrthogonalizeViewUp();
  }
  if (v.size() == 10)
  {
    camera->SetViewAngle(v[9]);
  }
  return std::string();
}

//------------------------------------------------------------------------------
std::string vtkDeepGICameraText::Write(vtkCamera* camera)
{
  if (!camera)
  {
    return std::string();
  }
  double values[10];
  camera->GetPosition(values);
  camera->GetFocalPoint(values + 3);
  camera->GetViewUp(values + 6);
  values[9] = camera->GetViewAngle();
  std::string text;
  for (int i = 0; i < 10; ++i)
  {
    text += (i ? "," : "") + Shortest(values[i]);
  }
  return text;
}

//------------------------------------------------------------------------------
void vtkDeepGICameraText::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
