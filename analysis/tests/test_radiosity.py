"""The radiosity section (radiosity.py): its table by time to solution, its plot, and the section
in a report only when a sweep has radiosity runs; on hand-made frames."""
import math
import os
import tempfile
import unittest

import pandas as pd

from lpvlab_analysis import radiosity as R
from lpvlab_analysis import report
from tests.fixtures import make_sweep

RMSE = "metric.indirect_vs_indirect1.rmse"


def frame():
    """Two LPV runs and three radiosity runs (hemicube at two patch counts, rays)."""
    rows = [("lpv16", "lpv", "baseline", 10.0, 0.04, {}),
            ("lpv32", "lpv", "baseline", 40.0, 0.01, {}),
            ("rad_coarse", "radiosity", "hemicube", 2.0, 0.03,
             {"method.patches": 500, "method.solution_ms.total": 900.0, "method.solution_ms.form_factors": 800.0,
              "method.form_factors.estimator.resolution": 64}),
            ("rad_fine", "radiosity", "hemicube", 2.5, 0.008,
             {"method.patches": 4000, "method.solution_ms.total": 12000.0, "method.solution_ms.form_factors": 11000.0,
              "method.form_factors.estimator.resolution": 64}),
            ("rad_rays", "radiosity", "rays", 2.2, 0.012,
             {"method.patches": 4000, "method.solution_ms.total": 3000.0,
              "method.form_factors.estimator.rays_per_side": 1024})]
    out = []
    for i, (name, method, series, t, e, figures) in enumerate(rows):
        r = {"config_id": f"{i:03d}", "config_name": name, "param.indirect.method": method,
             "param.series": series, "time.total.ms": t, RMSE: e}
        r.update(figures)
        out.append(r)
    return pd.DataFrame(out)


class RadiosityTest(unittest.TestCase):
    def test_table_lists_radiosity_runs_by_time_to_solution(self):
        t = R.table(frame(), RMSE)
        self.assertEqual(list(t["configuration"]), ["rad_coarse", "rad_rays", "rad_fine"])
        row = t.set_index("configuration").loc["rad_rays"]
        self.assertEqual(row["rays per side"], 1024)
        self.assertTrue(math.isnan(row["hemicube px"]))
        self.assertEqual(row["solution ms"], 3000.0)
        self.assertEqual(row["frame ms"], 2.2)
        self.assertEqual(row["error"], 0.012)

    def test_markdown_html_and_plot(self):
        md = R.to_markdown(frame(), RMSE)
        self.assertIn("| rad_fine | hemicube | 4000 |", md)
        self.assertNotIn("lpv16", md)
        self.assertIn("<td>rad_rays</td>", R.to_html(frame(), RMSE))
        with tempfile.TemporaryDirectory() as tmp:
            path = R.plot(frame(), os.path.join(tmp, "r.png"), RMSE)
            self.assertTrue(os.path.getsize(path) > 1000)
            self.assertIsNone(R.plot(frame().drop(columns=[R.SOLUTION_COL]), os.path.join(tmp, "s.png"), RMSE))
            # Two scenes (a report of several sweeps): one marker and one LPV line per scene.
            a, b = frame(), frame()
            a["param.scene.file"], b["param.scene.file"] = "shared:scenes/a.obj", "shared:scenes/b.gltf"
            both = pd.concat([a, b], ignore_index=True)
            self.assertTrue(os.path.getsize(R.plot(both, os.path.join(tmp, "t.png"), RMSE)) > 1000)
            self.assertEqual(sorted(set(R._scenes(both))), ["a.obj", "b.gltf"])

    def test_report_has_the_section_only_with_radiosity(self):
        with tempfile.TemporaryDirectory() as tmp:
            sweep = make_sweep(tmp)
            self.assertNotIn("<h2>Radiosity</h2>", open(report.build_report(sweep)).read())
            path = os.path.join(sweep, "summary.csv")
            d = pd.read_csv(path)
            d["param.indirect.method"] = ["lpv" if i < 6 else "radiosity" for i in range(len(d))]
            d[R.SOLUTION_COL] = [math.nan if i < 6 else 1000.0 + i for i in range(len(d))]
            d["method.patches"] = 100
            d.to_csv(path, index=False)
            page = open(report.build_report(sweep)).read()
            self.assertIn("<h2>Radiosity</h2>", page)
            self.assertIn("radiosity_time_to_solution.png", page)
            self.assertTrue(os.path.isfile(os.path.join(sweep, "report", "radiosity.md")))


if __name__ == "__main__":
    unittest.main()
