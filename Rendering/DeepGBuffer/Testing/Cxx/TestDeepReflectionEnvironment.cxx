// Rays that leave the image take the environment. A mirror floor alone
// under a camera looking down at it: every reflection ray leaves the view.
// (1) An equirectangular float environment texture (64 x 32, texel (i, j)
// has colour ((i + 0.5) / 64, (j + 0.5) / 32, 0.25), nearest filtering):
// each pixel's reflected radiance must be the texel VTK's image-based
// lighting convention gives for the exact world mirror direction r:
// u = atan2(r.z, r.x) / (2 pi) + 0.5, v = asin(r.y) / pi + 0.5.
// (1b) The same environment at 4x (HDR texels up to 4), written to an
// OpenEXR file with vtkDeepGIEXRWriter and read back with
// vtkDeepGIEXRReader as the texture's input: the same comparison at 4x, so
// radiance above 1 survives from the file to the reflection.
// (2) A cube map with one colour per face: the face of the mirror
// direction. (3) No environment texture: the background colour. (4) A
// gradient background: mix(Background, Background2, 0.5 + 0.5 r_y), r_y
// the camera-space up component. 200 x 150 px.

#include "DeepReflectionTestUtilities.h"

#include "vtkCamera.h"
#include "vtkCommand.h"
#include "vtkDeepGICaptureNames.h"
#include "vtkDeepGIEXRReader.h"
#include "vtkDeepGIEXRWriter.h"
#include "vtkDeepReflectionPass.h"
#include "vtkFloatArray.h"
#include "vtkMath.h"
#include "vtkTexture.h"

#include <algorithm>
#include <functional>

using namespace DeepGBufferTest;
using namespace DeepReflectionTest;
using namespace DeepGITest;

namespace
{
constexpr int EnvWidth = 64;
constexpr int EnvHeight = 32;

struct Comparison
{
  long Pixels = 0;
  long Exact = 0;       // within 1e-3 on every channel
  long Near = 0;        // within `nearTolerance` on every channel
  long Environment = 0; // hit layer -1
};

// Compares every traced pixel's reflected radiance with expected(world r,
// camera r), r the mirror direction about the exact floor normal, or about
// the G-buffer's decoded (Oct16) camera-space normal when `normals` is given.
Comparison Compare(vtkImageData* reflections,
  const std::function<Vector(const Vector&, const Vector&)>& expected,
  const double nearTolerance[3], vtkDataArray* normals = nullptr)
{
  Comparison result;
  const Camera cam(reflections);
  vtkDataArray* valid = reflections->GetPointData()->GetArray(vtkDeepGICaptureNames::Valid);
  vtkDataArray* hitLayer = reflections->GetPointData()->GetArray(vtkDeepGICaptureNames::HitLayer);
  vtkDataArray* radiance =
    reflections->GetPointData()->GetArray(vtkDeepGICaptureNames::ReflectedRadiance);
  const Vector eye = cam.Eye();
  for (int j = 0; j < cam.Height; ++j)
  {
    for (int i = 0; i < cam.Width; ++i)
    {
      const vtkIdType p = j * cam.Width + i;
      if (!valid->GetTuple1(p))
      {
        continue;
      }
      ++result.Pixels;
      result.Environment += hitLayer->GetTuple1(p) == -1.0 ? 1 : 0;
      // The floor point seen through the pixel centre: the view ray meets y = 0.
      const Vector far = cam.World(i, j, 1.0);
      const Vector v = Normalized({ far[0] - eye[0], far[1] - eye[1], far[2] - eye[2] });
      Vector r = Reflect(v, { 0.0, 1.0, 0.0 });
      if (normals)
      {
        // The G-buffer's normal, camera space -> world (rotation: transpose).
        Vector n;
        for (int k = 0; k < 3; ++k)
        {
          n[k] = cam.View[k] * normals->GetComponent(p, 0) +
            cam.View[4 + k] * normals->GetComponent(p, 1) +
            cam.View[8 + k] * normals->GetComponent(p, 2);
        }
        r = Reflect(v, Normalized(n));
      }
      Vector rc;
      for (int k = 0; k < 3; ++k)
      {
        rc[k] = cam.View[4 * k] * r[0] + cam.View[4 * k + 1] * r[1] + cam.View[4 * k + 2] * r[2];
      }
      const Vector e = expected(r, rc);
      bool exact = true, near = true;
      for (int c = 0; c < 3; ++c)
      {
        const double d = std::abs(radiance->GetComponent(p, c) - e[c]);
        exact = exact && d <= 1e-3;
        near = near && d <= nearTolerance[c];
      }
      result.Exact += exact ? 1 : 0;
      result.Near += near ? 1 : 0;
    }
  }
  return result;
}

// The environment: float RGB, colour = texel centre (u, v) and 0.25.
vtkSmartPointer<vtkImageData> MakeEnvironmentImage()
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(EnvWidth, EnvHeight, 1);
  vtkNew<vtkFloatArray> texels;
  texels->SetNumberOfComponents(3);
  texels->SetNumberOfTuples(EnvWidth * EnvHeight);
  for (int j = 0; j < EnvHeight; ++j)
  {
    for (int i = 0; i < EnvWidth; ++i)
    {
      texels->SetTuple3(j * EnvWidth + i, (i + 0.5) / EnvWidth, (j + 0.5) / EnvHeight, 0.25);
    }
  }
  image->GetPointData()->SetScalars(texels);
  return image;
}

