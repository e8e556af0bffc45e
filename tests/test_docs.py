"""Docs that run: every Python and shell example in README.md and docs/**/*.md is executed here.

The fences say what a block is:

* ``python``: run in document order, one namespace per file (a block may use what an earlier
  block of the same file defined);
* ``sh``: run by ``bash -e``;
* ``console``: a transcript; each ``$ command`` is run and what it printed (stdout and stderr
  together) must match the lines below it, where ``...`` matches anything;
* ``text``, ``toml`` and the rest are shown, never run.

Every block of a file runs in one scratch folder in which ``scenes/``, ``generated/`` and
``benchmarks/`` are the project's, so examples use the paths a user in a checkout would. An
HTML comment on the line before a fence can say more:

* ``<!-- docs: ci -->``: the block is the README's setup or test command; running it here
  would install the project again or run this suite inside itself, so the test checks instead
  that ``.ci/run`` runs exactly these lines;
* ``<!-- docs: slow -->``: the block takes minutes; it runs in the slow tier;
* ``<!-- docs: dev -->``: the block needs the ``dev`` extra (ruff, mypy); skipped without it;
* ``<!-- docs: not run: REASON -->``: the block needs what a test cannot have (several
  machines, the git history of a full clone, or more minutes than the whole suite may take);
  the reason is shown in the test report.
"""

from __future__ import annotations

import doctest
import importlib.util
import os
import re
import subprocess
import sys
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import pytest

ROOT = Path(__file__).resolve().parents[1]
DOCS = [ROOT / "README.md", *sorted((ROOT / "docs").rglob("*.md"))]
RUN_LANGS = ("python", "sh", "console")
_FENCE = re.compile(r"^(?:<!-- docs: (?P<mark>[^>]*?) -->\n)?```(?P<lang>[\w-]*)\n"
                    r"(?P<body>.*?)^```\s*$", re.M | re.S)
_TIMEOUT_S = 900


@dataclass(frozen=True)
class Block:
    path: Path
    line: int
    lang: str
    body: str
    mark: str

    @property
    def name(self) -> str:
        """The file's path in the checkout (docs/ has several index.md, accuracy.md, ...)."""
        return self.path.relative_to(ROOT).as_posix()

    @property
    def id(self) -> str:
        return f"{self.name}:{self.line}"


def blocks(path: Path) -> list[Block]:
    text = path.read_text(encoding="utf-8")
    out = []
    for m in _FENCE.finditer(text):
        line = text.count("\n", 0, m.start("lang")) + 1
        out.append(Block(path, line, m["lang"], m["body"], (m["mark"] or "").strip()))
    return out


def runnable() -> list[Any]:
    params = []
    for path in DOCS:
        for block in blocks(path):
            if block.lang not in RUN_LANGS or block.mark == "ci":
                continue
            marks = [pytest.mark.slow] if block.mark == "slow" else []
            params.append(pytest.param(block, id=block.id, marks=marks))
    return params


_SCRATCH: dict[Path, tuple[Path, dict[str, Any]]] = {}


@pytest.fixture(scope="module")
def scratch_root(tmp_path_factory: pytest.TempPathFactory) -> Path:
    return tmp_path_factory.mktemp("docs")


def _scratch(block: Block, root: Path) -> tuple[Path, dict[str, Any]]:
    """One folder and one Python namespace per documentation file."""
    if block.path not in _SCRATCH:
        folder = root / block.name.removesuffix(".md").replace("/", "__")
        folder.mkdir()
        for name in ("scenes", "generated", "benchmarks"):
            (folder / name).symlink_to(ROOT / name)
        _SCRATCH[block.path] = (folder, {"__name__": f"docs_{folder.name}"})
    return _SCRATCH[block.path]


def _environment() -> dict[str, str]:
    env = dict(os.environ)
    env["PATH"] = f"{Path(sys.executable).parent}{os.pathsep}{env.get('PATH', '')}"
    env.setdefault("MPLBACKEND", "Agg")
    return env


