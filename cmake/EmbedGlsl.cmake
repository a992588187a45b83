# Script mode: cmake -DINPUTS="a.vert;b.frag" -DINCLUDE_DIR=dir [-DSHARED_INCLUDE_DIR=dir] -DOUTPUT=out.cpp
#   -DNAMESPACE=ns -P EmbedGlsl.cmake
# An #include is looked up in INCLUDE_DIR, then in SHARED_INCLUDE_DIR.
# Writes each shader as a C++ string with its #include lines inlined (the GL driver has
# no include support), as `extern const char* const ns::<name>` (blade.vert -> blade_vert).
#
# Sources are handled as whole strings, never as CMake lists: GLSL is full of ';' and an
# unbalanced ']' in a comment would stop a list from splitting.

# The caller escapes the list separators so the list survives the command line.
string(REPLACE "\\;" ";" INPUTS "${INPUTS}")

function(inline_includes path out_var depth)
  if(depth GREATER 8)
    message(FATAL_ERROR "EmbedGlsl: includes nested too deep in ${path}")
  endif()
  file(READ "${path}" text)
  string(REGEX MATCHALL "#[ \t]*include[ \t]+\"[^\"]+\"" directives "${text}")
  foreach(directive IN LISTS directives)
    string(REGEX REPLACE "#[ \t]*include[ \t]+\"([^\"]+)\"" "\\1" name "${directive}")
    math(EXPR next "${depth} + 1")
    set(found "${INCLUDE_DIR}/${name}")
    if(NOT EXISTS "${found}" AND SHARED_INCLUDE_DIR)
      set(found "${SHARED_INCLUDE_DIR}/${name}") # a test's shader includes grass's (api/shaders)
    endif()
    inline_includes("${found}" included ${next})
    string(REPLACE "${directive}" "${included}" text "${text}")
  endforeach()
  set(${out_var} "${text}" PARENT_SCOPE)
endfunction()

set(body "// Generated from api/shaders by cmake/EmbedGlsl.cmake. Do not edit.\nnamespace ${NAMESPACE} {\n")
foreach(input IN LISTS INPUTS)
  get_filename_component(name "${input}" NAME)
  string(REPLACE "." "_" name "${name}")
  inline_includes("${input}" source 0)
  # As bytes, not a string literal: C++ compilers need only accept literals up to 65536
  # characters (clang warns past it, MSVC stops at 16380 a piece), and volume.frag with its
  # includes is longer.
  file(WRITE "${OUTPUT}.${name}.glsl" "${source}")
  file(READ "${OUTPUT}.${name}.glsl" hex HEX)
  file(REMOVE "${OUTPUT}.${name}.glsl")
  string(REGEX REPLACE "([0-9a-f][0-9a-f])" "0x\\1," bytes "${hex}")
  string(APPEND body "extern const char* const ${name};\nstatic const unsigned char ${name}_bytes[] = {\n${bytes}0x00};\n"
                     "const char* const ${name} = reinterpret_cast<const char*>(${name}_bytes);\n")
endforeach()
string(APPEND body "} // namespace ${NAMESPACE}\n")
file(WRITE "${OUTPUT}.tmp" "${body}")
execute_process(COMMAND ${CMAKE_COMMAND} -E copy_if_different "${OUTPUT}.tmp" "${OUTPUT}")
