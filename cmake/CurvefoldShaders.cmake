# Compiles GLSL to SPIR-V at build time and embeds it: each shader becomes a header
# <build>/shaders/<name>.h holding `const uint32_t <symbol>[]`, so the binary never loads a shader
# from a path. The symbol is the file name with '.' replaced by '_' plus "_spv"
# (sheet.frag -> sheet_frag_spv).
#
#   curvefold_add_shaders(TARGET curvefold_render SOURCES shaders/sheet.vert shaders/sheet.frag
#                         INCLUDES shaders/common.glsl)
#
# INCLUDES are files the shaders #include (GL_GOOGLE_include_directive): a change rebuilds them.
# MULTIVIEW also compiles each with CURVEFOLD_MULTIVIEW defined, for a multiview pass, into
# <name>.multiview.h (symbol <name>_multiview_spv).
find_program(GLSLANG_VALIDATOR glslangValidator REQUIRED)

function(curvefold_add_shaders)
  cmake_parse_arguments(ARG "MULTIVIEW" "TARGET" "SOURCES;INCLUDES" ${ARGN})
  set(out_dir ${PROJECT_BINARY_DIR}/shaders)
  file(MAKE_DIRECTORY ${out_dir})
  set(headers)
  set(includes)
  foreach(include ${ARG_INCLUDES})
    get_filename_component(include_abs ${include} ABSOLUTE BASE_DIR ${PROJECT_SOURCE_DIR})
    list(APPEND includes ${include_abs})
  endforeach()
  foreach(source ${ARG_SOURCES})
    get_filename_component(source_abs ${source} ABSOLUTE BASE_DIR ${PROJECT_SOURCE_DIR})
    get_filename_component(name ${source} NAME)
    string(REPLACE "." "_" symbol "${name}_spv")
    set(header ${out_dir}/${name}.h)
    add_custom_command(
      OUTPUT ${header}
      COMMAND ${GLSLANG_VALIDATOR} -V --quiet --target-env vulkan1.1 --vn ${symbol} -o ${header}
              ${source_abs}
      DEPENDS ${source_abs} ${includes}
      COMMENT "glslangValidator ${name}"
      VERBATIM)
    list(APPEND headers ${header})
    if(ARG_MULTIVIEW)
      string(REPLACE "." "_" multiview_symbol "${name}_multiview_spv")
      set(multiview_header ${out_dir}/${name}.multiview.h)
      add_custom_command(
        OUTPUT ${multiview_header}
        COMMAND ${GLSLANG_VALIDATOR} -V --quiet --target-env vulkan1.1 -DCURVEFOLD_MULTIVIEW
                --vn ${multiview_symbol} -o ${multiview_header} ${source_abs}
        DEPENDS ${source_abs} ${includes}
        COMMENT "glslangValidator ${name} (multiview)"
        VERBATIM)
      list(APPEND headers ${multiview_header})
    endif()
  endforeach()
  target_sources(${ARG_TARGET} PRIVATE ${headers})
  # Included as "shaders/sheet.frag.h".
  target_include_directories(${ARG_TARGET} PRIVATE ${PROJECT_BINARY_DIR})
endfunction()
