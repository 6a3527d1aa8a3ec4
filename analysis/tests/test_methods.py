"""The methods section (methods.py): labels by method, equal-time ratios against the LPV
baseline, the method figures, and the section in a report; on hand-made frames."""
import math
import os
import tempfile
import unittest

import pandas as pd

from lpvlab_analysis import methods as M
from lpvlab_analysis import report
from lpvlab_analysis import summary as S
from tests.fixtures import make_sweep

RMSE = "metric.indirect_vs_indirect1.rmse"


def frame():
    """LPV baseline at 10 and 40 ms (errors 0.04 and 0.01), instant radiosity at 20 ms and 80 ms,
    RSM gathering at 20 ms."""
    rows = [("lpv16", "lpv", "baseline", 16, 10.0, 0.04, {}),
            ("lpv32", "lpv", "baseline", 32, 40.0, 0.01, {}),
            ("ir64", "instant_radiosity", "ir", math.nan, 20.0, 0.01,
             {"method.vpls": 50, "method.clamp.removed_fraction": 0.1}),
            ("ir256", "instant_radiosity", "ir", math.nan, 80.0, 0.005,
             {"method.vpls": 200, "method.clamp.removed_fraction": 0.0}),
            ("rsm", "rsm_gather", "rsm", math.nan, 20.0, 0.04, {"method.gathered_pairs": 1e6})]
    out = []
    for i, (name, method, series, res, t, e, figures) in enumerate(rows):
        r = {"config_id": f"{i:03d}", "config_name": name, "param.indirect.method": method,
             "param.series": series, "param.grid.resolution": res, "time.total.ms": t, RMSE: e,
             "param.propagation.type": "standard" if method == "lpv" else math.nan}
        r.update(figures)
        out.append(r)
    d = pd.DataFrame(out)
    d["variant"] = [S.variant_label(r, []) for _, r in d.iterrows()]
    return d


def _read(path):
    with open(path) as f:
        return f.read()


class MethodsTest(unittest.TestCase):
    def test_labels_name_the_method(self):
        d = frame()
        self.assertEqual(list(d["variant"])[2:], ["instant_radiosity", "instant_radiosity", "rsm_gather"])
        self.assertTrue(d["variant"][0].startswith("standard"))
        self.assertEqual(list(M.by_method(d)["variant"])[2:], ["instant_radiosity"] * 2 + ["rsm_gather"])
        self.assertTrue(M.by_method(d)["variant"][0].startswith("LPV"))
        self.assertTrue(M.has_methods(d))
        self.assertFalse(M.has_methods(d[d["param.indirect.method"] == "lpv"].drop(columns=["param.indirect.method"])))

    def test_equal_time_ratios_against_the_lpv_baseline(self):
        t = M.table(frame(), RMSE).set_index("configuration")
        # At 20 ms the baseline's error is interpolated log-log between (10, 0.04) and (40, 0.01):
        # 0.04 * (0.01 / 0.04) ** 0.5 = 0.02.
        self.assertAlmostEqual(t.loc["ir64", "equal-time ratio"], 0.01 / 0.02)
        self.assertAlmostEqual(t.loc["rsm", "equal-time ratio"], 0.04 / 0.02)
        self.assertTrue(math.isnan(t.loc["ir256", "equal-time ratio"]))  # past the baseline: no guess
        # Past the baseline's slowest point and below its best error.
        self.assertEqual(t.loc["ir256", "why no ratio"],
                         "slower than the slowest LPV run; more accurate than every LPV run")
        self.assertEqual(t.loc["lpv16", "why no ratio"], "baseline")
        self.assertEqual(t.loc["ir64", "VPLs"], 50)
        self.assertAlmostEqual(t.loc["ir64", "clamp removed"], 0.1)
        self.assertTrue(math.isnan(t.loc["rsm", "VPLs"]))
        self.assertEqual(list(M.table(frame(), RMSE)["time ms"]), [10.0, 20.0, 20.0, 40.0, 80.0])

    def test_several_scenes_get_a_scene_column_and_baselines_of_their_own(self):
        a, b = frame(), frame()
        a["param.scene.file"] = "shared:scenes/a.gltf"
        b["param.scene.file"] = "shared:scenes/b.gltf"
        b["config_id"] = "b" + b["config_id"]
        b[RMSE] = b[RMSE] * 2  # b's baseline and methods alike: the same ratios
        t = M.table(pd.concat([a, b], ignore_index=True), RMSE)
        self.assertEqual(list(t.columns)[0], "scene")
        self.assertEqual(list(t["scene"]), ["a.gltf"] * 5 + ["b.gltf"] * 5)
        ratios = t[t["configuration"] == "ir64"]["equal-time ratio"]
        self.assertEqual([round(r, 6) for r in ratios], [0.5, 0.5])

    def test_markdown_and_html(self):
        md = M.to_markdown(frame(), RMSE)
        self.assertIn("| ir64 | instant_radiosity | ir | 20.0 | 0.01 | 0.500 |", md)
        self.assertIn("10.00%", md)
        self.assertIn("<b>0.500</b>", M.to_html(frame(), RMSE))  # beats the baseline: bold
        self.assertNotIn("<b>2.000</b>", M.to_html(frame(), RMSE))

    def test_a_sequences_figures_are_its_frames_mean(self):
        rows = [{"config_id": "a", "config_name": "seq", "repeat": f, "param.indirect.method": "lpv",
                 "time.total.ms": 10.0 + f, RMSE: [0.1, 0.2, 0.6][f], "method.coverage": [1.0, 2.0, 3.0][f]}
                for f in range(3)]
        agg = S.aggregate(pd.DataFrame(rows))
        self.assertAlmostEqual(agg[RMSE][0], 0.3)
        self.assertAlmostEqual(agg["method.coverage"][0], 2.0)
        self.assertEqual(agg["time.total.ms"][0], 11.0)  # timings: the median

    def test_report_has_the_section_only_with_methods(self):
        with tempfile.TemporaryDirectory() as tmp:
            sweep = make_sweep(tmp)
            page = _read(report.build_report(sweep))
            self.assertNotIn("<h2>Methods</h2>", page)
            path = os.path.join(sweep, "summary.csv")
            d = pd.read_csv(path)
            d["param.indirect.method"] = ["lpv" if i < 6 else "instant_radiosity" for i in range(len(d))]
            d["method.vpls"] = 12
            d.to_csv(path, index=False)
            page = _read(report.build_report(sweep))
            self.assertIn("<h2>Methods</h2>", page)
            self.assertIn("methods_speed_accuracy.png", page)
            self.assertTrue(os.path.isfile(os.path.join(sweep, "report", "methods.md")))


if __name__ == "__main__":
    unittest.main()
