# Scheduling weights of the longest discovered GoogleTest tests for `ctest --parallel` (the other
# tests' are at the end of CMakeLists.txt): the longest start first, so that a run without
# ctest's own timings yet (a fresh clone, as in CI) does not end with one core running a long
# test alone. Relative weights only; once ctest has timed a test it takes its own figure. A name
# a build does not run is passed over.
set_tests_properties(Heap.ItsAngleOfReposeGrowsWithRollingResistance PROPERTIES COST 50)
set_tests_properties(FrostFront.WithoutStonesTheSurfaceComesBackAndTheFinesStay
                     ServoWall.HoldsTheLoadItIsAskedAndTheFloorCarriesItWithTheWeight
                     ServoWall.AResumedRunIsTheWholeRun StageChanges.AGateRemovedOpensTheOrifice
                     CoarseGrain.ASettledBedsStressIsTheWeightAbove
                     CoarseGrain3.ASettledBedsStressIsTheWeightAbove
                     Stress.ASettledBedsStressIsItsWeightTimesItsHeight PROPERTIES COST 20)
