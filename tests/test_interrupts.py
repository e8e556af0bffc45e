"""Ctrl-C everywhere: a real SIGINT sent to the ``jointplay`` command while it imports, while
each integrator runs (one long output interval included: the compiled loops must look), while
it writes, and several times in a row. Each ends with exit 130, one line, no traceback and no
file that looks complete."""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest
from test_probes import check_contract, interrupt_when

# A long run whose output interval (30 s) holds millions of fixed steps or one long adaptive
# integration: between two outputs the command line never runs.
LONG_INTERVAL = ["--t-end", "3000", "--output-step", "30"]


def only_line(err: str) -> None:
    """Exactly one line on stderr (a progress bar's redraws aside): the interrupt's."""
    lines = [line for line in err.replace("\r", "\n").splitlines()
             if line.strip() and "it/s]" not in line and "s/it]" not in line
             and "%|" not in line]
    assert lines == ["jointplay: interrupted"], err


def press_ctrl_c(command: list[str], env: dict[str, str], marker: bytes, *, wait: float,
                 presses: int, timeout: float, ignored: bool = False) -> tuple[int, str]:
    """Run ``command`` (``ignored``: with SIGINT ignored, as a shell starts a background
    job); once its stdout shows ``marker``, wait ``wait`` s, then send SIGINT ``presses``
    times 50 ms apart (fewer if it has ended). Its exit status and stderr."""
    def ignore() -> None:
        signal.signal(signal.SIGINT, signal.SIG_IGN)

    proc = subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE, env=env,
                            preexec_fn=ignore if ignored else None)
    assert proc.stdout is not None
    try:
        seen = b""
        while marker not in seen:
            chunk = os.read(proc.stdout.fileno(), 4096)
            assert chunk, f"the command ended before printing {marker!r}"
            seen += chunk
        time.sleep(wait)
        for _ in range(presses):
            if proc.poll() is not None:
                break
            proc.send_signal(signal.SIGINT)
            time.sleep(0.05)
        try:
            _, err = proc.communicate(timeout=timeout)
        except subprocess.TimeoutExpired:
            pytest.fail(f"no end within {timeout} s of Ctrl-C; {_signal_state(proc.pid)}")
    finally:
        if proc.poll() is None:
            proc.kill()
            proc.wait()
    return proc.returncode, err.decode(errors="replace")


def _signal_state(pid: int) -> str:
    """What each of the process's threads blocks, ignores, catches and has pending, and where
    it waits: what a press that was not acted on needs to be explained."""
    lines = []
    for task in sorted(Path(f"/proc/{pid}/task").glob("*")):
        with open(task / "status", encoding="utf-8") as status:
            fields = [line.strip() for line in status
                      if line.startswith(("Name", "State", "Sig", "ShdPnd"))]
        wchan = (task / "wchan").read_text(encoding="utf-8") if (task / "wchan").exists() else ""
        lines.append(f"thread {task.name}: {'; '.join(fields)}; wchan {wchan}")
    return "\n".join(lines)


@pytest.mark.parametrize("integrator", ["bdf", "cvodes", "idas", "rk4", "radau"])
def test_interrupt_inside_a_long_output_interval(tmp_path: Path, integrator: str) -> None:
    out = tmp_path / "out"
    out.mkdir()
    step = ["--step", "1e-5"] if integrator in ("rk4", "radau") else []
    code, err = interrupt_when(["simulate", "--integrator", integrator, *LONG_INTERVAL, *step,
                                "--out", str(out / "r.h5"), "--csv", str(out / "r.csv")],
                               "ready in", 0.5, timeout=60)
    check_contract(code, err)
    assert code == 130, err
    only_line(err)
    assert list(out.iterdir()) == []


def test_interrupt_pressed_again_and_again(tmp_path: Path) -> None:
    """Five presses 50 ms apart while it integrates: still one line and exit 130."""
    command = [sys.executable, "-m", "jointplay.cli", "simulate", "--integrator", "rk4",
               *LONG_INTERVAL, "--step", "1e-5", "--out", str(tmp_path / "r.h5")]
    code, text = press_ctrl_c(command, {**os.environ, "PYTHONUNBUFFERED": "1"}, b"ready in",
                              wait=0.3, presses=5, timeout=60)
    check_contract(code, text)
    assert code == 130, text
    only_line(text)
    assert list(tmp_path.iterdir()) == []


