/**
 * @class   vtkDeepGIDemoScene
 * @brief   Procedural room with the depth complexity deep G-buffers are about.
 *
 * A closed-ish room, 10 x 4 x 8 world units (x from -5 to 5, y up from 0 to
 * 4, z from -4 to 4; the +z side is open), built entirely from triangles:
 *
 * - saturated walls: red left wall (x = -5), blue right wall (x = +5), green
 *   back wall (z = -4), light grey floor, optional white ceiling;
 * - a row of four columns (z = -2.7) with ring mouldings at the base and the
 *   capital, each standing in front of a coloured banner that hangs 0.15
 *   units in front of the back wall: the Sponza tapestry case of the paper
 *   (Mara et al. 2016, Figures 2 and 16), where a column occludes a banner
 *   and camera motion reveals and hides the banner's regions;
 * - local structure that a minimum separation must skip (paper section 2):
 *   baseboards, a chair rail and crown mouldings along the walls, a decal
 *   0.002 x room width (0.02 units) in front of the right wall, and a thin
 *   panel 0.05 units in front of the left wall;
 * - a sphere and a box on the floor.
 *
 * The tessellation is chosen so that the scene has at least
 * TargetNumberOfTriangles triangles: an edge length h is found such that
 * walls, banners, cylinders, tori and spheres subdivided with edges of about
 * h give the target (curved surfaces keep a minimum angular resolution), so
 * the same scene serves 10k and multi-million triangle runs. Each material
 * is one vtkPolyData of triangles with point normals from
 * vtkPolyDataNormals (splitting at FeatureAngle, so box edges stay hard),
 * unless ComputeNormals is off.
 *
 * Everything, geometry, lights and cameras, is multiplied by ScaleFactor,
 * for numerical-stability tests at very small and very large scales.
 *
 * Typical use:
 * @code
 * vtkNew<vtkDeepGIDemoScene> scene;
 * scene->SetTargetNumberOfTriangles(100000);
 * scene->Populate(renderer);                 // actors and lights
 * scene->SetCameraToDefaultView(renderer->GetActiveCamera());
 * @endcode
 *
 * The scene is a VTK source (no input): its output is GetScenePolyData(),
 * so that it can feed a pipeline (Update(), GetOutputPort()). The geometry
 * is (re)built lazily when a parameter changed, by Update() or by any
 * accessor.
 */

#ifndef vtkDeepGIDemoScene_h
#define vtkDeepGIDemoScene_h

#include "vtkDeepGIScenesModule.h" // for export macro
#include "vtkDeepGISetGet.h"       // for vtkDeepGISetClampMacro
#include "vtkPolyDataAlgorithm.h"
#include "vtkSmartPointer.h" // for ivars
#include "vtkTimeStamp.h"    // for ivars

#include <vector> // for ivars

class vtkCamera;
class vtkPolyData;
class vtkRenderer;

