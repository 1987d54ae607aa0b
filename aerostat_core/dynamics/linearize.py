"""Linearised dynamics about an equilibrium: eigenvalues, mode periods, damping (docs/dynamics.md V7).

As Lambert & Nahon (2003) did: the full nonlinear right-hand side is differentiated by central
finite differences at the static equilibrium, A = df/dy, and the eigenvalues lambda of A give the
small-motion modes: period T = 2 pi/|Im lambda|, damping ratio zeta = -Re lambda/|lambda|,
log-decrement delta = 2 pi zeta/sqrt(1 - zeta^2). Each mode is labelled by where its eigenvector's
kinetic-energy-weighted amplitude sits: hull surge (x), heave (z), pitch (theta), or the tether.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .kernel import ND, rhs_kernel
from .simulate import equilibrium, index_sets, straight_guess
from .system import DynamicSystem
from .wind import WindField, WindScenario


@dataclass(frozen=True)
class Mode:
    """One oscillatory (or real) mode of the linearised system.

    eigenvalue (complex) [1/s]; period [s] (inf for a real eigenvalue); damping_ratio [-];
    log_decrement [-]; label ("surge", "heave", "pitch", "tether"); hull_share [-] = fraction
    of the mode's kinetic energy in the body."""

    eigenvalue: complex
    period: float
    damping_ratio: float
    log_decrement: float
    label: str
    hull_share: float


@dataclass(frozen=True, eq=False)
class Linearization:
    """Jacobian A [1/s], its eigenvalues, the modes (slowest first), and ``stable`` (all
    Re(lambda) < tolerance)."""

    jacobian: np.ndarray
    eigenvalues: np.ndarray
    modes: tuple
    stable: bool
    state: np.ndarray

    def rigid_modes(self, min_share: float = 0.3) -> tuple:
        """Oscillatory modes with at least ``min_share`` of their kinetic energy in the body."""
        return tuple(m for m in self.modes if m.hull_share >= min_share and math.isfinite(m.period))

    def rows(self) -> list:
        """Table rows of the rigid-body modes (period [s], damping ratio [-], label)."""
        return [{"mode": m.label, "period_s": m.period, "damping_ratio": m.damping_ratio,
                 "log_decrement": m.log_decrement, "body_energy_share": m.hull_share}
                for m in self.rigid_modes()]


def jacobian(system: DynamicSystem, y: np.ndarray, wind: WindField, t: float = 0.0,
             rel: float = 1e-6) -> np.ndarray:
    """Dense Jacobian df/dy by central differences (step ``rel`` x max(|y|, 1))."""
    data = system.data(wind)
    n = y.size
    jac = np.empty((n, n))
    fp = np.empty(n)
    fm = np.empty(n)
    diag = np.empty(ND)
    for j in range(n):
        h = rel * max(1.0, abs(y[j]))
        yp = y.copy()
        ym = y.copy()
        yp[j] += h
        ym[j] -= h
        rhs_kernel(t, yp, fp, data, diag)
        rhs_kernel(t, ym, fm, data, diag)
        jac[:, j] = (fp - fm) / (2.0 * h)
    return jac


def linearize(system: DynamicSystem, speed: float | None = None, wind: WindField | None = None,
              state: np.ndarray | None = None, guess: np.ndarray | None = None) -> Linearization:
    """Linearise about the static equilibrium in a steady wind.

    Parameters
    ----------
    system : DynamicSystem
    speed : float or None
        Steady wind [m/s] (uniform profile) when ``wind`` is not given.
    wind : WindField or None
        A realised steady wind (profile allowed).
    state : ndarray or None
        The equilibrium state; found with :func:`.simulate.equilibrium` when ``None``.
    guess : ndarray or None
        Starting point of the equilibrium search.

    Returns
    -------
    Linearization
    """
    if wind is None:
        wind = WindScenario.steady(float(speed or 0.0)).realize(system.tether.length, 60.0)
    if state is None:
        g0 = guess if guess is not None else straight_guess(system, wind)
        state, _ = equilibrium(system, wind, g0)
    a = jacobian(system, state, wind)
    lam, vec = np.linalg.eig(a)
    pos, _acc, vel = index_sets(system)
    b = system.hull_index
    # kinetic-energy weights of the velocity components
    wts = np.zeros(system.n_state)
    wts[vel] = system.tether.node_mass
    if system.is_hull:
        mm = system.mass_matrix
        wts[b + 3:b + 6] = np.diag(mm)
    else:
        p = system.body
        wts[b + 2:b + 4] = p.mass + p.added_mass_coefficient * system.atmosphere.density * p.volume
    modes = []
    for k in np.argsort(np.abs(lam.imag) + 1e-9 * np.abs(lam.real)):
        lk = lam[k]
        if lk.imag < -1e-12:
            continue  # keep one of each conjugate pair
        v = vec[:, k]
        e = wts * np.abs(v) ** 2
        tot = float(np.sum(e)) or 1.0
        if system.is_hull:
            share = float(np.sum(e[b + 3:b + 6]) / tot)
            parts = {"surge": e[b + 3], "heave": e[b + 4], "pitch": e[b + 5]}
            # surge/heave in earth axes: use the position amplitudes of O
            ex, ez = abs(v[b]) ** 2, abs(v[b + 1]) ** 2
            lin = e[b + 3] + e[b + 4]
            parts["surge"] = lin * ex / (ex + ez + 1e-300)
            parts["heave"] = lin * ez / (ex + ez + 1e-300)
        else:
            share = float(np.sum(e[b + 2:b + 4]) / tot)
            ex, ez = abs(v[b]) ** 2, abs(v[b + 1]) ** 2
            lin = e[b + 2] + e[b + 3]
            parts = {"surge": lin * ex / (ex + ez + 1e-300),
                     "heave": lin * ez / (ex + ez + 1e-300)}
        label = max(parts, key=parts.get) if share >= 0.3 else "tether"
        mag = abs(lk)
        zeta = float(-lk.real / mag) if mag > 0 else 0.0
        period = float(2 * math.pi / lk.imag) if lk.imag > 1e-12 else math.inf
        logdec = (2 * math.pi * zeta / math.sqrt(max(1e-300, 1 - zeta**2))
                  if abs(zeta) < 1 else math.inf)
        modes.append(Mode(complex(lk), period, zeta, float(logdec), label, share))
    stable = bool(np.all(lam.real < 1e-6 * max(1.0, float(np.max(np.abs(lam))))))
    return Linearization(a, lam, tuple(modes), stable, state)
