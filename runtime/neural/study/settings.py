"""One settings object for identification, the controller and studies: ``[identify]``,
``[control]`` and ``[study]`` tables in a scene file or in a settings file beside it, over a
named preset, with command-line overrides on top (flags > file > preset).

    settings = resolve_settings({"identify": {"hidden": [24, 24]}}, preset="best")
    settings.identify.hidden            # (24, 24)
    settings_toml(settings, scene=None) # the resolved settings as a file, read back the same

Every problem of a file is reported at once, an unknown key with the nearest known one
(docs/how-to/settings-file.md lists every key).
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass, fields, replace
from pathlib import Path
from typing import Any

from jointplay.common.errors import DescriptionError, combined
from jointplay.common.hints import did_you_mean
from jointplay.common.validation import Problems, check_keys, read_toml
from jointplay.neural.control.imc_settings import ControllerSettings
from jointplay.neural.identify.config import IdentifyConfig
from jointplay.neural.study.cases import CASES
from jointplay.neural.study.settings_schema import (
    DEFAULT_PRESET,
    PRESETS,
    SCHEMA,
    SECTIONS,
    Key,
    checked,
    parse_text,
    toml_value,
)

SETTINGS_FILE = "settings.toml"
TEXT = Key("str")
# The top-level keys of a settings file (a scene file may hold all but ``scene``).
FILE_KEYS = ("preset", "scene", *SECTIONS)


@dataclass(frozen=True)
class StudySettings:
    """What ``jointplay control-study`` runs beyond one identification and one controller."""

    seeds: int = 3  # training seeds at the scene's clearance
    first_seed: int = 0  # the seeds are first_seed, first_seed + 1, ...
    cases: tuple[str, ...] = CASES  # the study's cases (jointplay.neural.study.cases)
    clearances: tuple[float, ...] = ()  # other radial clearances, m, each identified again
    clearance_seeds: int = 2  # seeds per other clearance
    workers: int = 2  # processes for the closed-loop runs
    undeclared_noise: bool = False  # the noise case without telling the controllers
    verify: bool = False  # every loop checked against the same loop 10x tighter


@dataclass(frozen=True)
class Settings:
    """The resolved settings: the preset they started from and the three tables."""

    preset: str
    identify: IdentifyConfig
    control: ControllerSettings
    study: StudySettings


_CLASSES = {"identify": IdentifyConfig, "control": ControllerSettings, "study": StudySettings}


def preset_settings(name: str = DEFAULT_PRESET) -> Settings:
    """A preset on its own (``"paper"`` or ``"best"``)."""
    return resolve_settings({}, preset=name)


def resolve_settings(tables: Mapping[str, Any], *, preset: str | None = None,
                     overrides: Sequence[str] = (), source: str | None = None) -> Settings:
    """The settings a file's tables give over their preset, ``overrides``
    (``"identify.hidden=24,24"``, as ``--set`` gives them) on top; ``preset`` (a flag)
    over the file's ``preset``. Every problem is reported at once."""
    problems = Problems()
    name = preset if preset is not None else tables.get("preset", DEFAULT_PRESET)
    with problems.check():
        if name not in PRESETS:
            raise DescriptionError("preset" if preset is None else "--preset",
                                   f"must be one of {', '.join(PRESETS)}, got {name!r}"
                                   f"{did_you_mean(str(name), PRESETS)}")
    values = {s: dict(PRESETS.get(str(name), {}).get(s, {})) for s in SECTIONS}
    for section in SECTIONS:
        table = tables.get(section, {})
        with problems.check():
            check_keys(table, list(SCHEMA[section]), section)
        if not isinstance(table, Mapping):
            continue
        for key, value in table.items():
            if key in SCHEMA[section]:
                with problems.check():
                    values[section][key] = checked(f"{section}.{key}", SCHEMA[section][key],
                                                   value)
    flags = Problems()  # the --set values: from the command line, not from the file
    for text in overrides:
        with flags.check():
            section, key, value = _override(text)
            values[section][key] = value
    if problems or flags:
        raise combined(problems.attributed(source) + flags.found)
    built: dict[str, Any] = {}
    for section in SECTIONS:  # the checks across keys (IdentifyConfig's __post_init__)
        with problems.check():
            built[section] = _build(section, values[section])
    problems.raise_any(source)
    return Settings(str(name), built["identify"], built["control"], built["study"])


