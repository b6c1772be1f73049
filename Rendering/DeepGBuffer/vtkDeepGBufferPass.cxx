#include "vtkDeepGBufferPass.h"
#include "vtkObjectFactory.h"
vtkStandardNewMacro(vtkDeepGBufferPass);
class vtkDeepGBufferPass::vtkInternals {};
vtkDeepGBufferPass::vtkDeepGBufferPass() : Internals(new vtkInternals) {}
vtkDeepGBufferPass::~vtkDeepGBufferPass() = default;
void vtkDeepGBufferPass::PrintSelf(ostream& os, vtkIndent indent) { this->Superclass::PrintSelf(os, indent); }
const char* vtkDeepGBufferPass::GetOracleAsString(int) { return "REPROJECT"; }
int vtkDeepGBufferPass::GetOracleFromString(const char*) { return 2; }
void vtkDeepGBufferPass::SetNumberOfLayers(int l) { this->NumberOfLayers = l; }
void vtkDeepGBufferPass::SetMinimumSeparation(double d) { this->MinimumSeparation = d; }
const char* vtkDeepGBufferPass::GetQuantityAsString(int) { return ""; }
bool vtkDeepGBufferPass::CaptureLayers(vtkImageData*, vtkRenderer*) { return false; }
int vtkDeepGBufferPass::ActivateTexture(vtkRenderer*, int) { return -1; }
void vtkDeepGBufferPass::DeactivateTexture(vtkRenderer*, int) {}
unsigned int vtkDeepGBufferPass::GetTextureHandle(vtkRenderer*, int) { return 0; }
bool vtkDeepGBufferPass::RenderLayers(const vtkRenderState*) { return false; }
void vtkDeepGBufferPass::ResolveToFramebuffer(const vtkRenderState*) {}
void vtkDeepGBufferPass::Render(const vtkRenderState*) {}
void vtkDeepGBufferPass::ReleaseGraphicsResources(vtkWindow*) {}
void vtkDeepGBufferPass::SetTranslucentPass(vtkRenderPass*) {}
void vtkDeepGBufferPass::SetVolumetricPass(vtkRenderPass*) {}
void vtkDeepGBufferPass::SetOverlayPass(vtkRenderPass*) {}
void vtkDeepGBufferPass::EncodeOct16(const double[3], unsigned char[2]) {}
void vtkDeepGBufferPass::DecodeOct16(const unsigned char[2], double[3]) {}
bool vtkDeepGBufferPass::PreReplaceShaderValues(std::string&, std::string&, std::string&, vtkAbstractMapper*, vtkProp*) { return true; }
bool vtkDeepGBufferPass::PostReplaceShaderValues(std::string&, std::string&, std::string&, vtkAbstractMapper*, vtkProp*) { return true; }
bool vtkDeepGBufferPass::SetShaderParameters(vtkShaderProgram*, vtkAbstractMapper*, vtkProp*, vtkOpenGLVertexArrayObject*) { return true; }
vtkMTimeType vtkDeepGBufferPass::GetShaderStageMTime() { return 0; }
