"""Equal settings and equal time against the baseline series, on hand-made frames."""
import math
import os
import tempfile
import unittest

import pandas as pd

from lpvlab_analysis import equal_time as ET
from lpvlab_analysis import report
from lpvlab_analysis import summary as S

RMSE = "metric.indirect_vs_indirect1.rmse"


def frame(rows, scene=None):
    """rows: (config_name, series, resolution, total ms, rmse)."""
    d = pd.DataFrame([{"config_id": f"{i:03d}", "config_name": n, "param.series": s,
                       "param.grid.resolution": res, "time.total.ms": t, "time.propagation.ms": t / 2,
                       RMSE: e} for i, (n, s, res, t, e) in enumerate(rows)])
    if scene is not None:
        d["param.scene.file"] = scene
    return d


# Baseline: error halves when the time quadruples, i.e. error ~ time^-1/2 between the points.
BASE = [("b16", "baseline", 16, 1.0, 0.4), ("b32", "baseline", 32, 4.0, 0.2), ("b48", "baseline", 48, 16.0, 0.1)]


def row(t, name):
    return t[t["config_name"] == name].iloc[0]


class InterpolationTest(unittest.TestCase):
    def test_log_log_between_points(self):
        pts = ET.baseline_points([1.0, 4.0, 16.0], [0.4, 0.2, 0.1])
        # t = 2: halfway in log time between 1 and 4 -> geometric mean of 0.4 and 0.2
        e, status = ET.error_at_time(pts, 2.0)
        self.assertEqual(status, "")
        self.assertAlmostEqual(e, math.sqrt(0.4 * 0.2), places=12)
        # t = 8 between 4 and 16, 1/2 of the log interval: 0.2 * (1/2)^(1/2)
        self.assertAlmostEqual(ET.error_at_time(pts, 8.0)[0], 0.2 / math.sqrt(2.0), places=12)
        # not halfway: t = 1.5, w = log 1.5 / log 4
        w = math.log(1.5) / math.log(4.0)
        self.assertAlmostEqual(ET.error_at_time(pts, 1.5)[0], 0.4 * 0.5 ** w, places=12)

    def test_exact_points_and_unsorted_input(self):
        pts = ET.baseline_points([16.0, 1.0, 4.0], [0.1, 0.4, 0.2])
        self.assertEqual(pts, [(1.0, 0.4), (4.0, 0.2), (16.0, 0.1)])
        for t, e in pts:
            self.assertEqual(ET.error_at_time(pts, t), (e, ""))

    def test_out_of_range_never_extrapolated(self):
        pts = ET.baseline_points([1.0, 4.0], [0.4, 0.2])
        for t in (0.5, 4.0001, 100.0):
            e, status = ET.error_at_time(pts, t)
            self.assertTrue(math.isnan(e))
            self.assertEqual(status, ET.OUT_OF_RANGE)

    def test_nan_and_nonpositive_points_dropped(self):
        pts = ET.baseline_points([1.0, math.nan, 4.0, 8.0, 16.0, math.inf],
                                 [0.4, 0.3, math.nan, 0.0, 0.1, 0.05])
        self.assertEqual(pts, [(1.0, 0.4), (16.0, 0.1)])
        self.assertAlmostEqual(ET.error_at_time(pts, 4.0)[0], 0.2, places=12)

    def test_bad_time(self):
        pts = ET.baseline_points([1.0, 4.0], [0.4, 0.2])
        for t in (math.nan, 0.0, -1.0, math.inf):
            e, status = ET.error_at_time(pts, t)
            self.assertTrue(math.isnan(e))
            self.assertEqual(status, "no time")

    def test_one_point_and_empty_series(self):
        pts = ET.baseline_points([2.0], [0.3])
        self.assertEqual(ET.error_at_time(pts, 2.0), (0.3, ""))
        self.assertEqual(ET.error_at_time(pts, 2.5)[1], ET.OUT_OF_RANGE)
        self.assertEqual(ET.error_at_time([], 2.0)[1], ET.OUT_OF_RANGE)


