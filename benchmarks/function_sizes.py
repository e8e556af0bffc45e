"""Where a model's C goes: bytes per emitted CasADi function, the constant tables, and
optionally gcc's CPU time on each top-level function compiled alone.

Emits (no gcc unless ``--gcc``) the model of a chain of k links with the given joint kind in
every joint, in the given formulation, and prints one Markdown table per k: every function's
C (from its ``/* name:(...) */`` comment to the next), largest first, and the total of the
``static const`` tables (sparsity patterns and constant matrices). With ``--gcc`` each
top-level function is also code-generated alone and compiled with the default flags; its gcc
CPU time includes the sub-functions it calls (so the times overlap and do not add up).

    python benchmarks/function_sizes.py --links 12,32 --gcc
"""

from __future__ import annotations

import argparse
import re
import resource
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from build_scaling import parse_links
from build_scaling_case import _robot, _section_sizes

CONSTANT = re.compile(r"^static const casadi_(?:int|real) casadi_\w+\[\d+\] = \n?  \{", re.M)


def constant_bytes(source: str) -> int:
    """Bytes of C in the ``static const`` tables CasADi writes before the functions."""
    return sum(source.index("};", m.end()) - m.start() for m in CONSTANT.finditer(source))


def gcc_cpu_seconds(source: str, folder: Path) -> float:
    """gcc's CPU time (user + system) compiling ``source`` with the default flags."""
    from jointplay.store.build import DEFAULT_CFLAGS

    path = folder / "function.c"
    path.write_text(source, encoding="utf-8")
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    subprocess.run(["gcc", *DEFAULT_CFLAGS, str(path), "-o", str(folder / "function.so"),
                    "-lm"], check=True)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return (after.ru_utime + after.ru_stime) - (before.ru_utime + before.ru_stime)


def report(k: int, structure: str, formulation: str, gcc: bool, top: int) -> str:
    import casadi as ca

    from jointplay.derive.codegen import build_functions
    from jointplay.derive.symbolic import derive

    t0 = time.perf_counter()
    functions, _ = build_functions(derive(_robot(structure, k).structure(), formulation),
                                   formulation)
    whole = ca.CodeGenerator("model.c", {"with_header": False})
    for fn in functions:
        whole.add(fn)
    source = whole.dump()
    emit_s = time.perf_counter() - t0
    sizes = sorted(_section_sizes(source).items(), key=lambda item: -item[1])
    lines = [f"### {structure}, k = {k}, {formulation}: {len(source) / 1e3:.0f} kB of C "
             f"(derive + emit {emit_s:.1f} s), constant tables {constant_bytes(source) / 1e3:.0f}"
             " kB", "", "| function | C kB |", "|---|---:|"]
    lines += [f"| {name} | {size / 1e3:.0f} |" for name, size in sizes[:top]]
    if gcc:
        lines += ["", "| top-level function, compiled alone | C kB | gcc CPU s |",
                  "|---|---:|---:|"]
        with tempfile.TemporaryDirectory(prefix="jointplay-sizes-") as tmp:
            for fn in functions:
                alone = ca.CodeGenerator("function.c", {"with_header": False})
                alone.add(fn)
                text = alone.dump()
                cpu = gcc_cpu_seconds(text, Path(tmp))
                lines.append(f"| {fn.name()} | {len(text) / 1e3:.0f} | {cpu:.2f} |")
    return "\n".join(lines) + "\n"


def main() -> int:
    parser = argparse.ArgumentParser(description=(__doc__ or "").split("\n\n")[0])
    parser.add_argument("--links", type=parse_links, default=parse_links("12"))
    parser.add_argument("--structure", default="clearance", choices=("clearance", "ideal"))
    parser.add_argument("--formulation", default="recursive", choices=("recursive", "closed"))
    parser.add_argument("--gcc", action="store_true",
                        help="also compile each top-level function alone and time gcc")
    parser.add_argument("--top", type=int, default=12, help="functions listed per table")
    args = parser.parse_args()
    for k in args.links:
        print(report(k, args.structure, args.formulation, args.gcc, args.top), flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
