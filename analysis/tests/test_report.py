"""End-to-end report on a synthetic sweep dir, and CLI errors (exit code 2)."""
import os
import re
import subprocess
import sys
import tempfile
import unittest

from lpvlab_analysis import images, report
from tests.fixtures import make_sweep

CLI = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "report.py")


def _srcs(index):
    with open(index) as f:
        page = f.read()
    return page, re.findall(r"(?:src|href)='([^']+)'", page)


class ReportTest(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.dir = make_sweep(self.tmp.name)

    def tearDown(self):
        self.tmp.cleanup()

    def _check(self, index):
        self.assertTrue(os.path.isfile(index))
        page, refs = _srcs(index)
        self.assertTrue(refs)
        base = os.path.dirname(index)
        for r in refs:
            self.assertTrue(os.path.exists(os.path.join(base, r)), r)
        self.assertIn("speed_accuracy.png", page)
        self.assertIn("<table class=\"ablation\">", page)
        self.assertIn("Trends vs the thesis", page)
        self.assertIn("thesis_8.5.png", page)
        self.assertIn("thesis_8.6.png", page)
        self.assertIn("stages_propagation.iterations.png", page)
        self.assertIn("error_propagation.iterations.png", page)
        self.assertNotIn(".tmp", "".join(os.listdir(os.path.join(base, "img"))))
        return page

    def test_end_to_end(self):
        index = report.build_report(self.dir)
        page = self._check(index)
        self.assertEqual(index, os.path.join(self.dir, "report", "index.html"))
        if images.have_oiio():
            self.assertIn("img/reference_0.png", page)
            self.assertIn("img/result_000.png", page)
        self.assertIn("../000/error_indirect.png", page)
        # Issue 35: times are named by their clock and where they ran, never all called GPU times.
        self.assertNotIn("GPU timestamp", page)
        self.assertIn("each stage by its own clock: GL stages on llvmpipe (LLVM 15.0.6, 256 bits), "
                      "CPU stages on Test CPU 9000", page)

    def test_configurations_appear_in_the_order_of_their_swept_values(self):
        # Config ids that say nothing of the order (reversed), iterations 1, 4, 16 (numbers, not
        # text: 16 is not before 4), propagation types as text.
        import csv
        path = os.path.join(self.dir, "summary.csv")
        with open(path) as f:
            rows = list(csv.DictReader(f))
        ids = sorted({r["config_id"] for r in rows})
        rename = dict(zip(ids, reversed(ids)))
        for old in ids:
            os.rename(os.path.join(self.dir, old), os.path.join(self.dir, "tmp-" + old))
        for old in ids:
            os.rename(os.path.join(self.dir, "tmp-" + old), os.path.join(self.dir, rename[old]))
        for r in rows:
            r["config_id"] = r["run_dir"] = rename[r["config_id"]]
        with open(path, "w", newline="") as f:
            w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
            w.writeheader()
            w.writerows(rows)
        page = self._check(report.build_report(self.dir))
        section = page[page.index("Images per configuration"):]
        names = re.findall(r"<h3>([a-z_0-9]+) <span", section)
        self.assertEqual(names, ["occlusion_it1", "occlusion_it4", "occlusion_it16",
                                 "standard_it1", "standard_it4", "standard_it16"])
        # Each links to its run's EXR and manifest (_check: every link exists).
        self.assertEqual(section.count(">EXR</a>"), 6 if images.have_oiio() else 0)
        self.assertEqual(section.count(">manifest</a>"), 6)

    def test_several_sweeps_in_one_report(self):
        other = make_sweep(os.path.join(self.tmp.name, "second"))
        out = os.path.join(self.tmp.name, "both")
        index = report.build_report([self.dir, other], out)
        page = self._check(index)
        self.assertIn("12 configurations", page)  # 6 from each, kept apart by their sweep's name
        self.assertIn("second", page)
        with self.assertRaises(report.S.SummaryError):
            report.build_report([self.dir, other])  # several sweeps need --out
        r = subprocess.run([sys.executable, CLI, self.dir, other, "--out", out + "2", "--no-exr"],
                           capture_output=True, text=True)
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertTrue(os.path.isfile(os.path.join(out + "2", "index.html")))

    def test_png_fallback_and_cli(self):
        out = os.path.join(self.tmp.name, "elsewhere")
        r = subprocess.run([sys.executable, CLI, self.dir, "--out", out, "--no-exr",
                            "--metric", "metric.indirect_vs_indirect1.flip"], capture_output=True, text=True)
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertIn("[report]", r.stderr)
        page = self._check(os.path.join(out, "index.html"))
        self.assertIn("combined.png", page)
        self.assertNotIn("reference_0.png", page)

    def test_the_gpu_estimate_speed_axis_is_labelled_and_an_unknown_gpu_refused(self):
        out = os.path.join(self.tmp.name, "estimated")
        r = subprocess.run([sys.executable, CLI, self.dir, "--out", out, "--no-exr", "--time", "gpu-estimate",
                            "--gpu", "rtx_4090"], capture_output=True, text=True)
        self.assertEqual(r.returncode, 0, r.stderr)
        page = self._check(os.path.join(out, "index.html"))
        self.assertIn("estimated on", page)
        self.assertIn("not a measurement", page)
        r = subprocess.run([sys.executable, CLI, self.dir, "--out", out + "2", "--time", "gpu-estimate",
                            "--gpu", "voodoo2"], capture_output=True, text=True)
        self.assertEqual(r.returncode, 2, r.stderr)
        self.assertIn("--gpu voodoo2", r.stderr)
        self.assertIn("rtx_4090", r.stderr)
        self.assertFalse(os.path.exists(out + "2"), "nothing written before the inputs are checked")

    def test_cli_errors(self):
        for d, needle in [(os.path.join(self.tmp.name, "missing"), "missing"),
                          (os.path.join(self.tmp.name, "000"), "summary.csv")]:
            r = subprocess.run([sys.executable, CLI, d], capture_output=True, text=True)
            self.assertEqual(r.returncode, 2, r.stderr)
            self.assertIn(needle, r.stderr)
            self.assertNotIn("Traceback", r.stderr)
        empty = os.path.join(self.tmp.name, "empty")
        os.makedirs(empty)
        open(os.path.join(empty, "summary.csv"), "w").close()
        r = subprocess.run([sys.executable, CLI, empty], capture_output=True, text=True)
        self.assertEqual(r.returncode, 2)
        self.assertIn(os.path.join(empty, "summary.csv"), r.stderr)

    def test_no_metrics(self):
        d = make_sweep(os.path.join(self.tmp.name, "nometrics"), with_exr=False, with_metrics=False)
        page, refs = _srcs(report.build_report(d))
        self.assertIn("No data for", page)
        # A metric named on the command line must exist: here there are none to name.
        r = subprocess.run([sys.executable, CLI, d, "--metric", "rmse", "--out",
                            os.path.join(self.tmp.name, "nometrics-report")],
                           capture_output=True, text=True)
        self.assertEqual(r.returncode, 2, r.stderr)
        self.assertIn("lpvlab: error: --metric rmse: this sweep has no error metrics", r.stderr)

    def test_unknown_metric_is_an_error_listing_the_sweeps_metrics(self):
        out = os.path.join(self.tmp.name, "nosuch-report")
        r = subprocess.run([sys.executable, CLI, self.dir, "--metric", "nosuch", "--out", out],
                           capture_output=True, text=True)
        self.assertEqual(r.returncode, 2, r.stderr)
        self.assertIn("lpvlab: error: --metric nosuch: not a metric of this sweep; it has ", r.stderr)
        self.assertIn("indirect_vs_indirect1.rmse", r.stderr)
        self.assertNotIn("Traceback", r.stderr)
        self.assertFalse(os.path.exists(out), "nothing is written for a refused metric")
        # --out naming a file: an error, not a traceback.
        afile = os.path.join(self.tmp.name, "a_file")
        open(afile, "w").close()
        r = subprocess.run([sys.executable, CLI, self.dir, "--out", afile], capture_output=True, text=True)
        self.assertEqual(r.returncode, 2, r.stderr)
        self.assertIn(f"lpvlab: error: --out {afile}: is a file, not a directory", r.stderr)
        self.assertNotIn("Traceback", r.stderr)
        # Bare and pair-qualified names of metrics the sweep has still resolve.
        for name in ("rmse", "indirect_vs_indirect1.rmse"):
            self.assertTrue(os.path.exists(report.build_report(self.dir, os.path.join(self.tmp.name, name), name)))


if __name__ == "__main__":
    unittest.main()
