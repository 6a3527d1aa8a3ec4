"""The particles section (particles.py): its table by drawing, scene and count, its plot, the
light-field resolution table and plot, and the section in a report only when a sweep has runs
with particles (the resolution part only for light fields at several resolutions); on hand-made
frames."""
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
                    P.ALIVE_COL: alive, P.TRIANGLES_COL: alive * 8, "time.total.ms": t, RMSE: e})
    return pd.DataFrame(out)


def resolution_frame():
    """Light fields of 12 000 particles at 16, 32 and 64 texels, 8 x 4 and 16 x 8 views, blended or
    not, and one geometry run of the same particles."""
    out = []
    for views in ((8, 4), (16, 8)):
        for interpolate in (True, False):
            for texels in (16, 32, 64):
                name = f"{views[0]}x{views[1]}-{texels}-{'b' if interpolate else 'n'}"
                out.append({"config_id": f"{len(out):03d}", "config_name": name, P.DRAW_COL: "light_field",
                            P.AZIMUTHS_COL: views[0], P.ELEVATIONS_COL: views[1], P.INTERPOLATE_COL: interpolate,
                            P.RESOLUTION_COL: texels, P.ALIVE_COL: 12000.0, P.TRIANGLES_COL: 96000.0,
                            "time.total.ms": 1000.0 + texels * (2 if interpolate else 1),
                            RMSE: 0.05 + 0.1 / texels / views[0]})
    out.append({"config_id": "999", "config_name": "geometry", P.DRAW_COL: "geometry", P.ALIVE_COL: 12000.0,
                P.TRIANGLES_COL: 96000.0, "time.total.ms": 300.0, RMSE: 0.055})
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

    def test_resolution_table_has_the_light_fields_by_views_blending_and_texels(self):
        t = P.resolution_table(resolution_frame(), RMSE)
        self.assertEqual(len(t), 12)  # not the geometry run
        self.assertEqual(list(t["texels"][:3]), [16.0, 32.0, 64.0])
        row = t.set_index("configuration").loc["16x8-32-n"]
        self.assertEqual(row["views"], "16 x 8")
        self.assertEqual(row["blending"], "nearest")
        self.assertEqual(row["frame ms"], 1032.0)
        self.assertAlmostEqual(row["error"], 0.05 + 0.1 / 32 / 16)
        self.assertEqual(t.set_index("configuration").loc["8x4-64-b"]["blending"], "blended")
        self.assertTrue(P.has_resolution_sweep(resolution_frame()))
        self.assertFalse(P.has_resolution_sweep(frame()))  # counts, no resolutions
        self.assertIn("| 8x4-16-b | 8 x 4 | blended | 16 | 12000 | 1032.0 |",
                      P.resolution_markdown(resolution_frame(), RMSE))
        with tempfile.TemporaryDirectory() as tmp:
            self.assertTrue(os.path.getsize(P.plot_resolution(resolution_frame(), os.path.join(tmp, "r.png"), RMSE)) > 1000)
            self.assertIsNone(P.plot_resolution(frame(), os.path.join(tmp, "s.png"), RMSE))
            # One count only: the count plot has nothing to draw.
            self.assertIsNone(P.plot(resolution_frame(), os.path.join(tmp, "c.png"), RMSE))

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
            self.assertNotIn("particles_resolution.png", page)
            d[P.DRAW_COL] = "light_field"
            d[P.RESOLUTION_COL] = [16 * (1 + i % 3) for i in range(len(d))]
            d.to_csv(path, index=False)
            page = open(report.build_report(sweep)).read()
            self.assertIn("particles_resolution.png", page)
            self.assertTrue(os.path.isfile(os.path.join(sweep, "report", "particles_resolution.md")))


if __name__ == "__main__":
    unittest.main()
