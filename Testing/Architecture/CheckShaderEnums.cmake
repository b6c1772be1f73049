# No shader compares an enum-valued uniform or define with a bare number:
# the values come from vtkDeepGIShaderConstants.h (DEEP_* names), shared by
# C++ and GLSL.
#   cmake -DSHADERS=<glsl folder> -P CheckShaderEnums.cmake
file(GLOB shaders "${SHADERS}/*.glsl")
set(found)
foreach (shader IN LISTS shaders)
  file(STRINGS "${shader}" lines REGEX
    "(deep(TestMode|Estimator|Quantity|Mode)|DEEP_ENVIRONMENT)[ ]*[!=]=[ ]*[0-9]")
  foreach (line IN LISTS lines)
    list(APPEND found "${shader}: ${line}")
  endforeach ()
endforeach ()
list(LENGTH shaders count)
if (count EQUAL 0)
  message(FATAL_ERROR "no shaders found in ${SHADERS}")
endif ()
if (found)
  string(REPLACE ";" "\n" found "${found}")
  message(FATAL_ERROR "enum values written as numbers in GLSL:\n${found}")
endif ()
message(STATUS "${count} shaders: every enum comparison uses a DEEP_* name")
