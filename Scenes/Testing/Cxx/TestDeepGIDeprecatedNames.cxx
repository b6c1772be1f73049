// The former class names of the scenes, kept for one release: each is the
// new class under the old name (New, IsA, the same behaviour).
//   TestDeepGIDeprecatedNames --data DIR

#include "DeepGITestChecks.h"
#include "DeepGITestData.h"

#include "vtkDeepGBufferDemoScene.h"
#include "vtkDeepGBufferSceneLoader.h"
#include "vtkNew.h"

#include <string>

namespace
{
using DeepGITest::Check;
using DeepGITest::Text;

void TestDemoScene()
{
  vtkNew<vtkDeepGBufferDemoScene> scene;
  vtkNew<vtkDeepGIDemoScene> current;
  Check(scene->IsA("vtkDeepGIDemoScene") &&
      std::string(scene->GetClassName()) == "vtkDeepGBufferDemoScene",
    "vtkDeepGBufferDemoScene is a vtkDeepGIDemoScene");
  Check(scene->GetNumberOfTriangles() == current->GetNumberOfTriangles(),
    Text("vtkDeepGBufferDemoScene builds the same room (", scene->GetNumberOfTriangles(),
      " triangles)"));
}

void TestSceneLoader(const std::string& data)
{
  vtkNew<vtkDeepGBufferSceneLoader> loader;
  const std::string obj = data + "/scenes/cornell-original/CornellBox-Original.obj";
  Check(loader->IsA("vtkDeepGISceneLoader"), "vtkDeepGBufferSceneLoader is a vtkDeepGISceneLoader");
  Check(loader->Load(obj.c_str()) && loader->GetNumberOfParts() == 8,
    Text("vtkDeepGBufferSceneLoader loads the Cornell box's 8 parts (", loader->GetNumberOfParts(),
      ")"));
}
}

int TestDeepGIDeprecatedNames(int argc, char* argv[])
{
  const std::string data = DeepGITestData::Folder(argc, argv, "TestDeepGIDeprecatedNames");
  if (!DeepGITestData::Require(
        data, { "scenes/cornell-original/CornellBox-Original.obj" }, "TestDeepGIDeprecatedNames"))
  {
    return EXIT_FAILURE;
  }
  TestDemoScene();
  TestSceneLoader(data);
  return DeepGITest::ExitStatus();
}
