"""The particles section (particles.py): its table by drawing, scene and count, its plot, and the
section in a report only when a sweep has runs with particles; on hand-made frames."""
import math
import os
import tempfile
import unittest

import pandas as pd

from lpvlab_analysis import particles as P
from lpvlab_analysis import report
from tests.fixtures import make_sweep

RMSE = "metric.indirect_vs_indirect1.rmse"


def frame():
    """Four counts drawn as geometry, two as light fields, and a run without particles."""
    rows = [("g100", "geometry", 120, 5.0, 0.05), ("g1k", "geometry", 1200, 9.0, 0.05),
            ("g10k", "geometry", 12000, 40.0, 0.06), ("g100k", "geometry", 96000, 300.0, 0.07),
            ("lf1k", "light_field", 1200, 6.0, 0.055), ("lf100k", "light_field", 96000, 30.0, 0.08),
            ("none", None, math.nan, 4.0, 0.05)]
    out = []
    for i, (name, draw, alive, t, e) in enumerate(rows):
        out.append({"config_id": f"{i:03d}", "config_name": name, P.DRAW_COL: draw,
                    P.ALIVE_COL: alive, P.TRIANGLES_COL: alive * 8, "gpu_ms.total": t, RMSE: e})
    return pd.DataFrame(out)


class ParticlesTest(unittest.TestCase):
    def test_table_orders_runs_by_drawing_and_count(self):
        t = P.table(frame(), RMSE)
        self.assertEqual(list(t["configuration"]), ["g100", "g1k", "g10k", "g100k", "lf1k", "lf100k"])
        row = t.set_index("configuration").loc["lf100k"]
        self.assertEqual(row["drawing"], "light_field")
        self.assertEqual(row["particles"], 96000)
        self.assertEqual(row["triangles"], 768000)
        self.assertEqual(row["frame ms"], 30.0)
        self.assertEqual(row["error"], 0.08)

    def test_a_sweep_without_the_draw_key_is_geometry(self):
        t = P.table(frame().drop(columns=[P.DRAW_COL]), RMSE)
        self.assertEqual(set(t["drawing"]), {"geometry"})

    def test_markdown_html_and_plot(self):
        md = P.to_markdown(frame(), RMSE)
        self.assertIn("| g10k |  | geometry | 12000 | 96000 | 40.0 | 0.06 |", md)
        self.assertNotIn("none", md)
        self.assertIn("<td>lf1k</td>", P.to_html(frame(), RMSE))
        with tempfile.TemporaryDirectory() as tmp:
            path = P.plot(frame(), os.path.join(tmp, "p.png"), RMSE)
            self.assertTrue(os.path.getsize(path) > 1000)
            self.assertIsNone(P.plot(frame()[frame()["config_name"] == "none"], os.path.join(tmp, "q.png"), RMSE))

    def test_report_has_the_section_only_with_particles(self):
        with tempfile.TemporaryDirectory() as tmp:
            sweep = make_sweep(tmp)
            self.assertNotIn("<h2>Particles</h2>", open(report.build_report(sweep)).read())
            path = os.path.join(sweep, "summary.csv")
            d = pd.read_csv(path)
            d[P.ALIVE_COL] = [100.0 * (1 + i) for i in range(len(d))]
            d[P.TRIANGLES_COL] = d[P.ALIVE_COL] * 8
            d.to_csv(path, index=False)
            page = open(report.build_report(sweep)).read()
            self.assertIn("<h2>Particles</h2>", page)
            self.assertIn("particles_count.png", page)
            self.assertTrue(os.path.isfile(os.path.join(sweep, "report", "particles.md")))


if __name__ == "__main__":
    unittest.main()