class CompareTest(unittest.TestCase):
    def test_ratios(self):
        agg = frame(BASE + [("gv", "gv", 32, 8.0, 0.1), ("fast", "x", 16, 2.0, 0.5),
                            ("slow", "x", 32, 20.0, 0.05), ("odd", "x", 64, 4.0, 0.3)])
        t = ET.compare(agg, RMSE)
        gv = row(t, "gv")
        self.assertFalse(gv["baseline"])
        self.assertAlmostEqual(gv["settings error"], 0.2)
        self.assertAlmostEqual(gv["settings ratio"], 0.5)
        self.assertAlmostEqual(gv["time error"], 0.2 / math.sqrt(2.0), places=12)
        self.assertAlmostEqual(gv["time ratio"], 0.1 / (0.2 / math.sqrt(2.0)), places=12)
        self.assertEqual(gv["time status"], "")
        fast = row(t, "fast")
        self.assertAlmostEqual(fast["settings ratio"], 0.5 / 0.4)
        self.assertAlmostEqual(fast["time ratio"], 0.5 / math.sqrt(0.08), places=12)
        slow = row(t, "slow")
        self.assertEqual(slow["time status"], ET.OUT_OF_RANGE)
        self.assertTrue(math.isnan(slow["time ratio"]))
        odd = row(t, "odd")  # no baseline at resolution 64: no equal-settings value
        self.assertTrue(math.isnan(odd["settings error"]))
        self.assertAlmostEqual(odd["time ratio"], 1.5)
        b32 = row(t, "b32")
        self.assertTrue(b32["baseline"])
        self.assertEqual((b32["settings ratio"], b32["time ratio"]), (1.0, 1.0))

    def test_nan_metric(self):
        agg = frame(BASE[:2] + [("b48", "baseline", 48, 16.0, math.nan), ("gv", "gv", 32, 10.0, math.nan),
                                 ("ok", "x", 32, 10.0, 0.1)])
        t = ET.compare(agg, RMSE)
        # the NaN baseline point is left out: 10 ms is past the series' last usable point (4 ms)
        self.assertEqual(row(t, "ok")["time status"], ET.OUT_OF_RANGE)
        self.assertTrue(math.isnan(row(t, "gv")["time ratio"]))
        self.assertTrue(math.isnan(row(t, "gv")["settings ratio"]))
        self.assertTrue(math.isnan(row(t, "b48")["settings ratio"]))

    def test_per_scene_baselines(self):
        a = frame(BASE + [("gv", "gv", 32, 8.0, 0.1)], scene="a")
        b = frame([("b16", "baseline", 16, 1.0, 0.8), ("b32", "baseline", 32, 4.0, 0.4),
                   ("gv", "gv", 32, 2.0, 0.2)], scene="b")
        t = ET.compare(pd.concat([a, b], ignore_index=True), RMSE)
        ga = t[(t["scene"] == "a") & (t["config_name"] == "gv")].iloc[0]
        gb = t[(t["scene"] == "b") & (t["config_name"] == "gv")].iloc[0]
        self.assertAlmostEqual(ga["settings ratio"], 0.5)
        self.assertAlmostEqual(gb["settings ratio"], 0.5)
        self.assertAlmostEqual(gb["time error"], math.sqrt(0.8 * 0.4), places=12)

    def test_baselines_per_clock(self):
        # A configuration timed on the CPU backend is never placed on a baseline timed by GL timer
        # queries: with no baseline on its clock it gets no equal-time value.
        agg = frame(BASE + [("gv", "gv", 32, 8.0, 0.1), ("cpu", "x", 32, 8.0, 0.1)])
        agg["time.total.clock"] = ["gl_timer_query"] * 4 + ["cpu_wall_clock"]
        t = ET.compare(agg, RMSE)
        self.assertEqual(row(t, "gv")["time status"], "")
        self.assertEqual(row(t, "cpu")["time status"], "no baseline")
        self.assertTrue(math.isnan(row(t, "cpu")["time ratio"]))

    def test_equal_time_on_the_methods_own_time(self):
        # The speed axis (summary.with_speed) is the method's time by default: the same
        # configurations, whose totals share 100 ms of raster passes, are compared at their own
        # stages' times. gv's method time 8 ms lies between the baseline's 4 and 16 ms; its total
        # (108 ms) between 104 and 116 gives another baseline error.
        rows = BASE + [("gv", "gv", 32, 8.0, 0.1)]
        agg = frame(rows)
        agg["time.method.ms"] = agg["time.total.ms"]
        agg["time.total.ms"] = agg["time.total.ms"] + 100.0
        method = ET.compare(S.with_speed(agg), RMSE)
        self.assertAlmostEqual(row(method, "gv")["time error"], 0.2 / math.sqrt(2.0), places=12)
        self.assertEqual(row(method, "gv")["time ms"], 8.0)
        total = ET.compare(S.with_speed(agg, "total"), RMSE)
        self.assertEqual(row(total, "gv")["time ms"], 108.0)
        w = (math.log(108.0) - math.log(104.0)) / (math.log(116.0) - math.log(104.0))
        self.assertAlmostEqual(row(total, "gv")["time error"], 0.2 * 0.5 ** w, places=12)

    def test_no_baseline(self):
        agg = frame([("a", "x", 32, 1.0, 0.1)])
        t = ET.compare(agg, RMSE)
        self.assertEqual(t.iloc[0]["time status"], "no baseline")
        self.assertFalse(ET.is_baseline(agg.drop(columns=["param.series"])).any())

    def test_missing_metric(self):
        self.assertTrue(ET.compare(frame(BASE), "metric.indirect_vs_indirect1.flip").empty)

    def test_metric_pairs(self):
        cols = ["metric.indirect_vs_indirect.rmse", "metric.indirect_vs_indirect1.flip",
                "metric.indirect_vs_indirect1.rmse", "metric.direct_vs_direct.rmse",
                "metric.indirect_vs_indirect1.pixels", "metric.indirect_vs_direct.flip"]
        self.assertEqual(ET.metrics_present(pd.DataFrame(columns=cols)),
                         ["metric.indirect_vs_indirect1.rmse", "metric.indirect_vs_indirect1.flip",
                          "metric.indirect_vs_direct.flip", "metric.indirect_vs_indirect.rmse"])

    def test_markdown_and_html(self):
        agg = frame(BASE + [("gv", "gv", 32, 8.0, 0.1), ("slow", "x", 32, 20.0, 0.05)])
        md = ET.to_markdown(agg)
        self.assertIn("|  | gv |  | 32 | 8 | 4 | 0.1 | 0.2 | 0.5 | 0.1414 | 0.7071 |", md)
        self.assertIn(ET.OUT_OF_RANGE, md)
        self.assertIn("0.7071", md)  # gv: 0.1 / (0.2 / sqrt 2)
        compact = ET.compact_markdown(agg)
        # named by series; RMSE only (no FLIP column in the frame): error, two ratios, equal-time value
        self.assertIn("| baseline 32 | 32 | 4 | 2 | 0.2 | 1 | 0.2 | 1 |", compact)
        self.assertIn("| gv | 32 | 8 | 4 | 0.1 | 0.5 | 0.1414 | 0.7071 |", compact)
        self.assertIn(f"| x | 32 | 20 | 10 | 0.05 | 0.25 | {ET.OUT_OF_RANGE} | - |", compact)
        self.assertLess(compact.index("baseline 48"), compact.index("| gv |"))
        page = ET.to_html(agg)
        self.assertIn("<b>0.7071</b>", page)
        self.assertIn("<b>0.5</b>", page)


