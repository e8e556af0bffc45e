"""The neural packages' import rules, read from the source with ast (every import, the ones
inside functions too): the shared model code imports none of the other neural packages,
identification and the controller import the model code only, the studies may import all.
Each package's ``__init__`` opens with what it does and what it may import."""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

NEURAL = Path(__file__).resolve().parent.parent / "runtime" / "neural"
PACKAGES = ("model", "identify", "control", "study")
ALLOWED = {
    "model": {"model"},
    "identify": {"model", "identify"},
    "control": {"model", "control"},
    "study": {"model", "identify", "control", "study"},
}


def neural_imports(path: Path) -> list[tuple[int, str]]:
    """(line, module) of every import of a ``jointplay.neural`` module in the file."""
    found = []
    for node in ast.walk(ast.parse(path.read_text(), str(path))):
        if isinstance(node, ast.ImportFrom) and node.module:
            names = [node.module] if node.level == 0 else []
            if node.module == "jointplay.neural":  # from jointplay.neural import identify
                names = [f"jointplay.neural.{a.name}" for a in node.names]
            found += [(node.lineno, n) for n in names]
        elif isinstance(node, ast.Import):
            found += [(node.lineno, a.name) for a in node.names]
        if isinstance(node, ast.ImportFrom) and node.level:
            raise AssertionError(f"{path}:{node.lineno}: a relative import; name the package")
    return [(line, name) for line, name in found if name.startswith("jointplay.neural.")]


def violations(package: str) -> list[str]:
    bad = []
    for path in sorted((NEURAL / package).rglob("*.py")):
        for line, name in neural_imports(path):
            target = name.split(".")[2]
            if target not in ALLOWED[package]:
                bad.append(f"{path.relative_to(NEURAL)}:{line} imports {name}")
    return bad


def test_every_neural_module_sits_in_one_of_the_packages() -> None:
    loose = sorted(p.name for p in NEURAL.glob("*.py") if p.name != "__init__.py")
    assert loose == []
    assert sorted(p.name for p in NEURAL.iterdir() if p.is_dir() and
                  (p / "__init__.py").is_file()) == sorted(PACKAGES)


@pytest.mark.parametrize("package", PACKAGES)
def test_package_imports_only_what_it_may(package: str) -> None:
    assert violations(package) == []


@pytest.mark.parametrize("package", PACKAGES)
def test_package_says_what_it_does_and_may_import(package: str) -> None:
    doc = ast.get_docstring(ast.parse((NEURAL / package / "__init__.py").read_text()))
    assert doc and "May import:" in doc


def test_the_check_sees_a_forbidden_import(tmp_path: Path) -> None:
    """The checker itself: a controller module importing training is caught, a lazy import
    inside a function included."""
    module = tmp_path / "bad.py"
    module.write_text("def f():\n    from jointplay.neural.identify.training import train_narx\n")
    assert neural_imports(module) == [(2, "jointplay.neural.identify.training")]
    assert "identify" not in ALLOWED["control"]


def test_no_neural_module_is_over_500_lines() -> None:
    long = {str(p.relative_to(NEURAL)): n for p in NEURAL.rglob("*.py")
            if (n := len(p.read_text().splitlines())) > 500}
    assert long == {}
