// The albedo layer holds VTK's colouring, whatever its source, and the
// G-buffer composes with what VTK draws after it:
// - the ambient layer holds VTK's ambient term (Ka x ambient colour), a
//   part of the radiance, and zeros once no prop has an ambient term (the
//   target is then not written), and the term again when one has;
// - actor colour; point scalars through a lookup table (interpolated as
//   colours, and through VTK's colour texture with
//   InterpolateScalarsBeforeMapping); an actor texture: each quad's
//   captured albedo equals the expected colour within 2/255;
// - the textures are reachable by consumers (handles, texture units) and
//   gone after ReleaseGraphicsResources;
// - a volume (vtkSmartVolumeMapper) and a 2D overlay (vtkTextActor) in the
//   same renderer are drawn by VTK after the G-buffer.

#include "DeepGBufferTestUtilities.h"

#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkDeepGICaptureNames.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkLookupTable.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPlaneSource.h"
#include "vtkPolyDataMapper.h"
#include "vtkSmartVolumeMapper.h"
#include "vtkTextActor.h"
#include "vtkTextProperty.h"
#include "vtkTexture.h"
#include "vtkTextureUnitManager.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"

#include <array>

using namespace DeepGBufferTest;
using namespace DeepGITest;

namespace
{
// A unit quad centred at (x, y) in the z = 0 plane, facing the camera.
vtkSmartPointer<vtkPlaneSource> Quad(double x, double y)
{
  auto quad = vtkSmartPointer<vtkPlaneSource>::New();
  quad->SetOrigin(x - 0.45, y - 0.45, 0.0);
  quad->SetPoint1(x + 0.45, y - 0.45, 0.0);
  quad->SetPoint2(x - 0.45, y + 0.45, 0.0);
  quad->Update();
  return quad;
}

// The captured albedo at the pixel where world point (x, y, 0) lands.
std::array<double, 3> AlbedoAt(vtkRenderer* renderer, vtkImageData* capture, double x, double y)
{
  double world[4] = { x, y, 0.0, 1.0 }, display[3];
  renderer->SetWorldPoint(world);
  renderer->WorldToDisplay();
  renderer->GetDisplayPoint(display);
  int dims[3];
  capture->GetDimensions(dims);
  const vtkIdType pixel =
    static_cast<vtkIdType>(display[1]) * dims[0] + static_cast<vtkIdType>(display[0]);
  vtkDataArray* albedo = Layer(capture, vtkDeepGICaptureNames::Albedo, 0);
  return { albedo->GetComponent(pixel, 0), albedo->GetComponent(pixel, 1),
    albedo->GetComponent(pixel, 2) };
}

void CheckAlbedo(vtkRenderer* renderer, vtkImageData* capture, double x, double y,
  const std::array<double, 3>& expected, const std::string& what)
{
  const std::array<double, 3> a = AlbedoAt(renderer, capture, x, y);
  double error = 0.0;
  for (int c = 0; c < 3; ++c)
  {
    error = std::max(error, std::abs(a[c] - expected[c]));
  }
  std::printf("  %s: albedo (%.3f %.3f %.3f), expected (%.3f %.3f %.3f)\n", what.c_str(), a[0],
    a[1], a[2], expected[0], expected[1], expected[2]);
  Check(error <= 2.0 / 255.0, what + " albedo");
}

// Actor colour, with the diffuse coefficient: albedo = Kd * colour.
vtkActor* AddColouredQuad(vtkRenderer* renderer)
{
  auto plain = Quad(-1.0, 1.0);
  vtkNew<vtkPolyDataMapper> plainMapper;
  plainMapper->SetInputConnection(plain->GetOutputPort());
  vtkNew<vtkActor> plainActor;
  plainActor->SetMapper(plainMapper);
  plainActor->GetProperty()->SetDiffuseColor(0.8, 0.4, 0.2);
  plainActor->GetProperty()->SetDiffuse(0.75);
  plainActor->GetProperty()->SetAmbientColor(1.0, 0.5, 0.25);
  plainActor->GetProperty()->SetAmbient(0.2);
  renderer->AddActor(plainActor);
  return plainActor;
}

// Point scalars (all 0.25) through a lookup table, mapped per vertex and
// through VTK's colour texture.
void AddScalarQuads(vtkRenderer* renderer, vtkLookupTable* lut)
{
  for (int interpolateBeforeMapping = 0; interpolateBeforeMapping < 2; ++interpolateBeforeMapping)
  {
    auto quad = Quad(interpolateBeforeMapping ? 1.0 : 0.0, 1.0);
    vtkPolyData* poly = quad->GetOutput();
    vtkNew<vtkFloatArray> scalars;
    scalars->SetNumberOfTuples(poly->GetNumberOfPoints());
    scalars->Fill(0.25);
    poly->GetPointData()->SetScalars(scalars);
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputData(poly);
    mapper->SetLookupTable(lut);
    mapper->SetScalarRange(0.0, 1.0);
    mapper->SetInterpolateScalarsBeforeMapping(interpolateBeforeMapping);
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    actor->GetProperty()->SetDiffuse(1.0);
    renderer->AddActor(actor);
  }
}

// An actor texture of one colour.
void AddTexturedQuad(vtkRenderer* renderer)
{
  vtkNew<vtkImageData> textureImage;
  textureImage->SetDimensions(4, 4, 1);
  textureImage->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  for (vtkIdType p = 0; p < 16; ++p)
  {
    textureImage->GetPointData()->GetScalars()->SetTuple3(p, 51, 204, 102);
  }
  vtkNew<vtkTexture> texture;
  texture->SetInputData(textureImage);
  auto texturedQuad = Quad(-1.0, 0.0);
  vtkNew<vtkPolyDataMapper> texturedMapper;
  texturedMapper->SetInputConnection(texturedQuad->GetOutputPort());
  vtkNew<vtkActor> texturedActor;
  texturedActor->SetMapper(texturedMapper);
  texturedActor->SetTexture(texture);
  texturedActor->GetProperty()->SetColor(1.0, 1.0, 1.0);
  texturedActor->GetProperty()->SetDiffuse(1.0);
  renderer->AddActor(texturedActor);
}

// A small volume behind the quads and a text overlay.
void AddVolumeAndOverlay(vtkRenderer* renderer)
{
  vtkNew<vtkImageData> volumeImage;
  volumeImage->SetDimensions(16, 16, 16);
  volumeImage->SetSpacing(0.05, 0.05, 0.05);
  volumeImage->SetOrigin(0.3, -0.9, -1.0);
  volumeImage->AllocateScalars(VTK_UNSIGNED_CHAR, 1);
  volumeImage->GetPointData()->GetScalars()->Fill(200);
  vtkNew<vtkSmartVolumeMapper> volumeMapper;
  volumeMapper->SetInputData(volumeImage);
  vtkNew<vtkColorTransferFunction> volumeColor;
  volumeColor->AddRGBPoint(0, 0, 0, 0);
  volumeColor->AddRGBPoint(255, 1.0, 0.0, 1.0);
  vtkNew<vtkPiecewiseFunction> volumeOpacity;
  volumeOpacity->AddPoint(0, 0.0);
  volumeOpacity->AddPoint(255, 1.0);
  vtkNew<vtkVolume> volume;
  volume->SetMapper(volumeMapper);
  volume->GetProperty()->SetColor(volumeColor);
  volume->GetProperty()->SetScalarOpacity(volumeOpacity);
  renderer->AddVolume(volume);
  vtkNew<vtkTextActor> text;
  text->SetInput("overlay");
  text->GetTextProperty()->SetFontSize(24);
  text->GetTextProperty()->SetColor(1.0, 1.0, 1.0);
  text->SetDisplayPosition(10, 10);
  renderer->AddActor2D(text);
}

void CheckAmbientLayer(vtkRenderer* renderer, vtkImageData* capture)
{
  double world[4] = { -1.0, 1.0, 0.0, 1.0 }, display[3];
  renderer->SetWorldPoint(world);
  renderer->WorldToDisplay();
  renderer->GetDisplayPoint(display);
  const vtkIdType pixel =
    static_cast<vtkIdType>(display[1]) * 300 + static_cast<vtkIdType>(display[0]);
  vtkDataArray* ambient = Layer(capture, vtkDeepGICaptureNames::Ambient, 0);
  vtkDataArray* radiance = Layer(capture, vtkDeepGICaptureNames::Radiance, 0);
  const double expected[3] = { 0.2, 0.1, 0.05 };
  double error = 0.0, leastDirect = 1.0;
  for (int c = 0; c < 3; ++c)
  {
    error = std::max(error, std::abs(ambient->GetComponent(pixel, c) - expected[c]));
    leastDirect =
      std::min(leastDirect, radiance->GetComponent(pixel, c) - ambient->GetComponent(pixel, c));
  }
  std::printf("  ambient (%.3f %.3f %.3f), radiance - ambient >= %.3f\n",
    ambient->GetComponent(pixel, 0), ambient->GetComponent(pixel, 1),
    ambient->GetComponent(pixel, 2), leastDirect);
  // R11F_G11F_B10F keeps 6-7 mantissa bits: 1 % relative.
  Check(error <= 0.01 * 0.2 && leastDirect > 0.0, "ambient layer = Ka x ambient colour");
}

// With Ambient 0 on every actor the AMBIENT target is not written: it must
// read as zeros, not as the last frame that wrote it; with Ambient back on
// it holds the term again.
void CheckAmbientFollowsProperties(
  vtkRenderWindow* window, vtkRenderer* renderer, vtkDeepGBufferPass* pass, vtkActor* ambientActor)
{
  ambientActor->GetProperty()->SetAmbient(0.0);
  window->Render();
  vtkNew<vtkImageData> capture;
  pass->CaptureLayers(capture, renderer);
  vtkDataArray* ambient = Layer(capture, vtkDeepGICaptureNames::Ambient, 0);
  double largest = 0.0;
  for (vtkIdType p = 0; p < ambient->GetNumberOfTuples(); ++p)
  {
    for (int c = 0; c < 3; ++c)
    {
      largest = std::max(largest, std::abs(ambient->GetComponent(p, c)));
    }
  }
  std::printf("  Ambient 0 everywhere: largest captured ambient %g\n", largest);
  Check(largest == 0.0, "no ambient term: the ambient layer reads zero");
  ambientActor->GetProperty()->SetAmbient(0.2);
  window->Render();
  pass->CaptureLayers(capture, renderer);
  CheckAmbientLayer(renderer, capture);
}

// The volume (magenta) is composited where the G-buffer is empty; the
// overlay text is white at the bottom left.
void CheckVolumeAndOverlayDrawn(vtkRenderer* renderer, vtkImageData* image)
{
  double world[4] = { 0.675, -0.525, -0.6, 1.0 }, display[3];
  renderer->SetWorldPoint(world);
  renderer->WorldToDisplay();
  renderer->GetDisplayPoint(display);
  vtkDataArray* rgb = image->GetPointData()->GetScalars();
  const vtkIdType volumePixel =
    static_cast<vtkIdType>(display[1]) * 300 + static_cast<vtkIdType>(display[0]);
  Check(rgb->GetComponent(volumePixel, 0) > 100 && rgb->GetComponent(volumePixel, 2) > 100 &&
      rgb->GetComponent(volumePixel, 1) < 60,
    "the volume is rendered after the G-buffer");
  long bright = 0;
  for (int y = 5; y < 40; ++y)
  {
    for (int x = 5; x < 120; ++x)
    {
      bright += rgb->GetComponent(y * 300 + x, 1) > 200 ? 1 : 0;
    }
  }
  Check(bright > 20, "the 2D overlay is drawn");
}

// Texture access for consuming passes.
void CheckTextureAccess(vtkRenderWindow* window, vtkRenderer* renderer, vtkDeepGBufferPass* pass)
{
  vtkOpenGLRenderWindow* glWindow = vtkOpenGLRenderWindow::SafeDownCast(window);
  bool handles = true;
  for (int q = 0; q < vtkDeepGBufferPass::REFLECTIVITY; ++q)
  {
    handles = handles && pass->GetTextureHandle(renderer, q) != 0;
  }
  // The optional quantity exists only while a consumer asks for it.
  Check(pass->GetTextureHandle(renderer, vtkDeepGBufferPass::REFLECTIVITY) == 0,
    "no REFLECTIVITY texture unless WriteReflectivity is on");
  const int unit = pass->ActivateTexture(renderer, vtkDeepGBufferPass::NORMAL);
  const bool allocated = unit >= 0 && glWindow->GetTextureUnitManager()->IsAllocated(unit);
  pass->DeactivateTexture(renderer, vtkDeepGBufferPass::NORMAL);
  const bool released = unit >= 0 && !glWindow->GetTextureUnitManager()->IsAllocated(unit);
  Check(handles && allocated && released && pass->GetTextureHandle(renderer, 99) == 0,
    "texture handles and units for consuming passes");
  pass->ReleaseGraphicsResources(window);
  Check(pass->GetTextureHandle(renderer, vtkDeepGBufferPass::DEPTH) == 0,
    "no textures after ReleaseGraphicsResources");
}
}