# Ctrl-C as the results file starts to be written, and again while its temporary file is
# being removed (the cleanup the first one started).
_TWICE_WHILE_WRITING = """
import contextlib, os, signal, sys
from pathlib import Path
import jointplay.common.files as files
real_atomic, real_unlink = files.atomic_path, Path.unlink
@contextlib.contextmanager
def atomic_path(path, *args, **kwargs):
    with real_atomic(path, *args, **kwargs) as tmp:
        tmp.write_bytes(b"half a file")
        os.kill(os.getpid(), signal.SIGINT)
        yield tmp
def unlink(self, *args, **kwargs):
    if self.name.endswith(".part"):
        os.kill(os.getpid(), signal.SIGINT)
    return real_unlink(self, *args, **kwargs)
files.atomic_path = atomic_path
Path.unlink = unlink
import jointplay.results.write as write
if hasattr(write, "atomic_path"):
    write.atomic_path = atomic_path
print("ready", flush=True)
from jointplay.cli import main
sys.exit(main(["simulate", "--t-end", "0.05", "--quiet", "--out", {out!r}]))
"""


def test_interrupt_twice_while_writing(tmp_path: Path) -> None:
    out = tmp_path / "out"
    out.mkdir()
    code, err = interrupt_when([], "ready", 0.0, sig=0, timeout=120,
                               code=_TWICE_WHILE_WRITING.format(out=str(out / "r.h5")))
    check_contract(code, err)
    assert code == 130, err
    only_line(err)
    assert list(out.iterdir()) == []


def test_library_threads_leave_ctrl_c_to_the_main_thread() -> None:
    """In the ``jointplay`` program the threads NumPy's BLAS starts as it imports have SIGINT
    blocked: one delivered to them would not wake the main thread from a sleep or a wait,
    and Ctrl-C would wait with it (seen once while an import slept). The main thread keeps
    it unblocked."""
    script = ("import os, sys\n"
              "sys.argv[0] = 'jointplay'\n"
              "import jointplay\n"
              "for tid in sorted(os.listdir('/proc/self/task')):\n"
              "    status = open(f'/proc/self/task/{tid}/status').read()\n"
              "    mask = [line for line in status.splitlines() if line.startswith('SigBlk')]\n"
              "    print(tid == str(os.getpid()), int(mask[0].split()[1], 16) >> 1 & 1)\n")
    env = {**os.environ, "OPENBLAS_NUM_THREADS": "2"}
    out = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True,
                         env=env, check=True).stdout.split("\n")
    threads = [line.split() for line in out if line]
    assert ["True", "0"] in threads and len(threads) >= 2, threads
    assert all(blocked == "1" for main, blocked in threads if main == "False"), threads


def test_interrupt_while_importing(tmp_path: Path) -> None:
    """The command line's modules import slowly here (a hook sleeps in the import of
    jointplay.cli, after jointplay itself): Ctrl-C then is one line and exit 130."""
    hook = tmp_path / "hook"
    hook.mkdir()
    (hook / "sitecustomize.py").write_text(
        "import importlib.abc, sys, time\n"
        "class Slow(importlib.abc.MetaPathFinder):\n"
        "    def find_spec(self, name, path=None, target=None):\n"
        "        if name == 'jointplay.cli.simulate':\n"
        "            print('importing', flush=True)\n"
        "            time.sleep(30)\n"
        "        return None\n"
        "sys.meta_path.insert(0, Slow())\n", encoding="utf-8")
    out = tmp_path / "r.h5"
    command = [sys.executable, "-m", "jointplay.cli", "simulate", "--out", str(out)]
    env = {**os.environ, "PYTHONPATH": os.pathsep.join(
        [str(hook), *filter(None, [os.environ.get("PYTHONPATH")])])}
    code, text = press_ctrl_c(command, env, b"importing", wait=0.0, presses=1, timeout=20)
    check_contract(code, text)
    assert code == 130, text
    only_line(text)
    assert not out.exists()


