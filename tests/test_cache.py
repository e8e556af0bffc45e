"""The model cache: what it loads is verified, killed and failed builds leave nothing behind,
`jointplay cache list|clear|prune` shows and removes entries, and the test suite itself never
touches the user's cache."""

from __future__ import annotations

import errno
import hashlib
import json
import os
import signal
import subprocess
import sys
import time
from pathlib import Path
from typing import Any

import pytest
from test_probes import check_contract

from jointplay import generated
from jointplay.cli import main
from jointplay.store import build as build_module
from jointplay.store import cache
from jointplay.store.build import (
    DEFAULT_CFLAGS,
    LIBRARY_NAME,
    MARKER_NAME,
    build_key,
    compile_source,
    elf_is_whole,
)

REPO = Path(__file__).resolve().parents[1]
SOURCE = (generated.folders()["paper_4dof"] / "model.c").read_text()
# Compiles in a fraction of the paper model's time, where any library will do.
TINY = ("/* GENERATED FILE: DO NOT EDIT.\n * model: tiny\n */\n"
        "double tiny(double x) { return 2.0 * x; }\n")


def _files(root: Path) -> list[str]:
    return sorted(str(p.relative_to(root)) for p in root.rglob("*")) if root.exists() else []


# ---- what is loaded is verified ----------------------------------------------------------------

def test_truncated_library_with_a_forged_marker_is_rebuilt_not_loaded(tmp_path: Path) -> None:
    """A library cut short in the cache, its marker rewritten to match (size and checksum):
    loading it would crash with SIGBUS. It is found incomplete and rebuilt, in a subprocess
    that must end normally."""
    cache_dir = tmp_path / "c"
    library, _ = compile_source(SOURCE, cache=cache_dir)
    whole = library.read_bytes()
    assert elf_is_whole(library)
    cut = whole[: len(whole) // 2]
    library.write_bytes(cut)
    marker_path = library.parent / MARKER_NAME
    marker = json.loads(marker_path.read_text())
    marker.update(sha256=hashlib.sha256(cut).hexdigest(), size=len(cut))
    marker_path.write_text(json.dumps(marker))
    assert not elf_is_whole(library)
    code = ("import numpy as np, jointplay\n"
            "from jointplay import generated\n"
            "m = jointplay.load_model(generated.folders()['paper_4dof'])\n"
            "m.forward_dynamics(np.zeros(m.n_state), [0.0, 0.0], m.parameter_vector())\n"
            "print(m.library)\n")
    proc = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                          timeout=300, env={**os.environ, "JOINTPLAY_CACHE": str(cache_dir)})
    assert proc.returncode == 0, proc.stderr
    assert "compiling it again" in proc.stderr
    assert library.read_bytes() == whole or elf_is_whole(library)
    assert len(library.read_bytes()) > len(cut)


@pytest.mark.parametrize("cut", [0, 16, 63, 200, 4096])
def test_elf_check_refuses_every_truncation(tmp_path: Path, cut: int) -> None:
    library, _ = compile_source(TINY, cache=tmp_path)
    whole = library.read_bytes()
    part = tmp_path / "part.so"
    part.write_bytes(whole[:cut] if cut < 4096 else whole[:-cut])
    assert not elf_is_whole(part)
    part.write_bytes(whole)
    assert elf_is_whole(part)


# ---- killed and failed builds ------------------------------------------------------------------

_KILLED_BUILD = """
import sys
from pathlib import Path
from jointplay.store.build import compile_source
print("building", flush=True)
compile_source(sys.stdin.read(), cache=Path({cache!r}))
"""


def test_sigkill_during_a_compile_leaves_nothing_the_next_build_keeps(tmp_path: Path) -> None:
    """SIGKILL while gcc runs: the compiler dies with it, and the next build of the entry
    (its only builder, holding the lock) removes every temporary file, even one whose owner
    looks alive, then builds and loads."""
    cache_dir = tmp_path / "c"
    source = SOURCE + "\n/* killed build */\n"
    entry = cache_dir / "build" / build_key(source)
    proc = subprocess.Popen([sys.executable, "-c", _KILLED_BUILD.format(cache=str(cache_dir))],
                            stdin=subprocess.PIPE, stdout=subprocess.PIPE, text=True)
    assert proc.stdin is not None and proc.stdout is not None
    proc.stdin.write(source)
    proc.stdin.close()
    assert proc.stdout.readline().strip() == "building"
    deadline = time.monotonic() + 60
    while not (entry / "model.c").exists() and time.monotonic() < deadline:
        time.sleep(0.02)
    time.sleep(0.3)  # gcc is running now
    gcc = subprocess.run(["pgrep", "-P", str(proc.pid)], capture_output=True, text=True)
    proc.send_signal(signal.SIGKILL)
    proc.wait()
    for pid in gcc.stdout.split():  # the compiler dies with its parent
        deadline = time.monotonic() + 10
        while time.monotonic() < deadline:
            try:
                os.kill(int(pid), 0)
            except ProcessLookupError:
                break
            time.sleep(0.05)
        else:
            pytest.fail(f"the compiler {pid} outlived the killed build")
    assert not (entry / MARKER_NAME).exists()
    # A leftover that the pid rule alone would keep: its owner (this process) is alive.
    from jointplay.common.files import temp_tag

    planted = entry / f".{LIBRARY_NAME}.{temp_tag()}.x.part"
    planted.write_bytes(b"half a library")
    library, seconds = compile_source(source, cache=cache_dir)
    assert seconds > 0 and elf_is_whole(library)
    assert list(entry.glob(".*.part")) == []


