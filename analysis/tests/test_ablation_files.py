"""Every shipped ablation (experiments/ablation_*.toml but the iteration sweep) can be read at
equal settings and at equal time: it compares with the reference and its sweep holds a baseline
series (series = "baseline") at two or more grid resolutions, one series per scene."""
import glob
import os
import tomllib
import unittest

EXPERIMENTS = os.path.join(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))),
                           "experiments")
NOT_ABLATIONS = {"ablation_iterations.toml"}


def load_chain(path):
    """The file merged over its `extends` bases (tables merged key by key, like lpvlab)."""
    with open(path, "rb") as f:
        doc = tomllib.load(f)
    base = {}
    if "extends" in doc:
        base = load_chain(os.path.join(os.path.dirname(path), doc.pop("extends")))

    def merge(a, b):
        for k, v in b.items():
            a[k] = merge(a[k], v) if isinstance(a.get(k), dict) and isinstance(v, dict) else v
        return a
    return merge(base, doc)


class AblationFilesTest(unittest.TestCase):
    def test_baseline_series_and_reference(self):
        files = sorted(f for f in glob.glob(os.path.join(EXPERIMENTS, "ablation_*.toml"))
                       if os.path.basename(f) not in NOT_ABLATIONS)
        self.assertGreaterEqual(len(files), 19)
        for path in files:
            with self.subTest(file=os.path.basename(path)):
                doc = load_chain(path)
                self.assertTrue(doc.get("reference", {}).get("compare"), "reference.compare is not true")
                zipped = doc["sweep"].get("zip", {})  # series and grid.resolution side by side
                self.assertNotIn("series", doc["sweep"].get("product", {}), "series must be zipped")
                series = zipped["series"]
                res = zipped.get("grid.resolution")
                self.assertIsNotNone(res, "grid.resolution is not zipped with series")
                scenes = [str(s) for s in zipped.get("scene", [None] * len(series))]
                for scene in set(scenes):
                    base = {r for s, r, sc in zip(series, res, scenes) if s == "baseline" and sc == scene}
                    self.assertGreaterEqual(len(base), 2, f"baseline resolutions {sorted(base)} for {scene}")


if __name__ == "__main__":
    unittest.main()
