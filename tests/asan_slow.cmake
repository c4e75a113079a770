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
#
# The longest of the rest (20-80 s each sanitised), each with a smaller sibling that runs the same code
# sanitised:
# - Hertz2D.CylinderExtrudedIntoHexahedra…: Hex27 contact with curved Quad9 facets; the V3Hex patch tests run
#   Hex27/Quad9 contact.
# - Elasticity/ManufacturedConvergence…/D3P1 and D3P2: refinement studies on 3D meshes; the 2D studies and the
#   3D P1/P2 derivative checks (unit) run.
# - Stacked/StackedBlocks…/3D_n3_5_4_P2_symmetric: the 3D P1 stacks and the 3D P2 contact patch tests run.
# - FrictionExamples/Units…/inclined_3d_inclined_toml_L3_F0: the 2D unit changes run, and InclinedInterface3D
#   solves the same 3D problem.
# - FrictionalIroning/Units…: 2 × 52 finite-strain frictional steps (about 4 min of CPU in Release); the other
#   unit changes run sanitised.
# Parameterised tests carry their parameter in their discovered name (see zoo_slow.cmake): matched by prefix.
# - Hertz3D.SphereOnRigidPlaneHex8 and …Hex27: 3D Hertz on hexahedra split from tetrahedra (24 s and 14 s in
#   Release); the V3Hex patch tests run Hex8/Hex27 contact with Quad4/Quad9 facets sanitised.
set_tests_properties("Hertz2D.CylinderExtrudedIntoHexahedraMatchesTheLineContact" "Hertz3D.SphereOnRigidPlaneHex8"
                     "Hertz3D.SphereOnRigidPlaneHex27" PROPERTIES LABELS "validation;asan_slow")
# - FrictionExamples/Units…/oring_axisymmetric_*: the O-ring in five unit systems, 150–180 s each sanitised; the
#   other examples' unit changes run sanitised, and Axisymmetric.NeoHookeanTube… runs the finite-strain
#   axisymmetric contact path.
# - ElasticityTensorCells/ManufacturedConvergence…/ of the quadratic 3D cells and the prisms (20–50 s each
#   sanitised): refinement studies of kernels whose derivative checks (unit, EnergyDerivatives) run sanitised;
#   the Quad, Hex8 and Pyramid5 studies run.
# - V8/CattaneoMindlin…/SmallContact* and SmallerContact*: finer meshes of the same solve (15–45 s each);
#   Matching and NonMatching run sanitised.
# A regular expression may stand for several names (".*").
foreach(prefix "Elasticity/ManufacturedConvergence.RatesMatchTheory/D3P1"
               "Elasticity/ManufacturedConvergence.RatesMatchTheory/D3P2"
               "Stacked/StackedBlocks.UniformPressureAtBothInterfacesAndOrderIndependent/3D_n3_5_4_P2_symmetric"
               "FrictionExamples/Units.RescaledProblemGivesTheSameDimensionlessAnswer/inclined_3d_inclined_toml_L3_F0"
               "FrictionalIroning/Units.RescaledProblemGivesTheSameDimensionlessAnswer/ironing_2d_ironing_mu0_3_toml_L3_F0"
               "FrictionExamples/Units.RescaledProblemGivesTheSameDimensionlessAnswer/oring_axisymmetric_oring_toml_.*"
               "ElasticityTensorCells/ManufacturedConvergence.RatesMatchTheory/(hex20|hex27|prism6|prism15|prism18|pyramid13|pyramid14)"
               "V8/CattaneoMindlin.StickZoneAndTangentialForceMatchTheClosedForm/Small(er)?Contact.*")
  set(found FALSE)
  foreach(test IN LISTS symcontact_validation_tests_TESTS)
    if(test MATCHES "^${prefix}( |$)")
      set_tests_properties("${test}" PROPERTIES LABELS "validation;asan_slow")
      set(found TRUE)
    endif()
  endforeach()
  if(NOT found AND symcontact_validation_tests_TESTS)
    message(FATAL_ERROR "tests/asan_slow.cmake: no validation test named '${prefix}'")
  endif()
endforeach()