@pytest.mark.parametrize("phase", ["source", "compiler", "marker"])
def test_no_space_while_writing_the_cache(tmp_path: Path, monkeypatch: pytest.MonkeyPatch,
                                          capsys: pytest.CaptureFixture[str],
                                          phase: str) -> None:
    """ENOSPC while the C file, the library or the marker is written: exit 1, one line
    naming the cache and the cause, and nothing left in the cache."""
    cache_dir = tmp_path / "c"
    monkeypatch.setenv("JOINTPLAY_CACHE", str(cache_dir))
    real_write_text = Path.write_text

    def full_disk(path: Path, *args: object, **kwargs: object) -> int:
        target = {"source": ".model.c.", "marker": f".{MARKER_NAME}."}.get(phase)
        if target and path.name.startswith(target) and str(cache_dir) in str(path):
            real_write_text(path, "partly written")
            raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC))
        return real_write_text(path, *args, **kwargs)  # type: ignore[arg-type]

    monkeypatch.setattr(Path, "write_text", full_disk)
    if phase == "compiler":
        real_popen = subprocess.Popen

        class CompilerOutOfSpace:
            """The compiler's process, out of space as it links."""

            def __init__(self, command: list[str], **kwargs: Any) -> None:
                output = Path(command[command.index("-o") + 1])
                output.write_bytes(b"\x7fELF partly")
                self.returncode = 1

            def communicate(self) -> tuple[str, str]:
                return "", "/usr/bin/ld: final link failed: No space left on device\n"

        def compiler_out_of_space(command: list[str], *args: Any, **kwargs: Any) -> Any:
            if command[0] != "gcc" or "-o" not in command:
                return real_popen(command, *args, **kwargs)
            return CompilerOutOfSpace(command, **kwargs)

        monkeypatch.setattr(build_module.subprocess, "Popen", compiler_out_of_space)
    code = main(["build"])
    err = capsys.readouterr().err
    check_contract(code, err)
    assert code == 1, err
    # what is compiling is said before the compiler starts; the error is then one line
    errors = [line for line in err.splitlines()
              if line.strip() and not line.startswith("jointplay: compiling ")]
    assert len(errors) == 1, err
    assert "no space left on device" in errors[0] and str(cache_dir) in errors[0]
    assert "JOINTPLAY_CACHE" in errors[0]
    assert [f for f in _files(cache_dir) if f != "build"] == []


# ---- jointplay cache list | clear | prune ----------------------------------------------------

@pytest.fixture
def two_entries(tmp_path: Path) -> Path:
    """A cache with two builds of a model (default flags and -O0), one used a day ago."""
    root = tmp_path / "c"
    compile_source(TINY, cache=root)
    compile_source(TINY, (*DEFAULT_CFLAGS, "-O0"), cache=root)
    old = time.time() - 86400 - 60
    os.utime(root / "build" / build_key(TINY) / MARKER_NAME, (old, old))
    return root


def test_cache_list(two_entries: Path, monkeypatch: pytest.MonkeyPatch,
                    capsys: pytest.CaptureFixture[str]) -> None:
    monkeypatch.setenv("JOINTPLAY_CACHE", str(two_entries))
    assert main(["cache", "list"]) == 0
    out = capsys.readouterr().out.splitlines()
    assert out[0] == f"cache {two_entries} (JOINTPLAY_CACHE)"
    rows = [line for line in out if line.startswith("build ")]
    assert len(rows) == 2 and all(" tiny " in row for row in rows)
    assert rows[0].endswith("1 d ago")  # least recently used first
    assert build_key(TINY)[:12] in rows[0]
    sizes = sum(e.size for e in cache.entries(two_entries))
    assert out[-1] == f"2 entries, {cache.format_size(sizes)}"


