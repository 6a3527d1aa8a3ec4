"""lpvlab sweep --emit slurm on a real (single-node) Slurm cluster.

Usage: slurm_sweep_test.py LPVLAB_EXECUTABLE
Starts munged, slurmctld and slurmd on localhost (local_slurm.py), submits emitted sweeps and
checks with `lpvlab summary` that every configuration ran exactly once, that a sweep whose
configurations compare with path-traced references renders each once (a task of the references'
array per reference, with resources of its own), and that the options for timing and GPU studies
(--exclusive, --gres, --array-throttle) reach the scripts and run. Exits 77
(skipped, for ctest) with the reason when Slurm cannot start here, except under CI (env CI
set), where that fails.
"""

import csv
import glob
import json
import os
import subprocess
import sys
import tempfile
import unittest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from local_slurm import LocalSlurm, SlurmUnavailable  # noqa: E402

LPVLAB = None
CLUSTER = None

# Small and quick: the point is the scheduling, not the images.
BASE = """
[output]
width = 32
height = 32
[grid]
resolution = 6
[propagation]
iterations = 2
[timing]
warmup = 0
repeats = 1
"""


class SlurmSweep(unittest.TestCase):
    def setUp(self):
        self.work = tempfile.mkdtemp(prefix="lpvlab-slurm-sweep-")
        self.cache = os.path.join(self.work, "cache")

    def emit(self, toml, *options):
        path = os.path.join(self.work, "experiment.toml")
        with open(path, "w") as f:
            f.write(BASE + toml)
        out = os.path.join(self.work, "sweep")
        env = dict(os.environ, LPVLAB_CACHE_DIR=self.cache)
        r = subprocess.run([LPVLAB, "sweep", path, "--emit", "slurm", "--out", out, *options],
                           env=env, capture_output=True, text=True)
        self.assertEqual(r.returncode, 0, r.stderr)
        return out

    def submit(self, script, *sbatch_options):
        # A bare environment: the scripts must state what lpvlab needs, not inherit it.
        env = {"PATH": "/usr/sbin:/usr/bin:/sbin:/bin", "SLURM_CONF": CLUSTER.conf}
        r = subprocess.run([script, *sbatch_options], env=env, capture_output=True, text=True)
        self.assertEqual(r.returncode, 0, f"{script}: {r.stdout}{r.stderr}")
        self.assertTrue(CLUSTER.wait_until_empty(900), CLUSTER.run(["squeue"]).stdout)
        return r

    def summary(self, out):
        r = subprocess.run([LPVLAB, "summary", out], capture_output=True, text=True)
        self.assertEqual(r.returncode, 0, r.stderr)
        with open(os.path.join(out, "summary.csv")) as f:
            return list(csv.DictReader(f))

    def task_logs(self, out):
        logs = {}
        for log in glob.glob(os.path.join(out, "logs", "*_*.out")):
            if log.endswith("_references.out"):
                continue
            with open(log, errors="replace") as f:
                logs[log] = f.read()
        return logs

    def manifests(self, out):
        with open(os.path.join(out, "sweep.json")) as f:
            ids = [c["id"] for c in json.load(f)["configurations"]]
        result = {}
        for i in ids:
            with open(os.path.join(out, i, "manifest.json")) as f:
                result[i] = json.load(f)
        return result

    def test_every_configuration_runs_once(self):
        out = self.emit('[sweep]\nproduct = { "propagation.iterations" = [1, 2, 3], '
                        '"grid.resolution" = [4, 6, 8] }\n',
                        "--cpus-per-task", "1", "--mem", "512M", "--time", "00:10:00")
        with open(os.path.join(out, "sweep.slurm")) as f:
            script = f.read()
        for line in ("#SBATCH --array=0-8", "#SBATCH --cpus-per-task=1", "#SBATCH --mem=512M",
                     "#SBATCH --time=00:10:00", "export LPVLAB_SHARED_DIR=",
                     f"export LPVLAB_CACHE_DIR='{self.cache}'"):
            self.assertIn(line, script)
        self.assertFalse(os.path.exists(os.path.join(out, "references.slurm")))

        self.submit(os.path.join(out, "submit.sh"))
        logs = self.task_logs(out)
        self.assertEqual(len(logs), 9, CLUSTER.tail("slurmctld.log"))
        ran = [line.split(":")[0] for text in logs.values() for line in text.splitlines()
               if ": lpvlab run on " in line]
        self.assertEqual(len(ran), 9, logs)
        self.assertEqual(len(set(ran)), 9, ran)  # each configuration once
        rows = self.summary(out)
        self.assertEqual(len(rows), 9)
        self.assertEqual({r["config_id"] for r in rows}, set(ran))

    def test_references_render_once_before_the_array(self):
        out = self.emit('[reference]\ncompare = true\nsamples = 4\n'
                        '[sweep]\nproduct = { "propagation.iterations" = [1, 2, 3, 4] }\n',
                        "--cpus-per-task", "1", "--mem", "512M")
        self.assertTrue(os.path.exists(os.path.join(out, "references.slurm")))
        # An sbatch option given to submit.sh reaches both jobs.
        self.submit(os.path.join(out, "submit.sh"), "--time=00:15:00")
        references = glob.glob(os.path.join(out, "logs", "*_references.out"))
        self.assertEqual(len(references), 1)
        with open(references[0]) as f:
            self.assertIn("rendered reference", f.read())
        manifests = self.manifests(out)
        self.assertEqual(len(manifests), 4)
        for i, m in manifests.items():
            self.assertTrue(m["reference"]["reused"], f"{i} rendered the reference again")
        self.assertEqual(len({m["reference"]["key"] for m in manifests.values()}), 1)
        self.assertEqual(len(self.summary(out)), 4)

    def test_timing_and_gpu_options_reach_the_scripts(self):
        out = self.emit('[reference]\ncompare = true\nsamples = 4\n'
                        '[sweep]\nproduct = { "propagation.iterations" = [1, 2, 3] }\n',
                        "--exclusive", "--gres", "gpu:2", "--array-throttle", "2",
                        "--ref-cpus-per-task", "1", "--ref-mem", "256M", "--ref-time", "00:20:00")
        with open(os.path.join(out, "sweep.slurm")) as f:
            sweep = f.read()
        for line in ("#SBATCH --array=0-2%2", "#SBATCH --exclusive", "#SBATCH --gres=gpu:2",
                     "#SBATCH --cpus-per-task=2", "#SBATCH --mem=4G"):
            self.assertIn(line, sweep)
        with open(os.path.join(out, "references.slurm")) as f:
            references = f.read()
        for line in ("#SBATCH --array=0-0%2", "#SBATCH --cpus-per-task=1", "#SBATCH --mem=256M",
                     "#SBATCH --time=00:20:00"):
            self.assertIn(line, references)
        # The references need no GPU and are not timed: neither option reaches them.
        self.assertNotIn("--gres", references)
        self.assertNotIn("--exclusive", references)
        # With --gres the runs use GL through EGL: every configuration says so.
        for config in glob.glob(os.path.join(out, "configs", "*.toml")):
            with open(config) as f:
                self.assertIn("backend = 'egl'", f.read(), config)

    def test_exclusive_throttled_sweep_renders_each_reference_in_its_own_task(self):
        # Two references (two image widths), each a task of the references' array; the sweep's
        # tasks each on the node alone, one at a time.
        out = self.emit('[reference]\ncompare = true\nsamples = 4\n'
                        '[sweep]\nproduct = { "propagation.iterations" = [1, 2], '
                        '"output.width" = [32, 40] }\n',
                        "--cpus-per-task", "1", "--mem", "512M", "--exclusive",
                        "--array-throttle", "1", "--ref-cpus-per-task", "1", "--ref-mem", "512M")
        self.submit(os.path.join(out, "submit.sh"))
        references = glob.glob(os.path.join(out, "logs", "*_references.out"))
        self.assertEqual(len(references), 2, references)
        for log in references:
            with open(log) as f:
                self.assertIn("rendered reference", f.read(), log)
        manifests = self.manifests(out)
        self.assertEqual(len(manifests), 4)
        for i, m in manifests.items():
            self.assertTrue(m["reference"]["reused"], f"{i} rendered its reference again")
        self.assertEqual(len({m["reference"]["key"] for m in manifests.values()}), 2)
        self.assertEqual(len(self.summary(out)), 4)

    def test_tasks_started_together_render_a_missing_reference_once(self):
        # The array alone, without the references job: two tasks start together on the two
        # CPUs and both need the missing reference; the cache's lock lets one render it.
        out = self.emit('[reference]\ncompare = true\nsamples = 16\n'
                        '[sweep]\nproduct = { "propagation.iterations" = [1, 2] }\n',
                        "--cpus-per-task", "1", "--mem", "512M")
        r = CLUSTER.run(["sbatch", "--parsable", os.path.join(out, "sweep.slurm")])
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertTrue(CLUSTER.wait_until_empty(900))
        manifests = self.manifests(out)
        rendered = [i for i, m in manifests.items() if not m["reference"]["reused"]]
        self.assertEqual(len(rendered), 1, manifests.keys())
        entries = [d for d in glob.glob(os.path.join(self.cache, "*")) if os.path.isdir(d)]
        self.assertEqual(len(entries), 1)


def main():
    global LPVLAB, CLUSTER
    if len(sys.argv) < 2:
        print("usage: slurm_sweep_test.py LPVLAB_EXECUTABLE", file=sys.stderr)
        return 2
    LPVLAB = os.path.abspath(sys.argv[1])
    try:
        CLUSTER = LocalSlurm()
    except SlurmUnavailable as why:
        # Under CI (env CI set) Slurm is installed by the test command and must start.
        print(("error" if os.environ.get("CI") else "skipped") + f": Slurm cannot start here: {why}")
        return 1 if os.environ.get("CI") else 77
    try:
        print(f"single-node Slurm on {CLUSTER.node}: {CLUSTER.cpus} CPUs, {CLUSTER.memory_mb} MB")
        result = unittest.main(argv=[sys.argv[0], "-v"], exit=False).result
        return 0 if result.wasSuccessful() else 1
    finally:
        CLUSTER.close()


if __name__ == "__main__":
    sys.exit(main())