class VTKDEEPGISCENES_EXPORT vtkDeepGIDemoScene : public vtkPolyDataAlgorithm
{
public:
  static vtkDeepGIDemoScene* New();
  vtkTypeMacro(vtkDeepGIDemoScene, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// The scene's materials; each becomes one actor with its own albedo.
  enum Material
  {
    FLOOR = 0,
    CEILING,
    LEFT_WALL,
    RIGHT_WALL,
    BACK_WALL,
    COLUMNS,
    BANNERS_GOLD,
    BANNERS_PURPLE,
    MOULDINGS,
    DECAL,
    PANEL,
    SPHERE,
    BOX,
    NUMBER_OF_MATERIALS
  };

  ///@{
  /**
   * Minimum number of triangles of the scene. The tessellation is refined
   * until the scene has at least this many triangles (it may have a few
   * percent more; below about 7,700 the coarsest tessellation is used).
   * Range 0 to 500,000,000. Default 10,000.
   *
   * @unit triangles
   * @range 0 to 500,000,000, clamped
   * @default 10,000
   */
  vtkSetClampMacro(TargetNumberOfTriangles, vtkIdType, 0, 500000000);
  vtkGetMacro(TargetNumberOfTriangles, vtkIdType);
  ///@}

  ///@{
  /**
   * Uniform scale of the whole scene: geometry, light positions and the
   * camera setups. Must be finite and positive; other values are rejected
   * with an error. Default 1 (room 10 x 4 x 8 units).
   *
   * @range finite and > 0; other values: error, ignored
   * @default 1
   */
  virtual void SetScaleFactor(double scale);
  vtkGetMacro(ScaleFactor, double);
  ///@}

  ///@{
  /**
   * Whether the room has a ceiling (y = 4). Default on.
   *
   * @range on/off
   * @default on
   */
  vtkSetMacro(Ceiling, bool);
  vtkGetMacro(Ceiling, bool);
  vtkBooleanMacro(Ceiling, bool);
  ///@}

  ///@{
  /**
   * Whether point normals are computed (vtkPolyDataNormals). Turn off to
   * exercise meshes without normals. Default on.
   *
   * @range on/off
   * @default on
   */
  vtkSetMacro(ComputeNormals, bool);
  vtkGetMacro(ComputeNormals, bool);
  vtkBooleanMacro(ComputeNormals, bool);
  ///@}

  ///@{
  /**
   * Edges between triangles meeting at more than this angle (degrees) are
   * hard: the normals are split there. Range 0 to 180. Default 30.
   *
   * @unit degrees
   * @range 0 to 180, clamped
   * @default 30
   */
  vtkDeepGISetClampMacro(FeatureAngle, double, 0.0, 180.0);
  vtkGetMacro(FeatureAngle, double);
  ///@}

  /// Number of triangles of the whole scene (builds if needed).
  vtkIdType GetNumberOfTriangles();

  /// Number of points of the whole scene (builds if needed).
  vtkIdType GetNumberOfPoints();

  /**
   * The tessellation edge length chosen for the target, in unscaled world
   * units (multiply by ScaleFactor for the scene's units).
   */
  double GetEdgeLength();

  /**
   * All geometry appended into one polydata: triangles, point normals
   * "Normals" (if ComputeNormals), cell data "Colors" (unsigned char RGB, the
   * diffuse albedo of the triangle's material) and "MaterialId" (int, a
   * Material value), field data "Diffuse" (the actors' diffuse coefficient,
   * 0.9). Owned by the scene; rebuilt when parameters change.
   */
  vtkPolyData* GetScenePolyData();

  /// The triangles of one material (nullptr if out of range); owned by the scene.
  vtkPolyData* GetMaterialPolyData(int material);

  /// Bounds of all geometry (xmin, xmax, ymin, ymax, zmin, zmax), scaled.
  void GetBounds(double bounds[6]);

  ///@{
  /// Names ("floor", "left wall", ...) and diffuse albedos (linear RGB, 0-1)
  /// of the materials. Unknown indices give nullptr and black.
  static int GetNumberOfMaterials() { return NUMBER_OF_MATERIALS; }
  static const char* GetMaterialName(int material);
  static void GetMaterialColor(int material, double rgb[3]);
  ///@}

  /**
   * Adds the scene to `renderer`: AddActors then AddLights. New actors and
   * lights are created on each call, so one scene can populate several
   * renderers.
   */
  void Populate(vtkRenderer* renderer);

  /**
   * Adds one actor per (non-empty) material: a vtkPolyDataMapper with
   * scalar colouring off and a property with the material's diffuse colour,
   * Ambient 0.1, Diffuse 0.9, Specular 0.
   */
  void AddActors(vtkRenderer* renderer);

  /**
   * Adds two scene lights: a warm positional point light (cone angle 180,
   * no attenuation, intensity 0.75) below the ceiling at (0, 3, 0.5), and a
   * cool directional fill light from (-2, 5, 3.5) towards the origin
   * (intensity 0.35). Positions are multiplied by ScaleFactor.
   */
  void AddLights(vtkRenderer* renderer);

  ///@{
  /**
   * Camera setups. Each sets position, focal point, view up (+y), view angle
   * and a clipping range (0.05 to 30 units, times ScaleFactor) that contains
   * the room from anywhere inside it; call the renderer's
   * ResetCameraClippingRange() afterwards if other props are present.
   *
   * SetCameraToDefaultView: a fixed view for regression images: from the
   * front right, looking at the back wall, the columns overlapping the
   * banners, with the red and blue walls, the panel and the decal in view.
   *
   * SetCameraToPathFrame: frame `frame` (any integer, taken modulo
   * numberOfFrames) of a closed, smooth path of `numberOfFrames` frames
   * (values < 1 count as 1): the camera circles along an ellipse in front of
   * the column row (x from -2.6 to 2.6, z from 1.9 to 2.9, height bobbing
   * around 1.7), looking at the back wall, so the columns sweep across the
   * banners and parallax reveals and hides banner regions. Frame 0 is the
   * centre of the arc; the path is deterministic (a pure function of the
   * arguments and ScaleFactor).
   *
   * SetCameraToNamedView: one of the views named by GetNamedViewName
   * ("default", "overview", "columns", "decal", "panel"); returns false
   * (camera unchanged, error reported) for unknown names.
   */
  void SetCameraToDefaultView(vtkCamera* camera);
  void SetCameraToPathFrame(vtkCamera* camera, int frame, int numberOfFrames);
  bool SetCameraToNamedView(vtkCamera* camera, const char* name);
  static int GetNumberOfNamedViews();
  static const char* GetNamedViewName(int index);
  ///@}

protected:
  vtkDeepGIDemoScene();
  ~vtkDeepGIDemoScene() override;

  vtkIdType TargetNumberOfTriangles = 10000;
  double ScaleFactor = 1.0;
  bool Ceiling = true;
  bool ComputeNormals = true;
  double FeatureAngle = 30.0;

  // Build results.
  double EdgeLength = 0.0;
  vtkTimeStamp BuildTime;
  std::vector<vtkSmartPointer<vtkPolyData>> MaterialPolyData;
  vtkSmartPointer<vtkPolyData> ScenePolyData;

  void SetCamera(
    vtkCamera* camera, const double position[3], const double focalPoint[3], double viewAngle);

  /// Builds the geometry if a parameter changed since the last build.
  void Build();

  /// The output: GetScenePolyData().
  int RequestData(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

private:
  vtkDeepGIDemoScene(const vtkDeepGIDemoScene&) = delete;
  void operator=(const vtkDeepGIDemoScene&) = delete;
};

#endif
