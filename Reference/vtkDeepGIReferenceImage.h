/**
 * @class   vtkDeepGIReferenceImage
 * @brief   ray-traced (Embree) reference of the image vtkDeepGIPass
 *          approximates, on the pixels of a deep G-buffer capture
 *
 * The lighting model of vtkDeepGIPass (Documentation/lighting-model.md),
 * evaluated on layer 0 of a capture (vtkDeepGBufferPass::CaptureLayers)
 * with ray-traced visibility and indirect light instead of screen-space
 * estimates:
 *
 *   AV_SCALES_AMBIENT:  L = RADIANCE - (1 - AV) * AMBIENT + rho * E / pi
 *   AV_SCALES_RADIANCE: L = AV * RADIANCE + rho * E / pi
 *
 * RADIANCE, AMBIENT and rho (Albedo) are the capture's layer-0 values, i.e.
 * VTK's own local shading of the pixel, which needs no estimate. AV is the
 * ambient visibility of vtkDeepGIReferenceObscurance (eq. 2 with Bias and
 * Epsilon 0, the quantity itself) within ObscuranceRadius, and E the
 * indirect irradiance of vtkDeepGIReferenceIrradiance with NumberOfBounces
 * bounces (undamped by default: the physical multi-bounce light) from
 * surfaces at any distance. AV_SCALES_AMBIENT is what vtkDeepGIPass does
 * when a visible actor has an ambient term; AV_SCALES_RADIANCE when none
 * has (VTK's default Ambient 0): VTK's lights then stand for all the light
 * that arrives, which surfaces nearby occlude.
 *
 * Output point arrays (float, dimensions of the capture): "Radiance" (RGB
 * L), "RadianceStandardError" (RGB, from both Monte Carlo estimates:
 * sqrt((AMBIENT or RADIANCE)^2 SE_AV^2 + SE_indirect^2)),
 * "AmbientVisibility", "IndirectRadiance" and "Valid" (unsigned char).
 * Empty pixels are 0 and not valid. Mirror reflections are not part of the
 * reference yet: a capture with "Reflectivity_0" is refused with an error.
 *
 * SceneFromRenderer() builds the scene polydata both references trace from
 * a renderer's visible opaque actors (world coordinates, cell "Colors" and
 * "Diffuse" from each actor's property), so any VTK scene has a reference.
 *
 * @sa vtkDeepGIReferenceObscurance vtkDeepGIReferenceIrradiance vtkDeepGIPass
 */

#ifndef vtkDeepGIReferenceImage_h
#define vtkDeepGIReferenceImage_h

#include "vtkDeepGIReferenceModule.h" // for export macro
#include "vtkObject.h"
#include "vtkSmartPointer.h" // for the sub-references

class vtkDeepGIReferenceIrradiance;
class vtkDeepGIReferenceObscurance;
class vtkImageData;
class vtkPolyData;
class vtkRenderer;

class VTKDEEPGIREFERENCE_EXPORT vtkDeepGIReferenceImage : public vtkObject
{
public:
  static vtkDeepGIReferenceImage* New();
  vtkTypeMacro(vtkDeepGIReferenceImage, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Which term ambient visibility scales (see the class description).
  enum VisibilityModel
  {
    AV_SCALES_AMBIENT = 0,
    AV_SCALES_RADIANCE = 1
  };

  ///@{
  /// Default AV_SCALES_RADIANCE (VTK's default actors have no ambient term).
  /// Which term AV scales: the ambient term (AV_SCALES_AMBIENT, scenes with one) or VTK's whole
  /// shading (AV_SCALES_RADIANCE, VTK's default actors), as
  /// vtkDeepAmbientObscurancePass::ResolveComposition decides for the pass.
  ///
  /// @range AV_SCALES_AMBIENT 0, AV_SCALES_RADIANCE 1; clamped
  /// @default AV_SCALES_RADIANCE
  vtkSetClampMacro(Visibility, int, AV_SCALES_AMBIENT, AV_SCALES_RADIANCE);
  vtkGetMacro(Visibility, int);
  ///@}

  /// The triangles both references trace (world coordinates).
  void SetScene(vtkPolyData* scene);

  /// The lights (vtkDeepGIReferenceIrradiance::SetLightsFromRenderer).
  void SetLightsFromRenderer(vtkRenderer* renderer);

  ///@{
  /// The obscurance radius r (world units), as the pass's effective radius.
  /// Use the pass's GetEffectiveRadius().
  ///
  /// @unit world units
  /// @range > 0 (Compute() fails otherwise)
  /// @default 1
  void SetObscuranceRadius(double radius);
  double GetObscuranceRadius();
  ///@}

  ///@{
  /// Bounces of indirect light, [1, 16]; default 4.
  /// The bounces are undamped.
  ///
  /// @unit bounces
  /// @range 1..16, clamped with a warning
  /// @default 4
  void SetNumberOfBounces(int bounces);
  int GetNumberOfBounces();
  ///@}

  ///@{
  /// Rays per pixel of each estimate; default 256.
  ///
  /// @unit rays
  /// @range 1..1048576, clamped
  /// @default 256
  void SetSamplesPerPixel(int samples);
  int GetSamplesPerPixel();
  ///@}

  /// The two references, for their other settings (seed, two-sided lighting).
  vtkDeepGIReferenceObscurance* GetObscurance();
  vtkDeepGIReferenceIrradiance* GetIrradiance();

  /**
   * Computes the output for layer 0 of `capture`. False with an error (and
   * an empty output) when either reference fails or the capture lacks
   * Radiance_0, Ambient_0 or Albedo_0, or has Reflectivity_0.
   */
  bool Compute(vtkImageData* capture);

  /// The result of the last Compute() (see the class description).
  vtkImageData* GetOutput();

  ///@{
  /// Mean and maximum over valid pixels of the largest RGB standard error.
  vtkGetMacro(MeanStandardError, double);
  vtkGetMacro(MaximumStandardError, double);
  ///@}

  /**
   * Sets `scene` to the visible actors of `renderer` with opaque polygonal
   * geometry as one triangle mesh in world coordinates, with cell arrays
   * "Colors" (the property's DiffuseColor, RGB double) and "Diffuse" (its
   * Diffuse) and the actors' point normals where they all have them.
   * Actors coloured by scalars or textures keep their property colour (a
   * warning says so); inputs that are not vtkPolyData are skipped with a
   * warning. Returns false (scene emptied) when no actor qualifies.
   */
  static bool SceneFromRenderer(vtkRenderer* renderer, vtkPolyData* scene);

protected:
  vtkDeepGIReferenceImage();
  ~vtkDeepGIReferenceImage() override;

private:
  vtkDeepGIReferenceImage(const vtkDeepGIReferenceImage&) = delete;
  void operator=(const vtkDeepGIReferenceImage&) = delete;

  bool CheckCapture(vtkImageData* capture);
  void Compose(vtkImageData* capture);

  int Visibility = AV_SCALES_RADIANCE;
  double MeanStandardError = 0.0;
  double MaximumStandardError = 0.0;
  vtkSmartPointer<vtkDeepGIReferenceObscurance> Obscurance;
  vtkSmartPointer<vtkDeepGIReferenceIrradiance> Irradiance;
  vtkSmartPointer<vtkImageData> Output;
};

#endif
