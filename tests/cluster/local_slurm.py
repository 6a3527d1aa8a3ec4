"""A single-node Slurm cluster on this machine, for tests: munged, slurmctld and slurmd on
localhost, with a minimal configuration, state and logs in a temporary folder.

Needs Debian's slurm-wlm and munge, and root (slurmd starts jobs as their user). Daemons are
started on free ports and stopped (with their process groups) when the cluster is closed.
"""

import os
import shutil
import signal
import socket
import subprocess
import tempfile
import time


class SlurmUnavailable(Exception):
    """Slurm cannot start here; the message says why (the test skips with it)."""


def _free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def _memory_mb():
    with open("/proc/meminfo") as f:
        for line in f:
            if line.startswith("MemTotal:"):
                return int(line.split()[1]) // 1024
    return 1024


class LocalSlurm:
    def __init__(self):
        for tool in ("munged", "slurmctld", "slurmd", "sbatch", "squeue", "sinfo"):
            if shutil.which(tool) is None:
                raise SlurmUnavailable(f"{tool} is not installed (Debian packages slurm-wlm, munge)")
        if os.geteuid() != 0:
            raise SlurmUnavailable("slurmd must run as root to start jobs")
        self.dir = tempfile.mkdtemp(prefix="lpvlab-slurm-")
        os.chmod(self.dir, 0o700)
        self.processes = []
        self.node = socket.gethostname().split(".")[0]
        self.conf = os.path.join(self.dir, "slurm.conf")
        self.env = dict(os.environ, SLURM_CONF=self.conf)
        try:
            self._start()
        except BaseException:
            self.close()
            raise

    def path(self, name):
        return os.path.join(self.dir, name)

    def _spawn(self, args, log):
        out = open(self.path(log), "wb")
        p = subprocess.Popen(args, stdout=out, stderr=subprocess.STDOUT, env=self.env,
                             start_new_session=True)
        self.processes.append(p)
        return p

    def _start(self):
        key = self.path("munge.key")
        with open(key, "wb") as f:
            f.write(os.urandom(1024))
        os.chmod(key, 0o400)
        socket_path = self.path("munge.socket")
        self._spawn(["munged", "--foreground", "--force", f"--key-file={key}", f"--socket={socket_path}",
                     f"--pid-file={self.path('munged.pid')}", f"--log-file={self.path('munged.log')}",
                     f"--seed-file={self.path('munged.seed')}"], "munged.out")
        self._wait_for(lambda: os.path.exists(socket_path), "munged", "munged.out")

        cpus = os.cpu_count() or 1
        memory = max(256, int(_memory_mb() * 0.8))
        for sub in ("state", "spool"):
            os.makedirs(self.path(sub))
        with open(self.conf, "w") as f:
            f.write(f"""ClusterName=lpvlab-test
SlurmctldHost={self.node}(127.0.0.1)
SlurmctldPort={_free_port()}
SlurmdPort={_free_port()}
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket={socket_path}
StateSaveLocation={self.path('state')}
SlurmdSpoolDir={self.path('spool')}
SlurmctldPidFile={self.path('slurmctld.pid')}
SlurmdPidFile={self.path('slurmd.pid')}
SlurmctldLogFile={self.path('slurmctld.log')}
SlurmdLogFile={self.path('slurmd.log')}
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
SwitchType=switch/none
MpiDefault=none
SchedulerType=sched/builtin
SelectType=select/cons_tres
SelectTypeParameters=CR_Core_Memory
ReturnToService=2
MinJobAge=600
NodeName={self.node} NodeAddr=127.0.0.1 CPUs={cpus} RealMemory={memory} State=UNKNOWN
PartitionName=test Nodes={self.node} Default=YES MaxTime=INFINITE State=UP
""")
        self.cpus, self.memory_mb = cpus, memory
        self._spawn(["slurmctld", "-D", "-i", "-f", self.conf], "slurmctld.out")
        self._spawn(["slurmd", "-D", "-f", self.conf, "-N", self.node], "slurmd.out")
        self._wait_for(self._node_idle, "slurmctld and slurmd", "slurmd.log")

    def _node_idle(self):
        r = subprocess.run(["sinfo", "-h", "-N", "-o", "%t"], env=self.env, capture_output=True,
                           text=True)
        return r.returncode == 0 and r.stdout.strip() in ("idle", "mix", "alloc")

    def _wait_for(self, ready, what, log, seconds=60):
        deadline = time.time() + seconds
        while time.time() < deadline:
            if ready():
                return
            for p in self.processes:
                if p.poll() is not None:
                    raise SlurmUnavailable(f"{what} did not start: {p.args[0]} exited with "
                                           f"{p.returncode}: {self.tail(log)}")
            time.sleep(0.2)
        raise SlurmUnavailable(f"{what} not ready after {seconds} s: {self.tail(log)}")

    def tail(self, name, lines=15):
        try:
            with open(self.path(name), errors="replace") as f:
                return "".join(f.readlines()[-lines:])
        except OSError:
            return "(no log)"

    def run(self, args, **kwargs):
        """Runs a Slurm client command (sbatch, squeue, ...) against this cluster."""
        return subprocess.run(args, env=self.env, capture_output=True, text=True, **kwargs)

    def wait_until_empty(self, seconds):
        """Waits until no job is pending or running; returns False on timeout."""
        deadline = time.time() + seconds
        while time.time() < deadline:
            r = self.run(["squeue", "-h", "-o", "%i %T %r"])
            if r.returncode == 0 and not r.stdout.strip():
                return True
            time.sleep(1)
        return False

    def close(self):
        for p in reversed(self.processes):
            if p.poll() is None:
                try:
                    os.killpg(p.pid, signal.SIGTERM)
                except ProcessLookupError:
                    pass
        for p in self.processes:
            try:
                p.wait(timeout=15)
            except subprocess.TimeoutExpired:
                os.killpg(p.pid, signal.SIGKILL)
                p.wait()
        shutil.rmtree(self.dir, ignore_errors=True)
