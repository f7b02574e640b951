# The OptiX GPU backend is built only when both the OptiX SDK headers and the CUDA toolkit are found.
# The SDK is located through OptiX_INSTALL_DIR, as a CMake variable or an environment variable; it holds
# include/optix.h. Sets CANDELA_HAS_OPTIX, OptiX_INCLUDE_DIR and CANDELA_OPTIX_VERSION.

set(OptiX_INSTALL_DIR "$ENV{OptiX_INSTALL_DIR}" CACHE PATH "NVIDIA OptiX SDK root (the folder holding include/optix.h)")
set(CANDELA_HAS_OPTIX OFF)

set(_candela_optix_how "to build the OptiX GPU backend, install the CUDA toolkit and the NVIDIA OptiX SDK 7.7 to 9.x, \
then configure with -DOptiX_INSTALL_DIR=/path/to/NVIDIA-OptiX-SDK (or export OptiX_INSTALL_DIR)")

if(OptiX_INSTALL_DIR)
  find_path(OptiX_INCLUDE_DIR optix.h PATHS "${OptiX_INSTALL_DIR}/include" NO_DEFAULT_PATH)
endif()
find_package(CUDAToolkit QUIET)

if(NOT OptiX_INSTALL_DIR)
  message(STATUS "OptiX backend: off, OptiX_INSTALL_DIR is not set; ${_candela_optix_how}")
elseif(NOT OptiX_INCLUDE_DIR)
  message(STATUS
    "OptiX backend: off, no include/optix.h under OptiX_INSTALL_DIR='${OptiX_INSTALL_DIR}'; ${_candela_optix_how}")
elseif(NOT CUDAToolkit_FOUND OR NOT CMAKE_CUDA_COMPILER)
  message(STATUS "OptiX backend: off, the CUDA toolkit (nvcc) was not found; ${_candela_optix_how}")
else()
  file(STRINGS "${OptiX_INCLUDE_DIR}/optix.h" _candela_optix_version_line REGEX "^#define OPTIX_VERSION [0-9]+")
  string(REGEX REPLACE "^#define OPTIX_VERSION ([0-9]+).*" "\\1"
         CANDELA_OPTIX_VERSION "${_candela_optix_version_line}")
  if(CANDELA_OPTIX_VERSION LESS 70700)
    message(STATUS
      "OptiX backend: off, OptiX ${CANDELA_OPTIX_VERSION} in ${OptiX_INCLUDE_DIR} is older than 7.7; ${_candela_optix_how}")
  else()
    set(CANDELA_HAS_OPTIX ON)
    math(EXPR _major "${CANDELA_OPTIX_VERSION} / 10000")
    math(EXPR _minor "(${CANDELA_OPTIX_VERSION} % 10000) / 100")
    message(STATUS "OptiX backend: on (OptiX ${_major}.${_minor} headers in ${OptiX_INCLUDE_DIR}, CUDA ${CUDAToolkit_VERSION})")
  endif()
endif()
