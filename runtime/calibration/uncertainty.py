"""What the data say about the estimates: covariance, correlations, conditioning, and which
parameters they cannot determine.

With residuals whitened by the sensors' standard deviations, the estimates' covariance at the
optimum is (JᵀJ)⁻¹ (J the whitened Jacobian), computed through the correlation form
C = D⁻¹ JᵀJ D⁻¹ (D the columns' norms), whose condition number is unit-free. A direction the
data do not see (a singular value of C below :data:`RANK_TOLERANCE` of the largest) leaves its
parameters undetermined: infinite standard deviation, interval the whole physical range.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

Z95 = 1.959963984540054
"""The two-sided 95 % quantile of the standard normal distribution."""
RANK_TOLERANCE = 1e-10
"""Singular values of the correlation form below this fraction of the largest: rank lost."""
MAX_CORRELATION = 0.99
"""Pairs more correlated than this, one of them with a wide interval: not separated by the data."""
MAX_RELATIVE_STD = 0.5
"""A 95 % interval wider than the value itself (std > half the value): not determined."""
NULL_COMPONENT = 0.1
"""A parameter taking part in a lost direction by more than this (unit vector) is undetermined."""


@dataclass(frozen=True)
class Uncertainty:
    covariance: np.ndarray
    std: np.ndarray
    correlation: np.ndarray
    condition_number: float
    low95: np.ndarray
    high95: np.ndarray
    determined: np.ndarray
    warnings: tuple[str, ...]
    seen_covariance: np.ndarray | None = None
    """The covariance within the directions the data see (the pseudo-inverse), finite where
    ``covariance`` is not; its axes of nonzero variance are the directions to move and check."""


def uncertainty(jacobian: np.ndarray, values: np.ndarray, lower: np.ndarray,
                upper: np.ndarray, names: tuple[str, ...]) -> Uncertainty:
    """The covariance (JᵀJ)⁻¹ of whitened-residual estimates ``values`` and what it implies."""
    n = values.size
    jtj = jacobian.T @ jacobian
    norms = np.sqrt(np.diag(jtj))
    seen = norms > 0
    unit = np.where(seen, norms, 1.0)
    corr_form = jtj / np.outer(unit, unit)
    corr_form[~seen, :] = 0.0
    corr_form[:, ~seen] = 0.0
    u, s, vt = np.linalg.svd(corr_form)
    s_max = float(s[0]) if s.size else 0.0
    lost = s <= RANK_TOLERANCE * s_max if s_max > 0 else np.ones(n, bool)
    condition = float(s_max / s[-1]) if s_max > 0 and s[-1] > 0 else float("inf")
    covariance = ((vt[~lost].T / s[~lost]) @ u[:, ~lost].T) / np.outer(unit, unit)
    undetermined = ~seen
    partners: dict[int, set[int]] = {i: set() for i in range(n)}
    for k in np.flatnonzero(lost):
        members = np.flatnonzero(np.abs(vt[k]) > NULL_COMPONENT)
        undetermined[members] = True
        for i in members:
            partners[int(i)].update(int(j) for j in members if j != i)
    std = np.sqrt(np.clip(np.diag(covariance), 0.0, None))
    std[undetermined] = np.inf
    correlation = _correlation(covariance, corr_form, vt, lost)
    span = upper - lower
    scale = np.where(values != 0, np.abs(values), np.where(np.isfinite(span), span, 1.0))
    wide = std > MAX_RELATIVE_STD * scale
    # A correlation, however close to one, leaves a parameter determined where its own
    # interval is narrow (the covariance already holds it): the verdict follows the interval.
    for i, j in zip(*np.triu_indices(n, 1), strict=True):
        r = correlation[i, j]
        if np.isfinite(r) and abs(r) > MAX_CORRELATION and (wide[i] or wide[j]):
            partners[int(i)].add(int(j))
            partners[int(j)].add(int(i))
    determined = ~(undetermined | wide)
    warnings = tuple(f"{names[i]} is not determined by the data "
                     f"({_reason(int(i), names, partners, undetermined, std, values)})"
                     for i in np.flatnonzero(~determined))
    low = np.where(np.isfinite(std), values - Z95 * std, lower)
    high = np.where(np.isfinite(std), values + Z95 * std, upper)
    infinite = undetermined[:, None] | undetermined[None, :]
    return Uncertainty(covariance=np.where(infinite, np.inf, covariance), std=std,
                       correlation=correlation, condition_number=condition,
                       low95=np.maximum(low, lower), high95=np.minimum(high, upper),
                       determined=determined, warnings=warnings, seen_covariance=covariance)


def _correlation(covariance: np.ndarray, corr_form: np.ndarray, vt: np.ndarray,
                 lost: np.ndarray) -> np.ndarray:
    """Correlations of the estimates; a pair in a lost direction gets +-1 from that direction
    (the data move them together), and a parameter the runs do not depend on gets NaN."""
    d = np.sqrt(np.clip(np.diag(covariance), 0.0, None))
    with np.errstate(divide="ignore", invalid="ignore"):
        corr = covariance / np.outer(d, d)
    np.fill_diagonal(corr, 1.0)
    # In a lost direction v the estimates move along v freely: correlated with sign v_i v_j.
    for v in vt[lost]:
        big = np.flatnonzero(np.abs(v) > NULL_COMPONENT)
        corr[np.ix_(big, big)] = np.sign(np.outer(v[big], v[big]))  # its diagonal: 1
    blind = np.flatnonzero(np.diag(corr_form) == 0)
    corr[blind, :] = np.nan
    corr[:, blind] = np.nan
    corr[blind, blind] = 1.0
    return corr


def _reason(i: int, names: tuple[str, ...], partners: dict[int, set[int]],
            undetermined: np.ndarray, std: np.ndarray, values: np.ndarray) -> str:
    if partners[i]:
        others = ", ".join(names[j] for j in sorted(partners[i]))
        return f"it cannot be separated from {others}"
    if undetermined[i]:
        return "the measured outputs do not depend on it"
    return f"standard deviation {std[i]:.3g} against a value of {values[i]:.6g}"
