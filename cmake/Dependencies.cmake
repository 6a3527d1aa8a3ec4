# Every dependency comes from a Debian 12 package (scripts/install-deps.sh installs them).
find_package(Threads REQUIRED)            # glslang's CMake config needs Threads::Threads
find_package(PkgConfig REQUIRED)
find_package(glm REQUIRED)                # vectors and matrices, GLSL-compatible
find_package(glslang CONFIG REQUIRED)     # GLSL -> SPIR-V at run time
find_package(assimp CONFIG REQUIRED)      # glTF and OBJ/MTL scene loading
find_package(tomlplusplus REQUIRED)       # experiment files
find_package(nlohmann_json REQUIRED)      # run manifests
find_package(CLI11 REQUIRED)              # command line
find_package(spdlog REQUIRED)             # messages on stderr by level (-q, -v)
find_package(GTest REQUIRED)              # tests
find_package(embree 3 CONFIG REQUIRED)    # ray queries of the reference path tracer
find_package(Ceres 2.1 REQUIRED)          # `lpvlab fit`: nonlinear least squares, covariance
find_package(TBB REQUIRED)                # threads of the CPU kernels
find_package(benchmark REQUIRED)          # CPU kernel benchmarks (tests/benchmarks)
# CGAL 5.5 (header-only): incremental instant radiosity's Delaunay triangulation of its VPLs.
# Its CMake config sets the build type when none is given; lpvlab's default stays RelWithDebInfo.
set(CGAL_DO_NOT_WARN_ABOUT_CMAKE_BUILD_TYPE TRUE)
find_package(CGAL 5.5 CONFIG REQUIRED)
# OpenImageIO 2.4's CMake config names /usr/include/opencv4; its pkg-config module works.
pkg_check_modules(OIIO REQUIRED IMPORTED_TARGET OpenImageIO)
# The GL context backends' headers only: libOSMesa (offscreen GL 4.5 core on llvmpipe) and libEGL
# are opened at run time (framework/gl/shared_library.h), so that lpvlab runs where either is
# missing (a GPU machine without Mesa, Mesa 25.1 without OSMesa) and bundles stay small.
pkg_check_modules(OSMESA REQUIRED osmesa)
add_library(lpvlab_gl_headers INTERFACE)
set_target_properties(lpvlab_gl_headers PROPERTIES EXPORT_NAME gl_headers)
target_include_directories(lpvlab_gl_headers INTERFACE ${OSMESA_INCLUDE_DIRS})
target_link_libraries(lpvlab_gl_headers INTERFACE ${CMAKE_DL_LIBS})

set(LPVLAB_HAVE_EGL_HEADERS FALSE)
if(LPVLAB_WITH_EGL)
  pkg_check_modules(EGL QUIET egl)
  if(EGL_FOUND)
    set(LPVLAB_HAVE_EGL_HEADERS TRUE)
    target_include_directories(lpvlab_gl_headers INTERFACE ${EGL_INCLUDE_DIRS})
  endif()
endif()
