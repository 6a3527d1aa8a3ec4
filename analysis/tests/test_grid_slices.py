"""Slices of a dumped light grid (grid_slices.py): the mean intensity per cell is the DC term's
luminance (c0 Y00), the middle slices are the planes through the middle cells, a malformed dump is
refused naming the file, and the report shows the slices of a run that dumped its grid."""
import json
import math
import os
import tempfile
import unittest

import numpy as np

from lpvlab_analysis import grid_slices as GS
from lpvlab_analysis import report
from tests.fixtures import make_sweep


def write_dump(run_dir, grid, axes=GS.AXES, stem="grid"):
    os.makedirs(run_dir, exist_ok=True)
    np.save(os.path.join(run_dir, stem + ".npy"), grid.astype(np.float32))
    with open(os.path.join(run_dir, stem + ".json"), "w") as f:
        json.dump({"axes": list(axes), "shape": list(grid.shape), "sh_order": 1,
                   "levels": [{"origin_m": [0, 0, 0], "cell_size_m": 0.1}] * grid.shape[0]}, f)


class GridSlicesTest(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        # Two levels, RGB, four coefficients, z y x = 4 3 5; one bright cell at (z, y, x) = (2, 1, 2)
        # in the finest level, white, and a higher-order coefficient that must not count.
        self.grid = np.zeros((2, 3, 4, 4, 3, 5))
        self.grid[0, :, 0, 2, 1, 2] = 2.0
        self.grid[0, :, 3, 2, 1, 2] = 50.0
        self.grid[1, :, 0] = 7.0

    def tearDown(self):
        self.tmp.cleanup()

    def test_the_mean_intensity_is_the_dc_terms_luminance(self):
        cells = GS.mean_intensity(self.grid)
        self.assertEqual(cells.shape, (4, 3, 5))
        self.assertAlmostEqual(cells[2, 1, 2], 2.0 * 0.5 / math.sqrt(math.pi), places=6)
        self.assertEqual(np.count_nonzero(cells), 1)
        # Luminance weights: a red-only cell counts 0.2126 of a white one.
        red = self.grid.copy()
        red[0, 1:, 0, 2, 1, 2] = 0.0
        self.assertAlmostEqual(GS.mean_intensity(red)[2, 1, 2] / cells[2, 1, 2], 0.2126, places=6)

    def test_middle_slices_go_through_the_middle_cells(self):
        s = GS.middle_slices(self.grid)
        self.assertEqual(s["x"].shape, (4, 3))
        self.assertEqual(s["y"].shape, (4, 5))
        self.assertEqual(s["z"].shape, (3, 5))
        self.assertGreater(s["x"][2, 1], 0)  # x = 5 // 2 = 2: the bright cell's plane
        self.assertGreater(s["y"][2, 2], 0)  # y = 3 // 2 = 1
        self.assertGreater(s["z"][1, 2], 0)  # z = 4 // 2 = 2

    def test_a_png_per_run_with_a_dump_and_none_without(self):
        run = os.path.join(self.tmp.name, "run")
        self.assertIsNone(GS.write_png(run, os.path.join(self.tmp.name, "none.png")))
        write_dump(run, self.grid)
        out = GS.write_png(run, os.path.join(self.tmp.name, "grid.png"))
        self.assertTrue(os.path.getsize(out) > 1000)

    def test_an_explanations_grids_side_by_side_on_one_scale(self):
        explained = os.path.join(self.tmp.name, "explained")
        write_dump(explained, self.grid)
        out = os.path.join(self.tmp.name, "pair.png")
        self.assertIsNone(GS.write_pair_png(explained, out))  # no exact grid yet
        write_dump(explained, 2.0 * self.grid, stem="exact_grid")
        self.assertTrue(os.path.getsize(GS.write_pair_png(explained, out)) > 1000)
        # Grids of different shapes cannot be compared slice for slice: refused by name.
        write_dump(explained, self.grid[:, :, :, :2], stem="exact_grid")
        with self.assertRaises(GS.GridDumpError) as caught:
            GS.write_pair_png(explained, out)
        self.assertIn("exact_grid.npy", str(caught.exception))

    def test_a_dump_whose_axes_or_shape_disagree_is_refused_naming_the_file(self):
        run = os.path.join(self.tmp.name, "bad")
        write_dump(run, self.grid, axes=("level", "channel", "coefficient", "x", "y", "z"))
        with self.assertRaises(GS.GridDumpError) as caught:
            GS.load(run)
        self.assertIn("grid.json", str(caught.exception))

    def test_the_report_shows_a_runs_grid(self):
        sweep = make_sweep(os.path.join(self.tmp.name, "sweep"), with_exr=False)
        write_dump(os.path.join(sweep, "000"), self.grid)
        page = open(report.build_report(sweep, use_exr=False)).read()
        self.assertIn("light grid: middle slices of the finest level", page)
        self.assertIn("grid_000.png", page)


if __name__ == "__main__":
    unittest.main()
