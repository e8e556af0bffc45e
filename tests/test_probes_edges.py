"""Probes at the edges: the cache removes only what jointplay made, a build holds what it
links against, the penetration stop reads the located extremes, the plausibility stop is a
setting, and every check that can fail runs before the work.

Each probe satisfies the contract of :mod:`test_probes` (exit 0, 1, 2 or 130, one error line,
no traceback)."""

from __future__ import annotations

import os
import subprocess
import sys
import textwrap
from pathlib import Path

import pytest
from test_probes import check_contract

from jointplay.cli import main
from jointplay.store import cache
from jointplay.store.build import OWNER_NAME, build_key, compile_source

# Compiles in a fraction of a second, where any library will do.
TINY = ("/* GENERATED FILE: DO NOT EDIT.\n * model: tiny\n */\n"
        "double tiny(double x) { return 2.0 * x; }\n")
USES_TINY = ("/* GENERATED FILE: DO NOT EDIT.\n * model: uses_tiny\n */\n"
             "double tiny(double x);\ndouble twice_tiny(double x) { return tiny(tiny(x)); }\n")


def _tree(folder: Path) -> list[str]:
    return sorted(str(p.relative_to(folder)) for p in folder.rglob("*"))


# ---- the cache owns only what it made --------------------------------------------------------

def test_clear_leaves_folders_jointplay_did_not_make(
        tmp_path: Path, capsys: pytest.CaptureFixture[str],
        monkeypatch: pytest.MonkeyPatch) -> None:
    root = tmp_path / "P"
    package = root / "build" / "lib" / "pkg"
    package.mkdir(parents=True)
    (package / "mod.py").write_text("x\n")
    (root / "models" / "notes").mkdir(parents=True)
    (root / "models" / "notes" / "a.txt").write_text("mine\n")
    ours, _ = compile_source(TINY, cache=root)
    assert (ours.parent / OWNER_NAME).is_file()
    before = _tree(root / "build" / "lib") + _tree(root / "models")
    monkeypatch.setenv("JOINTPLAY_CACHE", str(root))
    code = main(["cache", "clear"])
    out, err = capsys.readouterr()
    check_contract(code, err)
    assert code == 0
    assert "removed 1 entries" in out, out
    assert not ours.parent.exists()
    assert f"not jointplay's, left: {root / 'build' / 'lib'}" in out
    assert f"not jointplay's, left: {root / 'models' / 'notes'}" in out
    assert _tree(root / "build" / "lib") + _tree(root / "models") == before
    assert not (root / "build" / "lib" / ".lock").exists()


@pytest.mark.parametrize("action", [["clear"], ["prune", "--older-than", "0s"],
                                    ["prune", "--max-size", "0"]])
def test_clear_and_prune_never_follow_links(tmp_path: Path, action: list[str],
                                            capsys: pytest.CaptureFixture[str],
                                            monkeypatch: pytest.MonkeyPatch) -> None:
    """A link where an entry lives (even to a folder that looks like an entry, owner file and
    all), and ``build`` itself a link: nothing behind them is removed or written into."""
    root = tmp_path / "c"
    ours, _ = compile_source(TINY, cache=root)
    elsewhere = tmp_path / "elsewhere"
    elsewhere.mkdir()
    (elsewhere / "precious.txt").write_text("keep\n")
    (elsewhere / OWNER_NAME).write_text("forged\n")
    (root / "build" / "linked").symlink_to(elsewhere)
    (root / "models").symlink_to(elsewhere)
    monkeypatch.setenv("JOINTPLAY_CACHE", str(root))
    code = main(["cache", *action])
    out, err = capsys.readouterr()
    check_contract(code, err)
    assert code == 0, err
    assert "removed 1 entries" in out and not ours.parent.exists()
    assert sorted(p.name for p in elsewhere.iterdir()) == [OWNER_NAME, "precious.txt"]
    assert (root / "build" / "linked").is_symlink() and (root / "models").is_symlink()
    assert f"not jointplay's, left: {root / 'build' / 'linked'}" in out
    assert f"not jointplay's, left: {root / 'models'}" in out


def test_prune_with_a_size_of_400_digits_keeps_everything(
        tmp_path: Path, capsys: pytest.CaptureFixture[str],
        monkeypatch: pytest.MonkeyPatch) -> None:
    root = tmp_path / "c"
    ours, _ = compile_source(TINY, cache=root)
    monkeypatch.setenv("JOINTPLAY_CACHE", str(root))
    code = main(["cache", "prune", "--max-size", "9" * 400])
    out, err = capsys.readouterr()
    check_contract(code, err)
    assert code == 0 and "removed 0 entries" in out and ours.exists()
    assert cache.parse_size("1" + "0" * 399 + "K") == 10 ** 399 * 1024
    code = main(["cache", "prune", "--max-size", "9" * 5000])
    check_contract(code, capsys.readouterr().err)
    assert code == 2


_SLOW_LINKER = """#!{python}
import os, sys, time
# Any call that links against a cached library signals, then waits before linking.
if any(arg.endswith("/model.so") for arg in sys.argv[1:]):
    open({signal!r}, "w").close()
    time.sleep(4.0)
os.execv({gcc!r}, [{gcc!r}, *sys.argv[1:]])
"""


def test_clear_during_a_build_keeps_the_library_it_links_against(tmp_path: Path) -> None:
    """Two processes: one builds a library linked against a cached one (as a model's first
    deferred compile does), the other clears the cache meanwhile. The build succeeds, the
    library it links against is kept (in use), and the clear removes it once the build ends."""
    import shutil

    root = tmp_path / "c"
    eager, _ = compile_source(TINY, cache=root)
    tools = tmp_path / "bin"
    tools.mkdir()
    signal = tmp_path / "linking"
    gcc = shutil.which("gcc")
    gcc = gcc and os.path.realpath(gcc)
    assert gcc is not None
    wrapper = tools / "gcc"
    wrapper.write_text(_SLOW_LINKER.format(python=sys.executable, signal=str(signal), gcc=gcc))
    wrapper.chmod(0o755)
    code = textwrap.dedent(f"""
        from pathlib import Path
        from jointplay.store.build import compile_source
        lib, _ = compile_source({USES_TINY!r}, cache=Path({str(root)!r}),
                                libraries=({str(eager)!r},))
        print(lib)
    """)
    env = {**os.environ, "PATH": f"{tools}:{os.environ['PATH']}"}
    builder = subprocess.Popen([sys.executable, "-c", code], env=env, text=True,
                               stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    try:
        for _ in range(600):
            if signal.exists() or builder.poll() is not None:
                break
            import time
            time.sleep(0.05)
        assert signal.exists(), builder.communicate()
        removed, busy = cache.clear(root)
        assert eager.parent in [e.path for e in busy]
        assert eager.exists()
        out, err = builder.communicate(timeout=120)
    finally:
        if builder.poll() is None:
            builder.kill()
            builder.wait()
    assert builder.returncode == 0, err
    assert Path(out.strip()).exists()
    removed, busy = cache.clear(root)
    assert busy == [] and not eager.exists()
    assert build_key(TINY) in {e.key for e in removed}
