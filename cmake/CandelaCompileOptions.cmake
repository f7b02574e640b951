add_library(candela_warnings INTERFACE)
target_compile_options(candela_warnings INTERFACE
  $<$<COMPILE_LANGUAGE:CXX>:-Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wno-sign-conversion>
  $<$<AND:$<COMPILE_LANGUAGE:CXX>,$<BOOL:${CANDELA_WERROR}>>:-Werror>)

if(CANDELA_SANITIZE)
  add_compile_options($<$<COMPILE_LANGUAGE:CXX>:-fsanitize=address,undefined>
                      $<$<COMPILE_LANGUAGE:CXX>:-fno-omit-frame-pointer>
                      $<$<COMPILE_LANGUAGE:CXX>:-fno-sanitize-recover=undefined>)
  add_link_options(-fsanitize=address,undefined)
endif()

# ThreadSanitizer cannot share a build with AddressSanitizer (scripts/test-thread-sanitized.sh builds its own).
# TBB's library is not instrumented: what runs through tbb::parallel_for must run on one thread in such a build,
# or TSan reports the hand-over between TBB's threads as races.
option(CANDELA_SANITIZE_THREAD "Build with ThreadSanitizer (not with CANDELA_SANITIZE or CANDELA_FUZZERS)" OFF)
if(CANDELA_SANITIZE_THREAD)
  if(CANDELA_SANITIZE OR CANDELA_FUZZERS)
    message(FATAL_ERROR "CANDELA_SANITIZE_THREAD cannot be combined with CANDELA_SANITIZE or CANDELA_FUZZERS "
                        "(ThreadSanitizer and AddressSanitizer exclude each other): configure a build of its own")
  endif()
  add_compile_options($<$<COMPILE_LANGUAGE:CXX>:-fsanitize=thread> $<$<COMPILE_LANGUAGE:CXX>:-fno-omit-frame-pointer>)
  add_link_options(-fsanitize=thread)
  # GCC warns at every Boost.Asio source that TSan does not model its atomic_thread_fence; Asio hands work between
  # threads through its scheduler's mutex, which TSan does see.
  add_compile_options($<$<AND:$<COMPILE_LANGUAGE:CXX>,$<CXX_COMPILER_ID:GNU>>:-Wno-tsan>)

  # The dynamic loader runs a target_clones function's resolver while it relocates the program, before the TSan
  # runtime has started, and an instrumented resolver crashes there (GCC 12 and clang 14 alike). So the files that
  # use target_clones (the image filters' inner loops, which run on TBB) are compiled without TSan; this runs once
  # every target of src/ is defined.
  function(candela_compile_target_clones_without_tsan directory)
    get_property(targets DIRECTORY ${directory} PROPERTY BUILDSYSTEM_TARGETS)
    foreach(target IN LISTS targets)
      get_target_property(sources ${target} SOURCES)
      foreach(source IN LISTS sources)
        cmake_path(ABSOLUTE_PATH source BASE_DIRECTORY ${directory} OUTPUT_VARIABLE path)
        if(source MATCHES "\\.cpp$" AND EXISTS ${path})
          file(STRINGS ${path} clones REGEX "target_clones" LIMIT_COUNT 1)
          if(clones)
            set_property(SOURCE ${path} DIRECTORY ${directory} APPEND PROPERTY COMPILE_OPTIONS -fno-sanitize=thread)
          endif()
        endif()
      endforeach()
    endforeach()
    get_property(subdirectories DIRECTORY ${directory} PROPERTY SUBDIRECTORIES)
    foreach(subdirectory IN LISTS subdirectories)
      candela_compile_target_clones_without_tsan(${subdirectory})
    endforeach()
  endfunction()
  cmake_language(DEFER DIRECTORY ${PROJECT_SOURCE_DIR} CALL candela_compile_target_clones_without_tsan
                 ${PROJECT_SOURCE_DIR}/src)
endif()

if(CANDELA_FUZZERS)
  if(NOT CMAKE_CXX_COMPILER_ID MATCHES "Clang")
    message(FATAL_ERROR "CANDELA_FUZZERS needs clang: configure with -DCMAKE_CXX_COMPILER=clang++")
  endif()
  # Everything is instrumented for coverage and checked by the sanitizers; only the fuzz executables link
  # libFuzzer's main.
  add_compile_options($<$<COMPILE_LANGUAGE:CXX>:-fsanitize=fuzzer-no-link,address,undefined>
                      $<$<COMPILE_LANGUAGE:CXX>:-fno-sanitize-recover=undefined>
                      $<$<COMPILE_LANGUAGE:CXX>:-fno-omit-frame-pointer>)
  add_link_options(-fsanitize=address,undefined)
endif()

# The libraries are linked into executables and into shared objects (the public library and its Python module)
# from the same objects: position-independent code, with -fno-semantic-interposition so that calls inside a library
# stay direct and inlinable as they are in an executable.
set(CMAKE_POSITION_INDEPENDENT_CODE ON)
add_compile_options($<$<COMPILE_LANGUAGE:CXX>:-fno-semantic-interposition>)
