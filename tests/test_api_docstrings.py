"""The API reference teaches: every public name has its sections, and the examples run.

The reference (docs/reference/api.md) is written by mkdocstrings from the docstrings, parsed
as numpydoc (``docstring_style: numpy`` in mkdocs.yml). Every name in ``jointplay.__all__``
documents what it takes and gives: a function its Parameters (each one of its signature)
and Returns; a dataclass every field under Attributes; any other class its constructor's
Parameters or its Attributes. The main entry points carry an Examples section, run here as
doctests (short runs of the paper scene; the builds come from the test cache).
"""

from __future__ import annotations

import dataclasses
import doctest
import inspect
import logging
from pathlib import Path
from typing import Any

import pytest

import jointplay

griffe = pytest.importorskip("griffe")

PUBLIC = [name for name in jointplay.__all__ if name != "__version__"]
# The main entry points: each has an example a reader can paste.
WITH_EXAMPLES = ["simulate", "Stepper", "calibrate", "load_scene", "load_robot", "read",
                 "Robot", "Scene", "uniform_chain", "default_scene", "SimulationResult",
                 "CalibrationResult"]


def _sections(obj: Any) -> dict[str, Any]:
    """The docstring's numpydoc sections by kind (``parameters``, ``returns``, ...)."""
    text = inspect.getdoc(obj) or ""
    # griffe warns about what it cannot check without the source tree; the test checks it
    logging.getLogger("griffe").setLevel(logging.ERROR)
    parsed = griffe.Docstring(text, lineno=1).parse("numpy")
    return {section.kind.value: section for section in parsed}


def _documented(section: Any) -> set[str]:
    return {item.name.lstrip("*") for item in section.value}


def _signature_names(obj: Any) -> list[str]:
    return [p.name for p in inspect.signature(obj).parameters.values()]


def test_every_command_line_option_has_help_text() -> None:
    """The command reference (docs/hooks/cli_reference.py) is written from the parsers: every
    argument of every command and sub-command says what it does."""
    import argparse

    from jointplay.cli import make_parser

    def walk(parser: argparse.ArgumentParser, path: str) -> list[str]:
        silent = []
        for action in parser._actions:
            if isinstance(action, argparse._SubParsersAction):
                for name, sub in action.choices.items():
                    silent += walk(sub, f"{path} {name}")
            elif not isinstance(action, argparse._HelpAction | argparse._VersionAction) \
                    and not (action.help or "").strip():
                silent.append(f"{path} {'/'.join(action.option_strings) or action.dest}")
        return silent

    assert walk(make_parser(), "jointplay") == []


def test_every_public_name_is_listed_once_and_documented() -> None:
    assert len(PUBLIC) == len(set(PUBLIC))
    assert set(WITH_EXAMPLES) <= set(PUBLIC)


@pytest.mark.parametrize("name", PUBLIC)
def test_every_public_name_has_parameters_and_returns_or_attributes(name: str) -> None:
    obj = getattr(jointplay, name)
    sections = _sections(obj)
    summary = (inspect.getdoc(obj) or "").split("\n", 1)[0]
    assert summary.strip(), f"{name}: no one-line summary"
    if inspect.isclass(obj):
        if dataclasses.is_dataclass(obj):
            assert "attributes" in sections, f"{name}: a dataclass without Attributes"
            fields = {f.name for f in dataclasses.fields(obj)}
            missing = fields - _documented(sections["attributes"])
            assert not missing, f"{name}: fields not under Attributes: {sorted(missing)}"
            return
        assert "parameters" in sections or "attributes" in sections, \
            f"{name}: neither Parameters nor Attributes"
        if "__init__" in vars(obj) and "parameters" in sections:
            undocumented = set(_signature_names(obj)) - _documented(sections["parameters"])
            assert not undocumented, \
                f"{name}: constructor parameters not documented: {undocumented}"
        return
    assert "returns" in sections, f"{name}: no Returns"
    wanted = _signature_names(obj)
    if wanted:
        assert "parameters" in sections, f"{name}: no Parameters"
        documented = _documented(sections["parameters"])
        missing = set(wanted) - documented
        extra = documented - set(wanted)
        assert not missing, f"{name}: parameters not documented: {sorted(missing)}"
        assert not extra, f"{name}: documented but not in the signature: {sorted(extra)}"


@pytest.mark.parametrize("name", WITH_EXAMPLES)
def test_main_entry_points_have_examples_that_run(name: str, tmp_path: Path,
                                                  monkeypatch: pytest.MonkeyPatch) -> None:
    obj = getattr(jointplay, name)
    assert "examples" in _sections(obj), f"{name}: no Examples section"
    tests = doctest.DocTestFinder(recurse=False).find(obj, name, globs={})
    examples = sum(len(t.examples) for t in tests)
    assert examples >= 2, f"{name}: the Examples section has no doctest to run"
    monkeypatch.chdir(tmp_path)  # an example may write files
    runner = doctest.DocTestRunner(optionflags=doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE)
    report: list[str] = []
    for test in tests:
        runner.run(test, out=report.append)
    result = runner.summarize(verbose=False)
    assert result.failed == 0, "".join(report)
