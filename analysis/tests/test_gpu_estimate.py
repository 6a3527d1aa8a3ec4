"""The GPU estimate (gpu_estimate.py): the shipped GPU table, the roofline bound, how the
estimate follows the counters, the comparison with the thesis's tables, errors naming the file
and key, and the report's labelled section."""
import contextlib
import io
import math
import os
import tempfile
import unittest

import pandas as pd

from lpvlab_analysis import gpu_estimate as G
from lpvlab_analysis import summary as S
from lpvlab_analysis import thesis_tables as T


def _gpu(fma=1e12, bw=100e9):
    return G.Gpu("test", "Test GPU", fma, bw)


def _table(text):
    d = tempfile.mkdtemp()
    p = os.path.join(d, "gpus.toml")
    with open(p, "w") as f:
        f.write(text)
    return p


class GpuTableTest(unittest.TestCase):
    def test_shipped_table_has_the_thesis_gpus(self):
        gpus = {g.key: g for g in G.load_gpus()}
        self.assertEqual(gpus["r9_fury"].thesis_setup, "Intel")   # thesis table 8.1
        self.assertEqual(gpus["gtx_960"].thesis_setup, "AMD")
        # 3584 x 1.0 GHz and 1024 x 1.178 GHz multiply-adds; 512 and 112.2 GB/s.
        self.assertAlmostEqual(gpus["r9_fury"].fma_per_s, 3584 * 1.0e9, delta=1e6)
        self.assertAlmostEqual(gpus["gtx_960"].fma_per_s, 1024 * 1.178e9, delta=1e9)
        self.assertEqual(gpus["gtx_960"].bytes_per_s, 112.2e9)
        for g in gpus.values():
            self.assertGreater(g.fma_per_s, 0)
            self.assertGreater(g.bytes_per_s, 0)

    def test_malformed_tables_name_the_file_gpu_and_key(self):
        cases = {
            "[x]\nname = 'X'\nbytes_per_s = 1e9\n": "[x] has no 'fma_per_s'",
            "[x]\nname = 'X'\nfma_per_s = -1.0\nbytes_per_s = 1e9\n": "[x] fma_per_s = -1.0 is not a positive number",
            "[x]\nname = 'X'\nfma_per_s = nan\nbytes_per_s = 1e9\n": "fma_per_s = nan",
            "[x\n": "not valid TOML",
            "x = 3\n": "'x' is not a table of a GPU",
            "": "no GPUs",
        }
        for text, message in cases.items():
            path = _table(text)
            with self.assertRaises(G.GpuTableError) as ctx:
                G.load_gpus(path)
            self.assertIn(path, str(ctx.exception))
            self.assertIn(message, str(ctx.exception))
        with self.assertRaises(G.GpuTableError):
            G.load_gpus("/nonexistent/gpus.toml")