def _override(text: str) -> tuple[str, str, Any]:
    """``SECTION.KEY=VALUE`` parsed and checked; errors name ``--set``."""
    path, sep, value = text.partition("=")
    section, dot, key = path.strip().partition(".")
    known = [f"{s}.{k}" for s in SECTIONS for k in SCHEMA[s]]
    if not sep or not dot or section not in SCHEMA or key not in SCHEMA[section]:
        raise DescriptionError("--set", f"{text!r}: give SECTION.KEY=VALUE with a key of "
                               "docs/how-to/settings-file.md, e.g. identify.hidden=24,24"
                               f"{did_you_mean(path.strip(), known)}")
    return section, key, parse_text(f"--set {section}.{key}", SCHEMA[section][key],
                                    value.strip())


def _build(section: str, values: dict[str, Any]) -> Any:
    try:
        return _CLASSES[section](**values)
    except DescriptionError as err:  # IdentifyConfig names the field alone: say the table
        raise err.renamed(lambda name: f"{section}.{name}") from None


def with_overrides(settings: Settings, **sections: Mapping[str, Any]) -> Settings:
    """``settings`` with fields replaced per section (``identify={"seed": 3}``), each checked
    as a file's value."""
    changed: dict[str, Any] = {}
    for section, values in sections.items():
        checked_values = {k: checked(f"{section}.{k}", SCHEMA[section][k], v)
                          for k, v in values.items()}
        changed[section] = replace(getattr(settings, section), **checked_values)
    return replace(settings, **changed)


def is_settings_document(data: Mapping[str, Any]) -> bool:
    """A settings file (its keys among FILE_KEYS), not a scene with settings tables."""
    if "robot" in data or not data:
        return False
    if all(k in FILE_KEYS for k in data):
        return True
    # A misspelt key (``presett``, ``[identfy]``) beside ``scene = ...``, or close to a
    # settings key: read as a settings file, whose key check names it and the nearest key.
    from jointplay.sweep.spec import TOP_KEYS as SWEEP_KEYS

    unknown = [k for k in data if k not in FILE_KEYS]
    return ("scene" in data and not all(k in SWEEP_KEYS for k in unknown)) \
        or all(did_you_mean(k, FILE_KEYS) for k in unknown)


def settings_tables(data: Mapping[str, Any]) -> dict[str, Any]:
    """The settings part of a scene or settings document."""
    return {k: data[k] for k in ("preset", *SECTIONS) if k in data}


def read_settings_file(path: str | Path, *, preset: str | None = None,
                       overrides: Sequence[str] = ()) -> tuple[Settings, Path | None]:
    """A settings file's settings and the scene it names (relative to the file; None: the
    paper scene)."""
    path = Path(path)
    data, _ = read_toml(path, "settings")
    source = str(path)
    check_keys(data, list(FILE_KEYS), "", source)
    scene = data.get("scene")
    if scene is not None and not isinstance(scene, str):
        raise DescriptionError("scene", f"must be the path of a scene file, got {scene!r}",
                               source)
    if scene and (path.parent / scene).resolve() == path.resolve():
        raise DescriptionError("scene", f"names this settings file itself ({scene!r}); give "
                               "the scene file it runs, or leave scene out for the paper scene",
                               source)
    settings = resolve_settings(settings_tables(data), preset=preset, overrides=overrides,
                                source=source)
    return settings, (path.parent / scene if scene else None)


def settings_toml(settings: Settings, scene: str | Path | None,
                  rerun: str = "jointplay control-study settings.toml --out DIR") -> str:
    """The resolved settings as a settings file: every key, so that it reruns the same
    whatever the presets become (``engage`` left out when the run decides it)."""
    lines = ["# The resolved settings of this run (docs/how-to/settings-file.md); rerun with",
             f"#   {rerun}",
             f"preset = {toml_value(TEXT, settings.preset)}"]
    if scene is not None:
        lines.append(f"scene = {toml_value(TEXT, str(scene))}")
    for section in SECTIONS:
        lines += ["", f"[{section}]"]
        table = getattr(settings, section)
        for field in fields(table):
            value = getattr(table, field.name)
            if value is not None:
                lines.append(f"{field.name} = {toml_value(SCHEMA[section][field.name], value)}")
    return "\n".join(lines) + "\n"


__all__ = ["DEFAULT_PRESET", "FILE_KEYS", "PRESETS", "SETTINGS_FILE", "Settings",
           "StudySettings", "is_settings_document", "preset_settings", "read_settings_file",
           "resolve_settings", "settings_tables", "settings_toml", "with_overrides"]
