// Runs TestDeepGBufferShaderTokens (Rendering/DeepGBuffer/Testing/Cxx), the
// VTK 9.1 build's test of the VTK shader text the G-buffer relies on,
// against the VTK this program is linked with (ParaView's).
int TestDeepGBufferShaderTokens(int argc, char* argv[]);

int main(int argc, char* argv[])
{
  return TestDeepGBufferShaderTokens(argc, argv);
}
