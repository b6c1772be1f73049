// Regression image of a real mesh (the Stanford dragon, 43k triangles, from
// Testing/Data/meshes) in front of a floor and a wall: layer 1 shows the
// parts of the dragon and the floor hidden behind its body and head, with
// the automatic minimum separation (1.5 % of the scene's diagonal).
// Threshold 0.5, as for the demo scene.

#include "DeepGBufferImageTest.h"
#include "DeepGITestData.h"

#include "vtkLight.h"
#include "vtkPLYReader.h"
#include "vtkPlaneSource.h"
#include "vtkPolyDataMapper.h"
#include "vtkPolyDataNormals.h"

int TestDeepGBufferDragonImage(int argc, char* argv[])
{
  const std::string data = DeepGITestData::Folder(argc, argv, "TestDeepGBufferDragonImage");
  if (!DeepGITestData::Require(data, { "meshes/dragon.ply" }, "TestDeepGBufferDragonImage"))
  {
    return EXIT_FAILURE;
  }
  return DeepGBufferTest::RunLayerImageTest(
    argc, argv,
    [&data](vtkRenderer* renderer)
    {
      vtkNew<vtkPLYReader> reader;
      reader->SetFileName((data + "/meshes/dragon.ply").c_str());
      vtkNew<vtkPolyDataNormals> normals;
      normals->SetInputConnection(reader->GetOutputPort());
      normals->Update();
      vtkPolyData* dragon = normals->GetOutput();
      if (dragon->GetNumberOfCells() == 0)
      {
        std::printf("could not read %s/meshes/dragon.ply\n", data.c_str());
        return false;
      }
      double b[6];
      dragon->GetBounds(b);
      vtkNew<vtkPolyDataMapper> mapper;
      mapper->SetInputData(dragon);
      vtkNew<vtkActor> actor;
      actor->SetMapper(mapper);
      actor->GetProperty()->SetColor(0.85, 0.75, 0.45);
      renderer->AddActor(actor);

      // A floor under it and a wall behind it, slightly larger than the mesh.
      const double sx = b[1] - b[0], sz = b[5] - b[4];
      vtkNew<vtkPlaneSource> floor, wall;
      floor->SetOrigin(b[0] - sx, b[2], b[4] - sz);
      floor->SetPoint1(b[0] - sx, b[2], b[5] + sz); // normal +y
      floor->SetPoint2(b[1] + sx, b[2], b[4] - sz);
      wall->SetOrigin(b[0] - sx, b[2], b[4] - 0.5 * sz);
      wall->SetPoint1(b[1] + sx, b[2], b[4] - 0.5 * sz);
      wall->SetPoint2(b[0] - sx, b[3] + (b[3] - b[2]), b[4] - 0.5 * sz);
      for (vtkPlaneSource* plane : { floor.Get(), wall.Get() })
      {
        vtkNew<vtkPolyDataMapper> planeMapper;
        planeMapper->SetInputConnection(plane->GetOutputPort());
        vtkNew<vtkActor> planeActor;
        planeActor->SetMapper(planeMapper);
        planeActor->GetProperty()->SetColor(plane == floor.Get() ? 0.6 : 0.3,
          plane == floor.Get() ? 0.6 : 0.45, plane == floor.Get() ? 0.6 : 0.8);
        renderer->AddActor(planeActor);
      }
      // A key light above and in front, and VTK's headlight as fill.
      vtkNew<vtkLight> key;
      key->SetLightTypeToSceneLight();
      key->SetPosition(b[1] + sx, b[3] + 2.0 * (b[3] - b[2]), b[5] + 2.0 * sz);
      key->SetFocalPoint(0.5 * (b[0] + b[1]), b[2], 0.5 * (b[4] + b[5]));
      key->SetIntensity(0.8);
      vtkNew<vtkLight> fill;
      fill->SetLightTypeToHeadlight();
      fill->SetIntensity(0.5);
      renderer->AddLight(key);
      renderer->AddLight(fill);
      vtkCamera* camera = renderer->GetActiveCamera();
      const double c[3] = { 0.5 * (b[0] + b[1]), 0.5 * (b[2] + b[3]), 0.5 * (b[4] + b[5]) };
      camera->SetFocalPoint(c);
      camera->SetPosition(c[0] + 0.6 * sx, c[1] + 0.5 * (b[3] - b[2]), c[2] + 1.6 * sx);
      camera->SetViewUp(0, 1, 0);
      renderer->ResetCamera(b);
      camera->Zoom(1.3);
      renderer->ResetCameraClippingRange();
      return true;
    },
    -1.0, 3000, 0.5);
}
