# The names of the captures' arrays are spelled as string literals in one
# header only, Core/vtkDeepGICaptureNames.h; every other C++ file uses its
# constants (vtkDeepGICaptureNames::Depth, Layer(Depth, 0), ...).
#   cmake -DSOURCE=<repository root> -P CheckCaptureNames.cmake
# The names are the header's `constexpr const char* Name = "value";` lines.
# A C++ line fails when it holds a quoted string that is a name, or a name
# followed by "_" and digits or nothing ("Depth_0", "Depth_"): a per-layer
# name built by hand. Comment lines (starting with //, /* or *) are not code
# and are not checked; a literal that happens to spell a name for another
# purpose is written differently (e.g. through the object it names).
cmake_minimum_required(VERSION 3.16)
set(header "${SOURCE}/Core/vtkDeepGICaptureNames.h")
file(STRINGS "${header}" definitions
  REGEX "^constexpr const char\\* [A-Za-z]+ = \"[A-Za-z]+\";")
set(names)
foreach (definition IN LISTS definitions)
  string(REGEX REPLACE "^.* = \"([A-Za-z]+)\";.*$" "\\1" name "${definition}")
  list(APPEND names "${name}")
endforeach ()
list(LENGTH names count)
if (count LESS 10)
  message(FATAL_ERROR "only ${count} capture names read from ${header}")
endif ()
list(JOIN names "|" alternatives)
set(literal "\"(${alternatives})(_[0-9]*)?\"")

set(files)
foreach (folder IN ITEMS Core Scenes IO Reference Rendering Apps Examples Testing ParaView)
  file(GLOB_RECURSE found "${SOURCE}/${folder}/*.h" "${SOURCE}/${folder}/*.cxx")
  list(APPEND files ${found})
endforeach ()
list(REMOVE_ITEM files "${header}")
list(LENGTH files file_count)
if (file_count EQUAL 0)
  message(FATAL_ERROR "no C++ files found under ${SOURCE}")
endif ()

set(failures)
foreach (file IN LISTS files)
  file(STRINGS "${file}" lines REGEX "${literal}")
  if (NOT lines)
    continue ()
  endif ()
  # file(STRINGS) gives no line numbers: read the file once more and split
  # it at newlines, with the characters that a CMake list treats specially
  # (; [ ]) replaced first.
  file(READ "${file}" text)
  string(REPLACE ";" "<semicolon>" text "${text}")
  string(REPLACE "[" "<open>" text "${text}")
  string(REPLACE "]" "<close>" text "${text}")
  string(REPLACE "\n" ";" text "${text}")
  set(number 0)
  foreach (line IN LISTS text)
    math(EXPR number "${number} + 1")
    if (line MATCHES "^[ \t]*(//|/\\*|\\*)")
      continue ()
    endif ()
    if (line MATCHES "${literal}")
      file(RELATIVE_PATH relative "${SOURCE}" "${file}")
      string(STRIP "${line}" line)
      string(REPLACE "<open>" "[" line "${line}")
      string(REPLACE "<close>" "]" line "${line}")
      list(APPEND failures "${relative}:${number}: ${line}")
    endif ()
  endforeach ()
endforeach ()
if (failures)
  list(LENGTH failures failure_count)
  string(REPLACE ";" "\n" failures "${failures}")
  string(REPLACE "<semicolon>" ";" failures "${failures}")
  message(FATAL_ERROR "${failure_count} capture names written as literals outside "
    "Core/vtkDeepGICaptureNames.h (use its constants):\n${failures}")
endif ()
message(STATUS "${file_count} C++ files: the ${count} capture names are literals in "
  "Core/vtkDeepGICaptureNames.h only")