class ReportSectionTest(unittest.TestCase):
    def _sweep(self, root, rows):
        os.makedirs(root, exist_ok=True)
        lines = ["config_id,config_name,repeat,run_dir,param.series,param.grid.resolution,time.total.ms,"
                 "time.propagation.ms,memory_bytes,cells,metric.indirect_vs_indirect1.rmse"]
        for i, (n, s, res, t, e) in enumerate(rows):
            lines.append(f"{i:03d},{n},0,{i:03d},{s},{res},{t},{t / 2},1000,{res ** 3},{e}")
        with open(os.path.join(root, "summary.csv"), "w") as f:
            f.write("\n".join(lines) + "\n")
        return root

    def test_report_has_section(self):
        with tempfile.TemporaryDirectory() as tmp:
            d = self._sweep(tmp, BASE + [("gv", "gv", 32, 8.0, 0.1)])
            agg = S.aggregate(S.load_summary(os.path.join(d, "summary.csv")))
            self.assertEqual(list(ET.is_baseline(agg)), [True, True, True, False])
            with open(report.build_report(d, use_exr=False)) as f:
                page = f.read()
            self.assertIn("Equal settings and equal time", page)
            self.assertIn('class="equal_time"', page)
            with open(os.path.join(d, "report", "equal_time.md")) as f:
                self.assertIn("0.7071", f.read())

    def test_report_without_baseline(self):
        with tempfile.TemporaryDirectory() as tmp:
            d = self._sweep(tmp, [("a", "x", 32, 1.0, 0.1), ("b", "y", 32, 2.0, 0.2)])
            with open(report.build_report(d, use_exr=False)) as f:
                self.assertIn("No baseline series", f.read())


if __name__ == "__main__":
    unittest.main()