def _run_python(block: Block, folder: Path, namespace: dict[str, Any]) -> None:
    code = compile(block.body, f"{block.path}:{block.line}", "exec")
    cwd = Path.cwd()
    os.chdir(folder)
    try:
        exec(code, namespace)  # the documentation's own example, run as a reader would
    finally:
        os.chdir(cwd)


def _run_sh(block: Block, folder: Path) -> None:
    # Development commands act on the checkout itself, everything else in the scratch folder.
    cwd = ROOT if block.mark == "dev" else folder
    proc = subprocess.run(["bash", "-e", "-c", block.body], cwd=cwd, env=_environment(),
                          capture_output=True, text=True, timeout=_TIMEOUT_S, check=False)
    assert proc.returncode == 0, (f"{block.id} exited {proc.returncode}\n{proc.stdout[-3000:]}"
                                  f"\n{proc.stderr[-3000:]}")


def transcript(body: str) -> list[tuple[str, str]]:
    """``[(command, expected output)]`` of a console block."""
    steps: list[tuple[str, list[str]]] = []
    for line in body.splitlines():
        if line.startswith("$ "):
            steps.append((line[2:], []))
        elif steps:
            steps[-1][1].append(line)
        elif line.strip():
            raise AssertionError(f"a console block starts with '$ ', not {line!r}")
    return [(cmd, "\n".join(out).strip() + "\n") for cmd, out in steps]


def _run_console(block: Block, folder: Path) -> None:
    checker = doctest.OutputChecker()
    for command, expected in transcript(block.body):
        proc = subprocess.run(["bash", "-c", command], cwd=folder, env=_environment(),
                              capture_output=True, text=True, timeout=_TIMEOUT_S, check=False)
        got = (proc.stdout + proc.stderr).strip() + "\n"
        assert checker.check_output(expected, got, doctest.ELLIPSIS), \
            f"{block.id}: `{command}` printed\n{got}\nwhere the documentation shows\n{expected}"


@pytest.mark.parametrize("block", runnable())
def test_documentation_example_runs(block: Block, scratch_root: Path) -> None:
    if block.mark.startswith("not run:"):
        pytest.skip(f"{block.id}: {block.mark}")
    if block.mark == "dev" and not all(importlib.util.find_spec(m) for m in ("ruff", "mypy")):
        pytest.skip(f"{block.id} needs the dev extra: pip install -e '.[test,dev]'")
    assert block.mark in ("", "slow", "dev"), f"{block.id}: unknown docs mark {block.mark!r}"
    folder, namespace = _scratch(block, scratch_root)
    if block.lang == "python":
        _run_python(block, folder, namespace)
    elif block.lang == "sh":
        _run_sh(block, folder)
    else:
        _run_console(block, folder)


def test_readme_setup_and_test_commands_are_what_ci_runs() -> None:
    """The README's first screen is run by CI as it stands, not by this suite."""
    ci = (ROOT / ".ci" / "run").read_text(encoding="utf-8").splitlines()
    ci_blocks = [b for b in blocks(ROOT / "README.md") if b.mark == "ci"]
    assert len(ci_blocks) == 2, "the README's first screen has two commands marked for CI"
    for block in ci_blocks:
        commands = [ln for ln in block.body.splitlines() if ln and not ln.startswith("#")]
        for command in commands:
            assert command in ci, f"README.md:{block.line}: `{command}` is not what .ci/run runs"


def test_every_runnable_fence_is_recognised() -> None:
    """A typo in a fence (```pyhton) would silently stop an example from running."""
    known = {*RUN_LANGS, "text", "toml", "json", "csv", "c", "mermaid"}
    for path in DOCS:
        for block in blocks(path):
            assert block.lang in known, f"{block.id}: unknown fence language {block.lang!r}"
            assert block.lang != "" , f"{block.id}: give the fence a language (text if shown)"


def test_console_transcripts_are_parsed() -> None:
    assert transcript("$ a\nx\n...\n$ b\n") == [("a", "x\n...\n"), ("b", "\n")]
    with pytest.raises(AssertionError, match="starts with"):
        transcript("output first\n$ a\n")
