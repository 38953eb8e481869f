# Read by ctest after the discovered tests of ltrender_tests (CMakeLists.txt): labels `slow` the
# tests that must stay big (docs/testing.md). `ctest -LE slow` is the quick loop; ./test.sh runs all.
set(lt_slow_tests
  "^ArbIr\\.CounterAgreesWithTheTextCounterOnEveryGeneratedProgram$"
  "^ProgramCounter\\.EveryGeneratedProgramAgreesWithMesa$"
  "^GxPlan\\.EveryDemoSceneAndVariantProgramSetsWhatThePlanSays$"
  "^Budget\\.EveryDemoProgramFitsPs20InEveryVariant$"
  "^MapVsVertex\\.ErrorFallsAsTheTessellationRises$"
  "^ReportPageInBrowser\\."
  "^Bench\\.WritesOneRowPerPathVariantAndEveryReport$"
  "^Bench\\.PinsToOneCoreAndSaysSo$"
  "^Demo/Bounded\\."
)
foreach(lt_test IN LISTS ltrender_tests_TESTS)
  foreach(lt_pattern IN LISTS lt_slow_tests)
    if(lt_test MATCHES "${lt_pattern}")
      set_tests_properties("${lt_test}" PROPERTIES LABELS slow)
      break()
    endif()
  endforeach()
endforeach()
