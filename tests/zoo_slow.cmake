# Zoo cases labelled zoo_slow: scripts/test leaves them out of its default run (`ctest -LE zoo_slow`) and runs
# them with --all (CI). Included by CTest after the discovered tests (tests/CMakeLists.txt), so the names must
# exist: a renamed test fails here, loudly.
# - the two ironing examples as shipped: 110 finite-strain load steps each (about 80 s and 130 s in Release);
#   the validation suite runs the same problems (Ironing2D.*).
set_tests_properties(
  "Zoo/ExampleAsShipped.SolvesAndPassesItsChecks/ironing_2d_ironing"
  "Zoo/ExampleAsShipped.SolvesAndPassesItsChecks/ironing_2d_ironing_mu0_3"
  PROPERTIES LABELS "zoo;zoo_slow")
