# The longest tests, started first: CTest runs tests in decreasing COST (here the seconds measured in the
# Release suite), until a run has left its own timings in Testing/Temporary/CTestCostData.txt. Without it a
# fresh build folder (CI's) starts them in the order they were registered, and one that comes last runs
# alone at the end while the other job idles. Included by CTest after the discovered tests (like
# asan_slow.cmake), so the names must exist. The zoo's slow cases get theirs in zoo_slow.cmake.
set(long_tests
  "Ironing2D.FrictionalRunsThroughEveryStepWithoutPenetrationOrOscillation" 200
  "Ironing2D.FrictionlessRunsThroughEveryStepWithoutPenetrationOrOscillation" 85
  "Hertz3D.TwoElasticSpheresP2" 35
  "Hertz3D.SphereOnRigidPlaneHex8" 24
  "SelfContact3D.HairpinEqualsHalfModelOnARigidPlane" 25)
while(long_tests)
  list(POP_FRONT long_tests name seconds)
  set_tests_properties("${name}" PROPERTIES COST ${seconds})
endwhile()
# The frictional ironing's first 52 steps in m and in mm (test_units.cpp): a parameterised test, whose
# discovered name carries its parameter (zoo_slow.cmake), matched by its prefix.
set(found FALSE)
foreach(test IN LISTS symcontact_validation_tests_TESTS)
  if(test MATCHES "^FrictionalIroning/Units\\.")
    set_tests_properties("${test}" PROPERTIES COST 230)
    set(found TRUE)
  endif()
endforeach()
if(NOT found AND symcontact_validation_tests_TESTS)
  message(FATAL_ERROR "tests/long_tests.cmake: no test FrictionalIroning/Units.*")
endif()
