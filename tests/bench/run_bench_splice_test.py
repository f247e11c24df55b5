"""bench/run_bench.py rewrites docs/performance.md only between its generated-section marks:
the hand-written sections before and after survive byte for byte, a page without the marks is
left alone (the block goes beside it), and a new page gets the marks. And its ratios: against
the cheapest peer run at least as accurate, the most accurate one (*) when none is, and a
bound (<) from the stopped runs when every peer run hit the time limit. Run by ctest
(bench_run_bench_splice) with Debian's /usr/bin/python3."""

import os
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "..", "bench"))
import run_bench  # noqa: E402


def main():
    checks = 0
    with tempfile.TemporaryDirectory() as d:
        page = os.path.join(d, "performance.md")
        head = "# Performance\n\nhand text before\n\n"
        tail = "\n\n## Hand section\n\nkept ü\n"
        with open(page, "w") as f:
            f.write(head + run_bench.BEGIN_MARK + "\nold table\n" + run_bench.END_MARK + tail)
        assert run_bench.splice_generated(page, "new table 1") == page
        assert run_bench.splice_generated(page, "new table 2\n") == page  # twice: still one block
        text = open(page).read()
        assert text == (head + run_bench.BEGIN_MARK + "\nnew table 2\n" + run_bench.END_MARK +
                        tail), text
        checks += 1
        assert text.count(run_bench.BEGIN_MARK) == 1 and "old table" not in text
        checks += 1

        bare = os.path.join(d, "bare.md")
        with open(bare, "w") as f:
            f.write("hand only\n")
        assert run_bench.splice_generated(bare, "table") == bare + ".generated"
        assert open(bare).read() == "hand only\n"
        assert "table" in open(bare + ".generated").read()
        checks += 1

        fresh = os.path.join(d, "fresh.md")
        assert run_bench.splice_generated(fresh, "table") == fresh
        text = open(fresh).read()
        assert text.startswith("# Performance\n") and run_bench.END_MARK in text
        assert "## Reproducing" in text
        checks += 1
    checks += check_ratios()
    assert checks == 9
    print(f"run_bench splice and ratios: {checks} checks passed")


def row(engine, setting, n, cpu, error=None, status=0, model="m"):
    r = {"engine": engine, "setting": setting, "model": model, "n": n, "cpu": cpu,
         "status": status}
    if error is not None:
        r["error"] = error
    return r


def check_ratios():
    rows = [
        # N = 10: one peer run as accurate (the cheaper but less accurate one is not matched).
        row("OpenMSS", "GSTIFF ERROR=1e-4", 10, 1.0, 1e-6),
        row("Simbody", "RK-Merson 1e-4", 10, 0.5, 1e-5),
        row("Simbody", "RK-Merson 1e-6", 10, 4.0, 1e-7),
        # N = 100: no peer run as accurate: the most accurate one, marked *.
        row("OpenMSS", "GSTIFF ERROR=1e-6", 100, 3.0, 1e-9),
        row("OpenMSS", "HHT ERROR=1e-3", 100, 1.0, 1e-3),
        row("Simbody", "RK-Merson 1e-4", 100, 2.0, 1e-5),
        row("Simbody", "RK-Merson 1e-6", 100, 6.0, 1e-7),
        # N = 1000: every peer run stopped or skipped after a stopped one: a bound.
        row("OpenMSS", "GSTIFF ERROR=1e-3", 1000, 2.0, 1e-4),
        row("Simbody", "RK-Merson 1e-4", 1000, 80.0, status="timeout"),
        row("Simbody", "RK-Merson 1e-6", 1000, 0.0, status="skipped"),
        row("MuJoCo", "RK4 dt=0.01", 1000, 40.0, status="timeout"),
    ]
    run_bench.assign_ratios(rows)
    assert rows[0]["ratio"] == "0.25" and rows[0]["ratio_vs"] == "Simbody RK-Merson 1e-6", rows[0]
    assert rows[3]["ratio"] == "0.50*" and rows[4]["ratio"] == "0.50", (rows[3], rows[4])
    assert rows[7]["ratio"] == "<0.05" and "MuJoCo RK4" in rows[7]["ratio_vs"], rows[7]
    checks = 3
    # A peer run that failed (not stopped) gives no bound.
    failed = [row("OpenMSS", "GSTIFF ERROR=1e-3", 10, 2.0, 1e-4),
              row("Simbody", "RK-Merson 1e-4", 10, 80.0, status="timeout"),
              row("MuJoCo", "RK4 dt=0.01", 10, 1.0, status="failed")]
    run_bench.assign_ratios(failed)
    assert "ratio" not in failed[0], failed[0]
    table = run_bench.best_per_integrator(rows, [10, 100, 1000])
    lines = table.splitlines()
    assert lines[0] == "| model | N | GSTIFF | HHT |", table
    # At N = 100 GSTIFF's only ratio is a * one; HHT's plain ratio; at 1000 the bound.
    assert lines[3] == "| m | 100 | 0.50* at 1e-6 (1e-09 m) | 0.50 at 1e-3 (1e-03 m) |", table
    assert lines[4] == "| m | 1000 | <0.05 at 1e-3 (1e-04 m) | – |", table
    checks += 1
    # --replot reads the Results rows back; skipped rows and other tables are left out.
    with tempfile.TemporaryDirectory() as d:
        page = os.path.join(d, "p.md")
        with open(page, "w") as f:
            f.write("| model | N | engine | setting | wall s | CPU s | steps | CPU ms/step | "
                    "tip error m | peak RSS MB | ours / best peer (CPU) |\n"
                    "| m | 100 | OpenMSS | GSTIFF ERROR=1e-06 | 0.29 | 0.279 | 1519 | 0.182 | "
                    "8.6e-08 | 22 | 0.90 vs Simbody RK-Merson 1e-05 |\n"
                    "| m | 1000 | MuJoCo | RK4 dt=0.01 | skipped, > 90 s (timeout) | | | | | | |\n"
                    "| m | 100 | 0.90 at 1e-06 (9e-08 m) | – |\n")
        back = run_bench.rows_from_markdown(page)
        assert back == [{"model": "m", "n": 100, "engine": "OpenMSS",
                         "setting": "GSTIFF ERROR=1e-06", "cpu": 0.279, "steps": 1519}], back
    return checks + 1


if __name__ == "__main__":
    main()
