// vtkDeepGIShaderConstants.h: the values the shaders branch on, in one file
// that is both a C++ header and a GLSL include (it holds only preprocessor
// lines and comments). The passes' enums take their values from it, and the
// build embeds it into every shader with the shared deep G-buffer code,
// so C++ and GLSL cannot disagree on what a number means.
#ifndef vtkDeepGIShaderConstants_h
#define vtkDeepGIShaderConstants_h

// vtkDeepGBufferPass::Quantity: the G-buffer's quantities, in the order of
// its render targets.
#define DEEP_QUANTITY_RADIANCE 0
#define DEEP_QUANTITY_ALBEDO 1
#define DEEP_QUANTITY_NORMAL 2
#define DEEP_QUANTITY_DEPTH 3
#define DEEP_QUANTITY_AMBIENT 4
#define DEEP_QUANTITY_REFLECTIVITY 5
#define DEEP_NUMBER_OF_QUANTITIES 6

// vtkDeepGBufferPass: the minimum-separation test of a layer beyond the
// first (none; against the layer before at the same pixel; at the
// fragment's position in the other frame, for REPROJECT).
#define DEEP_TEST_NONE 0
#define DEEP_TEST_SAME_PIXEL 1
#define DEEP_TEST_REPROJECTED 2

// vtkDeepRadiosityPass::Estimator: how the gathered taps become E (eq. 4).
#define DEEP_ESTIMATOR_ACCEPTED_TAPS 0
#define DEEP_ESTIMATOR_ALL_TAPS 1
#define DEEP_ESTIMATOR_SOLID_ANGLE 2

// vtkDeepAmbientObscurancePass::Estimator: how the taps become AV (the
// paper's eq. 1 contrast curve, or each tap weighted by its solid angle).
#define DEEP_AO_ESTIMATOR_EQUATION_1 0
#define DEEP_AO_ESTIMATOR_SOLID_ANGLE 1
#define DEEP_AO_ESTIMATOR_VISIBILITY_BITMASK 2

// vtkDeepAmbientObscurancePass::Composition: what the visibility darkens.
#define DEEP_COMPOSITE_MULTIPLY 0
#define DEEP_COMPOSITE_AMBIENT 1
#define DEEP_COMPOSITE_AUTOMATIC 2

// vtkDeepReflectionPass: the environment a ray that leaves the layers reads.
#define DEEP_ENVIRONMENT_BACKGROUND 0
#define DEEP_ENVIRONMENT_EQUIRECTANGULAR 1
#define DEEP_ENVIRONMENT_CUBE_MAP 2

#endif
