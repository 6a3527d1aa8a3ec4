# The order in which ctest starts the tests: longest first (ctest -j starts tests in descending
# COST). A fresh build tree, as CI's, has no cost data from an earlier run, and ctest then starts
# tests in the order they were defined: these long ones came last, and with -j 2 one core ran them
# alone for minutes (the main suite 511 s against 411 s balanced; the checked build's 466 s against
# 290 s, measured on 2 cores). Each COST is the test's seconds there, in the build where it is
# longest (the checked build: fuzz and the Sobol sampler at -O0 under the sanitizers). Only the
# order depends on them: a renamed test keeps working, merely started later (ctest ignores
# properties of a test that does not exist). Read by ctest (TEST_INCLUDE_FILES, tests/CMakeLists.txt)
# after every test is defined.
set_tests_properties(fuzz PROPERTIES COST 122)
set_tests_properties(SobolSampler.IsUnbiasedAndConvergesFasterThanIndependentSamples PROPERTIES COST 89)
set_tests_properties(analysis PROPERTIES COST 55)
set_tests_properties(gpu_check PROPERTIES COST 52)
set_tests_properties(slurm_cluster PROPERTIES COST 47)
set_tests_properties(bundle_foreign_roots PROPERTIES COST 40)
set_tests_properties(ComputeBackend.CpuAndGlPropagationGiveTheSameImages PROPERTIES COST 38)
set_tests_properties(gpu_kernels PROPERTIES COST 30)
set_tests_properties(ShippedOnCpu.EachShippedExperimentRunsOnTheCpuAsOnGlOrIsRefusedByName PROPERTIES COST 26)
set_tests_properties(report_browser PROPERTIES COST 24)
set_tests_properties(bundle PROPERTIES COST 20)
set_tests_properties(TetrahedralCpu.MatchesTheGlslKernelsThroughAGeometryVolume PROPERTIES COST 18)
set_tests_properties(GpuBench.EveryCaseComputesWhatTheCpuKernelsCompute PROPERTIES COST 16)
set_tests_properties(EnergyAuditBackends.DirectedTetrahedralAndCascadesAgreeOnBothBackendsUnderEveryLight
                     PROPERTIES COST 15)
set_tests_properties(StandardTiled.SameGridAsTheSimpleKernelWithTheGvAndBounces PROPERTIES COST 15)
set_tests_properties(Radiosity.ObjCornellBoxIndirectApproachesThePathTracerAsPatchesShrink PROPERTIES COST 12)
set_tests_properties(RsmVplCpu.ItsNormalGridDrivesDirectedPropagationAsGlsOwnDoes PROPERTIES COST 12)
set_tests_properties(install_out_of_tree PROPERTIES COST 11)
set_tests_properties(Radiosity.OneBounceModeApproachesTheOneBounceReference PROPERTIES COST 11)
set_tests_properties(TemporalNoise.TwoReferencesOfOneStaticFrameHaveATemporalErrorConsistentWithZero
                     PROPERTIES COST 10)
set_tests_properties(analysis_pip_install PROPERTIES COST 9)
