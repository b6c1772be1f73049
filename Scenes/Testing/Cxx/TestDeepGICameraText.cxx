// vtkDeepGICameraText: the text of a camera sets exactly those values,
// what Write gives reads back to the same camera, the numbers do not depend
// on the user's locale, and every malformed text is rejected with its reason
// and the camera unchanged.
//   TestDeepGICameraText

#include "DeepGITestChecks.h"

#include "vtkCamera.h"
#include "vtkDeepGICameraText.h"
#include "vtkMath.h"
#include "vtkNew.h"

#include <cmath>
#include <locale>
#include <string>

namespace
{
using DeepGITest::Check;
using DeepGITest::Text;

bool Equal(const double* a, const double* b, int n, double tolerance)
{
  for (int i = 0; i < n; ++i)
  {
    if (!(std::abs(a[i] - b[i]) <= tolerance))
    {
      return false;
    }
  }
  return true;
}

// Position, focal point and angle as given; the view-up made perpendicular
// to the direction of view, in the plane of the one given.
void TestApply()
{
  vtkNew<vtkCamera> camera;
  const std::string error = vtkDeepGICameraText::Apply(" 1.5, -2 ,3e1,0,0.25,0,0,1,1,42", camera);
  Check(error.empty(), "a valid text is applied (" + error + ")");
  const double position[3] = { 1.5, -2.0, 30.0 }, focal[3] = { 0.0, 0.25, 0.0 };
  Check(Equal(camera->GetPosition(), position, 3, 0.0) &&
      Equal(camera->GetFocalPoint(), focal, 3, 0.0) && camera->GetViewAngle() == 42.0,
    "position, focal point and view angle are exactly the text's");
  double direction[3];
  vtkMath::Subtract(focal, position, direction);
  const double* up = camera->GetViewUp();
  const double given[3] = { 0.0, 1.0, 1.0 };
  double normal[3], upNormal[3];
  vtkMath::Cross(direction, given, normal);
  vtkMath::Cross(direction, up, upNormal);
  vtkMath::Normalize(normal);
  vtkMath::Normalize(upNormal);
  Check(std::abs(vtkMath::Dot(up, direction)) < 1e-12 * vtkMath::Norm(direction) &&
      std::abs(vtkMath::Norm(up) - 1.0) < 1e-12 && vtkMath::Dot(normal, upNormal) > 1.0 - 1e-12 &&
      vtkMath::Dot(up, given) > 0.0,
    "the view-up is the given one made perpendicular to the direction of view");

  vtkNew<vtkCamera> keepsAngle;
  keepsAngle->SetViewAngle(12.5);
  Check(vtkDeepGICameraText::Apply("0,0,5,0,0,0,0,1,0", keepsAngle).empty() &&
      keepsAngle->GetViewAngle() == 12.5,
    "nine numbers keep the camera's own view angle");
}

// Write gives ten numbers that Apply reads back to the same doubles.
void TestRoundTrip()
{
  vtkNew<vtkCamera> camera;
  camera->SetPosition(0.1, -1.0 / 3.0, 2.0e-7);
  camera->SetFocalPoint(1234567.891, 0.2, -0.3);
  camera->SetViewUp(0.0, 0.0, 1.0);
  camera->OrthogonalizeViewUp();
  camera->SetViewAngle(33.3);
  const std::string text = vtkDeepGICameraText::Write(camera);
  vtkNew<vtkCamera> copy;
  const std::string error = vtkDeepGICameraText::Apply(text.c_str(), copy);
  Check(error.empty() && Equal(copy->GetPosition(), camera->GetPosition(), 3, 0.0) &&
      Equal(copy->GetFocalPoint(), camera->GetFocalPoint(), 3, 0.0) &&
      Equal(copy->GetViewUp(), camera->GetViewUp(), 3, 1e-15) &&
      copy->GetViewAngle() == camera->GetViewAngle(),
    "Write reads back to the same camera (" + text + ")");
  Check(vtkDeepGICameraText::Write(copy) == text, "and writes the same text again");
  vtkNew<vtkCamera> plain;
  Check(vtkDeepGICameraText::Write(plain) == "0,0,1,0,0,0,0,1,0,30",
    "VTK's default camera is written with the fewest digits (" + vtkDeepGICameraText::Write(plain) +
      ")");
  Check(vtkDeepGICameraText::Write(nullptr).empty(), "no camera gives no text");
}

// A locale whose decimal separator is a comma (as de_DE's), built here so
// that the test needs no installed locale.
struct DecimalComma : std::numpunct<char>
{
  char do_decimal_point() const override { return ','; }
  char do_thousands_sep() const override { return '.'; }
  std::string do_grouping() const override { return "\3"; }
};

void TestLocale()
{
  const std::locale previous =
    std::locale::global(std::locale(std::locale::classic(), new DecimalComma));
  vtkNew<vtkCamera> camera;
  const std::string error = vtkDeepGICameraText::Apply("0.5,0,1234.25,0,0,0,0,1,0,30.5", camera);
  const std::string text = vtkDeepGICameraText::Write(camera);
  std::locale::global(previous);
  Check(error.empty() && camera->GetPosition()[0] == 0.5 && camera->GetPosition()[2] == 1234.25 &&
      camera->GetViewAngle() == 30.5,
    "the numbers are read in the classic locale under a decimal-comma locale (" + error + ")");
  Check(text == "0.5,0,1234.25,0,0,0,0,1,0,30.5", "and written in it (" + text + ")");
}

// Each malformed text names its fault and leaves the camera as it was.
void TestRejections()
{
  const struct
  {
    const char* Text;
    const char* Reason;
  } cases[] = {
    { "", "empty" },
    { "1,2,3", "9 or 10 numbers" },
    { "0,0,5,0,0,0,0,1,0,30,1", "9 or 10 numbers" },
    { "0,0,5,0,0,0,0,1,0,", "value 10 is missing" },
    { "0,0,5,,0,0,0,1,0", "value 4 is missing" },
    { "a,0,5,0,0,0,0,1,0", "value 1 ('a') is not a finite number" },
    { "0,0,5,0,0,0,0,1,0,30x", "value 10 ('30x') is not a finite number" },
    { "nan,0,5,0,0,0,0,1,0", "is not a finite number" },
    { "0,inf,5,0,0,0,0,1,0", "is not a finite number" },
    { "1e400,0,5,0,0,0,0,1,0", "is not a finite number" },
    { "0;0;5;0;0;0;0;1;0", "is not a finite number" },
    { "1,2,3,1,2,3,0,1,0", "the position is at the focal point" },
    { "0,0,5,0,0,0,0,0,0", "the view-up has length 0" },
    { "0,0,5,0,0,0,0,0,-2", "parallel to the direction of view" },
    { "0,0,5,0,0,0,0,1,0,0", "(0, 179]" },
    { "0,0,5,0,0,0,0,1,0,-10", "(0, 179]" },
    { "0,0,5,0,0,0,0,1,0,179.5", "(0, 179]" },
  };
  for (const auto& c : cases)
  {
    vtkNew<vtkCamera> camera;
    vtkNew<vtkCamera> untouched;
    const std::string error = vtkDeepGICameraText::Apply(c.Text, camera);
    Check(error.find(c.Reason) != std::string::npos &&
        vtkDeepGICameraText::Write(camera) == vtkDeepGICameraText::Write(untouched),
      Text("'", c.Text, "' is rejected with '", c.Reason, "', the camera unchanged (", error, ")"));
  }
  vtkNew<vtkCamera> camera;
  Check(vtkDeepGICameraText::Apply(nullptr, camera).find("empty") != std::string::npos,
    "no text is rejected");
  Check(!vtkDeepGICameraText::Apply("0,0,5,0,0,0,0,1,0", nullptr).empty(), "no camera is rejected");
}
}

int TestDeepGICameraText(int, char*[])
{
  TestApply();
  TestRoundTrip();
  TestLocale();
  TestRejections();
  return DeepGITest::ExitStatus();
}