class RooflineTest(unittest.TestCase):
    def test_the_slower_of_arithmetic_and_memory(self):
        gpu = _gpu(fma=1e12, bw=100e9)
        # 1e9 multiply-adds: 1 ms; 2e8 bytes: 2 ms -> memory-bound, 2 ms.
        self.assertAlmostEqual(G.stage_ms(1e9, 2e8, gpu), 2.0)
        # 4e9 multiply-adds: 4 ms -> arithmetic-bound.
        self.assertAlmostEqual(G.stage_ms(4e9, 2e8, gpu), 4.0)
        self.assertAlmostEqual(G.stage_ms(4e9, math.nan, gpu), 4.0)
        self.assertTrue(math.isnan(G.stage_ms(math.nan, math.nan, gpu)))

    def test_the_estimate_scales_as_the_counters_when_grid_or_iterations_change(self):
        # Per cell-iteration counts of a kernel (both terms matter on one of the two GPUs), at
        # grids 16^3 and 32^3 and 8 and 16 iterations: the estimate follows cells x iterations.
        per_madd, per_byte = 720.0, 432.0
        rows = []
        for res in (16, 32):
            for it in (8, 16):
                units = res ** 3 * it
                rows.append({"config_name": f"{res}-{it}", "time.propagation.ms": 1.0,
                             "gpu_work.propagation.cell-iterations": units,
                             "gpu_work.propagation.multiply_adds": per_madd * units,
                             "gpu_work.propagation.bytes": per_byte * units,
                             "gpu_work.injection.VPLs": 100.0})
        df = pd.DataFrame(rows)
        gpus = [_gpu(1e12, 100e9), _gpu(1e12, 1e15)]  # memory-bound, arithmetic-bound
        gpus[1].key = "fast_memory"
        est = G.with_estimates(df, gpus)
        self.assertEqual(G.counted_stages(df), ["propagation"])
        for g in gpus:
            col = est[f"{G.PREFIX}{g.key}.propagation"]
            base = col.iloc[0]
            self.assertGreater(base, 0)
            for i, row in df.iterrows():
                ratio = row["gpu_work.propagation.cell-iterations"] / df["gpu_work.propagation.cell-iterations"].iloc[0]
                self.assertAlmostEqual(col.iloc[i] / base, ratio, places=12)
            self.assertTrue((est[f"{G.PREFIX}{g.key}.total"] == col).all())
        # The first is memory-bound (432 B / 100 GB/s), the second arithmetic-bound (720 / 1e12).
        units = df["gpu_work.propagation.cell-iterations"].iloc[0]
        self.assertAlmostEqual(est[f"{G.PREFIX}test.propagation"].iloc[0], 1e3 * per_byte * units / 100e9)
        self.assertAlmostEqual(est[f"{G.PREFIX}fast_memory.propagation"].iloc[0], 1e3 * per_madd * units / 1e12)


class ThesisComparisonTest(unittest.TestCase):
    def test_per_unit_counts_at_the_thesis_configuration(self):
        # A sweep of iterations (as thesis_tables.toml), standard gathering on a 16^3 grid: the
        # comparison takes its per-unit counts to 32^3 x 4 levels x the thesis's iterations.
        per_madd, per_byte = 720.0, 432.0
        rows = []
        for i, it in enumerate((1, 2, 4, 8)):
            units = 16 ** 3 * it
            rows.append({"config_id": f"c{i}", "config_name": f"it{it}", "variant": "standard",
                         "param.propagation.type": "standard", "param.propagation.method": "gather",
                         "param.propagation.iterations": it, "time.propagation.ms": float(it),
                         "gpu_work.propagation.cell-iterations": units,
                         "gpu_work.propagation.multiply_adds": per_madd * units,
                         "gpu_work.propagation.bytes": per_byte * units})
        agg = pd.DataFrame(rows)
        gpus = G.load_gpus()
        rows = G.thesis_comparison(agg, gpus)
        by_gpu = {r["gpu"]: r for r in rows if r["table"] == "8.5"}
        self.assertEqual(set(by_gpu), {"AMD Radeon R9 Fury", "NVIDIA GeForce GTX 960"})
        fury = by_gpu["AMD Radeon R9 Fury"]
        self.assertEqual(fury["thesis_column"], "Intel CS gather")
        self.assertEqual(fury["thesis_ms"], T.TABLES["8.5"].columns["Intel CS gather"])
        units_32 = 4 * 32 ** 3 * 32
        i32 = fury["x"].index(32)
        expected = 1e3 * max(per_madd * units_32 / 3.584e12, per_byte * units_32 / 512e9)
        self.assertAlmostEqual(fury["estimate_ms"][i32], expected)
        self.assertAlmostEqual(fury["ratio"][i32], fury["thesis_ms"][i32] / expected)
        # The per-step increment: (t(64) - t(1)) / 63, for the thesis and the estimate.
        t = fury["thesis_ms"]
        self.assertAlmostEqual(fury["thesis_slope_ms"], (t[-1] - t[0]) / 63)
        self.assertAlmostEqual(fury["estimate_slope_ms"], 1e3 * per_byte * 4 * 32 ** 3 / 512e9)


    def test_injection_is_compared_once_per_gpu_whatever_else_varies(self):
        # An RSM-size sweep (tables 8.3-8.4) with two propagation methods: the injection's counts
        # do not depend on them, so one comparison per thesis GPU, per VPL at 4 levels x side^2.
        rows = []
        for i, side in enumerate((32, 64, 128)):
            for method in ("gather", "scatter"):
                units = side * side
                rows.append({"config_id": f"c{i}{method}", "config_name": f"{side}-{method}",
                             "variant": f"rsm_vpl/none/standard ({method})",
                             "param.injection.type": "rsm_vpl", "param.propagation.type": "standard",
                             "param.propagation.method": method,
                             "param.light_maps.rsm_resolution": side, "time.injection.ms": 1.0,
                             "gpu_work.injection.VPLs": units,
                             "gpu_work.injection.multiply_adds": 26.0 * units,
                             "gpu_work.injection.bytes": 176.0 * units})
        result = G.thesis_comparison(pd.DataFrame(rows), G.load_gpus())
        by_table = {}
        for r in result:
            by_table.setdefault(r["table"], []).append(r)
        self.assertEqual(sorted(by_table), ["8.3", "8.4"])
        for table, entries in by_table.items():
            self.assertEqual(len(entries), 1, table)
            r = entries[0]
            self.assertEqual((r["variant"], r["method"]), ("rsm_vpl", ""))
            i = r["x"].index(256)
            gpu = next(g for g in G.load_gpus() if g.name == r["gpu"])
            self.assertAlmostEqual(r["estimate_ms"][i], G.stage_ms(26.0 * 4 * 256 ** 2, 176.0 * 4 * 256 ** 2, gpu))


