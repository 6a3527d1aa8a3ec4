"""Loading summary.csv ("inf", errors) and per-configuration medians."""
import math
import os
import tempfile
import unittest

from lpvlab_analysis import summary as S
from tests.fixtures import make_sweep


class SummaryTest(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.dir = make_sweep(self.tmp.name, with_exr=False)

    def tearDown(self):
        self.tmp.cleanup()

    def test_load_inf(self):
        df = S.load_summary(os.path.join(self.dir, "summary.csv"))
        self.assertTrue(math.isinf(df["metric.direct_vs_direct.psnr"].iloc[0]))
        self.assertEqual(df["param.propagation.iterations"].dtype.kind, "i")

    def test_medians(self):
        # three repeats with an outlier: median ignores it
        p = os.path.join(self.dir, "s.csv")
        with open(p, "w") as f:
            f.write("config_id,config_name,repeat,run_dir,param.propagation.type,time.total.ms,memory_bytes,metric.indirect_vs_indirect1.rmse\n")
            f.write("a,A,0,a,standard,1.0,10,0.5\na,A,1,a,standard,100.0,10,0.5\na,A,2,a,standard,3.0,10,0.5\n")
            f.write("b,B,0,b,occlusion,4.0,20,inf\nb,B,1,b,occlusion,6.0,20,inf\n")
        agg = S.aggregate(S.load_summary(p))
        self.assertEqual(list(agg["config_id"]), ["a", "b"])
        self.assertEqual(list(agg["time.total.ms"]), [3.0, 5.0])
        self.assertEqual(list(agg["repeats"]), [3, 2])
        self.assertTrue(math.isinf(agg["metric.indirect_vs_indirect1.rmse"].iloc[1]))
        self.assertEqual(list(agg["variant"]), ["standard", "occlusion"])

    def test_times_say_their_clock_and_where_they_ran(self):
        # Issue 35: a CPU stage's time is no GPU time. The fixture's propagation ran on the CPU
        # backend and the rest on GL, so its total sums both clocks.
        agg = S.aggregate(S.load_summary(os.path.join(self.dir, "summary.csv")))
        self.assertEqual(S.timed_on(agg, "propagation"), "CPU backend on Test CPU 9000 (wall clock)")
        self.assertEqual(S.timed_on(agg, "rsm"), "GL on llvmpipe (LLVM 15.0.6, 256 bits) (timer queries)")
        self.assertEqual(S.timed_on(agg), "GL stages on llvmpipe (LLVM 15.0.6, 256 bits), CPU stages on Test CPU 9000")
        # A summary.csv written before times were labelled: its gpu_ms.* are read as times whose
        # clock nobody recorded, and said so.
        p = os.path.join(self.dir, "old.csv")
        with open(p, "w") as f:
            f.write("config_id,config_name,repeat,run_dir,gpu_ms.total,gpu_ms.propagation\n")
            f.write("a,A,0,a,2.0,1.0\n")
        old = S.aggregate(S.load_summary(p))
        self.assertEqual(old["time.total.ms"].iloc[0], 2.0)
        self.assertEqual(old["time.propagation.ms"].iloc[0], 1.0)
        self.assertIn("clock not recorded", S.timed_on(old))

    def test_stages_come_in_the_summarys_column_order(self):
        # lpvlab summary writes the time columns in the order the runs ran the stages; the report
        # stacks them in that order (no list of stage names of its own).
        p = os.path.join(self.dir, "o.csv")
        with open(p, "w") as f:
            f.write("config_id,config_name,repeat,run_dir,time.rsm.ms,time.vpls.ms,time.indirect.ms,time.total.ms\n")
            f.write("a,A,0,a,1,2,3,6\n")
        self.assertEqual(S.stages(S.load_summary(p)), ["rsm", "vpls", "indirect", "total"])

    def test_the_sums_of_stages_are_no_stages(self):
        # summary.csv has time.method.ms and time.shared.ms beside the stages: sums, which a plot
        # stacking the stages must not add again.
        p = os.path.join(self.dir, "sums.csv")
        with open(p, "w") as f:
            f.write("config_id,config_name,repeat,run_dir,time.gbuffer.ms,time.propagation.ms,"
                    "time.method.ms,time.shared.ms,time.total.ms\n")
            f.write("a,A,0,a,4,1,1,4,5\n")
        self.assertEqual(S.stages(S.load_summary(p)), ["gbuffer", "propagation", "total"])

    def test_the_speed_axis_is_the_methods_time_unless_total_is_asked(self):
        # Two configurations whose totals are dominated by the same raster passes: by the method's
        # time b is 4x dearer, by the total 1.3x. A run that recorded no method stages (c, a
        # summary from before) falls back to its total, and the words say so.
        p = os.path.join(self.dir, "speed.csv")
        with open(p, "w") as f:
            f.write("config_id,config_name,repeat,run_dir,time.method.ms,time.method.clock,"
                    "time.total.ms,time.total.clock\n")
            f.write("a,A,0,a,1,gl_timer_query,10,gl_timer_query\n"
                    "b,B,0,b,4,gl_timer_query,13,gl_timer_query\n")
        agg = S.aggregate(S.load_summary(p))
        self.assertEqual(list(agg[S.SPEED_COL]), [1.0, 4.0])
        self.assertEqual(list(agg[S.SPEED_CLOCK_COL]), ["gl_timer_query"] * 2)
        self.assertIn("method's own stages", S.speed_words(agg))
        self.assertEqual(S.speed_stage(agg), "method")
        total = S.aggregate(S.load_summary(p), "total")
        self.assertEqual(list(total[S.SPEED_COL]), [10.0, 13.0])
        self.assertIn("whole frame", S.speed_words(total))
        with open(p, "a") as f:
            f.write("c,C,0,c,,,20,gl_timer_query\n")
        mixed = S.aggregate(S.load_summary(p))
        self.assertEqual(list(mixed[S.SPEED_COL]), [1.0, 4.0, 20.0])
        self.assertIn("did not record", S.speed_words(mixed))
        with self.assertRaises(S.SummaryError):
            S.aggregate(S.load_summary(p), "frames")

    def test_the_gpu_estimate_axis_sums_the_methods_counted_kernels_and_says_it_estimates(self):
        # Issue 43: --time gpu-estimate. Two configurations whose propagation differs 4x in counted
        # work; direct light (the pipeline's own stage, counted too) is left out of the sum.
        from lpvlab_analysis import gpu_estimate as G
        p = os.path.join(self.dir, "gpu.csv")
        with open(p, "w") as f:
            f.write("config_id,config_name,repeat,run_dir,param.grid.sh_order,time.method.ms,time.method.clock,"
                    "gpu_work.propagation.multiply_adds,gpu_work.propagation.bytes,"
                    "gpu_work.direct.multiply_adds,gpu_work.direct.bytes\n")
            f.write("a,A,0,a,1,5,cpu_wall_clock,1e9,4e9,1e12,1e12\n"
                    "b,B,0,b,1,9,cpu_wall_clock,4e9,16e9,1e12,1e12\n")
        gpu = {g.key: g for g in G.load_gpus()}[S.DEFAULT_GPU]
        agg = S.aggregate(S.load_summary(p), "gpu-estimate", gpu)
        est = G.with_estimates(agg, [gpu])
        calibrated = f"{G.CALIBRATED}{gpu.key}.propagation"
        expected = est[calibrated] if calibrated in est.columns else est[f"{G.PREFIX}{gpu.key}.propagation"]
        self.assertEqual(list(agg[S.SPEED_COL]), list(expected))
        self.assertAlmostEqual(agg[S.SPEED_COL].iloc[1] / agg[S.SPEED_COL].iloc[0], 4.0)
        self.assertTrue(S.is_estimated_speed(agg))
        words = S.speed_words(agg)
        self.assertIn(gpu.name, words)
        self.assertIn("not a measurement", words)
        self.assertNotIn("median", S.speed_axis_label(agg))
        # Equal-time comparisons group by this clock: an estimate is never set against a time.
        self.assertEqual(set(agg[S.SPEED_CLOCK_COL]), {f"gpu_estimate:{gpu.key}"})
        with self.assertRaises(S.SummaryError):
            S.aggregate(S.load_summary(p), "gpu-estimate")  # no GPU named

    def test_memory_groups_are_numeric(self):
        p = os.path.join(self.dir, "m.csv")
        with open(p, "w") as f:
            f.write("config_id,config_name,repeat,run_dir,param.occlusion.type,memory_bytes,memory_bytes.geometry_volume\n")
            f.write("a,A,0,a,none,10,0\nb,B,0,b,geometry_volume,30,20\n")
        agg = S.aggregate(S.load_summary(p))
        self.assertEqual(list(agg["memory_bytes.geometry_volume"]), [0, 20])
        self.assertEqual(list(agg["variant"]), ["none", "geometry_volume"])

    def test_fixture_aggregate(self):
        agg = S.aggregate(S.load_summary(os.path.join(self.dir, "summary.csv")))
        self.assertEqual(len(agg), 6)
        # propagation at rep 0 = it*f, rep 1 = it*f+1 -> median it*f+0.5
        self.assertAlmostEqual(agg["time.propagation.ms"].iloc[2], 16.5)
        self.assertEqual(S.swept_params(agg), ["param.propagation.type", "param.propagation.iterations"])
        self.assertEqual(agg["variant"].iloc[0], "rsm_vpl/standard/trilinear")
        self.assertIn("propagation.iterations=4", agg["label"].iloc[1])

    def test_errors(self):
        with self.assertRaises(S.SummaryError) as cm:
            S.load_summary(os.path.join(self.dir, "nope.csv"))
        self.assertIn("nope.csv", str(cm.exception))
        empty = os.path.join(self.dir, "empty.csv")
        open(empty, "w").close()
        with self.assertRaises(S.SummaryError):
            S.load_summary(empty)
        with open(empty, "w") as f:
            f.write("config_id,config_name,repeat\n")
        with self.assertRaisesRegex(S.SummaryError, "empty.csv"):
            S.load_summary(empty)


if __name__ == "__main__":
    unittest.main()
