"""The distribution installs one import root, `jointplay`, with derive/ and generated/ under it."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

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
