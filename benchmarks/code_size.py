"""The size of a part of the code at git revisions: lines, and lines of code.

    python benchmarks/code_size.py [--folder runtime/calibration] [REV ...]

For each revision (default: the working tree), the Python files under ``--folder``: their
lines, and their lines of code (neither blank, nor only a comment, nor part of a docstring or
another string standing as a statement), per file and in all. A wrapped statement counts
each of its lines.
"""

from __future__ import annotations

import argparse
import ast
import subprocess
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent


def code_lines(source: str) -> int:
    """Lines of ``source`` that hold code (see the module docstring)."""
    strings: set[int] = set()
    for node in ast.walk(ast.parse(source)):
        if isinstance(node, ast.Expr) and isinstance(node.value, ast.Constant) \
                and isinstance(node.value.value, str):
            strings.update(range(node.lineno, (node.end_lineno or node.lineno) + 1))
    return sum(1 for number, line in enumerate(source.splitlines(), 1)
               if line.strip() and not line.strip().startswith("#") and number not in strings)


def sources(folder: str, revision: str | None) -> dict[str, str]:
    """The Python files under ``folder`` (relative to the repository) at ``revision`` (None:
    the working tree), by path."""
    if revision is None:
        return {str(p.relative_to(ROOT)): p.read_text(encoding="utf-8")
                for p in sorted((ROOT / folder).rglob("*.py"))}
    names = subprocess.run(["git", "ls-tree", "-r", "--name-only", revision, folder], cwd=ROOT,
                           capture_output=True, text=True, check=True).stdout.split()
    return {name: subprocess.run(["git", "show", f"{revision}:{name}"], cwd=ROOT,
                                 capture_output=True, text=True, check=True).stdout
            for name in names if name.endswith(".py")}


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("revisions", nargs="*", help="git revisions (default: the working tree)")
    parser.add_argument("--folder", default="runtime/calibration")
    args = parser.parse_args()
    for revision in args.revisions or [None]:
        files = sources(args.folder, revision)
        print(f"{revision or 'working tree'}: {args.folder}")
        total = code = 0
        for name, text in files.items():
            lines, coded = len(text.splitlines()), code_lines(text)
            total, code = total + lines, code + coded
            print(f"  {name:48s} {lines:6d} lines {coded:6d} of code")
        print(f"  {'all':48s} {total:6d} lines {code:6d} of code")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
