"""postprocess/sweep.py --scheduler slurm on a real Slurm: a one-node cluster (munged with its
own key, slurmctld and slurmd with their own slurm.conf, all in a temporary folder) started
here and stopped at the end whatever happens. A 4-task array (v_wall 0.2/0.4 × 2 seeds) of
the tiny column runs to completion; --collect tabulates the same observables as the local
runner gives for the same runs (same binary, same deck: the same digits); a second submit
submits nothing; a failing run is listed with its ERROR line; 2-rank tasks started by
mpirun and by srun (PMIx) give the local runner's observables."""

import csv
import glob
import json
import os
import re
import shutil
import signal
import socket
import subprocess
import tempfile
import time
import unittest

from liggghts_run import LIGGGHTS, DeckTestCase, main

SOURCE = os.environ["WIREGRAIN_SOURCE"]
SWEEP = os.path.join(SOURCE, "postprocess", "sweep.py")
TINY = ["--var", "R", "3", "--var", "nlayers", "1", "--var", "Np", "13", "--var", "t_layer", "0.5",
        "--var", "t_relax", "1", "--var", "t_end", "1.5", "--var", "t_obs", "0.1"]
BINARIES = ["munged", "slurmctld", "slurmd", "sbatch", "squeue", "sinfo"]


def why_not():
    if os.geteuid() != 0:
        return "a one-node Slurm needs root (slurmd runs the jobs as their user); not root"
    missing = [b for b in BINARIES if not shutil.which(b, path=os.environ.get("PATH", "") + ":/usr/sbin")]
    if missing:
        return "missing " + ", ".join(missing) + " (Debian packages slurmctld slurmd slurm-client munge; ./build.sh deps)"
    return None


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def sweep(*args, env=None, cwd):
    proc = subprocess.run(["/usr/bin/python3", SWEEP, *args], cwd=cwd, env=env, stdout=subprocess.PIPE,
                          stderr=subprocess.STDOUT, universal_newlines=True, timeout=300)
    return proc.returncode, proc.stdout


