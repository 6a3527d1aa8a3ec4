"""An explanation's page (explain.py): its bar chart has one bar per stage and labelled axes, the
page holds both tables with every stage, the chain's images are written at one exposure and each
flips to the reference, and a directory without budgets is refused by name."""
import json
import os
import tempfile
import unittest

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from lpvlab_analysis import explain as E  # noqa: E402
from lpvlab_analysis import images  # noqa: E402
from lpvlab_analysis import report  # noqa: E402
from lpvlab_analysis import summary as S  # noqa: E402

BUDGET = {
    "chain": ["method", "grid", "gather", "gather_visible"],
    "images": {"method": {"block_nrmse": 2.0, "rmse": 0.03, "mean_ratio": 1.2},
               "grid": {"block_nrmse": 0.3, "rmse": 0.005, "mean_ratio": 1.07, "oracle_noise_block_nrmse": 0.01},
               "gather": {"block_nrmse": 0.25, "rmse": 0.005, "mean_ratio": 1.14, "oracle_noise_block_nrmse": 0.02},
               "gather_visible": {"block_nrmse": "inf", "rmse": 0.004, "mean_ratio": 1.0,
                                  "oracle_noise_block_nrmse": 0.03}},
    "terms": [{"stage": s, "replaced_by": r, "block_nrmse_reduction": v, "brightness_factor": f,
               "against_replacement": {"block_nrmse": v + 0.01, "rmse": 0.0, "mean_ratio": 1.0}}
              for s, r, v, f in (("propagation", "grid", 1.7, 1.12), ("rendering", "gather", 0.05, 0.94),
                                 ("occlusion", "gather_visible", 0.16, 1.14), ("injection", "reference", 0.09, 1.0))],
    "total": {"block_nrmse": 2.0, "rmse": 0.03, "mean_ratio": 1.2},
    "leakage_factor": 1.14,
    "reference_noise_block_nrmse": 0.02,
}


def explanation(root, budget=BUDGET):
    with open(os.path.join(root, "explain.json"), "w") as f:
        json.dump({"experiment": "test", "budgets": {"indirect_vs_indirect1": budget},
                   "vpls": {"per_draw": 100, "draws": 2, "covered_rsm_texels": 4096, "block_side_texels": 8},
                   "reference": {"samples": 64}, "grid_blocks_light": False, "oracle_clock": "CPU wall clock",
                   "host": {"cpu": "test CPU"}}, f)
    if images.have_oiio():
        import numpy as np
        import OpenImageIO as oiio
        names = ["reference_indirect1"] + BUDGET["chain"]
        pixels = np.concatenate([np.full((4, 4, 3), 0.1 * (i + 1), np.float32) for i in range(len(names))], axis=2)
        spec = oiio.ImageSpec(4, 4, pixels.shape[2], oiio.FLOAT)
        spec.channelnames = tuple(f"{n}.{c}" for n in names for c in "RGB")
        out = oiio.ImageOutput.create(os.path.join(root, "explain.exr"))
        out.open(os.path.join(root, "explain.exr"), spec)
        out.write_image(pixels)
        out.close()


class Explain(unittest.TestCase):
    def test_the_chart_has_a_bar_per_stage_and_labelled_axes(self):
        fig = E.terms_figure("indirect_vs_indirect1", BUDGET)
        ax = fig.axes[0]
        self.assertEqual(len(ax.patches), 4)
        self.assertIn("block nRMSE", ax.get_xlabel())
        self.assertIn("stage", ax.get_ylabel())
        self.assertEqual([t.get_text() for t in ax.get_yticklabels()],
                         ["injection", "occlusion", "rendering", "propagation"])
        plt.close(fig)

    def test_the_page_has_both_tables_and_the_chain_flips_to_the_reference(self):
        with tempfile.TemporaryDirectory() as root:
            explanation(root)
            index = report.build_report(root)
            self.assertEqual(index, os.path.join(root, "report", "index.html"))
            with open(index) as f:
                page = f.read()
            for stage in ("propagation", "rendering", "occlusion", "injection"):
                self.assertIn(stage, page)
            self.assertIn("1.7000", page)        # the propagation term
            self.assertIn("inf", page)           # a black reference's block nRMSE, as the JSON has it
            self.assertIn("explain.json", page)  # the link to the data
            self.assertNotIn("The light grids", page)  # no grids written: no section
            if images.have_oiio():
                for name in ["reference_indirect1"] + BUDGET["chain"]:
                    self.assertTrue(os.path.isfile(os.path.join(root, "report", "img", f"{name}.png")), name)
                self.assertEqual(page.count("class='flip'"), len(BUDGET["chain"]))

    def test_the_page_shows_the_methods_grid_beside_the_exact_one(self):
        import numpy as np
        from tests.test_grid_slices import write_dump
        with tempfile.TemporaryDirectory() as root:
            explanation(root)
            grid = np.zeros((1, 3, 4, 4, 4, 4))
            grid[0, :, 0, 2, 2, 2] = 1.0
            write_dump(root, grid)
            write_dump(root, 1.5 * grid, stem="exact_grid")
            with open(report.build_report(root)) as f:
                page = f.read()
            self.assertIn("The light grids", page)
            self.assertIn("img/grids.png", page)
            self.assertTrue(os.path.isfile(os.path.join(root, "report", "img", "grids.png")))
            self.assertIn("exact_grid.npy", page)  # linked

    def test_a_directory_without_budgets_is_refused(self):
        with tempfile.TemporaryDirectory() as root:
            with open(os.path.join(root, "explain.json"), "w") as f:
                json.dump({"experiment": "x"}, f)
            with self.assertRaises(S.SummaryError) as caught:
                report.build_report(root)
            self.assertIn("explain.json", str(caught.exception))


if __name__ == "__main__":
    unittest.main()
