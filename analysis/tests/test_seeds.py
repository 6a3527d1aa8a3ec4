"""Bias over seeds (seeds.py): a heavy-tailed but unbiased estimator passes and shows a median
below its mean, a biased one is rejected, the reference's own standard error widens the test, and
the section applies only where a seed is swept."""
import os
import tempfile
import unittest

import numpy as np
import pandas as pd

from lpvlab_analysis import seeds as B
from lpvlab_analysis import summary as S

PAIR = "indirect_vs_indirect1"
RATIO = f"metric.{PAIR}.ratio_of_means"
REFERENCE_ERROR = f"metric.{PAIR}.mean_reference_relative_standard_error"
METRIC = f"metric.{PAIR}.rmse"


def sweep(draws_by_paths, reference_error=0.001):
    """One configuration per (light paths, seed); `draws_by_paths`: paths -> the draws' ratios."""
    rows = []
    for paths, draws in draws_by_paths.items():
        for seed, ratio in enumerate(draws, start=1):
            rows.append({"config_id": f"{paths}-{seed}", "config_name": f"ir{paths}_s{seed}",
                         "param.indirect.light_paths": paths, "param.indirect.seed": seed,
                         RATIO: ratio, REFERENCE_ERROR: reference_error, METRIC: 0.1})
    return pd.DataFrame(rows)


class SeedsTest(unittest.TestCase):
    def test_heavy_tailed_unbiased_draws_pass_with_the_median_below_the_mean(self):
        # Lognormal with mean exactly 1: exp(N(-sigma^2/2, sigma)), sigma 1 (heavy right tail).
        random = np.random.default_rng(7)
        heavy = np.exp(random.normal(-0.5, 1.0, 400))
        t = B.groups(sweep({256: heavy / heavy.mean() * 1.0}), METRIC)
        row = t.iloc[0]
        self.assertEqual(row["draws"], 400)
        self.assertAlmostEqual(row["mean ratio"], 1.0, places=9)
        self.assertLess(row["median ratio"], 0.75)  # the median of exp(N(-0.5, 1)) is 0.61
        self.assertEqual(row["unbiased at 1%"], "yes")

    def test_biased_draws_are_rejected(self):
        random = np.random.default_rng(8)
        t = B.groups(sweep({64: random.normal(0.85, 0.02, 16), 1024: random.normal(1.0, 0.02, 16)}), METRIC)
        t = t.set_index("indirect.light_paths")
        self.assertEqual(t.loc[64, "unbiased at 1%"], "no (biased)")
        self.assertLess(t.loc[64, "z"], -10)
        self.assertEqual(t.loc[1024, "unbiased at 1%"], "yes")

    def test_the_references_error_is_part_of_the_test(self):
        # Draws without spread at 0.99: z = -0.01 / e.
        loose = B.groups(sweep({256: [0.99] * 8}, reference_error=0.01), METRIC).iloc[0]
        self.assertAlmostEqual(loose["z"], -1.0, places=9)
        self.assertAlmostEqual(loose["largest share"], 1.0 / 8.0, places=9)  # equal draws: 1/K
        self.assertEqual(loose["unbiased at 1%"], "yes")
        tight = B.groups(sweep({256: [0.99] * 8}, reference_error=0.001), METRIC).iloc[0]
        self.assertAlmostEqual(tight["z"], -10.0, places=9)
        self.assertEqual(tight["unbiased at 1%"], "no (biased)")

    def test_the_section_applies_only_where_a_seed_is_swept_and_draws(self):
        with_seeds = sweep({64: [0.9, 1.1], 256: [1.0, 1.02]})
        self.assertTrue(B.has_groups(with_seeds))
        self.assertFalse(B.has_groups(with_seeds[with_seeds["param.indirect.seed"] == 1]))
        # The ratio of means is no error metric: not a column of the ablation table's metrics.
        self.assertNotIn(RATIO, S.metric_columns(with_seeds))
        self.assertNotIn(REFERENCE_ERROR, S.metric_columns(with_seeds))
        with tempfile.TemporaryDirectory() as d:
            path = B.plot(with_seeds, os.path.join(d, "bias.png"), METRIC)
            self.assertTrue(os.path.getsize(path) > 0)
            self.assertIn("| 64 |", B.to_markdown(with_seeds, METRIC))


if __name__ == "__main__":
    unittest.main()
