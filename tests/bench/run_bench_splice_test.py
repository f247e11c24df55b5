"""bench/run_bench.py rewrites docs/performance.md only between its generated-section marks:
the hand-written sections before and after survive byte for byte, a page without the marks is
left alone (the block goes beside it), and a new page gets the marks. Run by ctest
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
    assert checks == 4
    print(f"run_bench splice: {checks} checks passed")


if __name__ == "__main__":
    main()
