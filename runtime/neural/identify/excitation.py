"""Excitation torques for identification: random-phase multisines, a swept sine,
amplitude-modulated pseudo-random steps (as samples, and as a piecewise-linear table), each
drawn from a seeded generator and able to describe itself for the datasets file.

Multisine and Chirp are scene TimeFunctions (numpy and CasADi), so they drive the compiled
model like any torque expression."""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import casadi as ca
import numpy as np

from jointplay.scene.expressions import TimeFunction
from jointplay.scene.tables import TableColumn


@dataclass(frozen=True, eq=False)
class Multisine:
    """sum_i a_i sin(2 pi f_i t + phi_i): a TimeFunction for scenes (numpy and CasADi)."""

    amplitude: np.ndarray
    frequency: np.ndarray
    phase: np.ndarray

    def numpy(self, t: float | np.ndarray) -> np.ndarray:
        times = np.asarray(t, dtype=float)
        arg = 2 * np.pi * self.frequency[:, None] * times.reshape(-1)[None, :] \
            + self.phase[:, None]
        return np.asarray(np.sum(self.amplitude[:, None] * np.sin(arg), axis=0),
                          dtype=float).reshape(times.shape)

    def casadi(self, t: Any) -> Any:
        out = 0.0 * t
        for a, f, p in zip(self.amplitude, self.frequency, self.phase, strict=True):
            out = out + float(a) * ca.sin(2 * math.pi * float(f) * t + float(p))
        return out

    def describe(self) -> dict[str, Any]:
        return {"kind": "multisine", "amplitude": self.amplitude.tolist(),
                "frequency": self.frequency.tolist(), "phase": self.phase.tolist()}


@dataclass(frozen=True, eq=False)
class Chirp:
    """A linear sine sweep from f0 to f1 Hz over ``duration`` s, of amplitude ``amplitude``."""

    amplitude: float
    f0: float
    f1: float
    duration: float
    phase: float = 0.0

    def _arg(self, t: Any) -> Any:
        rate = (self.f1 - self.f0) / self.duration
        return 2 * math.pi * (self.f0 * t + 0.5 * rate * t * t) + self.phase

    def numpy(self, t: float | np.ndarray) -> np.ndarray:
        times = np.asarray(t, dtype=float)
        return np.asarray(self.amplitude * np.sin(self._arg(times)), dtype=float)

    def casadi(self, t: Any) -> Any:
        return self.amplitude * ca.sin(self._arg(t))

    def describe(self) -> dict[str, Any]:
        return {"kind": "chirp", "amplitude": self.amplitude, "f0": self.f0, "f1": self.f1,
                "duration": self.duration, "phase": self.phase}


def random_multisine(rng: np.random.Generator, peak: float, f_low: float, f_high: float,
                     period: float, max_lines: int = 12) -> Multisine:
    """Random-phase multisine on harmonics of 1/period in [f_low, f_high], scaled to ``peak``."""
    base = 1.0 / period
    lines = np.arange(max(1, math.ceil(f_low / base)), math.floor(f_high / base) + 1) * base
    if lines.size > max_lines:
        lines = np.sort(rng.choice(lines, max_lines, replace=False))
    if lines.size == 0:
        lines = np.array([f_low])
    phase = rng.uniform(0.0, 2 * np.pi, lines.size)
    unit = Multisine(np.ones(lines.size), lines, phase)
    grid = np.linspace(0.0, period, 4001)
    scale = peak / max(float(np.max(np.abs(unit.numpy(grid)))), 1e-12)
    return Multisine(np.full(lines.size, scale), lines, phase)


def aprbs(rng: np.random.Generator, n: int, peak: float, hold_min: int,
          hold_max: int) -> np.ndarray:
    """Amplitude-modulated pseudo-random steps: uniform levels in [-peak, peak], held for a
    log-uniform number of samples in [hold_min, hold_max]."""
    out = np.zeros(n)
    k = 0
    while k < n:
        hold = round(math.exp(rng.uniform(math.log(hold_min), math.log(hold_max))))
        out[k:k + max(hold, 1)] = rng.uniform(-peak, peak)
        k += max(hold, 1)
    return out


def step_torque(rng: np.random.Generator, peak: float, duration: float, hold_min: float,
                hold_max: float, ramp: float, name: str) -> TableColumn:
    """Amplitude-modulated steps as a piecewise-linear table (``ramp`` s between levels)."""
    times, values = [0.0], [0.0]
    t = 0.0
    while t < duration:
        level = rng.uniform(-peak, peak)
        times += [t + ramp]
        values += [level]
        t += rng.uniform(hold_min, hold_max)
        times += [t]
        values += [level]
    return TableColumn(name, np.array(times), np.array(values))



@dataclass(frozen=True, eq=False)
class Retimed:
    """``scale * base(rate * t + shift)``: another torque's shape at another amplitude and
    rate, shifted in time (a TimeFunction: numpy and CasADi)."""

    base: TimeFunction
    scale: float
    rate: float
    shift: float

    def numpy(self, t: float | np.ndarray) -> np.ndarray:
        times = np.asarray(t, dtype=float)
        return np.asarray(self.scale * self.base.numpy(self.rate * times + self.shift),
                          dtype=float)

    def casadi(self, t: Any) -> Any:
        return self.scale * self.base.casadi(self.rate * t + self.shift)

    def describe(self) -> dict[str, Any]:
        return {"kind": "retimed", "base": describe_torque(self.base), "scale": self.scale,
                "rate": self.rate, "shift": self.shift}


def describe_torque(f: TimeFunction) -> Any:
    """What a base torque was, for the datasets file (``jointplay control --test-cases`` drives
    the loop with it again)."""
    if isinstance(f, (Multisine, Chirp, Retimed)):
        return f.describe()
    if isinstance(f, TableColumn):
        return {"kind": "steps", "times": f.times.tolist(), "values": f.values.tolist()}
    return {"kind": "expression", "text": getattr(f, "text", repr(f))}


__all__ = ["Chirp", "Multisine", "Retimed", "aprbs", "describe_torque", "random_multisine",
           "step_torque"]
