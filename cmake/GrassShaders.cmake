# The shaders live once in api/shaders. The GL backend embeds their source (compiled by
# the driver at run time); the Vulkan backend embeds SPIR-V compiled at build time by glslc.

set(GRASS_SHADER_DIR "${PROJECT_SOURCE_DIR}/api/shaders")
file(GLOB GRASS_SHADER_INCLUDES CONFIGURE_DEPENDS "${GRASS_SHADER_DIR}/*.glsl")

# Both functions read shaders from GRASS_SHADER_DIR, or from SHADER_DIR when the caller sets
# it (the test hosts keep their own shaders); an #include is looked up in SHADER_DIR, then in
# GRASS_SHADER_DIR (a test's shader may include grass's).

# grass_embed_glsl(<out_cpp> <namespace> <shader>...): shader source strings for GL.
function(grass_embed_glsl out_cpp namespace)
  if(NOT SHADER_DIR)
    set(SHADER_DIR "${GRASS_SHADER_DIR}")
  endif()
  set(inputs "")
  foreach(s IN LISTS ARGN)
    list(APPEND inputs "${SHADER_DIR}/${s}")
  endforeach()
  string(REPLACE ";" "\\;" inputs_arg "${inputs}")
  add_custom_command(
    OUTPUT "${out_cpp}"
    COMMAND ${CMAKE_COMMAND} "-DINPUTS=${inputs_arg}" "-DINCLUDE_DIR=${SHADER_DIR}" "-DSHARED_INCLUDE_DIR=${GRASS_SHADER_DIR}"
            "-DOUTPUT=${out_cpp}" "-DNAMESPACE=${namespace}" -P "${PROJECT_SOURCE_DIR}/cmake/EmbedGlsl.cmake"
    DEPENDS ${inputs} ${GRASS_SHADER_INCLUDES} "${PROJECT_SOURCE_DIR}/cmake/EmbedGlsl.cmake"
    COMMENT "Embedding GLSL for the GL backend"
    VERBATIM)
endfunction()

# grass_compile_spirv(<out_cpp_list_var> <namespace> <shader>...): SPIR-V word arrays.
# With SPIRV_DEFINE set by the caller (macro names, a list), the shaders are compiled with
# them defined and their arrays are named <shader>_<lower-case macro>... in the list's order
# (blade_vert_grass_responsive, blade_vert_grass_responsive_grass_indexed_blocks).
function(grass_compile_spirv out_var namespace)
  if(NOT SHADER_DIR)
    set(SHADER_DIR "${GRASS_SHADER_DIR}")
  endif()
  find_program(GRASS_GLSLC glslc REQUIRED)
  set(define_args "")
  set(suffix "")
  foreach(d IN LISTS SPIRV_DEFINE)
    list(APPEND define_args "-D${d}")
    string(TOLOWER "_${d}" lower)
    string(APPEND suffix "${lower}")
  endforeach()
  set(outputs "")
  foreach(s IN LISTS ARGN)
    string(REPLACE "." "_" name "${s}")
    set(name "${name}${suffix}")
    set(inc "${CMAKE_CURRENT_BINARY_DIR}/spirv/${name}.inc")
    set(cpp "${CMAKE_CURRENT_BINARY_DIR}/spirv/${name}.cpp")
    add_custom_command(
      OUTPUT "${cpp}"
      COMMAND ${CMAKE_COMMAND} -E make_directory "${CMAKE_CURRENT_BINARY_DIR}/spirv"
      # No -O: spirv-opt's performance recipe made lavapipe's code for the volume tier about
      # 25% slower (docs/records/tier-cost.md); drivers optimise the module themselves.
      COMMAND ${GRASS_GLSLC} --target-env=vulkan1.1 -Werror -mfmt=c -I "${SHADER_DIR}" -I "${GRASS_SHADER_DIR}" ${define_args}
              -o "${inc}" "${SHADER_DIR}/${s}"
      COMMAND ${CMAKE_COMMAND} "-DINPUT=${inc}" "-DNAME=${name}" "-DOUTPUT=${cpp}" "-DNAMESPACE=${namespace}"
              -P "${PROJECT_SOURCE_DIR}/cmake/EmbedSpirv.cmake"
      DEPENDS "${SHADER_DIR}/${s}" ${GRASS_SHADER_INCLUDES} "${PROJECT_SOURCE_DIR}/cmake/EmbedSpirv.cmake"
      COMMENT "Compiling ${s} to SPIR-V"
      VERBATIM)
    list(APPEND outputs "${cpp}")
  endforeach()
  set(${out_var} "${outputs}" PARENT_SCOPE)
endfunction()
