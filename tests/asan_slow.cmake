# Tests labelled asan_slow: the sanitised suite of scripts/test (ASan + UBSan, `ctest -LE asan_slow`)
# leaves them out; the normal suite runs them. Included by CTest after the discovered tests
# (tests/CMakeLists.txt), so the names must exist: a renamed test fails here, loudly.
#
# - Ironing2D.FrictionalRunsThroughEveryStep…: 110 finite-strain frictional load steps, ~13,000 IPOPT
#   iterations (136–173 s in the Release suite); under ASan + UBSan it ran more than 10 minutes, a large
#   part of the CI budget, and exercises no code path that the other ironing, friction and step-cutting
#   tests (all run sanitised) do not.
set_tests_properties("Ironing2D.FrictionalRunsThroughEveryStepWithoutPenetrationOrOscillation"
                     PROPERTIES LABELS "validation;asan_slow")
