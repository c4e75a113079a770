# Zoo cases labelled zoo_slow: scripts/test leaves them out of its default run (`ctest -LE zoo_slow`) and runs
# them with --all (CI). Included by CTest after the discovered tests (tests/CMakeLists.txt). A parameterised
# test's discovered name carries its parameter ("…/ironing_2d_ironing  # GetParam() = …"), so the names are
# matched from the list gtest_discover_tests defines; a case that is not found stops CTest, loudly.
# - the two ironing examples as shipped: 110 finite-strain load steps each (about 60 s and 240 s of CPU in
#   Release, alone); the validation suite runs the same problems (Ironing2D.*);
# - the crushed ring at order 2, without and with Coulomb friction: 40 finite-strain load steps on 2,592
#   nodes, the last three with the bore closed (about 35 s and 60 s of CPU in Release);
# - the O-ring at order 2: 10 finite-strain steps with Coulomb friction (about 150 s).
# Each with its Release seconds in a `ctest -j2` run of the suite on two cores as COST (the ironing with
# friction 540 s there): CTest starts the longest first (the reason: long_tests.cmake).
set(zoo_slow_cases "ExampleAsShipped.SolvesAndPassesItsChecks/ironing_2d_ironing" 90
                   "ExampleAsShipped.SolvesAndPassesItsChecks/ironing_2d_ironing_mu0_3" 700
                   "ExampleVariant.SolvesAndPassesItsChecks/crushed_ring_2d_ring_order2" 35
                   "ExampleVariant.SolvesAndPassesItsChecks/crushed_ring_2d_ring_order2_coulomb" 90
                   "ExampleVariant.SolvesAndPassesItsChecks/oring_axisymmetric_oring_order2" 150)
while(zoo_slow_cases)
  list(POP_FRONT zoo_slow_cases case seconds)
  set(found FALSE)
  foreach(test IN LISTS symcontact_zoo_tests_TESTS)
    if(test MATCHES "^Zoo/${case}( |$)")
      set_tests_properties("${test}" PROPERTIES LABELS "zoo;zoo_slow" COST ${seconds})
      set(found TRUE)
    endif()
  endforeach()
  if(NOT found AND symcontact_zoo_tests_TESTS)
    message(FATAL_ERROR "tests/zoo_slow.cmake: no zoo test for the case '${case}'")
  endif()
endwhile()