class ReportSectionTest(unittest.TestCase):
    def test_a_malformed_gpu_table_is_an_error_before_anything_is_written(self):
        from lpvlab_analysis import report
        from tests.fixtures import make_sweep
        root = tempfile.mkdtemp()
        sweep = make_sweep(os.path.join(root, "sweep"), with_exr=False)
        out = os.path.join(root, "report")
        table = _table("[x]\nname = 'X'\nfma_per_s = 0\nbytes_per_s = 1e9\n")
        with self.assertRaises(G.GpuTableError) as ctx:
            report.build_report(sweep, out, use_exr=False, gpu_table=table)
        self.assertIn(table, str(ctx.exception))
        self.assertIn("fma_per_s", str(ctx.exception))
        self.assertFalse(os.path.exists(out))


    def test_the_report_labels_the_estimate(self):
        from lpvlab_analysis import report
        df = pd.DataFrame([{"config_name": "a", "time.propagation.ms": 12.5,
                            "gpu_work.propagation.multiply_adds": 1e9, "gpu_work.propagation.bytes": 1e6}])
        section, md = report._gpu_estimate_section(df, [_gpu(1e12, 100e9)])
        # The template's data (report.html.j2 heads each GPU's columns "<name>: roofline bound" and
        # "<name>: calibrated (range)"), and the Markdown.
        self.assertEqual(section["gpus"], ["Test GPU"])
        self.assertEqual(section["rows"], [{"configuration": "a", "stage": "propagation", "measured": "12.5",
                                            "cells": [("1", "—")]}])
        self.assertIn("Test GPU roofline bound (ms) | Test GPU calibrated (range) (ms)", md)
        self.assertIn("measured here (ms)", md)
        self.assertIn("| a | propagation | 12.5 | 1 | — |", md)   # 1e9 / 1e12 s = 1 ms; no measurement
        # Rendered: the page's table heads the columns by GPU, and escapes what it shows.
        from lpvlab_analysis import templating
        env = templating.environment()
        page = env.from_string("{% from 'macros.html.j2' import plot %}"
                               "{% for g in s.gpus %}<th>{{ g }}: roofline bound</th>{% endfor %}"
                               "{{ '<b>'|scrolling }}{{ '<i>' }}").render(s=section)
        self.assertIn("<th>Test GPU: roofline bound</th>", page)
        self.assertIn("<b>", page)
        self.assertIn("&lt;i&gt;", page)

    def test_the_calibrated_estimate_divides_the_bound_by_the_measured_efficiency(self):
        # A GPU measured at a quarter and at half of its roofline (bytes-bound: 400 bytes per unit
        # at 100 GB/s is 2.5e8 units/s): the median efficiency 3/8, the range 1/4..1/2.
        measured = [G.Measured("propagation", 1, 2.5e8 * e, 10, 400, "test") for e in (0.25, 0.5)]
        gpu = G.Gpu("m", "Measured GPU", 1e12, 100e9, measured=measured)
        like = G.Gpu("l", "Like GPU", 1e12, 50e9, calibrate_like="m")
        none = G.Gpu("n", "Other GPU", 1e12, 100e9)
        gpus = [gpu, like, none]
        self.assertEqual(G.efficiency(gpu, gpus, "propagation", 1), (0.375, 0.25, 0.5, "measured"))
        self.assertEqual(G.efficiency(like, gpus, "propagation", 1)[3], "like Measured GPU")
        self.assertEqual(G.efficiency(none, gpus, "propagation", 1)[3], "every measured GPU")
        self.assertIsNone(G.efficiency(gpu, gpus, "injection", 1))
        df = pd.DataFrame([{"config_name": "a", "param.grid.sh_order": 1,
                            "gpu_work.propagation.multiply_adds": 1e6, "gpu_work.propagation.bytes": 1e9}])
        est = G.with_estimates(df, gpus)
        bound = est["gpu_estimate_ms.m.propagation"][0]
        self.assertAlmostEqual(bound, 10.0)                         # 1e9 B / 100 GB/s
        self.assertAlmostEqual(est["gpu_calibrated_ms.m.propagation"][0], 10.0 / 0.375)
        self.assertAlmostEqual(est["gpu_calibrated_ms.m.propagation.low"][0], 20.0)
        self.assertAlmostEqual(est["gpu_calibrated_ms.m.propagation.high"][0], 40.0)
        # The like GPU has half the bandwidth: twice the bound, the same efficiencies.
        self.assertAlmostEqual(est["gpu_calibrated_ms.l.propagation"][0], 20.0 / 0.375)

    def test_malformed_measurements_name_the_file_gpu_and_key(self):
        base = "[x]\nname = 'X'\nfma_per_s = 1e12\nbytes_per_s = 1e9\n"
        for extra, needle in (("[[x.measured]]\nfamily = 'propagation'\n", "x.measured[0]] has no 'sh_order'"),
                              ("[[x.measured]]\nfamily = 'p'\nsh_order = 1\nunits_per_s = -1\n"
                               "multiply_adds_per_unit = 1\nbytes_per_unit = 1\nsource = 's'\n", "units_per_s = -1"),
                              ("calibrate_like = 'nope'\n", "calibrate_like = 'nope' names no GPU")):
            table = _table(base + extra)
            with self.assertRaises(G.GpuTableError) as ctx:
                G.load_gpus(table)
            self.assertIn(table, str(ctx.exception))
            self.assertIn(needle, str(ctx.exception))

    def test_the_shipped_measurements_say_the_gather_reaches_a_few_percent_on_an_h200(self):
        gpus = G.load_gpus()
        h200 = next(g for g in gpus if g.key == "h200")
        median, low, high, basis = G.efficiency(h200, gpus, "propagation", 1)
        self.assertEqual(basis, "measured")
        # 4.8e12 B/s / 432 B = 1.11e10 cell-iterations/s is the bound; 4.5e8..7.9e8 were measured.
        self.assertAlmostEqual(low, 4.5e8 * 432 / 4.8e12)
        self.assertAlmostEqual(high, 7.9e8 * 432 / 4.8e12)
        fury = next(g for g in gpus if g.key == "r9_fury")
        self.assertGreater(G.efficiency(fury, gpus, "propagation", 1)[0], 5 * median)
        h100 = next(g for g in gpus if g.key == "h100_sxm")
        self.assertEqual(G.efficiency(h100, gpus, "propagation", 3)[3], "like NVIDIA H200")


