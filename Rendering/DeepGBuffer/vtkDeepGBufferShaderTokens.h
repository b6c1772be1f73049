/**
 * The VTK 9.1 shader text vtkDeepGBufferPass relies on, in one place: the
 * hooks (//VTK:: tags) it substitutes in vtkOpenGLPolyDataMapper's shader
 * templates, and the declarations by which it recognises what a mapper's
 * final shader contains, with the variables it then reads. Another VTK may
 * rename any of them: TestDeepGBufferShaderTokens checks the hooks against
 * the templates in VTK's library, and the probes are exercised by
 * TestDeepGBufferColoring (textures), TestDeepReflectionRobustness (PBR,
 * unlit props, specular colour) and TestDeepGuardBand (point Gaussian
 * splats). Not part of the public API (a private header of the module).
 */
#ifndef vtkDeepGBufferShaderTokens_h
#define vtkDeepGBufferShaderTokens_h

namespace vtkDeepGBufferShaderTokens
{
// Hooks of vtkPolyDataVS.glsl.
constexpr const char* CameraDeclarations = "//VTK::Camera::Dec";
constexpr const char* PositionImplementation = "//VTK::PositionVC::Impl";
// Hooks of vtkPolyDataFS.glsl.
constexpr const char* DepthPeelingDeclarations = "//VTK::DepthPeeling::Dec";
constexpr const char* DepthPeelingPreColor = "//VTK::DepthPeeling::PreColor";
constexpr const char* TextureCoordinates = "//VTK::TCoord::Impl";
constexpr const char* UniformFlow = "//VTK::UniformFlow::Impl";

constexpr const char* VertexHooks[] = { CameraDeclarations, PositionImplementation };
constexpr const char* FragmentHooks[] = { DepthPeelingDeclarations, DepthPeelingPreColor,
  TextureCoordinates, UniformFlow };

// A mapper's own geometry shader that projects view-space positions itself
// (vtkPointGaussianMapper's splats): its projection matrix, its entry point
// and the call after which each vertex is final.
constexpr const char* GeometryProjects = "VCDCMatrix";
constexpr const char* GeometryMain = "void main()";
constexpr const char* GeometryEmitVertex = "EmitVertex();";

// Probes of the final fragment shader and the variables they make readable.
constexpr const char* PBRAlbedoDeclaration =
  "vec3 albedo";                                           // PBR: "albedo", "metallic", "roughness"
constexpr const char* PBRFresnelDeclaration = "vec3 F0 ="; // PBR where lit: "F0"
constexpr const char* TextureColorDeclaration = "vec4 tcolor ";           // a texture: "tcolor"
constexpr const char* ShadingNormalDeclaration = "vec3 normalVCVSOutput"; // lit props
constexpr const char* SpecularColorDeclaration = "vec3 specularColor =";  // Phong/Gouraud
}

#endif
