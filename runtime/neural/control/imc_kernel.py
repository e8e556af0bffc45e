"""The controller step as loops over small dense matrices, in C: the same law, a fraction of
the cost.

CasADi's SX code for the step is straight-line: every multiply-add of the d-step rollout and
of its forward derivative is one line, about 5 400 operations per step of the horizon (29 000
at d = 5). That code no longer fits the instruction cache, and its cost is the cost of reading
it. The structure is simple, though: each step of the rollout is the same network, and the
rollout's Jacobian is the product of the per-step Jacobians, carried forward as nu tangent
directions through the same layers. Written as loops over the weight matrices (constants in
the file, hexadecimal floats, so exact), the step is a few kilobytes of code the compiler can
keep in cache and vectorise.

The CasADi function (jointplay.neural.control.imc_step.build_step) stays the definition: the kernel
is generated from the same model and settings, exported under the same C interface (so it loads
and runs through the same buffers), and the tests check that the two agree to 1e-12 on random
states, guard on and off, with and without the fallback. The kernel covers one Gauss-Newton
iteration (the AIMNC law, the default); more iterations use CasADi's code.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import casadi as ca
import numpy as np

from jointplay.neural.control.imc_settings import ControllerSettings
from jointplay.neural.control.imc_step import _tracking_matrix
from jointplay.neural.control.internal_model import (
    _inner_gains,
    affine_rollout,
    input_bound,
    is_linear,
    training_box,
)
from jointplay.neural.control.kernel_network import TANH, _array, _c, _network, gain_size
from jointplay.neural.control.mismatch_filter import pair_gains
from jointplay.neural.model.narx import Narx


def _branch(prefix: str, model: Narx, s: ControllerSettings, rows: list[int],
            scales: tuple[float, ...]) -> str:
    """C for one internal model's increment and trust:
    ``{prefix}branch(hist, upast, v_prev, w, g, e_f, target, step) -> ok`` (``g``: the
    scheduled direct path, formed once per step by the kernel; unused without one)."""
    ny, nt = model.n_outputs, len(rows)
    lo, hi = training_box(model, s.trust_range)
    out = [_array(f"{prefix}LO", lo), _array(f"{prefix}HI", hi)]
    lines = [f"static int {prefix}branch(const double* hist, const double* upast, "
             "const double* vp, const double* w, const double* g, const double* ef, "
             "const double* target, "
             "double* step) {",
             f"  double n0[{ny}], res[{nt}];",
             "  int i, j, k, ok = 1;"]
    if is_linear(model):
        arrays, body = _linear_increment(prefix, model, s, rows, scales)
        out += arrays
        lines += body
    else:
        lines += _network_increment(prefix, model, s, rows, scales)
    if s.guard:
        lines += _trust_lines(prefix, model, s, rows, scales)
    lines += ["  return ok;", "}"]
    return "".join(out) + "\n".join(lines) + "\n"


def _residual(i: int, row: int, scale: float) -> str:
    """The scaled tracking residual of tracked output ``i`` (output ``row``)."""
    return f"  res[{i}] = (target[{row}] - ef[{row}] - n0[{row}]) * {_c(1.0 / scale)};"


def _linear_increment(prefix: str, model: Narx, s: ControllerSettings, rows: list[int],
                      scales: tuple[float, ...]) -> tuple[list[str], list[str]]:
    """(arrays, lines) for a linear model: its d-step prediction and the regularised inverse
    are constant matrices."""
    ny, nu, na, nb = model.n_outputs, model.n_inputs, model.output_lags, model.input_lags
    nt = len(rows)
    mh, mu, mv, c = affine_rollout(model, s.horizon)
    cj = _tracking_matrix(model, s) @ mv
    gain = np.linalg.solve(cj.T @ cj + s.regularisation * np.eye(nu), cj.T)
    arrays = [_array(f"{prefix}MH", mh), _array(f"{prefix}MUP", mu), _array(f"{prefix}MV", mv),
              _array(f"{prefix}MC", c), _array(f"{prefix}G", gain)]
    lines = [
        f"  for (i = 0; i < {ny}; ++i) {{",
        f"    double s = {prefix}MC[i];",
        f"    for (j = 0; j < {na * ny}; ++j) s += {prefix}MH[i * {na * ny} + j] * hist[j];",
        f"    for (j = 0; j < {nb * nu}; ++j) s += {prefix}MUP[i * {nb * nu} + j] * upast[j];",
        f"    for (j = 0; j < {nu}; ++j) s += {prefix}MV[i * {nu} + j] * vp[j];",
        "    n0[i] = s;",
        "  }"]
    lines += [_residual(i, row, scale)
              for i, (row, scale) in enumerate(zip(rows, scales, strict=True))]
    lines += [
        f"  for (i = 0; i < {nu}; ++i) {{",
        "    double s = 0;",
        f"    for (j = 0; j < {nt}; ++j) s += {prefix}G[i * {nt} + j] * res[j];",
        "    step[i] = s;",
        "  }"]
    return arrays, lines


def _network_increment(prefix: str, model: Narx, s: ControllerSettings, rows: list[int],
                       scales: tuple[float, ...]) -> list[str]:
    """Lines for a network: the d-step rollout with its Jacobian in v (nu tangent directions),
    the scaled residual and tracked Jacobian, and the regularised normal equations solved."""
    ny, nu, na = model.n_outputs, model.n_inputs, model.output_lags
    lines = _rollout_lines(prefix, model, s.horizon, len(rows))
    for i, (row, scale) in enumerate(zip(rows, scales, strict=True)):
        lines.append(_residual(i, row, scale))
        lines.append(f"  for (k = 0; k < {nu}; ++k) cj[{i} * {nu} + k] = "
                     f"dys[k * {na * ny} + {row}] * {_c(1.0 / scale)};")
    return lines + _normal_equation_lines(nu, len(rows), s.regularisation)


def _rollout_lines(prefix: str, model: Narx, d: int, nt: int) -> list[str]:
    """The network run ``d`` samples ahead with v held, carrying d y / d v forward."""
    ny, nu, na, nb = model.n_outputs, model.n_inputs, model.output_lags, model.input_lags
    nphi, ns = model.n_regressor, model.n_scheduling
    o_w = na * ny + nb * nu
    # The scheduling signals are held over the horizon: in the regressor, with no tangent.
    held = [f"  for (i = 0; i < {ns}; ++i) phi[{o_w} + i] = w[i];",
            f"  for (k = 0; k < {nu}; ++k) for (i = 0; i < {ns}; ++i) "
            f"dphi[k * {nphi} + {o_w} + i] = 0;"] if ns else ["  (void) w;"]
    return [
        f"  double phi[{nphi}], dphi[{nu * nphi}], ys[{na * ny}], dys[{nu * na * ny}];",
        f"  double yn[{ny}], dyn[{nu * ny}], us[{nb * nu}], dus[{nu * nb * nu}];",
        f"  double cj[{nt * nu}], a[{nu * nu}], b[{nu}];",
        f"  for (i = 0; i < {na * ny}; ++i) ys[i] = hist[i];",
        f"  for (i = 0; i < {nu * na * ny}; ++i) dys[i] = 0;",
        f"  for (i = 0; i < {nu}; ++i) us[i] = vp[i];",
        f"  for (i = {nu}; i < {nb * nu}; ++i) us[i] = upast[i - {nu}];",
        f"  for (i = 0; i < {nu * nb * nu}; ++i) dus[i] = 0;",
        f"  for (k = 0; k < {nu}; ++k) dus[k * {nb * nu} + k] = 1;",
        *held,
        *([] if gain_size(model) else ["  (void) g;"]),
        f"  for (int t = 0; t < {d}; ++t) {{",
        f"    for (i = 0; i < {na * ny}; ++i) phi[i] = ys[i];",
        f"    for (i = 0; i < {nb * nu}; ++i) phi[{na * ny} + i] = us[i];",
        f"    for (k = 0; k < {nu}; ++k) {{",
        f"      for (i = 0; i < {na * ny}; ++i) dphi[k * {nphi} + i] = dys[k * {na * ny} + i];",
        f"      for (i = 0; i < {nb * nu}; ++i) dphi[k * {nphi} + {na * ny} + i] = "
        f"dus[k * {nb * nu} + i];",
        "    }",
        f"    {prefix}eval(phi, dphi, yn, dyn, 1, {'g' if gain_size(model) else '0'});",
        f"    for (i = {na * ny} - 1; i >= {ny}; --i) ys[i] = ys[i - {ny}];",
        f"    for (i = 0; i < {ny}; ++i) ys[i] = yn[i];",
        f"    for (k = 0; k < {nu}; ++k) {{",
        f"      for (i = {na * ny} - 1; i >= {ny}; --i) dys[k * {na * ny} + i] = "
        f"dys[k * {na * ny} + i - {ny}];",
        f"      for (i = 0; i < {ny}; ++i) dys[k * {na * ny} + i] = dyn[k * {ny} + i];",
        f"      for (i = {nb * nu} - 1; i >= {nu}; --i) dus[k * {nb * nu} + i] = "
        f"dus[k * {nb * nu} + i - {nu}];",
        f"      for (i = 0; i < {nu}; ++i) dus[k * {nb * nu} + i] = (i == k);",
        "    }",
        f"    for (i = {nb * nu} - 1; i >= {nu}; --i) us[i] = us[i - {nu}];",
        f"    for (i = 0; i < {nu}; ++i) us[i] = vp[i];",
        "  }",
        f"  for (i = 0; i < {ny}; ++i) n0[i] = ys[i];"]


def _normal_equation_lines(nu: int, nt: int, regularisation: float) -> list[str]:
    """((CJ)'(CJ) + lam I) step = (CJ)' res, solved by Cholesky (symmetric positive definite)."""
    return [
        f"  for (i = 0; i < {nu}; ++i) {{",
        "    double s = 0;",
        f"    for (j = 0; j < {nt}; ++j) s += cj[j * {nu} + i] * res[j];",
        "    b[i] = s;",
        f"    for (k = 0; k < {nu}; ++k) {{",
        f"      double q = (i == k) ? {_c(regularisation)} : 0.0;",
        f"      for (j = 0; j < {nt}; ++j) q += cj[j * {nu} + i] * cj[j * {nu} + k];",
        f"      a[i * {nu} + k] = q;",
        "    }",
        "  }",
        f"  for (i = 0; i < {nu}; ++i) {{",
        "    for (k = 0; k <= i; ++k) {",
        f"      double q = a[i * {nu} + k];",
        f"      for (j = 0; j < k; ++j) q -= a[i * {nu} + j] * a[k * {nu} + j];",
        f"      if (i == k) a[i * {nu} + i] = sqrt(q); else a[i * {nu} + k] = q / "
        f"a[k * {nu} + k];",
        "    }",
        "  }",
        f"  for (i = 0; i < {nu}; ++i) {{",
        "    double q = b[i];",
        f"    for (j = 0; j < i; ++j) q -= a[i * {nu} + j] * step[j];",
        f"    step[i] = q / a[i * {nu} + i];",
        "  }",
        f"  for (i = {nu} - 1; i >= 0; --i) {{",
        "    double q = step[i];",
        f"    for (j = i + 1; j < {nu}; ++j) q -= a[j * {nu} + i] * step[j];",
        f"    step[i] = q / a[i * {nu} + i];",
        "  }"]


def _trust_lines(prefix: str, model: Narx, s: ControllerSettings, rows: list[int],
                 scales: tuple[float, ...]) -> list[str]:
    """The guard: regressor and prediction inside the widened training box, the scaled
    mismatch below its bound, and a finite increment."""
    ny, nu, na, nb = model.n_outputs, model.n_inputs, model.output_lags, model.input_lags
    lines = [
        f"  for (i = 0; i < {na * ny}; ++i) ok &= (hist[i] - {prefix}LO[i] >= 0) & "
        f"({prefix}HI[i] - hist[i] >= 0);",
        f"  for (i = 0; i < {nu}; ++i) ok &= (vp[i] - {prefix}LO[{na * ny} + i] >= 0) & "
        f"({prefix}HI[{na * ny} + i] - vp[i] >= 0);",
        f"  for (i = 0; i < {(nb - 1) * nu}; ++i) ok &= "
        f"(upast[i] - {prefix}LO[{na * ny + nu} + i] >= 0) & "
        f"({prefix}HI[{na * ny + nu} + i] - upast[i] >= 0);",
        f"  for (i = 0; i < {ny}; ++i) ok &= (n0[i] - {prefix}LO[i] >= 0) & "
        f"({prefix}HI[i] - n0[i] >= 0);"]
    for row, scale in zip(rows, scales, strict=True):
        lines.append(f"  ok &= ({_c(s.trust_mismatch)} - fabs(ef[{row}] * "
                     f"{_c(1.0 / scale)}) >= 0);")
    if model.n_scheduling:
        o_w = na * ny + nb * nu
        lines.append(f"  for (i = 0; i < {model.n_scheduling}; ++i) ok &= "
                     f"(w[i] - {prefix}LO[{o_w} + i] >= 0) & ({prefix}HI[{o_w} + i] - w[i] >= 0);")
    lines.append(f"  for (i = 0; i < {nu}; ++i) ok &= (fabs(step[i]) < 1e300);")
    return lines


def kernel_source(model: Narx, settings: ControllerSettings, fallback: Narx | None,
                  name: str) -> str:
    """C of ``name``'s computation: ``static int {name}_kernel(arg, res)``."""
    s = settings
    if s.iterations != 1:
        raise ValueError("the loop kernel implements one Gauss-Newton iteration")
    if pair_gains(model, s):
        raise ValueError("the loop kernel implements the first-order mismatch filter only")
    if fallback is not None and not s.guard:
        fallback = None
    nu = model.n_inputs
    rows = [model.output_index(n) for n in s.tracked]
    parts = [TANH, _network("m_", model, nu), _branch("m_", model, s, rows, s.scales)]
    if fallback is not None:
        parts += [_network("f_", fallback, nu), _branch("f_", fallback, s, rows, s.scales)]
    q_idx, dq_idx, kp, kd = _inner_gains(model)
    rate = [r * model.sample_time for r in s.rate_limit]
    limit = [lim if math.isfinite(lim) else 1e300 for lim in s.torque_limit]
    bound = input_bound(model, s.trust_input) if s.guard else np.full(nu, 1e300)
    parts += [_array("RATE", rate), _array("LIMIT", limit), _array("BOUND", bound),
              _array("KP", kp if len(kp) else np.zeros(nu)),
              _array("KD", kd if len(kd) else np.zeros(nu))]
    x = _Shape.of(model, fallback)
    inner = "\n".join(
        f"  inner[{i}] = -KP[{i}] * dev[{q}] - KD[{i}] * dev[{dq}];"
        for i, (q, dq) in enumerate(zip(q_idx, dq_idx, strict=True))) if q_idx else \
        f"  for (i = 0; i < {nu}; ++i) inner[i] = 0;"
    body = (_kernel_head(name, x, s, _scheduling_lines(model, fallback)) + inner + "\n"
            + _kernel_limits(x, s) + _kernel_predictions(x) + _kernel_next_state(x, s))
    return "".join(parts) + body


def _scheduling_lines(model: Narx, fallback: Narx | None) -> str:
    """C filling ``w`` with the scheduling signals from the reference ``r`` and the
    feedforward ``ff`` (jointplay.neural.model.scheduling; the models share one list or take
    none)."""
    from jointplay.neural.model.scheduling import _source

    names = max((m.scheduling for m in (model, fallback) if m is not None), key=len)
    lines = []
    for i, name in enumerate(names):
        kind, j = _source(name, model.output_names, model.input_names)
        value = {"cos": f"cos(r[{j}])", "sin": f"sin(r[{j}])", "r": f"r[{j}]",
                 "tau": f"ff[{j}]"}[kind]
        lines.append(f"  w[{i}] = {value};")
    return "\n".join(lines) + "\n"


@dataclass(frozen=True)
class _Shape:
    """The step's sizes and where each part of its state starts (build_step's order; the
    network's history starts at 0)."""

    ny: int
    nu: int
    na: int
    nb: int
    naf: int  # the fallback's output lags, 0 without one
    nbf: int  # the fallback's input lags, 1 without one
    n_phi_max: int
    ns: int  # scheduling signals of the network (0: none)
    nsf: int  # of the fallback
    fb: bool  # with a fallback
    gain: int  # doubles of the network's scheduled input gain (0: no bilinear part)
    gainf: int  # of the fallback's
    o_histf: int
    o_up: int
    o_ef: int
    o_eff: int
    o_yd: int
    o_hold: int

    @classmethod
    def of(cls, model: Narx, fallback: Narx | None) -> _Shape:
        ny, nu, na, nb = model.n_outputs, model.n_inputs, model.output_lags, model.input_lags
        naf = fallback.output_lags if fallback is not None else 0
        o_histf = na * ny
        o_up = o_histf + naf * ny
        o_ef = o_up + nb * nu
        o_eff = o_ef + ny
        o_yd = o_eff + (ny if fallback is not None else 0)
        return cls(ny, nu, na, nb, naf, fallback.input_lags if fallback is not None else 1,
                   max(model.n_regressor, fallback.n_regressor if fallback is not None else 0),
                   model.n_scheduling, fallback.n_scheduling if fallback is not None else 0,
                   fallback is not None, gain_size(model),
                   gain_size(fallback) if fallback is not None else 0,
                   o_histf, o_up, o_ef, o_eff, o_yd, o_yd + ny)


def _kernel_head(name: str, x: _Shape, s: ControllerSettings, scheduling: str) -> str:
    """The kernel's declarations, the mismatch filters, the target and both branches."""
    ny, nu, fb = x.ny, x.nu, x.fb
    a_d = s.setpoint_filter ** s.horizon
    b = s.mismatch_filter
    return f"""
static int {name}_kernel(const double** arg, double** res) {{
  const double *y = arg[0], *r = arg[1], *ff = arg[2], *x = arg[3];
  double *tau = res[0], *xn = res[1], *vout = res[2], *ypred = res[3], *flags = res[4];
  double dev[{ny}], ef[{ny}], eff[{ny}], target[{ny}], dvm[{nu}], dvf[{nu}], step[{nu}];
  double vtry[{nu}], vtr[{nu}], vnew[{nu}], inner[{nu}], phi[{x.n_phi_max}];
  double yn[{ny}], yfn[{ny}], w[{max(x.ns, x.nsf, 1)}];
  const double *hist = x + 0, *histf = x + {x.o_histf}, *upast = x + {x.o_up};
  const double *vp = upast;
  double hold = x[{x.o_hold}], episodes = x[{x.o_hold + 1}];
  int i, okm, okf = 0, use_main, use_back, at_bound = 0, at_limit = 0;
  /* the scheduled direct paths, once per step (the signals are held over the horizon) */
  double gm[{max(x.gain, 1)}], gf[{max(x.gainf, 1)}];
  w[0] = 0;
{scheduling}{"  m_gain(w, gm);" if x.gain else "  gm[0] = 0;"}
{"  f_gain(w, gf);" if x.gainf else "  gf[0] = 0;"}
  for (i = 0; i < {ny}; ++i) {{
    dev[i] = y[i] - r[i];
    ef[i] = {_c(b)} * x[{x.o_ef} + i] + {_c(1 - b)} * (dev[i] - hist[i]);
    {f"eff[i] = {_c(b)} * x[{x.o_eff} + i] + {_c(1 - b)} * (dev[i] - histf[i]);" if fb else
     "eff[i] = 0;"}
    target[i] = {_c(a_d)} * x[{x.o_yd} + i];
  }}
  okm = m_branch(hist, upast, vp, w, gm, ef, target, dvm);
  use_main = okm && hold <= 0;
  {"if (!use_main) okf = f_branch(histf, upast, vp, w, gf, eff, target, dvf);" if fb else ""}
  use_back = !use_main && okf;
"""


def _kernel_limits(x: _Shape, s: ControllerSettings) -> str:
    """The chosen increment through the rate limit, the trust bound and the actuator limits."""
    return f"""  for (i = 0; i < {x.nu}; ++i) {{
    step[i] = use_main ? dvm[i] : (use_back ? dvf[i] : -vp[i]);
    step[i] = fmin(fmax(step[i], -RATE[i]), RATE[i]);
    vtry[i] = vp[i] + step[i];
    vtr[i] = {"fmin(fmax(vtry[i], -BOUND[i]), BOUND[i])" if s.guard else "vtry[i]"};
    vnew[i] = fmin(fmax(vtr[i], -LIMIT[i] - ff[i] - inner[i]), LIMIT[i] - ff[i] - inner[i]);
    tau[i] = fmin(fmax(ff[i] + inner[i] + vnew[i], -LIMIT[i]), LIMIT[i]) - ff[i];
    vout[i] = vnew[i];
    at_bound |= fabs(vtr[i] - vtry[i]) > 0;
    at_limit |= fabs(vnew[i] - vtr[i]) > 0;
  }}
"""


def _eval_call(prefix: str, out: str, gain: int) -> str:
    """One network's prediction (no tangent), with the scheduled input gain formed at the
    step's start if it has one."""
    return f"{prefix}_eval(phi, 0, {out}, 0, 0, {f'g{prefix}' if gain else '0'});"


def _kernel_predictions(x: _Shape) -> str:
    """Both internal models advanced one sample with the applied v."""
    ny, nu, na, nb, naf, nbf = x.ny, x.nu, x.na, x.nb, x.naf, x.nbf
    return f"""  for (i = 0; i < {na * ny}; ++i) phi[i] = hist[i];
  for (i = 0; i < {nu}; ++i) phi[{na * ny} + i] = vnew[i];
  for (i = 0; i < {(nb - 1) * nu}; ++i) phi[{na * ny + nu} + i] = upast[i];
  for (i = 0; i < {x.ns}; ++i) phi[{na * ny + nb * nu} + i] = w[i];
  {_eval_call("m", "yn", x.gain)}
  {f'''for (i = 0; i < {naf * ny}; ++i) phi[i] = histf[i];
  for (i = 0; i < {nu}; ++i) phi[{naf * ny} + i] = vnew[i];
  for (i = 0; i < {(nbf - 1) * nu}; ++i) phi[{naf * ny + nu} + i] = upast[i];
  for (i = 0; i < {x.nsf}; ++i) phi[{naf * ny + nbf * nu} + i] = w[i];
  {_eval_call("f", "yfn", x.gainf)}''' if x.fb else ""}
"""


def _kernel_next_state(x: _Shape, s: ControllerSettings) -> str:
    """The next state in build_step's order, the predicted deviation and the flags."""
    ny, nu, na, nb, naf, fb = x.ny, x.nu, x.na, x.nb, x.naf, x.fb
    o_histf, o_up, o_ef, o_eff, o_yd = x.o_histf, x.o_up, x.o_ef, x.o_eff, x.o_yd
    o_hold = x.o_hold
    return f"""  {{
    /* next state: network history, fallback history, inputs, filters, setpoint, counters */
    int reseed = {"!use_main" if fb and naf == na else "0"};
    for (i = 0; i < {ny}; ++i) xn[i] = reseed ? yfn[i] : yn[i];
    for (i = {ny}; i < {na * ny}; ++i) xn[i] = reseed ? histf[i - {ny}] : hist[i - {ny}];
    {f'''for (i = 0; i < {ny}; ++i) xn[{o_histf} + i] = yfn[i];
    for (i = {ny}; i < {naf * ny}; ++i) xn[{o_histf} + i] = histf[i - {ny}];''' if fb else ""}
    for (i = 0; i < {nu}; ++i) xn[{o_up} + i] = vnew[i];
    for (i = {nu}; i < {nb * nu}; ++i) xn[{o_up} + i] = upast[i - {nu}];
    for (i = 0; i < {ny}; ++i) xn[{o_ef} + i] = {"use_main ? ef[i] : eff[i]" if fb else "ef[i]"};
    {f"for (i = 0; i < {ny}; ++i) xn[{o_eff} + i] = eff[i];" if fb else ""}
    for (i = 0; i < {ny}; ++i) xn[{o_yd} + i] = {_c(s.setpoint_filter)} * x[{o_yd} + i];
    {{
      int distrusted = !okm, first = distrusted && hold <= 0;
      double ep = episodes + (first ? 1 : 0), e1 = fmin(fmax(ep - 1, 0), 6);
      double length = {_c(float(s.fallback_hold))} * ldexp(1.0, (int) floor(e1));
      xn[{o_hold}] = distrusted ? length : fmax(hold - 1, 0);
      xn[{o_hold + 1}] = ep;
      flags[0] = distrusted;
    }}
    for (i = 0; i < {ny}; ++i) ypred[i] = xn[i];
  }}
  flags[1] = use_back;
  flags[2] = !(use_main || use_back);
  flags[3] = at_bound;
  flags[4] = at_limit;
  return 0;
}}
"""


def kernel_library_source(model: Narx, settings: ControllerSettings, fallback: Narx | None,
                          function: ca.Function, name: str) -> str:
    """A complete C file: CasADi's interface for ``function``'s signature (names, sparsity,
    work) around the loop kernel."""
    y, r, ff, x = (ca.SX.sym(n, function.nnz_in(i)) for i, n in enumerate(
        ("y", "r", "tau_ff", "state")))
    outs = [ca.SX.zeros(function.nnz_out(i), 1) for i in range(function.n_out())]
    shell = ca.Function(name, [y, r, ff, x], outs, function.name_in(), function.name_out())
    gen = ca.CodeGenerator(f"{name}.c", {"with_header": False, "verbose": False})
    gen.add(shell)
    code = gen.dump()
    call = "  return casadi_f0(arg, res, iw, w, mem);"
    if call not in code:
        raise RuntimeError("unexpected CasADi code layout: cannot attach the loop kernel")
    code = code.replace(call, f"  return {name}_kernel(arg, res);")
    marker = "static int casadi_f0("
    kernel = kernel_source(model, settings, fallback, name)
    return code.replace(marker, kernel + "\n" + marker, 1)


__all__ = ["kernel_library_source", "kernel_source"]
