"""Convergence curves (convergence.py): the fitted slope recovers known power laws and ignores
points at the noise floor, each configuration's budget is its method's own count, curves are
grouped by series, the section applies only with three budgets or more, and the reference's
noise is no metric of the ablation table."""
import math
import os
import tempfile
import unittest

import pandas as pd

from lpvlab_analysis import convergence as C
from lpvlab_analysis import sections
from lpvlab_analysis import summary as S

METRIC = "metric.indirect_vs_indirect1.rmse"
FLOOR = "metric.indirect_vs_indirect1.noise_floor_rmse"


def sweep(floor=0.0):
    """LPV over cell-iterations with error = 2 budget^-0.25 (a slow method), instant radiosity over
    walks with 3 walks^-0.5 (Monte Carlo), and two RSM-gathering points (too few for a curve)."""
    rows = []
    for res in (8, 16, 32, 64):
        budget = float(res ** 3 * res)
        rows.append({"config_name": f"lpv{res}", "param.indirect.method": "lpv", "param.series": "lpv_scaled",
                     "work.propagation.cell-iterations": budget, S.TIME_COL: budget * 1e-6,
                     METRIC: 2.0 * budget ** -0.25, FLOOR: floor})
    for walks in (16, 64, 256, 1024, 4096):
        rows.append({"config_name": f"ir{walks}", "param.indirect.method": "instant_radiosity",
                     "param.series": "", "method.light_paths": float(walks), S.TIME_COL: walks * 0.01,
                     METRIC: 3.0 * walks ** -0.5, FLOOR: floor})
    for samples in (100, 400):
        rows.append({"config_name": f"rsm{samples}", "param.indirect.method": "rsm_gather", "param.series": "",
                     "method.samples_per_pixel_and_view": float(samples), S.TIME_COL: samples * 0.01,
                     METRIC: 0.1, FLOOR: floor})
    return pd.DataFrame(rows)


class ConvergenceTest(unittest.TestCase):
    def test_slopes_recover_power_laws(self):
        t = C.table(sweep(), METRIC).set_index("series")
        self.assertEqual(sorted(t.index), ["instant_radiosity", "lpv_scaled"])  # rsm_gather: 2 points
        self.assertAlmostEqual(t.loc["lpv_scaled", "slope vs budget"], -0.25, places=6)
        self.assertAlmostEqual(t.loc["instant_radiosity", "slope vs budget"], -0.5, places=6)
        # Time is proportional to budget here, so the slope against time is the same.
        self.assertAlmostEqual(t.loc["instant_radiosity", "slope vs time"], -0.5, places=6)
        self.assertEqual(t.loc["lpv_scaled", "budget"], "cell-iterations")
        self.assertEqual(t.loc["instant_radiosity", "budget"], "light paths")
        self.assertEqual(t.loc["instant_radiosity", "points"], 5)

    def test_points_at_the_floor_are_left_out_of_the_fit(self):
        # A floor of 0.03: IR's last points (3/sqrt(1024) = 0.094, 3/64 = 0.047) stay above 2x the
        # floor only down to 1024 walks; an error flattened at the floor must not pull the slope up.
        df = sweep(floor=0.03)
        df.loc[df["config_name"] == "ir4096", METRIC] = 0.031
        t = C.table(df, METRIC).set_index("series")
        self.assertAlmostEqual(t.loc["instant_radiosity", "slope vs budget"], -0.5, places=6)
        self.assertAlmostEqual(t.loc["instant_radiosity", "noise floor"], 0.03)
        self.assertTrue(math.isnan(C.slope([1, 2], [1, 0.5])))  # too few points
        self.assertTrue(math.isnan(C.noise_floor(df, "metric.indirect_vs_indirect1.ssim")))  # RMSE only

    def test_the_section_applies_and_draws(self):
        self.assertTrue(C.has_curves(sweep()))
        self.assertFalse(C.has_curves(sweep().iloc[:2]))
        with tempfile.TemporaryDirectory() as d:
            path = C.plot(sweep(floor=0.01), os.path.join(d, "c.png"), METRIC)
            self.assertTrue(path and os.path.getsize(path) > 0)
        html = str(C.to_html(sweep(), METRIC))
        self.assertIn("slope vs budget", html)
        self.assertIn("-0.50", html)
        self.assertIn("Convergence", [s.title for s in sections._REGISTRY])

    def test_the_noise_floor_is_no_metric(self):
        self.assertIn(METRIC, S.metric_columns(sweep()))
        self.assertNotIn(FLOOR, S.metric_columns(sweep()))


if __name__ == "__main__":
    unittest.main()