@unittest.skipIf(why_not(), f"no Slurm here: {why_not()}")
class SlurmSweep(DeckTestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.mkdtemp(prefix="wiregrain-slurm-")
        cls.procs = []
        try:
            cls.start_cluster()
        except BaseException:
            cls.tearDownClass()
            raise

    @classmethod
    def start_cluster(cls):
        t = cls.tmp
        sbin = shutil.which("munged", path="/usr/sbin:" + os.environ.get("PATH", ""))
        key = os.path.join(t, "munge.key")
        with open(key, "wb") as f:
            f.write(os.urandom(1024))
        os.chmod(key, 0o600)
        os.chmod(t, 0o700)
        cls.munge_socket = os.path.join(t, "munge.socket")
        cls.procs.append(subprocess.Popen(
            [sbin, "-F", "--force", f"--key-file={key}", f"--socket={cls.munge_socket}",
             f"--pid-file={t}/munged.pid", f"--log-file={t}/munged.log", f"--seed-file={t}/munged.seed"],
            stdout=subprocess.DEVNULL, stderr=subprocess.STDOUT))
        for d in ("state", "spool"):
            os.makedirs(os.path.join(t, d))
        cls.conf = os.path.join(t, "slurm.conf")
        with open(cls.conf, "w") as f:
            f.write(f"""ClusterName=wiregrain
SlurmctldHost=localhost
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket={cls.munge_socket}
SlurmctldPort={free_port()}
SlurmdPort={free_port()}
StateSaveLocation={t}/state
SlurmdSpoolDir={t}/spool
SlurmctldPidFile={t}/slurmctld.pid
SlurmdPidFile={t}/slurmd.pid
SlurmctldLogFile={t}/slurmctld.log
SlurmdLogFile={t}/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
MpiDefault=none
ReturnToService=2
SchedulerType=sched/builtin
JobCompType=jobcomp/none
AccountingStorageType=accounting_storage/none
SlurmctldTimeout=30
SlurmdTimeout=30
InactiveLimit=0
KillWait=5
NodeName=localhost NodeHostname={socket.gethostname()} CPUs={os.cpu_count()} State=UNKNOWN
PartitionName=debug Nodes=localhost Default=YES MaxTime=INFINITE State=UP
""")
        cls.env = dict(os.environ, SLURM_CONF=cls.conf)
        cls.wait(lambda: os.path.exists(cls.munge_socket), 10, "munged")
        ctld = shutil.which("slurmctld", path="/usr/sbin:" + os.environ.get("PATH", ""))
        slurmd = shutil.which("slurmd", path="/usr/sbin:" + os.environ.get("PATH", ""))
        cls.procs.append(subprocess.Popen([ctld, "-D", "-c", "-i", "-f", cls.conf], env=cls.env,
                                          stdout=subprocess.DEVNULL, stderr=subprocess.STDOUT))
        cls.procs.append(subprocess.Popen([slurmd, "-D", "-f", cls.conf, "-N", "localhost"], env=cls.env,
                                          stdout=subprocess.DEVNULL, stderr=subprocess.STDOUT))

        def idle():
            out = subprocess.run(["sinfo", "-h", "-o", "%t"], env=cls.env, stdout=subprocess.PIPE,
                                 stderr=subprocess.DEVNULL, universal_newlines=True).stdout
            return out.strip() == "idle"
        cls.wait(idle, 30, "the node to be idle (sinfo)")

    @classmethod
    def wait(cls, ready, timeout, what):
        end = time.time() + timeout
        while time.time() < end:
            if ready():
                return
            time.sleep(0.3)
        logs = ""
        for name in ("munged.log", "slurmctld.log", "slurmd.log"):
            path = os.path.join(cls.tmp, name)
            if os.path.exists(path):
                logs += f"--- {name}\n" + open(path, errors="replace").read()[-1500:]
        raise RuntimeError(f"timed out after {timeout} s waiting for {what}\n{logs}")

    @classmethod
    def tearDownClass(cls):
        for proc in reversed(cls.procs):
            if proc.poll() is None:
                proc.send_signal(signal.SIGTERM)
        for proc in reversed(cls.procs):
            try:
                proc.wait(timeout=10)
            except subprocess.TimeoutExpired:
                proc.kill()
                proc.wait()
        shutil.rmtree(cls.tmp, ignore_errors=True)

    def queue_empty(self):
        out = subprocess.run(["squeue", "-h"], env=self.env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                             universal_newlines=True)
        return out.returncode == 0 and not out.stdout.strip()

    def rows(self, out):
        with open(os.path.join(out, "summary.csv"), newline="") as f:
            return list(csv.DictReader(f))

    def test_array_local_collect_resume_and_failure(self):
        work = os.path.join(self.tmp, "work")
        os.makedirs(work)
        common = ["v_wall", "0.2", "0.4", "--seeds", "11", "22", "--liggghts", LIGGGHTS, "--var", "wire", "0"] + TINY
        slurm_out, local_out = os.path.join(work, "slurm"), os.path.join(work, "local")
        status, text = sweep(*common, "--out", slurm_out, "--scheduler", "slurm", "--ranks", "1",
                             "--time", "5", "--partition", "debug", "--sbatch=--job-name=tiny",
                             env=self.env, cwd=work)
        self.assertEqual(status, 0, text)
        self.assertIn("submitted job array", text)
        self.assertIn("4 runs", text)
        # the local runner on the same runs meanwhile
        status, text = sweep(*common, "--out", local_out, "--jobs", "1", cwd=work)
        self.assertEqual(status, 0, text)
        self.wait(self.queue_empty, 120, "the array to finish (squeue)")
        status, text = sweep(*common, "--out", slurm_out, "--collect", cwd=work)
        self.assertEqual(status, 0, text)
        self.assertIn("4 runs finished, 0 failed", text)
        slurm_rows, local_rows = self.rows(slurm_out), self.rows(local_out)
        self.assertEqual([(r["value"], r["seed"]) for r in slurm_rows],
                         [("0.2", "11"), ("0.2", "22"), ("0.4", "11"), ("0.4", "22")])
        # the same binary and deck: the same digits for every observable
        for s, l in zip(slurm_rows, local_rows):
            self.assertEqual({k: v for k, v in s.items() if k != "wall_s"},
                             {k: v for k, v in l.items() if k != "wall_s"})
        self.assertTrue(os.path.exists(os.path.join(slurm_out, "v_wall=0.4", "seed=22", "log.liggghts")))

        # a second submit: every run finished, nothing submitted
        status, text = sweep(*common, "--out", slurm_out, "--scheduler", "slurm", env=self.env, cwd=work)
        self.assertEqual(status, 0, text)
        self.assertIn("every run is finished: nothing submitted", text)

        # one more value, one of them failing: only the two new runs are submitted; the
        # failed run is listed by --collect with its ERROR line
        more = ["v_wall", "0.2", "0.4", "-1", "--seeds", "11", "22", "--liggghts", LIGGGHTS,
                "--var", "wire", "0"] + TINY + ["--out", slurm_out]
        status, text = sweep(*more, "--scheduler", "slurm", env=self.env, cwd=work)
        self.assertEqual(status, 0, text)
        self.assertIn("2 runs", text)
        self.wait(self.queue_empty, 60, "the second array to finish (squeue)")
        status, text = sweep(*more, "--collect", cwd=work)
        self.assertEqual(status, 1, text)
        self.assertIn("4 runs finished, 2 failed", text)
        self.assertIn("FAILED v_wall=-1 seed=11:", text)
        self.assertIn("in.column: v_wall must be > 0, got -1", text)
        self.assertEqual(len(self.rows(slurm_out)), 4)


    def test_two_ranks_per_task(self):
        # --ranks 2: each task asks Slurm for 2 tasks and starts the run with mpirun -np 2
        # inside its allocation; the run's log shows a 2-rank processor grid, and its
        # observables are those of the local runner's 2-rank run of the same deck and seed
        work = os.path.join(self.tmp, "two_ranks")
        os.makedirs(work)
        common = ["v_wall", "0.2", "--seeds", "11", "--liggghts", LIGGGHTS] + TINY
        slurm_out, local_out = os.path.join(work, "slurm"), os.path.join(work, "local")
        status, text = sweep(*common, "--out", slurm_out, "--scheduler", "slurm", "--ranks", "2", "--time", "5",
                             env=self.env, cwd=work)
        self.assertEqual(status, 0, text)
        with open(glob.glob(os.path.join(slurm_out, "slurm", "array-*.sh"))[0]) as f:
            self.assertIn("#SBATCH --ntasks=2", f.read())
        status, text = sweep(*common, "--out", local_out, "--jobs", "1", "--ranks", "2", cwd=work)
        self.assertEqual(status, 0, text)
        self.wait(self.queue_empty, 120, "the 2-rank array to finish (squeue)")
        self.assertSameTwoRankRun(common, work, slurm_out, local_out, 11)

    def assertSameTwoRankRun(self, common, work, slurm_out, local_out, seed):
        # collected, the array's one run has a 2-rank grid in its log and the observables of
        # the local runner's run (its wall time aside)
        status, text = sweep(*common, "--out", slurm_out, "--collect", cwd=work)
        self.assertEqual(status, 0, text)
        self.assertIn("1 runs finished, 0 failed", text)
        with open(os.path.join(slurm_out, "v_wall=0.2", f"seed={seed}", "log.liggghts")) as f:
            grid = re.search(r"(\d+) by (\d+) by (\d+) MPI processor grid", f.read())
        self.assertIsNotNone(grid)
        self.assertEqual(int(grid.group(1)) * int(grid.group(2)) * int(grid.group(3)), 2)
        (s,), (l,) = self.rows(slurm_out), self.rows(local_out)
        self.assertEqual({k: v for k, v in s.items() if k != "wall_s"}, {k: v for k, v in l.items() if k != "wall_s"})

    def test_srun_launcher(self):
        # --launcher srun --ranks 2: each task starts its 2 ranks with srun inside its
        # allocation (PMIx, as SLURM_MPI_TYPE tells srun; clusters set it in slurm.conf's
        # MpiDefault), not with mpirun: the same 2-rank grid and the same observables as the
        # local runner's mpirun -np 2 run of the same deck and seed
        work = os.path.join(self.tmp, "srun")
        os.makedirs(work)
        common = ["v_wall", "0.2", "--seeds", "12", "--liggghts", LIGGGHTS] + TINY
        slurm_out, local_out = os.path.join(work, "slurm"), os.path.join(work, "local")
        env = dict(self.env, SLURM_MPI_TYPE="pmix")
        status, text = sweep(*common, "--out", slurm_out, "--scheduler", "slurm", "--ranks", "2", "--time", "5",
                             "--launcher", "srun", env=env, cwd=work)
        self.assertEqual(status, 0, text)
        job = re.search(r"submitted job array (\d+)", text).group(1)
        with open(glob.glob(os.path.join(slurm_out, "slurm", "array-*.sh"))[0]) as f:
            self.assertIn("#SBATCH --ntasks=2", f.read())
        with open(glob.glob(os.path.join(slurm_out, "slurm", "array-*.json"))[0]) as f:
            self.assertEqual(json.load(f)["launcher"], "srun")
        status, text = sweep(*common, "--out", local_out, "--jobs", "1", "--ranks", "2", cwd=work)
        self.assertEqual(status, 0, text)
        self.wait(self.queue_empty, 120, "the srun array to finish (squeue)")
        # srun made a job step of the task (mpirun on one node starts its ranks itself: none)
        with open(os.path.join(self.tmp, "slurmd.log")) as f:
            self.assertIn(f"launch task StepId={job}.0 ", f.read())
        self.assertSameTwoRankRun(common, work, slurm_out, local_out, 12)


if __name__ == "__main__":
    main()