if __name__ == "__main__":
    unittest.main()


class RunEstimatesTest(unittest.TestCase):
    """lpvlab-gpu-estimate (run_estimates.py), which `lpvlab tune` runs with time = "gpu-estimate"."""

    TABLE = ("[m]\nname = 'Measured GPU'\nfma_per_s = 1e12\nbytes_per_s = 100e9\n"
             "[[m.measured]]\nfamily = 'propagation'\nsh_order = 1\nunits_per_s = 1.25e8\n"
             "multiply_adds_per_unit = 10\nbytes_per_unit = 400\nsource = 'test'\n")

    def _run(self, csv_text, gpu="m"):
        from lpvlab_analysis import run_estimates as R
        d = tempfile.mkdtemp()
        rows, out = os.path.join(d, "rows.csv"), os.path.join(d, "out.json")
        with open(rows, "w") as f:
            f.write(csv_text)
        status = R.main([rows, "--gpu", gpu, "--table", _table(self.TABLE), "--out", out])
        if status != 0:
            return status, None
        import json
        with open(out) as f:
            return status, json.load(f)

    def test_the_estimate_of_a_run_is_the_reports_speed_axis(self):
        # Propagation: 1e9 bytes at 100 GB/s is a 10 ms bound; the GPU was measured at half its
        # roofline (1.25e8 of 2.5e8 units/s), so 20 ms calibrated. Injection was never measured:
        # its roofline bound, 2 ms. The raster passes (rsm) are the pipeline's, not the method's.
        csv = ("id,param.grid.sh_order,gpu_work.propagation.multiply_adds,gpu_work.propagation.bytes,"
               "gpu_work.injection.bytes,gpu_work.rsm.bytes\n"
               "0,1,1e6,1e9,2e8,5e9\n1,1,1e6,2e9,2e8,5e9\n2,1,,,,\n")
        status, out = self._run(csv)
        self.assertEqual(status, 0)
        self.assertAlmostEqual(out["runs"]["0"], 22.0)
        self.assertAlmostEqual(out["runs"]["1"], 42.0)  # the bound follows the bytes
        self.assertIsNone(out["runs"]["2"])              # nothing counted: no estimate, not 0 ms
        self.assertEqual(out["gpu"], "Measured GPU")
        self.assertIn("estimate", out["words"])
        self.assertIn("not a measurement", out["words"])
        # The report's own estimate of the same rows gives the same figures.
        df = pd.read_csv(io.StringIO(csv))
        report_ms = S.with_speed(df, "gpu-estimate", G.load_gpus(_table(self.TABLE))[0])[S.SPEED_COL]
        self.assertAlmostEqual(report_ms[0], out["runs"]["0"])

    def test_no_rows_checks_the_gpu_and_an_unknown_gpu_is_refused_by_name(self):
        status, out = self._run("id,param.grid.sh_order\n")
        self.assertEqual((status, out["runs"]), (0, {}))
        err = io.StringIO()
        with contextlib.redirect_stderr(err):
            status, _ = self._run("id,param.grid.sh_order\n", gpu="nope")
        self.assertEqual(status, 2)
        self.assertIn("--gpu nope: not a GPU of", err.getvalue())
        self.assertIn("it has m", err.getvalue())
