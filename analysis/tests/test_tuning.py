"""A tune's page (tuning.py): the Pareto front is what nothing beats, the plot has labelled axes
and marks the chosen configuration, the page lists the last rung and the held-out views, and a
directory without rungs is refused by name."""
import json
import os
import tempfile
import unittest

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from lpvlab_analysis import report  # noqa: E402
from lpvlab_analysis import summary as S  # noqa: E402
from lpvlab_analysis import tuning as T  # noqa: E402

RESULT = {
    "file": "tune.toml", "goal": "the least indirect_vs_indirect1.block_nrmse within 5 ms (method)",
    "metric": "indirect_vs_indirect1.block_nrmse", "time": "method", "eta": 3, "host": {"cpu": "test CPU"},
    "clock": "each run's own", "candidates": {"baseline": [], "a1": ["grid.resolution=16"], "b2": ["grid.resolution=48"]},
    "rungs": [
        {"samples": 16, "budget_ms": 5.0, "promoted": ["a1"], "results": [
            {"id": "baseline", "error": 2.0, "ms": 4.0, "feasible": True},
            {"id": "a1", "error": 1.0, "ms": 3.0, "feasible": True},
            {"id": "b2", "error": 0.8, "ms": 9.0, "feasible": False}]},
        {"samples": 64, "budget_ms": 5.0, "promoted": [], "results": [
            {"id": "baseline", "error": 2.1, "ms": 4.1, "feasible": True},
            {"id": "a1", "error": 0.9, "ms": 3.1, "feasible": True}]}],
    "chosen": {"id": "a1", "error": 0.9, "ms": 3.1, "feasible": True, "overrides": ["grid.resolution=16"]},
    "held_out": {"other": {"chosen": {"error": 0.5, "ms": 3.0}, "baseline": {"error": 1.5, "ms": 4.0},
                           "baseline_over_chosen": 3.0}},
}


def _page_of(result):
    """The tune page built from `result` as tune.json."""
    with tempfile.TemporaryDirectory() as root:
        with open(os.path.join(root, "tune.json"), "w") as f:
            json.dump(result, f)
        with open(report.build_report(root)) as f:
            return f.read()


class Tuning(unittest.TestCase):
    def test_the_front_keeps_only_what_nothing_beats(self):
        self.assertEqual(T.pareto([(3, 1.0, "a"), (4, 2.0, "b"), (9, 0.8, "c"), (5, 0.9, "d")]),
                         [(3, 1.0, "a"), (5, 0.9, "d"), (9, 0.8, "c")])

    def test_the_plot_names_its_axes_and_marks_the_chosen(self):
        fig = T.figure(RESULT)
        ax = fig.axes[0]
        self.assertIn("ms", ax.get_xlabel())
        self.assertIn("test CPU", ax.get_xlabel())
        self.assertIn("block_nrmse", ax.get_ylabel())
        labels = [t.get_text() for t in ax.get_legend().get_texts()]
        self.assertIn("chosen", labels)
        self.assertIn("time budget", labels)
        plt.close(fig)

    def test_the_page_lists_the_last_rung_and_the_held_out_views(self):
        with tempfile.TemporaryDirectory() as root:
            with open(os.path.join(root, "tune.json"), "w") as f:
                json.dump(RESULT, f)
            index = report.build_report(root)
            with open(index) as f:
                page = f.read()
            self.assertIn("grid.resolution=16", page)
            self.assertIn("3.00", page)  # baseline / chosen on the held-out view
            self.assertTrue(os.path.isfile(os.path.join(root, "report", "img", "pareto.png")))

    def test_an_estimated_tune_says_its_times_are_an_estimate_and_on_which_gpu(self):
        result = dict(RESULT, time="gpu-estimate", gpu="h100_sxm",
                      clock="an estimate from counted work, not a measurement: the indirect method's GL kernels")
        fig = T.figure(result)
        label = fig.axes[0].get_xlabel()
        plt.close(fig)
        self.assertIn("h100_sxm", label)
        self.assertIn("not a measurement", label)
        self.assertNotIn("test CPU", label)  # not timed there
        page = _page_of(result)
        self.assertIn("GPU-estimated ms", page)
        self.assertIn("not a measurement", page)

    def test_the_page_shows_the_fitted_constants_and_whether_they_were_adopted(self):
        result = dict(RESULT, fit={
            "directory": "/x/fit", "converged": True, "adopted": False,
            "parameters": [{"key": "propagation.far_face_solid_angle", "before": 0.4007, "after": 0.2468,
                            "undetermined": False}],
            "before": {"id": "a1", "error": 0.9, "ms": 3.1, "feasible": True},
            "after": {"id": "fitted", "error": 0.95, "ms": 3.1, "feasible": True}})
        page = _page_of(result)
        self.assertIn("propagation.far_face_solid_angle", page)
        self.assertIn("0.2468", page)
        self.assertIn("not adopted", page)

    def test_a_directory_without_rungs_is_refused(self):
        with tempfile.TemporaryDirectory() as root:
            with open(os.path.join(root, "tune.json"), "w") as f:
                json.dump({"file": "x"}, f)
            with self.assertRaises(S.SummaryError) as caught:
                report.build_report(root)
            self.assertIn("tune.json", str(caught.exception))


if __name__ == "__main__":
    unittest.main()
