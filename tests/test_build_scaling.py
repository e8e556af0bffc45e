"""The build-scaling bench (benchmarks/build_scaling.py) on a tiny case, and the watched child
it runs each case in: what it writes is well formed and consistent, and a case killed for time
or memory is a row that says so. No timing is asserted: the numbers depend on the machine."""

from __future__ import annotations

import csv
import importlib
import math
import sys
from pathlib import Path
from types import ModuleType

import pytest

from jointplay.bench.child import STAGE_MARK, ChildLimits, watch_child

ROOT = Path(__file__).resolve().parents[1]
BENCH = ROOT / "benchmarks" / "build_scaling.py"
PNG_SIGNATURE = b"\x89PNG\r\n\x1a\n"

# A child that reports a stage (the line report_stage writes; the real one is exercised by the
# quick bench below), grows to about 300 MiB resident, then prints its row. It imports nothing
# of jointplay, to start fast.
GROWING_CHILD = """
import json, sys, time
note = {"stage": "grow", "clock": "build", "measured": {"before": 1.5}}
print(sys.argv[2] + json.dumps(note), file=sys.stderr, flush=True)
block = bytearray(300 << 20)
for i in range(0, len(block), 4096):
    block[i] = 1
time.sleep(float(sys.argv[1]))
print('{"done": true}')
"""


def _child(hold_s: float) -> list[str]:
    return [sys.executable, "-c", GROWING_CHILD, str(hold_s), STAGE_MARK]


def test_watched_child_finishes_with_its_row_and_peak() -> None:
    outcome = watch_child(_child(1.0), ChildLimits(timeout_s=60.0))
    assert outcome.failure is None
    assert outcome.row == {"done": True}
    assert outcome.measured == {"before": 1.5}
    assert outcome.stage == "grow"
    assert outcome.peak_rss_mib > 250.0  # the block, seen by the parent's samples


@pytest.mark.parametrize(("limits", "says"), [
    (ChildLimits(timeout_s=60.0, memory_mib=150.0), "memory"),
    (ChildLimits(timeout_s=60.0, clock_s={"build": 0.5}), "build exceeded its limit of 0.5 s"),
    (ChildLimits(timeout_s=0.5), "timed out after 0.5 s"),
])
def test_watched_child_killed_for_time_or_memory_keeps_what_it_measured(
        limits: ChildLimits, says: str) -> None:
    outcome = watch_child(_child(30.0), limits)
    assert outcome.row is None
    assert outcome.failure is not None and says in outcome.failure
    assert outcome.elapsed_s < 20.0  # killed, not waited for
    if "memory" in says or "build" in says:
        assert "in stage grow" in outcome.failure
        assert outcome.measured == {"before": 1.5}


def test_watched_child_failure_names_its_last_words() -> None:
    outcome = watch_child([sys.executable, "-c", "raise SystemExit('no model here')"],
                          ChildLimits(timeout_s=60.0))
    assert outcome.row is None
    assert outcome.failure == "exit 1 (in stage start): no model here"


def _rows(path: Path) -> list[dict[str, str]]:
    with open(path, newline="", encoding="utf-8") as fh:
        return list(csv.DictReader(fh))


@pytest.fixture(scope="module")
def build_scaling() -> ModuleType:
    """benchmarks/build_scaling.py as a module (its folder on the path, as when it runs)."""
    sys.path.insert(0, str(BENCH.parent))
    try:
        return importlib.import_module("build_scaling")
    finally:
        sys.path.remove(str(BENCH.parent))


def test_quick_bench_one_clearance_link_beside_pinocchio(
        build_scaling: ModuleType, tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    pytest.importorskip("pinocchio")
    out = tmp_path / "bench"
    status = build_scaling.main(["--links", "1", "--structures", "clearance", "--no-paper",
                                 "--quick", "--out", str(out)])
    assert status == 0, capsys.readouterr().err[-2000:]
    (row,) = _rows(out / "build_scaling.csv")
    assert (row["structure"], row["k"], row["n_coords"]) == ("clearance", "1", "3")
    assert row["pin_nv"] == "3"  # a planar joint stands in for the clearance joint
    assert row["formulation"] in ("closed", "recursive") and not row["error"]
    for key in ("derive_s", "emit_s", "compile_s", "derive_mib", "emit_mib", "gcc_mib",
                "build_peak_mib", "group_peak_mib", "fd_trigger_us", "jac_state_us",
                "pin_aba_us", "pin_derivatives_us"):
        assert math.isfinite(float(row[key])) and float(row[key]) > 0, key
    assert float(row["build_peak_mib"]) >= float(row["gcc_mib"])
    assert float(row["fd_vs_aba"]) == pytest.approx(
        float(row["fd_trigger_us"]) / float(row["pin_aba_us"]), rel=1e-12)
    assert float(row["jac_vs_derivatives"]) == pytest.approx(
        float(row["jac_state_us"]) / float(row["pin_derivatives_us"]), rel=1e-12)
    text = (out / "build_scaling.md").read_text(encoding="utf-8")
    assert "| clearance | 1 | 3 |" in text and "## Requirements" in text
    assert "not measured" in text  # no 12- or 32-link row: said, not passed
    assert (out / "build_scaling.png").read_bytes()[:8] == PNG_SIGNATURE
    assert "clearance k=1: " in capsys.readouterr().err  # the progress line of the case


def test_a_case_over_the_memory_limit_is_a_row_that_says_so(
        build_scaling: ModuleType, tmp_path: Path) -> None:
    spec = {"structure": "ideal", "k": 1, "repeats": 3, "batch_s": 0.002, "formulation": None,
            "pinocchio": True, "levels": []}
    row = build_scaling.run_in_child(spec, ChildLimits(timeout_s=120.0, memory_mib=40.0))
    assert (row["structure"], row["k"]) == ("ideal", 1)
    assert "exceeded the limit of 40 MiB" in row["error"]
    assert row["group_peak_mib"] > 40.0
    assert "**failed:** memory" in build_scaling.markdown([row], build_scaling.BUILD_COLUMNS)
    assert "FAIL" not in "".join(build_scaling._checks([row], 20.0))  # a 1-link row claims
    png = build_scaling.plot([row], tmp_path / "failed.png")  # nothing; its plot still draws
    assert png.read_bytes()[:8] == PNG_SIGNATURE
