# `cmake --install BUILD --prefix PREFIX` (docs/install.md):
#   PREFIX/bin/lpvlab, PREFIX/bin/lpvlab-gpubench
#   PREFIX/share/lpvlab/{shaders, spirv, experiments, analysis, REVISION}   found relative to bin/lpvlab
#                                                                    (framework/core/install_layout.h)
#   PREFIX/include/lpvlab/{framework, variants, glad}/...            the headers
#   PREFIX/lib/lpvlab/*.a, PREFIX/lib/lpvlab/objects/                the libraries, the strategies
#   PREFIX/lib/cmake/lpvlab/lpvlabConfig.cmake                       find_package(lpvlab)
# Another CMake project then links lpvlab::cli (main() and the commands) and lpvlab::variants (the
# shipped strategies) with strategies of its own into its own lpvlab.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(LPVLAB_EXPORTED
    lpvlab_core lpvlab_math lpvlab_scene lpvlab_animation lpvlab_io lpvlab_metrics lpvlab_gl
    lpvlab_pipeline lpvlab_reference lpvlab_raster lpvlab_particles lpvlab_experiment lpvlab_fit lpvlab_explain lpvlab_tune
    lpvlab_many_lights lpvlab_radiosity lpvlab_gl_kernels lpvlab_variants lpvlab_glad lpvlab_gl_headers lpvlab_cli)
install(TARGETS lpvlab RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
# lpvlab-gpubench and its SPIR-V when they were built (the README's run command builds lpvlab alone).
install(TARGETS lpvlab-gpubench RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} OPTIONAL)
install(TARGETS ${LPVLAB_EXPORTED} EXPORT lpvlabTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}/lpvlab
        OBJECTS DESTINATION ${CMAKE_INSTALL_LIBDIR}/lpvlab/objects)
install(DIRECTORY "${CMAKE_SOURCE_DIR}/framework" "${CMAKE_SOURCE_DIR}/variants"
        DESTINATION include/lpvlab FILES_MATCHING PATTERN "*.h")
install(DIRECTORY "${LPVLAB_GLAD_DIR}/include/" DESTINATION include/lpvlab)
install(DIRECTORY "${CMAKE_SOURCE_DIR}/shaders" "${CMAKE_SOURCE_DIR}/experiments"
        DESTINATION share/lpvlab)
install(DIRECTORY "${CMAKE_BINARY_DIR}/spirv/" DESTINATION share/lpvlab/spirv OPTIONAL
        FILES_MATCHING PATTERN "*.spv")
install(FILES "${CMAKE_SOURCE_DIR}/analysis/report.py" "${CMAKE_SOURCE_DIR}/analysis/gpu_estimate.py"
              "${CMAKE_SOURCE_DIR}/analysis/pyproject.toml"
        DESTINATION share/lpvlab/analysis)
install(DIRECTORY "${CMAKE_SOURCE_DIR}/analysis/lpvlab_analysis" DESTINATION share/lpvlab/analysis
        PATTERN "__pycache__" EXCLUDE)
# The revision of the source tree at install time (lpvlabRevision reads it where the binary does
# not run from its source tree).
install(CODE "
  execute_process(COMMAND git -C \"${CMAKE_SOURCE_DIR}\" rev-parse HEAD
                  OUTPUT_VARIABLE head OUTPUT_STRIP_TRAILING_WHITESPACE RESULT_VARIABLE failed
                  ERROR_QUIET)
  execute_process(COMMAND git -C \"${CMAKE_SOURCE_DIR}\" status --porcelain
                  OUTPUT_VARIABLE changes ERROR_QUIET)
  if(failed)
    set(head unknown)
  elseif(NOT changes STREQUAL \"\")
    set(head \"\${head}-dirty\")
  endif()
  file(WRITE \"\$ENV{DESTDIR}\${CMAKE_INSTALL_PREFIX}/share/lpvlab/REVISION\" \"\${head}\\n\")
")
install(EXPORT lpvlabTargets NAMESPACE lpvlab:: DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/lpvlab)
set(LPVLAB_DATA_INSTALL_DIR share/lpvlab)
configure_package_config_file("${CMAKE_SOURCE_DIR}/cmake/lpvlabConfig.cmake.in"
                              "${CMAKE_BINARY_DIR}/lpvlabConfig.cmake"
                              INSTALL_DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/lpvlab
                              PATH_VARS LPVLAB_DATA_INSTALL_DIR)
write_basic_package_version_file("${CMAKE_BINARY_DIR}/lpvlabConfigVersion.cmake"
                                 COMPATIBILITY SameMinorVersion)
install(FILES "${CMAKE_BINARY_DIR}/lpvlabConfig.cmake" "${CMAKE_BINARY_DIR}/lpvlabConfigVersion.cmake"
        DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/lpvlab)
