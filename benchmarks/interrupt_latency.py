"""How long Ctrl-C waits, with each integrator, inside one long output interval.

Each integrator runs the paper scene with 30 s between outputs (`--t-end 3000 --output-step
30`, rk4 and radau at `--step 1e-5`: 3 million fixed steps per output), so the command line
never runs between outputs. Once the run is under way (`ready in` printed, then 1 s), SIGINT is
sent; the time until the process has exited, its exit status and its stderr are reported.
The model is compiled first, in the cache the command uses (`$JOINTPLAY_CACHE`).

    python benchmarks/interrupt_latency.py --out DIR [--repeats 3]

Writes DIR/interrupt_latency.md (the table below, with the machine's load) and prints it.
Wall seconds: the wait is what a person at the terminal sees.
"""

from __future__ import annotations

import argparse
import os
import platform
import signal
import statistics
import subprocess
import sys
import time
from pathlib import Path

INTEGRATORS = ("bdf", "cvodes", "idas", "rk4", "radau")


def one(integrator: str) -> tuple[float, int, str]:
    command = [sys.executable, "-m", "jointplay.cli", "simulate", "--integrator", integrator,
               "--t-end", "3000", "--output-step", "30", "--step", "1e-5"]
    proc = subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                            env={**os.environ, "PYTHONUNBUFFERED": "1"})
    assert proc.stdout is not None
    seen = b""
    while b"ready in" not in seen:
        chunk = os.read(proc.stdout.fileno(), 4096)
        if not chunk:
            raise SystemExit(f"{integrator}: the command ended before it was ready")
        seen += chunk
    time.sleep(1.0)
    start = time.perf_counter()
    proc.send_signal(signal.SIGINT)
    try:
        _, err = proc.communicate(timeout=300)
    except subprocess.TimeoutExpired:
        proc.kill()
        _, err = proc.communicate()
    waited = time.perf_counter() - start
    lines = [line for line in err.decode(errors="replace").replace("\r", "\n").splitlines()
             if line.strip() and "%|" not in line]
    return waited, proc.returncode, " / ".join(lines)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", required=True, help="folder for interrupt_latency.md")
    parser.add_argument("--repeats", type=int, default=3)
    args = parser.parse_args()
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    subprocess.run([sys.executable, "-m", "jointplay.cli", "simulate", "--t-end", "0.01",
                    "--quiet"], check=True)
    lines = [f"{platform.processor() or platform.machine()}, {os.cpu_count()} CPUs, load "
             f"average {os.getloadavg()[0]:.1f} at the start; {args.repeats} runs each", "",
             "| integrator | exit | median s | worst s | stderr |", "|---|---:|---:|---:|---|"]
    for integrator in INTEGRATORS:
        runs = [one(integrator) for _ in range(args.repeats)]
        waits = [w for w, _, _ in runs]
        codes = sorted({c for _, c, _ in runs})
        lines.append(f"| {integrator} | {','.join(map(str, codes))} | "
                     f"{statistics.median(waits):.2f} | {max(waits):.2f} | {runs[-1][2]} |")
    text = "\n".join(lines) + "\n"
    tmp = out / ".interrupt_latency.md.part"
    tmp.write_text(text, encoding="utf-8")
    os.replace(tmp, out / "interrupt_latency.md")
    print(text, end="")


if __name__ == "__main__":
    main()