def test_started_with_ctrl_c_ignored_it_stays_ignored(tmp_path: Path) -> None:
    """A command started with SIGINT ignored (``cmd &`` in a script, ``nohup``) keeps it
    ignored, during its imports and its run alike: three presses, and it runs to its end."""
    out = tmp_path / "r.h5"
    command = [sys.executable, "-m", "jointplay.cli", "simulate", "--integrator", "rk4",
               "--t-end", "0.2", "--step", "1e-6", "--out", str(out)]
    code, text = press_ctrl_c(command, {**os.environ, "PYTHONUNBUFFERED": "1"}, b"ready in",
                              wait=0.3, presses=3, timeout=120, ignored=True)
    assert code == 0, text
    assert "interrupted" not in text
    assert out.exists()


def test_fixed_step_blocks_change_nothing(monkeypatch: pytest.MonkeyPatch) -> None:
    """An output interval taken in blocks (so that Ctrl-C is seen) gives the very same run as
    taken whole: 200 rk4 steps per output, in blocks of 50 and in one."""
    import numpy as np

    import jointplay
    import jointplay.sim.fixed as fixed

    scene = jointplay.default_scene().with_run(integrator="rk4", t_end=0.01,
                                               output_step=0.002, step=1e-5)
    whole = jointplay.simulate(scene)
    monkeypatch.setattr(fixed, "FIXED_BLOCK_STEPS", 50)
    blocks = jointplay.simulate(scene)
    np.testing.assert_array_equal(blocks.q, whole.q)
    np.testing.assert_array_equal(blocks.u, whole.u)
    np.testing.assert_array_equal(blocks.impacts.time, whole.impacts.time)
    assert whole.impacts.time.size > 0  # the blocks met contact onsets


# A Ctrl-C delivered while Python runs the fork hooks (where logging releases its lock): a hook
# registered after logging's sends SIGINT, and the loop gives the handler a place to run
# inside the hook, as a real press landing there does.
_PRESS_WHILE_FORKING = """
import os, signal, sys
from jointplay.common import interrupts
from jointplay.common.pool import parallel_map

def press():
    os.kill(os.getpid(), signal.SIGINT)
    for _ in range(100):
        pass

os.register_at_fork(after_in_parent=press)
with interrupts.installed():
    try:
        {call}
        print("not interrupted")
    except KeyboardInterrupt:
        print("interrupted", interrupts.interrupted())
    signal.signal(signal.SIGINT, signal.SIG_IGN)  # the pool's own forks are over
"""


@pytest.mark.parametrize("call", [
    "pid = interrupts.fork()\n        if pid == 0: os._exit(0)",
    "parallel_map(abs, 4, 2)",
    # the compiler's start (its preexec function makes Python run the fork hooks)
    "import tempfile, pathlib; from jointplay.store.build import _compile\n        "
    "d = pathlib.Path(tempfile.mkdtemp()); (d / 'm.c').write_text('int f(void) {return 1;}')"
    "\n        _compile('gcc', ('-shared', '-fPIC'), d / 'm.c', d / 'm.so')",
], ids=["fork", "pool", "compiler"])
def test_a_press_during_a_fork_is_raised_after_it(call: str) -> None:
    """Python prints an error raised in a fork hook as "Exception ignored" with a traceback,
    and drops it: the press would be lost. Forks go through interrupts.fork() or deferred(),
    and the press is raised once the fork has returned (in the parent only)."""
    proc = subprocess.run([sys.executable, "-c", _PRESS_WHILE_FORKING.format(call=call)],
                          capture_output=True, text=True, timeout=60)
    assert proc.returncode == 0, proc.stderr
    assert "Traceback" not in proc.stderr and "Exception ignored" not in proc.stderr, proc.stderr
    assert proc.stdout.split() == ["interrupted", "True"], proc.stdout
