"""One network of the loop kernel in C: its value and its tangent directions in one pass over
the weights (constants in the file, hexadecimal floats, so exact), tanh four lanes at a time.

The weights are stored transposed (column by column) and padded to whole vectors of four
outputs: each layer's sums for four outputs, for the value and every tangent direction, stay
in registers over one pass down the layer's inputs (GCC's vector extension), each sum in the
inputs' order as in the definition; the scheduling signals, held over the horizon, carry no
tangent. The step cost half of what the same loops cost with the sums in memory and tanh
through expm1 element by element (benchmarks/control_step.py --kernel-before).
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from jointplay.neural.model.narx import Narx

# Four doubles as one vector (GCC's vector extension: AVX registers where the build has them,
# pairs of SSE registers or scalars where not); LD/ST move them to and from any double array
# (the 8-byte alignment of the load type allows unaligned addresses).
VECTOR = """#include <math.h>
#include <string.h>
typedef double jp_v4 __attribute__((vector_size(32)));
typedef long long jp_v4i __attribute__((vector_size(32)));
typedef double jp_v4u __attribute__((vector_size(32), aligned(8)));
#define LD(p) ((jp_v4) * (const jp_v4u*) (p))
#define ST(p, v) (*(jp_v4u*) (p) = (v))
"""

# tanh on four lanes at once: e = exp(2x) by Cody-Waite reduction (2x = n ln 2 + r, |r| <=
# ln 2 / 2) and exp(r)'s Taylor polynomial to r^13 (truncation below 1e-17 relative), 2^n put
# into the exponent bits; tanh = (e - 1) / (e + 1). |x| >= 20 gives +-1, where tanh is 1 to
# double precision; NaN stays NaN. Within 3e-16 of libm's tanh (absolute; the values lie in
# [-1, 1]; tests/test_control_guard.py); it replaced an expm1 call per element.
TANH = VECTOR + """static inline jp_v4 jp_tanh4(jp_v4 x) {
  const jp_v4 hi = {20.0, 20.0, 20.0, 20.0}, lo = -hi;
  const jp_v4 shifter = {0x1.8p52, 0x1.8p52, 0x1.8p52, 0x1.8p52};
  const jp_v4i bias = {1023, 1023, 1023, 1023};
  jp_v4i above = x > hi, below = x < lo;
  jp_v4 y, n, nm, r, p, e;
  x = (jp_v4) (((jp_v4i) x & ~above) | ((jp_v4i) hi & above));
  x = (jp_v4) (((jp_v4i) x & ~below) | ((jp_v4i) lo & below));
  y = x + x;
  nm = y * 0x1.71547652b82fep0 + shifter;  /* round(y / ln 2) in the low bits */
  n = nm - shifter;
  r = y - n * 0x1.62e42fefa3800p-1;
  r = r - n * 0x1.ef35793c76730p-45;
  p = r * (1.0 / 6227020800.0) + 1.0 / 479001600.0;
  p = p * r + 1.0 / 39916800.0;
  p = p * r + 1.0 / 3628800.0;
  p = p * r + 1.0 / 362880.0;
  p = p * r + 1.0 / 40320.0;
  p = p * r + 1.0 / 5040.0;
  p = p * r + 1.0 / 720.0;
  p = p * r + 1.0 / 120.0;
  p = p * r + 1.0 / 24.0;
  p = p * r + 1.0 / 6.0;
  p = p * r + 0.5;
  p = p * r + 1.0;
  p = p * r + 1.0;
  e = p * (jp_v4) ((((jp_v4i) nm - (jp_v4i) shifter) + bias) << 52);
  return (e - 1.0) / (e + 1.0);
}
"""


def padded(n: int) -> int:
    """``n`` rounded up to whole vectors of four."""
    return (n + 3) // 4 * 4


def _c(x: float) -> str:
    """An exact C literal for a float64."""
    if math.isinf(x):
        return "1e300" if x > 0 else "-1e300"
    return float(x).hex()


def _array(name: str, values: Any) -> str:
    flat = np.asarray(values, dtype=float).ravel()
    if flat.size == 0:
        return f"static const double {name}[1] = {{0}};\n"
    body = ", ".join(_c(v) for v in flat)
    return f"static const double {name}[{flat.size}] = {{{body}}};\n"


def _network(prefix: str, model: Narx, nd: int) -> str:
    """C for one network: ``{prefix}eval(phi, dphi, y, dy, tangent, g)``; ``dphi`` holds
    ``nd`` tangent directions (direction-major), ``dy`` likewise. The scheduling signals
    (the regressor's last entries) are held over the controller's horizon: their tangent
    entries of ``dphi`` are zero and are not read."""
    ny, nphi = model.n_outputs, model.n_regressor
    n_tan = nphi - model.n_scheduling  # regressor entries with a tangent
    widths = [nphi, *[w.shape[0] for w in model.weights]]
    width_max = padded(max(widths))
    last = len(model.weights) - 1
    lines = _input_lines(prefix, nphi, nd, width_max)
    src = ("z", "dz", nphi)
    for i in range(len(model.weights)):
        sources = [(f"{prefix}W{i}", *src, widths[i], n_tan if i == 0 else widths[i])]
        if i == last:
            # The direct linear path on the normalised regressor, on the output layer's sums:
            # with a bilinear part the scheduled input gain ``g`` ({prefix}gain), else
            # {prefix}L.
            if model.bilinear is not None:
                sources.append(("g", "z", "dz", nphi, nphi, n_tan))
            elif model.linear is not None:
                sources.append((f"{prefix}L", "z", "dz", nphi, nphi, n_tan))
        lines += _layer_lines(f"{prefix}B{i}", sources, widths[i + 1], nd, width_max)
        if i < last:
            lines += [
                f"  for (i = 0; i < {padded(widths[i + 1])}; i += 4) ST(h + i, "
                "jp_tanh4(LD(a + i)));",
                "  if (tangent) {",
                f"    for (k = 0; k < {nd}; ++k) for (i = 0; i < {widths[i + 1]}; ++i)",
                f"      dh[k * {width_max} + i] = (1 - h[i] * h[i]) * da[k * {width_max} + i];",
                "  }"]
            src = ("h", "dh", width_max)
    if model.bilinear is None:
        lines.append("  (void) g;")
    lines += [
        f"  for (i = 0; i < {ny}; ++i)",
        f"    y[i] = {prefix}CARRY[i] * phi[i] + {prefix}TM[i] + {prefix}TS[i] * a[i];",
        "  if (tangent) {",
        f"    for (k = 0; k < {nd}; ++k) for (i = 0; i < {ny}; ++i)",
        f"      dy[k * {ny} + i] = {prefix}CARRY[i] * dphi[k * {nphi} + i] + "
        f"{prefix}TS[i] * da[k * {width_max} + i];",
        "  }",
        "}"]
    gain = _gain_function(prefix, model) if model.bilinear is not None else ""
    return _constants(prefix, model) + gain + "\n".join(lines) + "\n"


def gain_size(model: Narx) -> int:
    """Doubles of the scheduled direct path ``g`` that ``{prefix}eval`` takes (0: none)."""
    return model.n_regressor * padded(model.n_outputs) if model.bilinear is not None else 0


def _gain_function(prefix: str, model: Narx) -> str:
    """``{prefix}gain(w, g)``: the direct path with the bilinear part's input gain
    sum_s w_s B_s added on the input lags' columns, at the raw scheduling signals ``w``; once
    per call of the step (the loop holds the signals over the horizon, with no tangent, so
    the bilinear part is a linear term in the input lags there), laid out as ``{prefix}L``
    (regressor j: g[j * P .. j * P + ny - 1], P = ny rounded up to whole vectors)."""
    ny, nw, nz = padded(model.n_outputs), model.n_scheduling, model.n_input_regressors
    first_w, start = model.n_regressor - nw, model.output_lags * model.n_outputs
    base = (f"  for (i = 0; i < {gain_size(model)}; ++i) g[i] = {prefix}L[i];"
            if model.linear is not None else
            f"  for (i = 0; i < {gain_size(model)}; ++i) g[i] = 0;")
    return "\n".join([
        f"static void {prefix}gain(const double* w, double* g) {{",
        "  int i, s;",
        base,
        f"  for (s = 0; s < {nw}; ++s) {{",
        f"    const double ws = (w[s] - {prefix}MU[{first_w} + s]) * {prefix}ISG[{first_w} + s];",
        f"    const double* col = {prefix}BL + s * {nz * ny};",
        f"    for (i = 0; i < {nz * ny}; ++i) g[{start * ny} + i] += ws * col[i];",
        "  }",
        "}"]) + "\n"


def _padded_rows(values: Any) -> np.ndarray:
    """A matrix's rows (one per output) as columns padded with zeros to whole vectors: the
    layout the kernel reads four outputs at a time from."""
    m = np.asarray(values, dtype=float)
    out = np.zeros((m.shape[1], padded(m.shape[0])))
    out[:, : m.shape[0]] = m.T
    return out


def _constants(prefix: str, model: Narx) -> str:
    """The network's normalisation, weights (transposed, padded) and direct linear term."""
    out = [_array(f"{prefix}MU", model.regressor_mean),
           _array(f"{prefix}ISG", 1.0 / model.regressor_scale),
           _array(f"{prefix}TM", model.increment_mean),
           _array(f"{prefix}TS", model.increment_scale),
           _array(f"{prefix}CARRY", model.carry)]
    for i, (w, b) in enumerate(zip(model.weights, model.biases, strict=True)):
        out += [_array(f"{prefix}W{i}", _padded_rows(w)),
                _array(f"{prefix}B{i}", _padded_rows(np.asarray(b)[:, None]))]
    if model.linear is not None:
        out.append(_array(f"{prefix}L", _padded_rows(model.linear)))
    if model.bilinear is not None:
        out.append(_array(f"{prefix}BL", _padded_rows(model.bilinear)))
    return "".join(out)


def _input_lines(prefix: str, nphi: int, nd: int, width_max: int) -> list[str]:
    """The function's head: the regressor normalised, with its tangents."""
    return [f"static void {prefix}eval(const double* phi, const double* dphi, double* y, "
            "double* dy, int tangent, const double* g) {",
            f"  double z[{nphi}], dz[{nd * nphi}], h[{width_max}], dh[{nd * width_max}];",
            f"  double a[{width_max}], da[{nd * width_max}];",
            "  int i, k;",
            f"  for (i = 0; i < {nphi}; ++i) z[i] = (phi[i] - {prefix}MU[i]) * {prefix}ISG[i];",
            "  if (tangent) {",
            f"    for (k = 0; k < {nd}; ++k) for (i = 0; i < {nphi}; ++i)",
            f"      dz[k * {nphi} + i] = dphi[k * {nphi} + i] * {prefix}ISG[i];",
            "  }"]


def _layer_lines(bias: str, sources: list[tuple[str, str, str, int, int, int]], n_out: int,
                 nd: int, width_max: int) -> list[str]:
    """One layer's sums into ``a`` (and ``da``), a = b + sum over the sources of M x, four
    outputs at a time held in registers over one pass down the inputs, for the value and
    every tangent direction. A source is (matrix, x, dx, dx's direction stride, inputs, the
    first inputs with a tangent): the inputs past those have no tangent and add to the value
    alone. Each output's sum runs in the inputs' order, as the definition's does."""
    blocks = padded(n_out) // 4
    acc = [f"a{b}" for b in range(blocks)]
    dacc = [[f"d{k}_{b}" for b in range(blocks)] for k in range(nd)]
    init = ", ".join(f"{a} = LD({bias} + {4 * b})" for b, a in enumerate(acc))
    lines = ["  {", f"    jp_v4 {init};", "    int j;", "    if (tangent) {",
             f"      jp_v4 {', '.join(f'{d} = {{0}}' for row in dacc for d in row)};"]
    for matrix, x, dx, stride, n_in, n_tan in sources:
        p = 4 * blocks
        loads = " ".join(f"const double t{k} = {dx}[{k * stride} + j];" for k in range(nd))
        body = " ".join(f"{a} += LD(wj + {4 * b}) * xj;" for b, a in enumerate(acc))
        tangents = " ".join(f"{dacc[k][b]} += LD(wj + {4 * b}) * t{k};"
                            for k in range(nd) for b in range(blocks))
        lines += [f"      for (j = 0; j < {n_tan}; ++j) {{",
                  f"        const double* wj = {matrix} + j * {p}; const double xj = {x}[j]; "
                  f"{loads}",
                  f"        {body} {tangents}",
                  "      }"]
        if n_tan < n_in:
            lines += [f"      for (j = {n_tan}; j < {n_in}; ++j) {{",
                      f"        const double* wj = {matrix} + j * {p}; const double xj = "
                      f"{x}[j];",
                      f"        {body}",
                      "      }"]
    lines += [f"      ST(da + {k * width_max + 4 * b}, {dacc[k][b]});"
              for k in range(nd) for b in range(blocks)]
    lines.append("    } else {")
    for matrix, x, _, _, n_in, _ in sources:
        p = 4 * blocks
        body = " ".join(f"{a} += LD(wj + {4 * b}) * xj;" for b, a in enumerate(acc))
        lines += [f"      for (j = 0; j < {n_in}; ++j) {{",
                  f"        const double* wj = {matrix} + j * {p}; const double xj = {x}[j];",
                  f"        {body}",
                  "      }"]
    lines += ["    }", *[f"    ST(a + {4 * b}, {a});" for b, a in enumerate(acc)], "  }"]
    return lines


__all__ = ["TANH", "gain_size", "padded"]
