"""Shared by the bench scripts (contact_pile.py, walking_foot.py): one `openmss run` of a
command file, timed.

The CPU time is the child process's user + system time (getrusage of the children before and
after): the figure to compare on a shared machine, where the wall time depends on the load.
"""
import re
import resource
import subprocess
import time

STEPS = re.compile(r"reached t = (\S+) with (\d+) integration steps")


def run_command_file(openmss, acf, workdir):
    """Runs `openmss run ACF` in WORKDIR. Returns (proc, wall, cpu, match): the completed
    process, wall and CPU seconds, and the match of the "reached t = T with N integration
    steps" line (groups 1 and 2), or None when the run failed or printed no such line."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    proc = subprocess.run([openmss, "run", acf], cwd=workdir, capture_output=True, text=True)
    wall = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    m = STEPS.search(proc.stdout + proc.stderr)
    return proc, wall, cpu, (m if proc.returncode == 0 else None)
