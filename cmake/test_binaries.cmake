enable_testing()
# One test binary: its sources, the libraries it needs beyond the core, the labels of its tests
# and each case's time limit in seconds. Its cases run as ctest tests in batches of one suite
# (tests/runner/: a process costs a case ~0.1 s of CPU before it starts; a crash or a hang still
# fails only its own case, and the batch goes on in a new process). tests/schedule.json says
# which cases get a process of their own, labels, costs and fixtures; docs/testing.md, "Test time".
# The test binaries' precompiled header, owned by a target that compiles one empty file and links
# nothing: REUSE_FROM makes the owner a dependency of every test binary, and when the owner was
# dolphin_tests, whose link waits for the core, ltrender_tests' batches (the build's longest jobs)
# could not start before the core was built. Its flags are the tests' (the same options and the
# same libraries' definitions and include directories); -Winvalid-pch says so if one ever differs,
# and GCC then parses the headers instead.
# Written only when its text changes, so a reconfigure leaves the object up to date.
file(CONFIGURE OUTPUT ${CMAKE_BINARY_DIR}/generated/test_pch.cpp
  CONTENT "// the test binaries' precompiled header\n")
add_library(lt_test_pch OBJECT ${CMAKE_BINARY_DIR}/generated/test_pch.cpp)
target_include_directories(lt_test_pch PRIVATE ${CMAKE_SOURCE_DIR}/src)
target_compile_definitions(lt_test_pch PRIVATE GL_GLEXT_PROTOTYPES=1)
target_link_libraries(lt_test_pch PRIVATE ${LT_CORE_LIBRARIES} GTest::gtest)
target_compile_options(lt_test_pch PRIVATE -O0)
target_precompile_headers(lt_test_pch PRIVATE ${CMAKE_SOURCE_DIR}/tests/precompiled.h)
# The test helpers that walk every pixel (tests/test_pixels.cpp) at the build type's -O3: the
# test files are compiled at -O0 (below), where non_finite's loop of std::isfinite calls and vector
# iterators was ~10% of Demo/Bounded's CPU (`perf record`), ~1% optimised.
add_library(lt_test_support STATIC ${CMAKE_SOURCE_DIR}/tests/test_pixels.cpp)
target_include_directories(lt_test_support PRIVATE ${CMAKE_SOURCE_DIR}/src)
target_link_libraries(lt_test_support PRIVATE ${LT_CORE_LIBRARIES} GTest::gtest)
target_compile_options(lt_test_support PRIVATE ${LT_WARNINGS})

function(lt_test_binary name)
  cmake_parse_arguments(T "" "TIMEOUT" "SOURCES;LIBS;LABELS" ${ARGN})
  add_executable(${name} ${T_SOURCES})
  target_link_libraries(${name} PRIVATE lt_test_support ltrender_cli ${T_LIBS} GTest::gtest
    GTest::gtest_main)
  # Compile time is most of ./test.sh from a fresh clone (issue 28): the tests were two thirds of
  # the build, and their own code is thin (the work is in ltrender_core, still -O3). -O0 and a
  # precompiled header of what nearly every test includes make them much cheaper to compile:
  # a batch of 32 test files took 80.5 s of CPU at -O1, 62.6 s at -Og, 45.8 s at -O0
  # (`/usr/bin/time` on its compile); in whole fresh clones the test binaries' steps took 150-160 s
  # at -O0 against 169 s at -Og (`.ninja_log`, docs/testing.md "Test time").
  target_compile_options(${name} PRIVATE -O0)
  # -O0 has a price at link time, paid here: of the copies of an inline function or template
  # (std::vector's growth, OpenMesh's containers, arbfp's IR), the linker keeps the first it meets,
  # and the test files' unoptimised ones came first, so the core called them (ArbIr's sweep took
  # 3 times as long). The core's and the commands' archives are read whole before the test
  # files, so their -O3 / -O1 copies are the ones kept (GNU ld keeps the first COMDAT group of a
  # name; `--whole-archive` loads every member where it stands on the command line).
  target_link_options(${name} PRIVATE -Wl,--whole-archive $<TARGET_FILE:ltrender_core>
    $<TARGET_FILE:ltrender_cli> -Wl,--no-whole-archive)
  # One precompiled header for every test binary (lt_test_pch below): each made its own, 9.7 s
  # of CPU apiece (.ninja_log of a fresh clone).
  target_precompile_headers(${name} REUSE_FROM lt_test_pch)
  # A unity build too, with the core's rules (tests/source/ checks tests/ as it checks src/).
  # Sixty-four files a batch: a test file is mostly GoogleTest's macros and the templates they
  # instantiate, compiled once a batch; four batches of eight took 44.0 s of CPU as one and
  # 64.2 s apart (-O1 with the precompiled header), two of thirty-two 82.1 s as one and 93.7 s
  # apart (-O0; `/usr/bin/time` on the compile).
  set_target_properties(${name} PROPERTIES UNITY_BUILD ${LT_UNITY_BUILD} UNITY_BUILD_BATCH_SIZE 64)
  set(plan ${CMAKE_BINARY_DIR}/${name}_batches.cmake)
  set(labels)
  foreach(label ${T_LABELS})
    list(APPEND labels --label ${label})
  endforeach()
  add_custom_command(OUTPUT ${plan}
    COMMAND ${LT_PYTHON} ${CMAKE_SOURCE_DIR}/tests/runner/plan_batches.py
      --binary $<TARGET_FILE:${name}> --schedule ${CMAKE_SOURCE_DIR}/tests/schedule.json
      --runner ${CMAKE_SOURCE_DIR}/tests/runner/run_batch.py --python ${LT_PYTHON}
      --build-dir ${CMAKE_BINARY_DIR} --timeout ${T_TIMEOUT} ${labels} --out ${plan}
    DEPENDS ${name} ltrender ${CMAKE_SOURCE_DIR}/tests/schedule.json
      ${CMAKE_SOURCE_DIR}/tests/runner/plan_batches.py
    COMMENT "Planning the test batches of ${name}" VERBATIM)
  add_custom_target(${name}_batches ALL DEPENDS ${plan})
  # Read by ctest; before the build, one failing test says the binary is not built.
  file(WRITE ${CMAKE_BINARY_DIR}/${name}_include.cmake
    "if(EXISTS [==[${plan}]==])\n  include([==[${plan}]==])\nelse()\n"
    "  add_test(${name}_NOT_BUILT ${name}_NOT_BUILT)\nendif()\n")
  set_property(DIRECTORY APPEND PROPERTY TEST_INCLUDE_FILES ${CMAKE_BINARY_DIR}/${name}_include.cmake)