// The texel VTK's image-based lighting convention gives for the world
// direction r.
Vector Equirectangular(const Vector& r, const Vector&)
{
  const double u = std::atan2(r[2], r[0]) / (2.0 * vtkMath::Pi()) + 0.5;
  const double v = std::asin(std::min(1.0, std::max(-1.0, r[1]))) / vtkMath::Pi() + 0.5;
  const int i = std::min(EnvWidth - 1, static_cast<int>(std::floor(u * EnvWidth)));
  const int j = std::min(EnvHeight - 1, static_cast<int>(std::floor(v * EnvHeight)));
  return { (i + 0.5) / EnvWidth, (j + 0.5) / EnvHeight, 0.25 };
}

const double ExactTolerance[3] = { 1e-3, 1e-3, 1e-3 };
// One texel of slack: the shader reflects about the Oct16 normal.
const double OneTexel[3] = { 1.0 / EnvWidth + 1e-3, 1.0 / EnvHeight + 1e-3, 1e-3 };

// (1) The equirectangular environment, through the exact and the stored
// normals.
void CheckEquirectangularEnvironment(vtkRenderer* renderer, vtkDeepReflectionPass* pass)
{
  vtkNew<vtkImageData> reflections;
  pass->CaptureReflections(reflections, renderer);
  Check(AllFinite(reflections), "reflection capture is finite");
  const Comparison c = Compare(reflections, Equirectangular, OneTexel);
  std::printf("equirectangular: %ld traced pixels, %ld environment, %ld exact texel, %ld within "
              "one texel\n",
    c.Pixels, c.Environment, c.Exact, c.Near);
  Check(c.Pixels > 10000 && c.Environment == c.Pixels, "every ray leaves the image");
  Check(c.Near == c.Pixels,
    "every pixel shows the environment within one texel of the exact direction");
  // About the normal the shader used (Oct16-decoded), the texel is exact
  // but where float rounding puts the direction on the other side of a
  // texel border.
  vtkNew<vtkImageData> layers;
  pass->GetGBufferPass()->CaptureLayers(layers, renderer);
  const Comparison decoded = Compare(
    reflections, Equirectangular, OneTexel, Layer(layers, vtkDeepGICaptureNames::Normal, 0));
  std::printf(
    "about the G-buffer's normals: %ld of %ld exact texel\n", decoded.Exact, decoded.Pixels);
  Check(decoded.Exact >= 0.995 * decoded.Pixels,
    "99.5 % show exactly the texel of the direction about the stored normal");
}

