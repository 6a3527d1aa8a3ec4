# The order in which ctest starts the tests: longest first (ctest -j starts tests in descending
# COST). A fresh build tree, as CI's, has no cost data from an earlier run, and ctest then starts
# tests in the order they were defined: the long ones ran last, one core running them alone for
# minutes (docs/testing.md). Each COST is the test's seconds on 2 cores, in the build where it is
# longest (the Sobol sampler's at -O0 under the sanitizers). Only the order depends on them: a
# renamed test keeps working, merely started later (ctest ignores properties of a test that does
# not exist). This file names the tests that gtest_discover_tests defines: ctest reads it
# (TEST_INCLUDE_FILES, tests/CMakeLists.txt) after their lists, but before the add_test()s of the
# tests/CMakeLists.txt itself, whose costs are set there.
set_tests_properties(SobolSampler.IsUnbiasedAndConvergesFasterThanIndependentSamples PROPERTIES COST 89)
set_tests_properties(ComputeBackend.CpuAndGlPropagationGiveTheSameImages PROPERTIES COST 38)
set_tests_properties(ShippedOnCpu.EachShippedExperimentRunsOnTheCpuAsOnGlOrIsRefusedByName PROPERTIES COST 26)
set_tests_properties(TetrahedralCpu.MatchesTheGlslKernelsThroughAGeometryVolume PROPERTIES COST 18)
set_tests_properties(GpuBench.EveryCaseComputesWhatTheCpuKernelsCompute PROPERTIES COST 16)
set_tests_properties(EnergyAuditBackends.DirectedTetrahedralAndCascadesAgreeOnBothBackendsUnderEveryLight
                     PROPERTIES COST 15)
set_tests_properties(StandardTiled.SameGridAsTheSimpleKernelWithTheGvAndBounces PROPERTIES COST 15)
set_tests_properties(Radiosity.ObjCornellBoxIndirectApproachesThePathTracerAsPatchesShrink PROPERTIES COST 12)
set_tests_properties(RsmVplCpu.ItsNormalGridDrivesDirectedPropagationAsGlsOwnDoes PROPERTIES COST 12)
set_tests_properties(Radiosity.OneBounceModeApproachesTheOneBounceReference PROPERTIES COST 11)
set_tests_properties(TemporalNoise.TwoReferencesOfOneStaticFrameHaveATemporalErrorConsistentWithZero
                     PROPERTIES COST 10)
set_tests_properties(PhongBrdf.WhiteFurnaceUnderAUniformSky PROPERTIES COST 16)
set_tests_properties(LightCharts.PlacingByPowerGivesTheVplsEqualShares PROPERTIES COST 16)
set_tests_properties(PhongBrdf.SamplesTheDensityItReports PROPERTIES COST 8)
set_tests_properties(PhongBrdf.ReflectsNoMoreThanItReceives PROPERTIES COST 4)
set_tests_properties(InstantRadiosity.ClampCompensationGivesTheClampedLightBackWithoutBias PROPERTIES COST 6)
