// Minimal consumer of the installed or built library.
#include "vtkDeepGBufferPass.h"
#include "vtkNew.h"

#include <cstdio>

int main()
{
  vtkNew<vtkDeepGBufferPass> pass;
  pass->SetOracleToReproject();
  std::printf(
    "vtkDeepGBufferPass oracle %s\n", vtkDeepGBufferPass::GetOracleAsString(pass->GetOracle()));
  return 0;
}