// (1b) The same environment at 4x through an OpenEXR file (plain R, G, B
// channels: the array is named "RGB").
void CheckOpenEXREnvironment(
  vtkRenderWindow* window, vtkRenderer* renderer, vtkDeepReflectionPass* pass, vtkImageData* image)
{
  vtkTexture* environment = renderer->GetEnvironmentTexture();
  {
    vtkNew<vtkImageData> hdr;
    hdr->SetDimensions(EnvWidth, EnvHeight, 1);
    vtkNew<vtkFloatArray> hdrTexels;
    hdrTexels->DeepCopy(image->GetPointData()->GetScalars());
    hdrTexels->SetName("RGB");
    for (vtkIdType v = 0; v < hdrTexels->GetNumberOfValues(); ++v)
    {
      hdrTexels->SetValue(v, 4.0f * hdrTexels->GetValue(v));
    }
    hdr->GetPointData()->SetScalars(hdrTexels);
    const std::string file = "TestDeepReflectionEnvironment.exr";
    vtkNew<vtkDeepGIEXRWriter> writer;
    writer->SetFileName(file.c_str());
    writer->SetInputData(hdr);
    Check(writer->Write() == 1, "environment written as OpenEXR");
    vtkNew<vtkDeepGIEXRReader> reader;
    reader->SetFileName(file.c_str());
    vtkNew<vtkTexture> fromFile;
    fromFile->SetInputConnection(reader->GetOutputPort());
    fromFile->SetColorModeToDirectScalars();
    fromFile->InterpolateOff();
    renderer->SetEnvironmentTexture(fromFile);
    window->Render();
    vtkNew<vtkImageData> hdrReflections;
    pass->CaptureReflections(hdrReflections, renderer);
    auto scaled = [](const Vector& r, const Vector& rc) -> Vector
    {
      const Vector e = Equirectangular(r, rc);
      return { 4.0 * e[0], 4.0 * e[1], 4.0 * e[2] };
    };
    const double fourTexels[3] = { 4.0 * OneTexel[0], 4.0 * OneTexel[1], 4.0 * OneTexel[2] };
    const Comparison h = Compare(hdrReflections, scaled, fourTexels);
    double range[2];
    hdrReflections->GetPointData()
      ->GetArray(vtkDeepGICaptureNames::ReflectedRadiance)
      ->GetRange(range, 0);
    std::printf("OpenEXR environment at 4x: %ld traced pixels, %ld within one texel, red up to "
                "%.3f\n",
      h.Pixels, h.Near, range[1]);
    Check(h.Pixels > 10000 && h.Near == h.Pixels && range[1] > 1.05,
      "the OpenEXR environment's radiance, above 1, is reflected");
    renderer->SetEnvironmentTexture(environment);
  }
}

// (2) A cube map: one colour per face (GL's face order +x, -x, +y, -y, +z,
// -z); the face is the largest component of e (its sign), e reflected
// about the stored normal. Pixels whose direction lies within 0.001 of a
// face border are left out (float rounding decides there).
void CheckCubeMapEnvironment(
  vtkRenderWindow* window, vtkRenderer* renderer, vtkDeepReflectionPass* pass)
{
  const double faceColors[6][3] = { { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 }, { 1, 1, 0 }, { 0, 1, 1 },
    { 1, 0, 1 } };
  vtkNew<vtkTexture> cube;
  cube->CubeMapOn();
  for (int f = 0; f < 6; ++f)
  {
    vtkNew<vtkImageData> face;
    face->SetDimensions(4, 4, 1);
    vtkNew<vtkUnsignedCharArray> rgb;
    rgb->SetNumberOfComponents(3);
    rgb->SetNumberOfTuples(16);
    for (int t = 0; t < 16; ++t)
    {
      rgb->SetTuple3(t, 255 * faceColors[f][0], 255 * faceColors[f][1], 255 * faceColors[f][2]);
    }
    face->GetPointData()->SetScalars(rgb);
    cube->SetInputData(f, face);
  }
  renderer->SetEnvironmentTexture(cube);
  // A steeper view, so that mirror directions cross from the -z face to +y.
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetPosition(0.3, 4.0, 2.0);
  camera->SetFocalPoint(0.0, 0.0, 0.0);
  renderer->ResetCameraClippingRange();
  window->Render();
  vtkNew<vtkImageData> reflections, layers;
  pass->CaptureReflections(reflections, renderer);
  long borderPixels = 0;
  long faceCount[6] = { 0, 0, 0, 0, 0, 0 };
  auto cubeFace = [&](const Vector& r, const Vector&) -> Vector
  {
    int axis = 0;
    for (int k = 1; k < 3; ++k)
    {
      axis = std::abs(r[k]) > std::abs(r[axis]) ? k : axis;
    }
    for (int k = 0; k < 3; ++k)
    {
      if (k != axis && std::abs(std::abs(r[k]) - std::abs(r[axis])) < 0.001)
      {
        ++borderPixels;
        return { -1.0, -1.0, -1.0 }; // never matches: counted separately
      }
    }
    const int face = 2 * axis + (r[axis] < 0.0 ? 1 : 0);
    ++faceCount[face];
    const double* c = faceColors[face];
    return { c[0], c[1], c[2] };
  };
  pass->GetGBufferPass()->CaptureLayers(layers, renderer);
  const Comparison c =
    Compare(reflections, cubeFace, ExactTolerance, Layer(layers, vtkDeepGICaptureNames::Normal, 0));
  std::printf("cube map: %ld of %ld pixels exact (%ld near a face border)\n", c.Exact, c.Pixels,
    borderPixels);
  std::printf("  pixels per face +x -x +y -y +z -z: %ld %ld %ld %ld %ld %ld\n", faceCount[0],
    faceCount[1], faceCount[2], faceCount[3], faceCount[4], faceCount[5]);
  Check(c.Pixels > 10000 && c.Exact + borderPixels == c.Pixels && borderPixels < 0.05 * c.Pixels &&
      faceCount[2] > 1000 && faceCount[5] > 1000,
    "a cube map environment gives the face of the mirror direction (+y and -z faces seen)");
}

