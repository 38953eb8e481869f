# Read by ctest after the discovered tests of ltrender_tests (CMakeLists.txt): labels `slow` the
# tests that must stay big (docs/testing.md). `ctest -LE slow` is the quick loop; ./test.sh runs all.
set(lt_slow_tests
  "^ArbIr\\.EveryGeneratedProgramParsesBackToTheSameCounts$"
  "^ProgramCounter\\.EveryGeneratedProgramAgreesWithMesa$"
  "^GxPlan\\.EveryDemoSceneAndVariantProgramSetsWhatThePlanSays$"
  "^Budget\\.EveryDemoProgramFitsPs20InEveryVariant$"
  "^MapVsVertex\\.ErrorFallsAsTheTessellationRises$"
  "^ReportPageInBrowser\\."
  "^Bench\\.WritesOneRowPerPathVariantAndEveryReport$"
  "^Bench\\.PinsToOneCoreAndSaysSo$"
  "^Demo/Bounded\\."
  "^Scenes/GxExportCompiles\\."
)
foreach(lt_test IN LISTS ltrender_tests_TESTS)
  foreach(lt_pattern IN LISTS lt_slow_tests)
    if(lt_test MATCHES "${lt_pattern}")
      # A slow test gets twice the default 300 s: e.g. the teapot's exports compile 8 variants
      # against two libogc checkouts, 146 s alone and past 300 s on a machine busy with a build
      # (when LTRENDER_LIBOGC names them; without it they skip at once).
      set_tests_properties("${lt_test}" PROPERTIES LABELS slow TIMEOUT 600)
      break()
    endif()
  endforeach()
endforeach()

# The bounds tests read each scene's reference from one folder per ctest run
# (tests/reference_cache.h), emptied first by the fixture BoundsReferenceCache.Clear.
foreach(lt_test IN LISTS ltrender_tests_TESTS)
  if(lt_test MATCHES "^Demo/Bounded\\.")
    set_tests_properties("${lt_test}" PROPERTIES FIXTURES_REQUIRED bounds_reference_cache
      ENVIRONMENT "LT_TEST_REFERENCE_CACHE=@CMAKE_BINARY_DIR@/test-cache/references")
  endif()
endforeach()

# The long poles, started first: with no cost data (a fresh clone) ctest runs the tests in the
# order it reads them, and a minute-long test read last runs alone on one core after everything
# else has finished. COST is the order `ctest -j` starts them in (highest first); the figures
# are seconds measured in one `./test.sh` on the 2-core machine, under load.
set(lt_long_poles
  "^GxPlan\\.EveryDemoSceneAndVariantProgramSetsWhatThePlanSays$" 61
  "^ArbIr\\.EveryGeneratedProgramParsesBackToTheSameCounts$" 60
  "^Bench\\.PinsToOneCoreAndSaysSo$" 20
  "^MapVsVertex\\.ErrorFallsAsTheTessellationRises$" 18
  "^BenchJobs\\.TwoJobsMakeTheReportOneProcessMakes$" 17
  "^ArbGuards\\.ElidedProgramsRenderTheSameAsGuardedOnes$" 13
)
list(LENGTH lt_long_poles lt_pole_items)
math(EXPR lt_pole_last "${lt_pole_items} - 1")
foreach(lt_test IN LISTS ltrender_tests_TESTS)
  foreach(lt_index RANGE 0 ${lt_pole_last} 2)
    list(GET lt_long_poles ${lt_index} lt_pattern)
    if(lt_test MATCHES "${lt_pattern}")
      math(EXPR lt_cost_index "${lt_index} + 1")
      list(GET lt_long_poles ${lt_cost_index} lt_cost)
      set_tests_properties("${lt_test}" PROPERTIES COST ${lt_cost})
      break()
    endif()
  endforeach()
endforeach()