endfunction()

file(GLOB LT_TEST_SOURCES CONFIGURE_DEPENDS ${CMAKE_SOURCE_DIR}/tests/*_test.cpp)
# Tests that run programs that are not ltrender's (Dolphin, Xvfb: src/judge/) are a binary of
# their own, labelled `dolphin`: `ctest -L dolphin` runs only them, `ctest -LE dolphin` skips them.
# Each case bounds its own time (deadlines of a few seconds); 120 s is the backstop.
file(GLOB LT_DOLPHIN_TEST_SOURCES CONFIGURE_DEPENDS ${CMAKE_SOURCE_DIR}/tests/dolphin_*_test.cpp)
list(REMOVE_ITEM LT_TEST_SOURCES ${LT_DOLPHIN_TEST_SOURCES})
lt_test_binary(dolphin_tests SOURCES ${LT_DOLPHIN_TEST_SOURCES} TIMEOUT 120 LABELS dolphin)

# The tests that write odd image files (five channels, one-channel EXR, TIFF) or read JUnit XML
# with OpenImageIO itself. Linked in, OpenImageIO maps ~270 libraries before main(): 0.3 s of
# every test process, 1,818 processes, about half of the suite's CPU time (issue 28 measured
# it). The other binaries reach it only through the image module, when a test reads or writes
# an image. A test that includes an OpenImageIO header elsewhere fails to link: add it here.
set(LT_OIIO_TEST_NAMES albedo_map albedo_paths arb_ramp combiners_ramp compare exr_file exr_map_paths gx_map_path png_file regress regress_isolation thickness_map)
set(LT_OIIO_TEST_SOURCES)
foreach(name ${LT_OIIO_TEST_NAMES})
  list(APPEND LT_OIIO_TEST_SOURCES ${CMAKE_SOURCE_DIR}/tests/${name}_test.cpp)
endforeach()
list(REMOVE_ITEM LT_TEST_SOURCES ${LT_OIIO_TEST_SOURCES})
lt_test_binary(ltrender_oiio_tests SOURCES ${LT_OIIO_TEST_SOURCES} LIBS PkgConfig::OIIO
  TIMEOUT 300)

# Tests over the time budget of issue 28 that are a whole binary (advise's search against an
# exhaustive one over a whole variant grid): tests/slow_*_test.cpp, labelled `slow`.
file(GLOB LT_SLOW_TEST_SOURCES CONFIGURE_DEPENDS ${CMAKE_SOURCE_DIR}/tests/slow_*_test.cpp)
list(REMOVE_ITEM LT_TEST_SOURCES ${LT_SLOW_TEST_SOURCES})
lt_test_binary(slow_tests SOURCES ${LT_SLOW_TEST_SOURCES} TIMEOUT 300 LABELS slow)

lt_test_binary(ltrender_tests SOURCES ${LT_TEST_SOURCES} TIMEOUT 300)
# `ctest -L slow` / `ctest -LE slow`: the tests that must stay big because size is their point --
# sweeps over every generated program (each against a second counter or Mesa), the bounds at the
# demo scenes' own size, Chromium, the bench. tests/schedule.json names them.
# The bounds tests share each demo scene's reference image within one ctest run
# (tests/reference_cache.h); this fixture empties the folder first, so none outlives the run.
add_test(NAME BoundsReferenceCache.Clear
  COMMAND ${CMAKE_COMMAND} -E rm -rf ${CMAKE_BINARY_DIR}/test-cache/references)
set_tests_properties(BoundsReferenceCache.Clear PROPERTIES FIXTURES_SETUP bounds_reference_cache)
# The runner of the batches above (tests/runner/).
add_subdirectory(tests/runner)
# The documents: the README's first run as written, and every relative link (tests/docs/).
add_subdirectory(tests/docs)
# The sources themselves: what the unity build needs of them (tests/source/).
add_subdirectory(tests/source)
# ltrender installed, packaged and run as CI runs it (tests/install/); the empty-frame warning.
add_subdirectory(tests/install)
add_subdirectory(tests/nothing_drawn)