// (3) No environment texture: the background colour.
void CheckBackgroundWithoutEnvironment(
  vtkRenderWindow* window, vtkRenderer* renderer, vtkDeepReflectionPass* pass)
{
  renderer->SetEnvironmentTexture(nullptr);
  window->Render();
  vtkNew<vtkImageData> reflections;
  pass->CaptureReflections(reflections, renderer);
  auto plain = [](const Vector&, const Vector&) -> Vector { return { 0.2, 0.4, 0.6 }; };
  const Comparison c = Compare(reflections, plain, ExactTolerance);
  std::printf("background: %ld of %ld pixels exact\n", c.Exact, c.Pixels);
  Check(c.Pixels > 10000 && c.Exact == c.Pixels,
    "without an environment texture: the background colour");
}

// (4) Gradient background: Background at the bottom, Background2 at the top.
void CheckGradientBackground(
  vtkRenderWindow* window, vtkRenderer* renderer, vtkDeepReflectionPass* pass)
{
  renderer->GradientBackgroundOn();
  renderer->SetBackground2(1.0, 0.0, 0.0);
  window->Render();
  vtkNew<vtkImageData> reflections;
  pass->CaptureReflections(reflections, renderer);
  auto gradient = [](const Vector&, const Vector& rc) -> Vector
  {
    const double t = 0.5 + 0.5 * rc[1];
    return { 0.2 + t * 0.8, 0.4 - t * 0.4, 0.6 - t * 0.6 };
  };
  const double gradientTolerance[3] = { 0.01, 0.01, 0.01 };
  const Comparison c = Compare(reflections, gradient, gradientTolerance);
  std::printf("gradient: %ld of %ld pixels within 0.01\n", c.Near, c.Pixels);
  Check(c.Pixels > 10000 && c.Near == c.Pixels,
    "gradient background follows the ray's camera-space elevation");
}

// A float environment in VTK's default colour mode is mapped to 8 bits
// through a lookup table by VTK: one warning says so.
void CheckMappedFloatEnvironmentWarns(
  vtkRenderWindow* window, vtkRenderer* renderer, vtkDeepReflectionPass* pass, vtkImageData* image)
{
  EventCounter warnings(pass, vtkCommand::WarningEvent);
  vtkNew<vtkTexture> mapped;
  mapped->SetInputData(image);
  renderer->SetEnvironmentTexture(mapped);
  window->Render();
  window->Render();
  Check(warnings.Count == 1, "one warning for a float environment that VTK maps to 8 bits");
}
}

int TestDeepReflectionEnvironment(int, char*[])
{
  auto window = MakeWindow(200, 150);
  vtkNew<vtkRenderer> renderer;
  renderer->SetBackground(0.2, 0.4, 0.6);
  window->AddRenderer(renderer);
  MakeMirror(AddQuad(renderer, { -50, 0, 50 }, { 50, 0, 50 }, { -50, 0, -50 }));
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetPosition(0.3, 2.0, 4.0);
  camera->SetFocalPoint(0.0, 0.0, -4.0);
  camera->SetViewUp(0.0, 1.0, 0.0);
  camera->SetViewAngle(50.0);
  renderer->ResetCameraClippingRange();

  auto image = MakeEnvironmentImage();
  vtkNew<vtkTexture> environment;
  environment->SetInputData(image);
  environment->SetColorModeToDirectScalars(); // float texels stay float (VTK's rule)
  environment->InterpolateOff();
  renderer->SetEnvironmentTexture(environment);
  vtkNew<vtkDeepReflectionPass> pass;
  renderer->SetPass(pass);
  window->Render();

  CheckEquirectangularEnvironment(renderer, pass);
  CheckOpenEXREnvironment(window, renderer, pass, image);
  CheckCubeMapEnvironment(window, renderer, pass);
  CheckBackgroundWithoutEnvironment(window, renderer, pass);
  CheckGradientBackground(window, renderer, pass);
  CheckMappedFloatEnvironmentWarns(window, renderer, pass, image);
  pass->ReleaseGraphicsResources(window);
  return ExitStatus();
}
