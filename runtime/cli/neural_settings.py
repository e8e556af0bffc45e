"""The settings the neural commands read: a scene file's ``[identify]``, ``[control]`` and
``[study]`` tables or a settings file naming its scene, over a preset, ``--set`` on top, and
the flags given on top of that, each checked as the key it sets (named by the flag when
refused). The flags themselves: :mod:`jointplay.cli.neural_args`."""

from __future__ import annotations

import argparse
from dataclasses import replace
from pathlib import Path
from typing import TYPE_CHECKING, Any

from jointplay.cli.neural_args import FlagKeys, load_control_scene
from jointplay.common.errors import DescriptionError, combined
from jointplay.neural.control.imc import ControllerSettings, resolve_settings
from jointplay.neural.study.settings_schema import SCHEMA

if TYPE_CHECKING:
    from jointplay.neural.model.narx import Narx
    from jointplay.neural.study.settings import Settings
    from jointplay.scene.definition import Scene


# ---- the settings file ----------------------------------------------------------------------

SETTINGS_HELP = ("every key of the [identify], [control] and [study] tables, its meaning and "
                 "its default per preset: docs/how-to/settings-file.md")


def add_settings_file_arguments(parser: argparse.ArgumentParser) -> None:
    """``--preset`` and ``--set``: the settings' preset and any key of them."""
    parser.add_argument("--preset", metavar="NAME",
                        help="the settings' starting point: best (the best setting measured; "
                             "the default) or paper (the paper's NARX 13/14)")
    parser.add_argument("--set", dest="overrides", action="append", default=[],
                        metavar="SECTION.KEY=VALUE",
                        help="override one key of the settings, e.g. identify.hidden=24,24 "
                             "(repeatable; " + SETTINGS_HELP + ")")


def settings_flags(parser: argparse.ArgumentParser, flags: FlagKeys,
                   shown: tuple[str, ...] | None = None) -> None:
    """The flags in ``flags`` override the settings: not given, they are None; their help
    names the key. With ``shown``, --help lists only those of them (the others stay accepted,
    as the overrides the settings file documents)."""
    names = {}
    for action in parser._actions:
        if action.dest not in flags:
            continue
        action.default = None
        names[action.dest] = action.option_strings[-1]
        if shown is not None and action.dest not in shown:
            action.help = argparse.SUPPRESS
        elif action.help:
            keys = flags[action.dest]
            key = ", ".join(keys) if isinstance(keys, tuple) else keys.lstrip("!")
            action.help += f" (settings: {key})"
    parser.set_defaults(flag_names=names)


def scene_and_settings(args: argparse.Namespace, flags: FlagKeys
                       ) -> tuple[Scene, Settings, Path | None, dict[str, str]]:
    """The scene, the settings (the file's tables over its preset, ``--set`` on top, the
    flags given on top of that), the scene file to record, and which flag gave which key.
    ``args.scene`` is a scene file (its settings tables, if any, read too), a settings file
    naming its scene, or None (the paper scene)."""
    from jointplay.common.validation import read_toml
    from jointplay.neural.study.settings import (
        DEFAULT_PRESET,
        PRESETS,
        is_settings_document,
        preset_settings,
        read_settings_file,
        resolve_settings,
        settings_tables,
    )

    path = Path(args.scene) if args.scene else None
    scene_file: Path | None = path
    data, _ = read_toml(path, "scene or settings") if path is not None else ({}, "")
    if path is not None and not data:  # neither kind: say both, not a scene's missing [robot]
        raise DescriptionError("(file)", "is empty: give a scene (a [robot] table, as in "
                               "scenes/paper_4dof.toml) or a settings file (preset = ..., "
                               "scene = ...: docs/how-to/settings-file.md)", str(path))
    found: DescriptionError | None = None
    try:
        if path is not None and is_settings_document(data):
            settings, scene_file = read_settings_file(path, preset=args.preset,
                                                      overrides=args.overrides)
        else:
            settings = resolve_settings(settings_tables(data), preset=args.preset,
                                        overrides=args.overrides,
                                        source=str(path) if path else None)
    except DescriptionError as err:  # the flags are checked too: every problem at once
        found = err
        settings = preset_settings(args.preset if args.preset in PRESETS else DEFAULT_PRESET)
    try:
        settings, given = apply_flags(args, settings, flags)
    except DescriptionError as err:
        raise combined([found, err] if found else [err]) from None
    if found is not None:
        raise found
    scene = load_control_scene(str(scene_file) if scene_file else None, args.quiet)
    return scene, settings, scene_file.resolve() if scene_file else None, given


def apply_flags(args: argparse.Namespace, settings: Settings, flags: FlagKeys
                ) -> tuple[Settings, dict[str, str]]:
    """``settings`` with every flag given on top, each checked as the settings file's key
    and named by its flag when refused (all problems at once); and which flag gave which
    key."""
    from jointplay.common.validation import Problems

    problems = Problems()
    values: dict[str, dict[str, Any]] = {}
    given: dict[str, str] = {}
    for dest, keys in flags.items():
        raw = getattr(args, dest, None)
        if raw is None:
            continue
        flag = getattr(args, "flag_names", {}).get(dest, dest)
        with problems.check():
            for key, value in _flag_values(flag, keys, raw):
                section, field = key.split(".")
                values.setdefault(section, {})[field] = value
                given[key] = flag
    problems.raise_any()
    changed = {}
    for section, table in values.items():
        def name(field: str, section: str = section) -> str:
            return given.get(f"{section}.{field}", f"{section}.{field}")

        try:  # the checks across keys (IdentifyConfig's), named by the flag when one gave it
            changed[section] = replace(getattr(settings, section), **table)
        except DescriptionError as err:
            raise err.renamed(name) from None
    return replace(settings, **changed), given


def _flag_values(flag: str, keys: str | tuple[str, ...], raw: Any) -> list[tuple[str, Any]]:
    if isinstance(keys, tuple):
        parts = [p for p in str(raw).split(",") if p.strip()]
        if len(parts) != len(keys):
            raise DescriptionError(flag, f"expects {len(keys)} comma-separated values "
                                   f"({', '.join(keys)}), got {raw!r}")
        return [(k, _flag_value(flag, _key(k), p)) for k, p in zip(keys, parts, strict=True)]
    if keys.startswith("!"):
        return [(keys[1:], not raw)]
    return [(keys, _flag_value(flag, _key(keys), raw))]


def _key(key: str) -> Any:
    section, _, name = key.partition(".")
    return SCHEMA[section][name]


def _flag_value(flag: str, key: Any, raw: Any) -> Any:
    """A flag's value checked as the key's, the error naming the flag."""
    from jointplay.neural.study.settings_schema import checked, parse_text

    try:
        return parse_text(flag, key, raw) if isinstance(raw, str) else checked(flag, key, raw)
    except DescriptionError as err:
        raise err.renamed(lambda _: flag) from None


def controller_settings(settings: Settings, narx: Narx | None) -> ControllerSettings:
    """The controller's settings, resolved against ``narx`` when given (defaults filled from
    it, every value checked), else as given (each model resolves them for itself)."""
    return resolve_settings(narx, settings.control) if narx is not None else settings.control