def test_cache_prune_by_age_then_size_and_clear(two_entries: Path,
                                                monkeypatch: pytest.MonkeyPatch,
                                                capsys: pytest.CaptureFixture[str]) -> None:
    monkeypatch.setenv("JOINTPLAY_CACHE", str(two_entries))
    old_key = build_key(TINY)
    assert main(["cache", "prune", "--older-than", "12h"]) == 0
    out = capsys.readouterr().out
    assert f"removed build tiny {old_key[:12]}" in out and "removed 1 entries" in out
    assert not (two_entries / "build" / old_key).exists()
    left = cache.entries(two_entries)
    assert len(left) == 1
    # a size limit above what is left removes nothing; one below removes the rest
    assert main(["cache", "prune", "--max-size", f"{left[0].size}"]) == 0
    assert "removed 0 entries" in capsys.readouterr().out
    assert main(["cache", "prune", "--max-size", "1K"]) == 0
    assert "removed 1 entries" in capsys.readouterr().out
    assert cache.entries(two_entries) == []
    compile_source(TINY, cache=two_entries)
    assert main(["cache", "clear"]) == 0
    assert "removed 1 entries" in capsys.readouterr().out
    assert cache.entries(two_entries) == []


def test_cache_keeps_an_entry_being_built(two_entries: Path) -> None:
    """An entry whose lock another process holds is not removed (kept, and said so)."""
    entry = two_entries / "build" / build_key(TINY)
    code = ("import fcntl, sys, time\n"
            f"fh = open({str(entry / '.lock')!r}, 'a')\n"
            "fcntl.flock(fh, fcntl.LOCK_EX)\n"
            "print('locked', flush=True)\n"
            "time.sleep(60)\n")
    holder = subprocess.Popen([sys.executable, "-c", code], stdout=subprocess.PIPE, text=True)
    try:
        assert holder.stdout is not None and holder.stdout.readline().strip() == "locked"
        removed, busy = cache.clear(two_entries)
        assert [e.path for e in busy] == [entry] and len(removed) == 1
        assert entry.exists()
    finally:
        holder.kill()
        holder.wait()


@pytest.mark.parametrize(("argv", "field"), [
    (["cache", "prune"], "--older-than"),
    (["cache", "prune", "--max-size", "lots"], "--max-size"),
    (["cache", "prune", "--older-than", "soon"], "--older-than"),
])
def test_cache_prune_bad_input(argv: list[str], field: str,
                               capsys: pytest.CaptureFixture[str]) -> None:
    assert main(argv) == 2
    assert f"jointplay: error: {field}:" in capsys.readouterr().err


def test_sizes_and_ages_parse() -> None:
    assert cache.parse_size("500M") == 500 << 20
    assert cache.parse_size("1.5GiB") == int(1.5 * (1 << 30))
    assert cache.parse_size("0") == 0
    assert cache.parse_age("30d") == 30 * 86400
    assert cache.parse_age("90m") == 5400
    assert cache.parse_age("2") == 2 * 86400


# ---- the test suite leaves the user's cache alone ------------------------------------------

def test_the_suite_builds_in_a_temporary_cache(model_cache: Path) -> None:
    assert os.environ["JOINTPLAY_CACHE"] == str(model_cache)
    assert build_module.cache_root() == model_cache


def test_running_tests_creates_nothing_in_the_users_cache(tmp_path: Path) -> None:
    """Run a test that compiles a model in a subprocess (so the subprocess must inherit the
    temporary cache) with a fresh home, no JOINTPLAY_CACHE and no XDG_CACHE_HOME: nothing
    appears in that home's cache, and the temporary cache is gone afterwards."""
    home, scratch = tmp_path / "home", tmp_path / "tmp"
    home.mkdir()
    scratch.mkdir()
    env = {k: v for k, v in os.environ.items()
           if k not in ("JOINTPLAY_CACHE", "XDG_CACHE_HOME", "JOINTPLAY_TEST_CACHE")}
    env.update(HOME=str(home), TMPDIR=str(scratch))
    proc = subprocess.run(
        [sys.executable, "-m", "pytest", "-q", "-p", "no:cacheprovider",
         "tests/test_install.py::test_runtime_does_not_import_sympy"],
        cwd=REPO, env=env, capture_output=True, text=True, timeout=600)
    assert proc.returncode == 0, proc.stdout[-3000:] + proc.stderr[-3000:]
    assert "1 passed" in proc.stdout
    assert not (home / ".cache" / "jointplay").exists(), _files(home)
    assert list(scratch.glob("jointplay-test-cache-*")) == []


def test_marker_without_a_size_still_counts(tmp_path: Path,
                                            capsys: pytest.CaptureFixture[str]) -> None:
    """Entries built before markers recorded the size are reused (checksum and ELF checks
    still hold), not reported damaged."""
    library, _ = compile_source(TINY, cache=tmp_path)
    marker_path = library.parent / MARKER_NAME
    marker = json.loads(marker_path.read_text())
    del marker["size"]
    marker_path.write_text(json.dumps(marker))
    again, seconds = compile_source(TINY, cache=tmp_path)
    assert again == library and seconds == 0.0
    assert capsys.readouterr().err == ""
