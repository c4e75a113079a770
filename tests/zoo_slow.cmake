# Zoo cases labelled zoo_slow: scripts/test leaves them out of its default run (`ctest -LE zoo_slow`) and runs
# them with --all (CI). Included by CTest after the discovered tests (tests/CMakeLists.txt). A parameterised
# test's discovered name carries its parameter ("…/ironing_2d_ironing  # GetParam() = …"), so the names are
# matched from the list gtest_discover_tests defines; a case that is not found stops CTest, loudly.
# - the two ironing examples as shipped: 110 finite-strain load steps each (about 80 s and 130 s in Release);
#   the validation suite runs the same problems (Ironing2D.*).
set(zoo_slow_cases "ironing_2d_ironing" "ironing_2d_ironing_mu0_3")
foreach(case IN LISTS zoo_slow_cases)
  set(found FALSE)
  foreach(test IN LISTS symcontact_zoo_tests_TESTS)
    if(test MATCHES "^Zoo/ExampleAsShipped\\.SolvesAndPassesItsChecks/${case}( |$)")
      set_tests_properties("${test}" PROPERTIES LABELS "zoo;zoo_slow")
      set(found TRUE)
    endif()
  endforeach()
  if(NOT found AND symcontact_zoo_tests_TESTS)
    message(FATAL_ERROR "tests/zoo_slow.cmake: no zoo test for the case '${case}'")
  endif()
endforeach()
