# Sanitizer and fuzzer builds (clang only). Both are meant for their own build folder:
#
#   CC=clang-14 CXX=clang++-14 cmake -S . -B build-asan -G Ninja \
#       -DCMAKE_BUILD_TYPE=RelWithDebInfo -DBOUNCE_SANITIZE=ON -DBOUNCE_FUZZ=ON
#
# BOUNCE_SANITIZE: AddressSanitizer + UndefinedBehaviorSanitizer everywhere; any UB report
# aborts (-fno-sanitize-recover). Only the CPU-side test suites are registered (the GPU
# suites on lavapipe are too slow under ASan); bounce-render and the plugins are built for
# the hostile-input corpus (tests/hostile).
# BOUNCE_FUZZ: libFuzzer targets in tests/fuzz. Everything is compiled with
# -fsanitize=fuzzer-no-link so coverage reaches into the engine library; only the fuzz
# executables link libFuzzer's main.
option(BOUNCE_SANITIZE "Build with AddressSanitizer and UndefinedBehaviorSanitizer (clang)" OFF)
option(BOUNCE_FUZZ "Build the libFuzzer targets in tests/fuzz (clang; implies BOUNCE_SANITIZE)" OFF)

if(BOUNCE_FUZZ)
  set(BOUNCE_SANITIZE ON CACHE BOOL "" FORCE)
endif()

if(BOUNCE_SANITIZE)
  if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    message(FATAL_ERROR "BOUNCE_SANITIZE/BOUNCE_FUZZ need clang: configure with CXX=clang++-14")
  endif()
  # -O1 and line tables only (they are enough for symbolized reports): the build is about
  # twice as fast as -O2 -g on CI's two cores. They follow the build type's flags, so win.
  set(BOUNCE_SANITIZER_FLAGS -fsanitize=address,undefined -fno-sanitize-recover=undefined
                             -fno-omit-frame-pointer -O1 -gline-tables-only)
  if(BOUNCE_FUZZ)
    list(APPEND BOUNCE_SANITIZER_FLAGS -fsanitize=fuzzer-no-link)
  endif()
  add_compile_options(${BOUNCE_SANITIZER_FLAGS})
  add_link_options(-fsanitize=address,undefined)
endif()

# Debian's glslang is built without RTTI, so UBSan's vptr check cannot see its classes'
# type information (undefined typeinfo at link time). The files that use glslang are
# compiled without that one check; everything else keeps it. Call it from the folder
# whose CMakeLists.txt adds the files (source properties are per folder).
function(bounce_no_vptr_check)
  if(BOUNCE_SANITIZE)
    set_source_files_properties(${ARGN} PROPERTIES COMPILE_OPTIONS -fno-sanitize=vptr)
  endif()
endfunction()
