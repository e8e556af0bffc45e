"""``jointplay cache list|clear|prune``: what the model cache holds, its size and age, and
removing it (see :mod:`jointplay.store.cache`)."""

from __future__ import annotations

import argparse
import os
from pathlib import Path
from typing import Any

_WHERE = ("the cache is $JOINTPLAY_CACHE, else $XDG_CACHE_HOME/jointplay, else "
          "~/.cache/jointplay")


def register(subparsers: Any) -> argparse.ArgumentParser:
    p = subparsers.add_parser(
        "cache", help="list the cached models with their size and age, clear or prune them",
        description="The per-user cache of derived models and compiled libraries; " + _WHERE
                    + ". Entries in use by a running build are kept.")
    actions = p.add_subparsers(dest="action", required=True)
    actions.add_parser("list", help="every entry: kind, model, key, size, time since last use")
    actions.add_parser("clear", help="remove every entry")
    prune = actions.add_parser(
        "prune", help="remove entries not used for a while, and/or the least recently used "
                      "until the cache fits a size")
    prune.add_argument("--older-than", metavar="AGE",
                       help="remove entries not used for AGE: 30d, 12h, 90m, 2w (a bare "
                            "number is days)")
    prune.add_argument("--max-size", metavar="SIZE",
                       help="then remove the least recently used until the cache holds at "
                            "most SIZE: 500M, 2G")
    p.set_defaults(func=cmd_cache)
    return p


def cmd_cache(args: argparse.Namespace) -> int:
    from jointplay.common.errors import DescriptionError
    from jointplay.common.names import file_above
    from jointplay.store import cache
    from jointplay.store.build import cache_root

    root = cache_root()
    env = os.environ.get("JOINTPLAY_CACHE")
    source = "JOINTPLAY_CACHE" if env else "default"
    if env == "":  # set but empty counts as unset: say which cache that leaves
        source = "default: JOINTPLAY_CACHE is empty, which counts as unset"
    where = "JOINTPLAY_CACHE" if env else "cache"
    if root.exists() and not root.is_dir():
        raise DescriptionError(where, f"{root} is not a folder; point JOINTPLAY_CACHE at a "
                               "folder (or unset it for the default)")
    blocker = file_above(root)
    if blocker is not None:
        raise DescriptionError(where, f"{root} lies under {blocker}, which is a file, not a "
                               "folder; point JOINTPLAY_CACHE at a folder")
    if args.action == "list":
        listed = cache.entries(root)
        print(f"cache {root} ({source})")
        if listed:
            print("\n".join(cache.table(listed)))
        total = sum(e.size for e in listed)
        _report_foreign(cache.foreign(root))
        print(f"{len(listed)} entries, {cache.format_size(total)}")
        return 0
    if args.action == "clear":
        removed, busy = cache.clear(root)
    else:
        if args.older_than is None and args.max_size is None:
            raise DescriptionError("--older-than", "give --older-than, --max-size or both")
        older = None if args.older_than is None else cache.parse_age(args.older_than)
        size = None if args.max_size is None else cache.parse_size(args.max_size)
        removed, busy = cache.prune(root, older_than=older, max_size=size)
    for entry in removed:
        kind = "model" if entry.kind == "models" else "build"
        print(f"removed {kind} {entry.name} {entry.key[:12]} ({cache.format_size(entry.size)}, "
              f"last used {cache.format_age(entry.age())} ago)")
    for entry in busy:
        print(f"kept {entry.path}: in use by a running build")
    _report_foreign(cache.foreign(root))
    left = cache.entries(root)
    print(f"removed {len(removed)} entries, {cache.format_size(sum(e.size for e in removed))}; "
          f"{len(left)} left, {cache.format_size(sum(e.size for e in left))} ({root}, "
          f"{source})")
    return 0


def _report_foreign(paths: list[Path]) -> None:
    from jointplay.store.build import OWNER_NAME

    for path in paths:
        print(f"not jointplay's, left: {path} (no {OWNER_NAME} file, or a link)")
