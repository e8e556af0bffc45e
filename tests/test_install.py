"""The distribution installs one import root, `jointplay`, with derive/ and generated/ under it."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parents[1]

CHECK = """
import importlib.util, json
import jointplay, jointplay.derive, jointplay.generated, jointplay.cli
from importlib.resources import files
print(json.dumps({
    "jointplay": jointplay.__file__,
    "derive": jointplay.derive.__file__,
    "generated": jointplay.generated.__file__,
    "bare": [n for n in ("derive", "runtime", "generated", "scenes")
             if importlib.util.find_spec(n)],
    "robot": (files("jointplay") / "robots" / "paper_4dof.toml").is_file(),
    "scene": (files("jointplay.scenes") / "paper_4dof.toml").is_file(),
    "models": sorted(jointplay.generated.folders()),
}))
"""


def _probe(cwd: Path, env_path: str | None = None) -> dict:
    import json
    import os

    env = dict(os.environ)
    if env_path is not None:
        env["PYTHONPATH"] = env_path
    out = subprocess.run([sys.executable, "-c", CHECK], cwd=cwd, env=env, capture_output=True,
                         text=True, check=True, timeout=120)
    return json.loads(out.stdout)


def test_installed_import_paths(tmp_path: Path) -> None:
    """As installed in this environment (editable or not), from outside the repository."""
    info = _probe(tmp_path)
    root = Path(info["jointplay"]).parent
    assert Path(info["derive"]).parent.name in ("derive",)
    assert Path(info["generated"]).parent.name in ("generated",)
    assert root.name in ("runtime", "jointplay")
    assert info["bare"] == [], "bare generic top-level names must not be importable"
    assert info["robot"]
    assert info["scene"]
    assert "paper_4dof" in info["models"]


def test_runtime_does_not_import_sympy(tmp_path: Path) -> None:
    code = ("import sys, numpy as np, jointplay\n"
            "from jointplay import generated\n"
            "m = jointplay.load_model(generated.folders()['paper_4dof'])\n"
            "p = m.parameter_vector()\n"
            "x = np.zeros(m.n_state)\n"
            "m.forward_dynamics(x, [0.0, 0.0], p)\n"
            "import jointplay.cli\n"
            "assert 'sympy' not in sys.modules, 'the runtime imported sympy'\n"
            "print('ok')\n")
    out = subprocess.run([sys.executable, "-c", code], cwd=tmp_path, capture_output=True,
                         text=True, timeout=120)
    assert out.returncode == 0, out.stderr
    assert out.stdout.strip() == "ok"


def test_regular_install_layout(tmp_path: Path) -> None:
    """`pip install .` (not editable) puts the same import paths and data in site-packages."""
    target = tmp_path / "site"
    proc = subprocess.run(
        [sys.executable, "-m", "pip", "install", "--quiet", "--no-deps", "--no-build-isolation",
         "--target", str(target), str(REPO)],
        capture_output=True, text=True, timeout=600)
    assert proc.returncode == 0, proc.stderr[-3000:]
    info = _probe(tmp_path, env_path=str(target))
    assert Path(info["jointplay"]) == target / "jointplay" / "__init__.py"
    assert Path(info["derive"]) == target / "jointplay" / "derive" / "__init__.py"
    assert Path(info["generated"]) == target / "jointplay" / "generated" / "__init__.py"
    assert info["bare"] == []
    assert info["robot"]
    assert info["scene"]
    assert info["models"] == ["paper_4dof"]
    assert (target / "jointplay" / "generated" / "paper_4dof" / "model.c").is_file()


OPTIONAL = ("torch", "dask", "distributed", "pyarrow", "pandas", "xarray", "h5netcdf")


def test_simulate_imports_no_optional_dependency(tmp_path: Path) -> None:
    """The core path (import, compile, simulate, write the results) needs none of the extras:
    in a fresh interpreter, none of their packages is imported."""
    out_file = str(tmp_path / "r.h5")
    code = ("import sys\n"
            "from jointplay.cli import main\n"
            f"code = main(['simulate', '--t-end', '0.02', '--quiet', '--out', {out_file!r}])\n"
            "assert code == 0, code\n"
            f"print(sorted(m for m in {OPTIONAL!r} if m in sys.modules))\n")
    out = subprocess.run([sys.executable, "-c", code], cwd=tmp_path, capture_output=True,
                         text=True, timeout=300)
    assert out.returncode == 0, out.stderr
    assert out.stdout.strip().splitlines()[-1] == "[]"
    assert (tmp_path / "r.h5").is_file()


@pytest.mark.parametrize(("argv", "extra", "module"), [
    (["identify", "--out", "m"], "control", "torch"),
    (["control", "--model", "m"], "control", "torch"),
    (["control-study", "--out", "s"], "control", "torch"),
    (["sweep", "sweep.toml", "--out", "s"], "sweep", "pyarrow"),
])
def test_a_missing_extra_is_named(tmp_path: Path, monkeypatch: pytest.MonkeyPatch,
                                  capsys: pytest.CaptureFixture[str], argv: list[str],
                                  extra: str, module: str) -> None:
    """Without the extra's packages, the command stops before any work with one line naming
    the pip install that adds them."""
    from jointplay.cli import main

    monkeypatch.chdir(tmp_path)
    monkeypatch.setitem(sys.modules, module, None)  # what find_spec sees when it is absent
    assert main(argv) == 1
    err = capsys.readouterr().err.strip()
    assert err == (f"jointplay: error: jointplay {argv[0]} needs {module}, not installed; "
                   f"install it with pip install 'jointplay[{extra}]'")
    assert list(tmp_path.iterdir()) == []


def test_a_missing_extra_is_named_by_the_api(monkeypatch: pytest.MonkeyPatch) -> None:
    from jointplay.common.extras import MissingExtra
    from jointplay.scene.definition import default_scene

    monkeypatch.setitem(sys.modules, "xarray", None)
    result = jointplay_simulate_short()
    with pytest.raises(MissingExtra, match=r"pip install 'jointplay\[xarray\]'"):
        result.to_xarray()
    monkeypatch.setitem(sys.modules, "torch", None)
    from jointplay.neural.identify.pipeline import IdentifyConfig, identify

    with pytest.raises(MissingExtra, match=r"pip install 'jointplay\[control\]'"):
        identify(default_scene(), Path("never-written"), IdentifyConfig())
    assert not Path("never-written").exists()


def jointplay_simulate_short():  # type: ignore[no-untyped-def]
    import jointplay

    return jointplay.simulate(jointplay.default_scene().with_run(t_end=0.01))


def test_extras_match_pyproject() -> None:
    """Each extra of jointplay.common.extras is declared in pyproject.toml with a package
    for every module it names, and [all] holds them all."""
    import tomllib

    from jointplay.common.extras import EXTRAS

    declared = tomllib.loads((REPO / "pyproject.toml").read_text())["project"][
        "optional-dependencies"]
    dists = {"dask": "dask[distributed]", "distributed": "dask[distributed]", "pyarrow": "pyarrow",
             "pandas": "pandas", "torch": "torch", "xarray": "xarray", "h5netcdf": "h5netcdf"}
    for extra, modules in EXTRAS.items():
        names = [d.split(">")[0].split("=")[0].split("<")[0] for d in declared[extra]]
        for module in modules:
            assert dists[module] in names, (extra, module)
    assert declared["all"] == [f"jointplay[{','.join(EXTRAS)}]"]
    # the tests cover every command and build the documentation: every extra and the docs
    test_extras = [d for d in declared["test"] if d.startswith("jointplay[")]
    assert len(test_extras) == 1, declared["test"]
    assert {"all", "docs"} <= set(test_extras[0][len("jointplay["):-1].split(","))
    assert "torch==2.13.0" in declared["control"]
