# Every dependency comes from the system's packages (scripts/install-dependencies.sh installs them).
find_package(PkgConfig REQUIRED)

find_package(embree 4 QUIET CONFIG)
if(embree_FOUND)
  set(CANDELA_EMBREE_VERSION 4)
else()
  find_package(embree 3 REQUIRED CONFIG)
  set(CANDELA_EMBREE_VERSION 3)
endif()
find_package(TBB REQUIRED CONFIG)
find_package(glm REQUIRED CONFIG)
find_package(CLI11 REQUIRED CONFIG)
find_package(nlohmann_json REQUIRED CONFIG)
find_package(OpenEXR REQUIRED CONFIG)
find_package(ZLIB REQUIRED)
# Texture decoding: PNG through libpng, JPEG through libjpeg-turbo, WebP (glTF's EXT_texture_webp) through libwebp
# (stb_image keeps TGA, BMP and Radiance HDR).
find_package(PNG REQUIRED)
find_package(JPEG REQUIRED)
pkg_check_modules(STB REQUIRED IMPORTED_TARGET stb)
pkg_check_modules(WEBP REQUIRED IMPORTED_TARGET libwebp)
pkg_check_modules(XXHASH REQUIRED IMPORTED_TARGET libxxhash)
# Single-header libraries: candela compiles their implementations itself (src/scene/loaders/*_impl.cpp).
find_path(TINYOBJLOADER_INCLUDE_DIR tiny_obj_loader.h REQUIRED)
find_path(TINYGLTF_INCLUDE_DIR tiny_gltf.h REQUIRED)

# glTF's KHR_draco_mesh_compression through Google's Draco library (libdraco-dev). Without it candela still builds;
# a glTF file that requires the extension is then refused with a line naming it. CANDELA_DRACO_ENABLED says whether.
find_package(draco QUIET CONFIG)
if(TARGET draco::draco)
  set(CANDELA_DRACO_ENABLED ON)
  message(STATUS "draco: on (Draco ${draco_VERSION}): glTF files compressed with KHR_draco_mesh_compression load")
else()
  set(CANDELA_DRACO_ENABLED OFF)
  message(STATUS "draco: off (needs libdraco-dev): glTF files that require KHR_draco_mesh_compression are refused")
endif()

# glTF's EXT_meshopt_compression through meshoptimizer's decoder (libmeshoptimizer-dev); optional as Draco is.
find_package(meshoptimizer QUIET CONFIG)
if(TARGET meshoptimizer::meshoptimizer)
  set(CANDELA_MESHOPT_ENABLED ON)
  message(STATUS "meshopt: on (meshoptimizer ${meshoptimizer_VERSION}): glTF files compressed with "
                 "EXT_meshopt_compression load")
else()
  set(CANDELA_MESHOPT_ENABLED OFF)
  message(STATUS "meshopt: off (needs libmeshoptimizer-dev): glTF files that require EXT_meshopt_compression are "
                 "refused")
endif()

# candela serve, the viewer in a web browser: Boost.Beast (headers only) for HTTP and WebSocket, libjpeg-turbo for
# the JPEG frames, x264 for the H.264 video stream. It is built when all are found; CANDELA_SERVE_ENABLED says
# whether.
set(CANDELA_SERVE_ENABLED OFF)
find_package(Boost 1.74 QUIET)
pkg_check_modules(TURBOJPEG QUIET IMPORTED_TARGET libturbojpeg)
pkg_check_modules(X264 QUIET IMPORTED_TARGET x264)
find_package(Threads)
if(Boost_FOUND AND TURBOJPEG_FOUND AND X264_FOUND AND Threads_FOUND)
  set(CANDELA_SERVE_ENABLED ON)
  message(STATUS "serve: on (Boost ${Boost_VERSION}, libjpeg-turbo ${TURBOJPEG_VERSION}, x264 ${X264_VERSION})")
else()
  message(STATUS "serve: off (needs Boost.Beast, libjpeg-turbo and x264: libboost-dev libturbojpeg0-dev "
                 "libx264-dev)")
endif()

# Distributed rendering (`mpirun candela render`): built when MPI (Open MPI: libopenmpi-dev) is found;
# CANDELA_MPI_ENABLED says whether.
find_package(MPI QUIET COMPONENTS CXX)
if(MPI_CXX_FOUND)
  set(CANDELA_MPI_ENABLED ON)
  message(STATUS "mpi: on (MPI ${MPI_CXX_VERSION})")
else()
  set(CANDELA_MPI_ENABLED OFF)
  message(STATUS "mpi: off (needs an MPI implementation: libopenmpi-dev openmpi-bin)")
endif()

if(CANDELA_BUILD_TESTS)
  find_package(GTest REQUIRED CONFIG)
endif()

# nvcc, when present, compiles the kernel headers for the device on every build.
include(CheckLanguage)
check_language(CUDA)
if(CMAKE_CUDA_COMPILER)
  if(NOT DEFINED CMAKE_CUDA_ARCHITECTURES)
    set(CMAKE_CUDA_ARCHITECTURES 90)
  endif()
  enable_language(CUDA)
  set(CMAKE_CUDA_STANDARD 17)
  set(CMAKE_CUDA_STANDARD_REQUIRED ON)
  message(STATUS "nvcc found: the kernel headers are compiled for sm_${CMAKE_CUDA_ARCHITECTURES} too")
else()
  message(STATUS "nvcc not found: the kernel headers are compiled for the host only")
endif()
