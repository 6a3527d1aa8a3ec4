"""Sequences in the report: per-frame series from frame records, the plot, and the section with
its video on a synthetic sweep."""
import json
import os
import re
import tempfile
import unittest

from lpvlab_analysis import report, sequences
from tests.fixtures import make_sweep


def _records():
    """Three frames: frame 1 at rest (only the camera moved), frame 2 not."""
    def comparison(rmse):
        return {"indirect_vs_indirect1": {"metrics": {"rmse": rmse, "flip": rmse / 2}}}
    return [
        {"frame": 0, "reference": {"comparison": comparison(0.1)}},
        {"frame": 1, "reference": {"comparison": comparison(0.2)},
         "temporal": {"at_rest": True,
                      "change": {"indirect": {"relative": 0.01}},
                      "error": {"indirect_vs_indirect1": {"relative": 0.03}}}},
        {"frame": 2, "reference": {"comparison": comparison(0.3)},
         "temporal": {"at_rest": False,
                      "change": {"indirect": {"relative": None}},  # a black frame
                      "error": {"indirect_vs_indirect1": {"relative": 0.05}}}},
    ]


class SequencesTest(unittest.TestCase):
    def test_frame_series(self):
        series, at_rest = sequences.frame_series(_records())
        self.assertEqual(series[("error", "rmse indirect_vs_indirect1")], [(0, 0.1), (1, 0.2), (2, 0.3)])
        self.assertEqual(series[("error", "flip indirect_vs_indirect1")], [(0, 0.05), (1, 0.1), (2, 0.15)])
        self.assertEqual(series[("temporal", "change indirect")], [(1, 0.01)])  # null left out
        self.assertEqual(series[("temporal", "temporal error indirect_vs_indirect1")], [(1, 0.03), (2, 0.05)])
        self.assertEqual(at_rest, {1})

    def test_static_runs_have_no_section(self):
        with tempfile.TemporaryDirectory() as tmp:
            self.assertIsNone(sequences.read_records(tmp))  # no manifest
            with open(os.path.join(tmp, "manifest.json"), "w") as f:
                json.dump({"sequence": {"frame_records": [{"frame": 0}]}}, f)  # one frame
            self.assertIsNone(sequences.read_records(tmp))
            self.assertEqual(sequences.sequence_section([("a", "000", tmp)], tmp, tmp), [])

    def test_report_shows_the_plot_and_the_video(self):
        with tempfile.TemporaryDirectory() as tmp:
            root = make_sweep(tmp)
            run = os.path.join(root, "001")
            with open(os.path.join(run, "manifest.json")) as f:
                manifest = json.load(f)
            manifest["sequence"] = {"frames": 3, "frame_records": _records()}
            with open(os.path.join(run, "manifest.json"), "w") as f:
                json.dump(manifest, f)
            with open(os.path.join(run, "video.mp4"), "wb") as f:
                f.write(b"\0")
            index = report.build_report(root)
            with open(index) as f:
                page = f.read()
            self.assertIn("<h2>Sequences</h2>", page)
            self.assertEqual(page.count("<video"), 1)
            base = os.path.dirname(index)
            srcs = re.findall(r"src='([^']+)'", page)
            self.assertIn("img/frames_001.png", srcs)
            self.assertIn("../001/video.mp4", srcs)
            for src in srcs:
                self.assertTrue(os.path.exists(os.path.join(base, src)), src)


if __name__ == "__main__":
    unittest.main()
