"""The sensors' noise read from the data alone, and whether a fit's residuals are that noise.

Noise not stated is estimated before any fit from each column's sample-to-sample scatter
(difference-based estimation: Rice, Ann. Statist. 12 (1984) 1215; Gasser, Sroka and
Jennen-Steinmetz, Biometrika 73 (1986) 625): a difference of order k removes a smooth signal up
to its k-th derivative times the step to the k; the order rises while the scale still falls by
more than a tenth, then one more. The scale is robust (OUTLIER_SIGMAS), as an impact makes the
signal rough over a few samples; no model enters, so a misfit cannot inflate it.

A fit explains the data when its chi² lies in its two-sided 99 % range (for an estimated
noise widened by the estimate's own spread) and each column's residuals pass the Ljung-Box
test at 1 % overall: slow waves (a fit in another valley) correlate neighbouring samples.
"""

from __future__ import annotations

import math

import numpy as np

from jointplay.calibration.measured import Measured
from jointplay.common.errors import DescriptionError

MAX_ORDER = 8  # the highest order of difference tried
OUTLIER_SIGMAS = 3.0  # the scale: root mean square within this many sigmas, corrected for the cut
FALLING = 0.9  # the order rises while the next order's scale is below this fraction
MAD_TO_SIGMA = 1.482602218505602  # 1 / Phi^-1(3/4)
LEVEL = 0.01  # the share of fits of correct models with the right noise that the check flags
LAGS = 20  # the autocorrelations the Ljung-Box test sums


def _pseudo_residuals(t: np.ndarray, y: np.ndarray, order: int) -> np.ndarray:
    """Differences of ``order`` of ``y`` at times ``t``: each the unit-norm combination of
    order + 1 consecutive samples that removes every polynomial of degree order - 1 (the
    binomial differences where the times are evenly spaced)."""
    n = t.size - order
    windows = np.lib.stride_tricks.sliding_window_view(t, order + 1)[:n]
    local = (windows - windows.mean(axis=1, keepdims=True)) / np.ptp(windows, axis=1)[:, None]
    vandermonde = np.stack([local**p for p in range(order)], axis=1)  # (n, order, order + 1)
    coefficients = np.linalg.svd(vandermonde)[2][:, -1, :]
    return np.einsum("ij,ij->i", coefficients,
                     np.lib.stride_tricks.sliding_window_view(y, order + 1)[:n])


def _robust_scale(d: np.ndarray) -> float:
    from scipy.stats import norm

    mad = MAD_TO_SIGMA * float(np.median(np.abs(d - np.median(d))))
    if not mad > 0:
        return mad
    inside = d[np.abs(d) <= OUTLIER_SIGMAS * mad]
    # the root mean square of a normal sample cut at c of its sigma, made whole again
    kept = 1 - 2 * OUTLIER_SIGMAS * norm.pdf(OUTLIER_SIGMAS) / (2 * norm.cdf(OUTLIER_SIGMAS) - 1)
    return float(np.sqrt(np.mean(inside**2) / kept)) if inside.size else mad


def column_noise(measured: Measured) -> tuple[np.ndarray, np.ndarray]:
    """Each column's noise standard deviation from its pseudo-residuals, and the relative
    variance of the estimated variance (white Gaussian noise: 2 (1 + 2 sum of the squared
    autocorrelations of the difference) / samples). Raises :class:`DescriptionError` where a
    column has too few samples, or no scatter (state the noise)."""
    t = measured.t
    sigma, spread = [], []
    for k, column in enumerate(measured.columns):
        y = measured.values[:, k]
        if t.size < 4 * (MAX_ORDER + 1):
            raise DescriptionError("noise", f"cannot be estimated from {t.size} samples "
                                   f"(at least {4 * (MAX_ORDER + 1)}); state it with --noise",
                                   measured.source)
        order = 2
        scale = _robust_scale(_pseudo_residuals(t, y, order))
        while order < MAX_ORDER:
            higher = _robust_scale(_pseudo_residuals(t, y, order + 1))
            if not higher < FALLING * scale:
                break
            order, scale = order + 1, higher
        order = min(order + 1, MAX_ORDER)
        scale = _robust_scale(_pseudo_residuals(t, y, order))
        if not scale > 0:
            raise DescriptionError(f"noise {column}", "cannot be estimated: the column has no "
                                   "sample-to-sample scatter; state it with --noise",
                                   measured.source)
        binomial = np.array([(-1.0)**j * math.comb(order, j) for j in range(order + 1)])
        binomial /= np.linalg.norm(binomial)
        correlation = np.correlate(binomial, binomial, mode="full")[order + 1:]
        sigma.append(scale)
        spread.append(2 * (1 + 2 * float(np.sum(correlation**2))) / (t.size - order))
    return np.array(sigma), np.array(spread)


def ljung_box(residuals: np.ndarray, lags: int = LAGS) -> float:
    """The p-value of the Ljung-Box test that ``residuals`` are white: Q = n (n + 2) sum over
    the first ``lags`` lags of the squared autocorrelation over (n - lag), against chi² on
    ``lags`` degrees of freedom (Ljung and Box, Biometrika 65 (1978) 297)."""
    from scipy.stats import chi2

    x = residuals - residuals.mean()
    n = x.size
    lags = max(1, min(lags, n // 4))
    power = float(x @ x)
    if not power > 0:
        return 1.0
    rho = np.array([float(x[:-k] @ x[k:]) / power for k in range(1, lags + 1)])
    q = n * (n + 2) * float(np.sum(rho**2 / (n - np.arange(1, lags + 1))))
    return float(chi2.sf(q, lags))


def residual_check(raw: np.ndarray, sigma: np.ndarray, dof: int,
                   noise_spread: np.ndarray | None, columns: tuple[str, ...]) -> str | None:
    """None where the residuals ``raw`` (samples by columns) are the noise ``sigma``;
    otherwise why not, in a sentence. ``noise_spread``: the estimated noise's relative
    variances (None: stated)."""
    from scipy.stats import chi2 as chi2_dist
    from scipy.stats import norm

    chi2 = float(np.sum((raw / sigma) ** 2))
    dof = max(dof, 1)
    if noise_spread is None:
        low, high = chi2_dist.ppf(LEVEL / 2, dof), chi2_dist.ppf(1 - LEVEL / 2, dof)
    else:
        # log chi² is near normal: its variance the chi²'s own plus the noise estimate's
        # (the columns' weighted by their share of chi²)
        share = np.sum((raw / sigma) ** 2, axis=0) / max(chi2, 1e-300)
        half = norm.ppf(1 - LEVEL / 2) * math.sqrt(2 / dof + float(np.sum(share**2
                                                                         * noise_spread)))
        low, high = dof * math.exp(-half), dof * math.exp(half)
    source = "estimated from the data's scatter" if noise_spread is not None else "stated"
    if not low <= chi2 <= high:
        side = ("the residuals are larger than the noise: the fit sits in another valley "
                "of the cost, or the model lacks something the robot does" if chi2 > high
                else "the residuals are smaller than the noise: the noise is overstated")
        return (f"chi²/dof = {chi2 / dof:.4g} lies outside its 99 % range "
                f"{low / dof:.4g}-{high / dof:.4g} for the noise {source}: {side}")
    for k, column in enumerate(columns):
        p = ljung_box(raw[:, k])
        if p < LEVEL / len(columns):
            return (f"the residuals are not white noise: the Ljung-Box test of their first "
                    f"{LAGS} autocorrelations fails in {column} (p = {p:.2g}): slow waves the "
                    "noise does not make, a fit in another valley of the cost or a model "
                    "that lacks something")
    return None
