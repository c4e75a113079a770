# Tests labelled asan_slow: the sanitised suite of scripts/test (ASan + UBSan, `ctest -LE asan_slow`)
# leaves them out; the normal suite runs them. Included by CTest after the discovered tests
# (tests/CMakeLists.txt), so the names must exist: a renamed test fails here, loudly.
#
# - Ironing2D.FrictionalRunsThroughEveryStep…: 110 finite-strain frictional load steps, ~13,000 IPOPT
#   iterations (136–173 s in the Release suite); under ASan + UBSan it ran more than 10 minutes, a large
#   part of the CI budget, and exercises no code path that the other ironing, friction and step-cutting
#   tests (all run sanitised) do not.
# - Ironing2D.FrictionlessRunsThroughEveryStep…: the same 110 steps without friction, 83 s in Release and
#   300 s sanitised; the frictionless finite-strain contact path runs sanitised in CrushedRing2D and the
#   hyperelastic Hertz cases.
set_tests_properties("Ironing2D.FrictionalRunsThroughEveryStepWithoutPenetrationOrOscillation"
                     "Ironing2D.FrictionlessRunsThroughEveryStepWithoutPenetrationOrOscillation"
                     PROPERTIES LABELS "validation;asan_slow")
#
# - Hertz3D.TwoElasticSpheresP2: two 10-node-tetrahedron spheres, 385 s sanitised against 38 s in the
#   Release suite. Hertz3D.SphereOnRigidPlaneP2 runs the same Tri6 facet and P2 assembly paths
#   sanitised in 6 s.
# - SelfContact3D.HairpinEqualsHalfModelOnARigidPlane: two full 3D solves, 200 s sanitised against 29 s.
#   SelfContactFriction3D.AnArmSlidingOnItsOwnBody… runs 3D self-contact detection and assembly
#   sanitised.
set_tests_properties("Hertz3D.TwoElasticSpheresP2" "SelfContact3D.HairpinEqualsHalfModelOnARigidPlane"
                     PROPERTIES LABELS "validation;asan_slow")
