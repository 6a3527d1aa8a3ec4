"""The plots as a reader needs them (issue 39): every point of the speed/accuracy plot named, its
y axis with its metric's unit; the error-vs-parameter panels in rows, each with a labelled y axis."""
import os
import tempfile
import unittest

import matplotlib.image as mpimg

from lpvlab_analysis import plots
from lpvlab_analysis import summary as S
from tests.fixtures import make_sweep


class PlotsTest(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.dir = make_sweep(self.tmp.name, with_exr=False)
        self.agg = S.aggregate(S.load_summary(os.path.join(self.dir, "summary.csv")))
        self.figures = []
        self.save = plots._save

        def keep(fig, path):  # the figure as drawn, before it is saved and closed
            self.figures.append(fig)
            return self.save(fig, path)
        plots._save = keep

    def tearDown(self):
        plots._save = self.save
        self.tmp.cleanup()

    def test_every_speed_accuracy_point_is_named_and_the_axis_has_its_unit(self):
        path = plots.speed_accuracy(self.agg, os.path.join(self.tmp.name, "sa.png"),
                                    "metric.indirect_vs_indirect1.rmse")
        self.assertTrue(os.path.isfile(path))
        ax = self.figures[0].axes[0]
        named = {t.get_text() for t in ax.texts}
        self.assertEqual(named & set(self.agg["config_name"]), set(self.agg["config_name"]))
        self.assertIn("W/(m² sr)", ax.get_ylabel())
        self.assertIn("lower is better", ax.get_ylabel())
        self.assertIn("ms, median", ax.get_xlabel())

    def test_error_panels_wrap_into_rows_with_labelled_y_axes(self):
        metrics = S.metric_columns(self.agg)
        self.assertGreater(len(metrics), plots.ERROR_PANELS_PER_ROW)
        path = plots.error_vs_param(self.agg, "param.propagation.iterations",
                                    os.path.join(self.tmp.name, "err.png"))
        visible = [ax for ax in self.figures[0].axes if ax.get_visible()]
        self.assertEqual(len(visible), len(metrics))
        for ax in visible:
            self.assertTrue(ax.get_ylabel(), ax.get_title())
            self.assertTrue(ax.get_xlabel())
        # At most ERROR_PANELS_PER_ROW to a row: no strip many times wider than tall.
        height, width = mpimg.imread(path).shape[:2]
        self.assertLess(width / height, 2.0)

    def test_metric_axis_labels_name_the_pair_unit_and_direction(self):
        self.assertEqual(S.metric_axis_label("metric.indirect_vs_indirect1.psnr"),
                         "indirect_vs_indirect1 psnr (dB; higher is better)")
        self.assertIn("over the reference's mean", S.metric_axis_label("metric.direct_vs_direct.block_nrmse"))
        self.assertEqual(S.metric_axis_label("metric.a_vs_b.novel"), "a_vs_b novel (lower is better)")


if __name__ == "__main__":
    unittest.main()
