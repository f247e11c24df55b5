"""Our .res against our .req (src/output's writers, docs/output-files.md), read by the package's
own two readers: for the piston and the nine ADAMS joint cases (run with RESULTS/XRF added),
every request value the .req prints must be the .res value printed with six significant
digits. Also: a Run reads the .res (eight components) when the run wrote one."""

import math
import re
import shutil

import numpy as np

import openmss
from conftest import JOINTS, PISTON

REQ_COLUMNS = [1, 2, 3, 5, 6, 7]  # F2 F3 F4 F6 F7 F8 of the eight (docs/output-files.md)


def with_results(acf, into):
    """Copies an .acf and its data set into `into`, adding RESULTS/XRF to the data set when it
    has none. Returns the copied .acf."""
    lines = acf.read_text().splitlines()
    adm = acf.parent / lines[0].strip()
    if not adm.suffix:
        adm = adm.with_suffix(".adm")
    text = adm.read_text(errors="replace")
    if not re.search(r"^RESULTS", text, re.IGNORECASE | re.MULTILINE):
        text = re.sub(r"^END\s*$", "RESULTS/XRF\nEND", text, count=1,
                      flags=re.IGNORECASE | re.MULTILINE)
    into.mkdir(parents=True)
    (into / adm.name).write_text(text)
    shutil.copy(acf, into / acf.name)
    return into / acf.name


def compare(run):
    """Every .req value against the .res value it prints. The .req prints %13.5E, six
    significant digits: |printed - exact| <= 5e-6 |exact| (half a unit of the sixth digit over
    a mantissa >= 1), and 5e-5 |exact| for values whose exponent needs three digits
    (|v| < 1e-99 or >= 1e100), which are printed with five (%13.4E, docs/output-files.md);
    1e-12 more covers the radians-to-degrees product of the displacement angles. Returns the
    count of values compared."""
    req = openmss.read_req(run.req)
    res = openmss.read_res(run.res)
    count = 0
    for e in req.entries:
        ours8 = res.request(e.id)
        assert ours8.shape[1] == 8, (e.id, list(ours8.columns))
        six = req.requests[e.id]
        assert len(six) == len(ours8), (run.req, e.id)
        t_res = ours8.index.to_numpy()
        assert np.all(np.abs(six.index.to_numpy() - t_res) <= 5e-6 * np.abs(t_res))
        exact = ours8.to_numpy()[:, REQ_COLUMNS]
        if e.kind == "displacement":
            exact[:, 3:] = np.degrees(exact[:, 3:])  # the .req prints the angles in degrees
        printed = six.to_numpy()
        mag = np.abs(exact)
        digits = np.where((mag < 1e-99) | (mag >= 1e100), 5e-5, 5e-6)
        bound = digits * mag * (1 + 1e-12) + 1e-300
        bad = np.abs(printed - exact) > bound
        assert not bad.any(), (run.req, e.id, np.argwhere(bad)[:3], printed[bad][:3],
                               exact[bad][:3])
        count += printed.size
    return count


def test_res_and_req_agree_to_print_precision(tmp_path):
    cases = [PISTON / "piston.acf"] + sorted(JOINTS.glob("*/test_*.acf"))
    assert len(cases) == 10
    total, per_case = 0, {}
    for acf in cases:
        run = openmss.run_acf(with_results(acf, tmp_path / acf.stem), outdir=tmp_path / "out" / acf.stem)
        assert run.res and run.req, acf
        per_case[acf.stem] = compare(run)
        total += per_case[acf.stem]
    # Piston: 201 records x 8 requests x 6; each joint case 501 records x its requests x 6
    # (5 requests; Prismatic_Case02 has 6).
    assert per_case["piston"] == 201 * 8 * 6
    assert total == 201 * 8 * 6 + 501 * 6 * (8 * 5 + 6), per_case


def test_a_run_reads_the_eight_components_of_its_res(piston_run):
    assert piston_run.res.endswith("piston.res")  # examples/piston has RESULTS/XRF
    d = piston_run.requests[11]
    assert list(d.columns) == ["mag", "x", "y", "z", "rmag", "r1", "r2", "r3"]
    assert d.attrs["units"]["x"] == "inch" and d.attrs["units"]["r1"] == "rad"
    assert len(d) == 201
    # PSI and THETA of the piston's CM marker stay at 90 degrees (REULER=90D,90D,0).
    assert np.allclose(d[["r1", "r2"]].to_numpy(), math.pi / 2, atol=1e-4 * math.pi / 2)
