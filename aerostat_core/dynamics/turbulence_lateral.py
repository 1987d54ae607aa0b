"""Lateral turbulence v' for the 6-DOF model: the MIL-HDBK-1797 Dryden lateral component on the
same height levels, frequencies and IEC 61400-1 coherence as the u' and w' of :mod:`.turbulence`
(docs/dynamics.md §7.3).

MIL-F-8785C low altitude: L_v = L_u, sigma_v = sigma_u, and the lateral spectrum has the form of
the vertical one, Phi_v(omega) = sigma_v^2 L_v/(pi U) (1 + 3 (L_v omega/U)^2)/(1 + (L_v omega/U)^2)^2.
The phases are drawn from their own stream of the run's seed, so u' and w' are those of the 3-DOF
run with the same seed.
"""

from __future__ import annotations

import numpy as np

from aerostat_core.dynamics.turbulence import (
    IEC_COHERENCE_DECAY,
    TurbulenceField,
    cumulative_psd_w,
    iec_coherence,
)

__all__ = ["IEC_COHERENCE_DECAY", "lateral_coefficients", "lateral_table"]


def lateral_coefficients(rec: TurbulenceField) -> np.ndarray:
    """Complex amplitudes (levels, K) [m/s] of v' on the levels of a realised field (Veers'
    synthesis with the field's coherence: S = H H^T per frequency, hull level first)."""
    omega = rec.omega
    k_max = omega.size
    dw = omega[0]
    edges = np.concatenate([[0.0], (np.arange(1, k_max + 1) + 0.5) * dw])
    n_lev = rec.z_levels.size
    var = np.empty((n_lev, k_max))
    for i, p in enumerate(rec.level_params):
        var[i] = np.diff(cumulative_psd_w(edges, p.sigma_u, p.length_u, rec.speed))
    rng = np.random.default_rng([int(rec.seed), 3])
    phases = rng.uniform(0.0, 2.0 * np.pi, (n_lev, k_max))
    order = np.concatenate([[rec.hull_level], np.delete(np.arange(n_lev), rec.hull_level)])
    a = np.sqrt(2.0 * var[order])
    xi = np.exp(1j * phases[order]).T
    if n_lev == 1:
        return a * np.exp(1j * phases)
    zo = rec.z_levels[order]
    dz = zo[:, None] - zo[None, :]
    c = np.empty((n_lev, k_max), complex)
    for k0 in range(0, k_max, 1024):
        ks = slice(k0, min(k0 + 1024, k_max))
        coh = iec_coherence(dz[None], omega[ks, None, None] / (2 * np.pi), rec.speed)
        ak = a[:, ks].T
        cov = coh * ak[:, :, None] * ak[:, None, :] + 1e-14 * np.eye(n_lev)[None]
        h = np.linalg.cholesky(cov)
        c[:, ks] = np.einsum("kij,kj->ki", h, xi[ks]).T
    out = np.empty_like(c)
    out[order] = c
    return out


def lateral_table(field_) -> np.ndarray:
    """Rows (v', dv'/dtau) per level on the grid of the field's u'/w' table (appended after
    them for the kernel, :func:`.sixdof_kernel.lateral_turbulence`)."""
    rec = field_.turbulence
    cached = rec.__dict__.get("_lateral")
    if cached is not None:
        return cached
    _dt, tab = rec.table()
    n = tab.shape[1]
    coef = lateral_coefficients(rec)
    k = rec.omega.size
    out = np.empty((2 * rec.z_levels.size, n))
    for lev in range(rec.z_levels.size):
        c = np.zeros(n // 2 + 1, complex)
        c[1:k + 1] = 0.5 * coef[lev] * n
        out[2 * lev] = np.fft.irfft(c, n)
        c[1:k + 1] *= 1j * rec.omega
        out[2 * lev + 1] = np.fft.irfft(c, n)
    rec.__dict__["_lateral"] = out
    return out
