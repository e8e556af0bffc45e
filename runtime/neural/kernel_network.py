"""One network of the loop kernel in C: its value and its tangent directions in one pass over
the weights (constants in the file, hexadecimal floats, so exact), tanh through expm1.

The weights are stored transposed (column by column): the products are then sums of scaled
columns, independent accumulators the compiler vectorises without reassociating any sum (a
row-by-row dot product is one serial chain of additions).
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from jointplay.neural.narx import Narx

# tanh through expm1: half the cost of libm's tanh here, within 4e-16 of it, exact in sign and
# saturation (|x| > 20 gives +-1, where tanh is 1 to double precision).
TANH = """#include <math.h>
static inline double jp_tanh(double x) {
  double e;
  if (x > 20) return 1;
  if (x < -20) return -1;
  e = expm1(2 * x);
  return e / (e + 2);
}
"""


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
    """C for one network: ``{prefix}eval(phi, dphi, y, dy, tangent)``; ``dphi`` holds ``nd``
    tangent directions (direction-major), ``dy`` likewise."""
    ny, nphi = model.n_outputs, model.n_regressor
    widths = [nphi, *[w.shape[0] for w in model.weights]]
    width_max = max(widths)
    last = len(model.weights) - 1
    lines = _input_lines(prefix, nphi, nd, width_max)
    for i in range(len(model.weights)):
        lines += _layer_lines(f"{prefix}W{i}", f"{prefix}B{i}", widths[i], widths[i + 1], nd,
                              width_max, hidden=i < last)
    if model.bilinear is not None:
        # The direct path with the scheduled input gain added (``{prefix}gain``).
        lines += _linear_lines("g", nphi, ny, nd, width_max)
    else:
        if model.linear is not None:
            lines += _linear_lines(f"{prefix}L", nphi, ny, nd, width_max)
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
    return model.n_regressor * model.n_outputs if model.bilinear is not None else 0


def _gain_function(prefix: str, model: Narx) -> str:
    """``{prefix}gain(w, g)``: the direct path with the bilinear part's input gain
    sum_s w_s B_s added on the input lags' columns, at the raw scheduling signals ``w``; once
    per call of the step (the loop holds the signals over the horizon, with no tangent, so
    the bilinear part is a linear term in the input lags there), laid out as ``{prefix}L``
    (regressor j: g[j * ny .. j * ny + ny - 1])."""
    ny, nw, nz = model.n_outputs, model.n_scheduling, model.n_input_regressors
    first_w, start = model.n_regressor - nw, model.output_lags * ny
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


def _constants(prefix: str, model: Narx) -> str:
    """The network's normalisation, weights (transposed) and direct linear term as arrays."""
    out = [_array(f"{prefix}MU", model.regressor_mean),
           _array(f"{prefix}ISG", 1.0 / model.regressor_scale),
           _array(f"{prefix}TM", model.increment_mean),
           _array(f"{prefix}TS", model.increment_scale),
           _array(f"{prefix}CARRY", model.carry)]
    for i, (w, b) in enumerate(zip(model.weights, model.biases, strict=True)):
        out += [_array(f"{prefix}W{i}", w.T), _array(f"{prefix}B{i}", b)]
    if model.linear is not None:
        out.append(_array(f"{prefix}L", model.linear.T))
    if model.bilinear is not None:
        out.append(_array(f"{prefix}BL", model.bilinear.T))
    return "".join(out)


def _input_lines(prefix: str, nphi: int, nd: int, width_max: int) -> list[str]:
    """The function's head: the regressor normalised, with its tangents, as the first layer's
    input."""
    return [f"static void {prefix}eval(const double* phi, const double* dphi, double* y, "
            "double* dy, int tangent, const double* g) {",
            f"  double z[{nphi}], dz[{nd * nphi}], h[{width_max}], dh[{nd * width_max}];",
            f"  double a[{width_max}], da[{nd * width_max}];",
            "  int i, j, k;",
            f"  for (i = 0; i < {nphi}; ++i) z[i] = (phi[i] - {prefix}MU[i]) * {prefix}ISG[i];",
            "  if (tangent) {",
            f"    for (k = 0; k < {nd}; ++k) for (i = 0; i < {nphi}; ++i)",
            f"      dz[k * {nphi} + i] = dphi[k * {nphi} + i] * {prefix}ISG[i];",
            "  }",
            f"  for (i = 0; i < {nphi}; ++i) h[i] = z[i];",
            "  if (tangent) {",
            f"    for (k = 0; k < {nd}; ++k) for (i = 0; i < {nphi}; ++i)",
            f"      dh[k * {width_max} + i] = dz[k * {nphi} + i];",
            "  }"]


def _layer_lines(wname: str, bias: str, n_in: int, n_out: int, nd: int, width_max: int,
                 hidden: bool) -> list[str]:
    """One layer, a = W h + b, in one pass over the weights for the value and every tangent
    direction; a hidden layer then applies tanh."""
    tangents = "".join(f" da[{k * width_max} + i] += wji * dh{k};" for k in range(nd))
    loads = " ".join(f"const double dh{k} = dh[{k * width_max} + j];" for k in range(nd))
    lines = [
        f"  for (i = 0; i < {n_out}; ++i) a[i] = {bias}[i];",
        "  if (tangent) {",
        f"    for (k = 0; k < {nd}; ++k) for (i = 0; i < {n_out}; ++i) "
        f"da[k * {width_max} + i] = 0;",
        f"    for (j = 0; j < {n_in}; ++j) {{",
        f"      const double hj = h[j]; {loads}",
        f"      for (i = 0; i < {n_out}; ++i) {{",
        f"        const double wji = {wname}[j * {n_out} + i];",
        f"        a[i] += wji * hj;{tangents}",
        "      }",
        "    }",
        "  } else {",
        f"    for (j = 0; j < {n_in}; ++j) {{",
        "      const double hj = h[j];",
        f"      for (i = 0; i < {n_out}; ++i) a[i] += {wname}[j * {n_out} + i] * hj;",
        "    }",
        "  }"]
    if hidden:
        lines += [
            f"  for (i = 0; i < {n_out}; ++i) h[i] = jp_tanh(a[i]);",
            "  if (tangent) {",
            f"    for (k = 0; k < {nd}; ++k) for (i = 0; i < {n_out}; ++i)",
            f"      dh[k * {width_max} + i] = (1 - h[i] * h[i]) * da[k * {width_max} + i];",
            "  }"]
    return lines


def _linear_lines(matrix: str, nphi: int, ny: int, nd: int, width_max: int) -> list[str]:
    """The direct linear term (``matrix``, transposed) on the normalised regressor, added to
    the output layer."""
    tangents = "".join(f" da[{k * width_max} + i] += lji * dz{k};" for k in range(nd))
    loads = " ".join(f"const double dz{k} = dz[{k * nphi} + j];" for k in range(nd))
    return [
        "  if (tangent) {",
        f"    for (j = 0; j < {nphi}; ++j) {{",
        f"      const double zj = z[j]; {loads}",
        f"      for (i = 0; i < {ny}; ++i) {{",
        f"        const double lji = {matrix}[j * {ny} + i];",
        f"        a[i] += lji * zj;{tangents}",
        "      }",
        "    }",
        "  } else {",
        f"    for (j = 0; j < {nphi}; ++j) {{",
        "      const double zj = z[j];",
        f"      for (i = 0; i < {ny}; ++i) a[i] += {matrix}[j * {ny} + i] * zj;",
        "    }",
        "  }"]


__all__ = ["TANH", "gain_size"]