int TestDeepGBufferColoring(int, char*[])
{
  auto window = MakeWindow(300, 300);
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  vtkActor* ambientActor = AddColouredQuad(renderer);
  vtkNew<vtkLookupTable> lut;
  lut->SetHueRange(0.0, 0.66);
  lut->SetRange(0.0, 1.0);
  lut->Build();
  double lutColor[3];
  lut->GetColor(0.25, lutColor);
  AddScalarQuads(renderer, lut);
  AddTexturedQuad(renderer);
  AddVolumeAndOverlay(renderer);

  renderer->GetActiveCamera()->SetPosition(0, 0.5, 6);
  renderer->GetActiveCamera()->SetFocalPoint(0, 0.5, 0);
  renderer->ResetCameraClippingRange();
  vtkNew<vtkDeepGBufferPass> pass;
  renderer->SetPass(pass);
  window->Render();
  window->Render();
  vtkNew<vtkImageData> capture, image;
  pass->CaptureLayers(capture, renderer);
  ReadWindow(window, image, nullptr);

  CheckAlbedo(renderer, capture, -1.0, 1.0, { 0.6, 0.3, 0.15 }, "actor colour x diffuse");
  CheckAlbedo(renderer, capture, 0.0, 1.0, { lutColor[0], lutColor[1], lutColor[2] },
    "scalars through a lookup table");
  CheckAlbedo(renderer, capture, 1.0, 1.0, { lutColor[0], lutColor[1], lutColor[2] },
    "scalars through VTK's colour texture");
  CheckAlbedo(renderer, capture, -1.0, 0.0, { 0.2, 0.8, 0.4 }, "actor texture");
  CheckAmbientLayer(renderer, capture);
  CheckVolumeAndOverlayDrawn(renderer, image);
  CheckAmbientFollowsProperties(window, renderer, pass, ambientActor);
  CheckTextureAccess(window, renderer, pass);
  return ExitStatus();
}
