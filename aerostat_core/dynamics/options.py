"""Integrator settings and the driver's status codes (shared by :mod:`.simulate` and
:mod:`.results`)."""

from __future__ import annotations

import math
from dataclasses import dataclass

#: Extra status codes of the driver.
STATUS_DRIVER = {
    8: "wall-clock budget exceeded",
    9: "step budget exhausted",
    10: "scipy solver failed",
}
METHODS = ("trbdf2", "Radau", "BDF", "LSODA")
#: Largest output grid (states + diagnostics) a run may allocate [bytes].
MAX_OUTPUT_BYTES = 256 * 2**20


@dataclass(frozen=True)
class SolverOptions:
    """Integrator settings.

    Parameters
    ----------
    method : {"trbdf2", "Radau", "BDF", "LSODA"}
        "trbdf2": the compiled L-stable integrator of :mod:`.solver` (default, fast).
        Others: ``scipy.integrate.solve_ivp`` with the same compiled right-hand side and a banded
        Jacobian (cross-checks, V6).
    rtol : float
        Relative tolerance [-], valid [1e-10, 1e-2].
    atol_position, atol_velocity : float
        Absolute tolerances on positions [m] and velocities [m/s], valid [1e-12, 1].
    atol_angle : float
        Absolute tolerance on pitch [rad] and pitch rate [rad/s], valid [1e-12, 1].
    initial_step, max_step : float
        [s]; ``max_step`` valid (0, 100].
    output_interval : float
        Sampling of the time histories [s], valid [1e-3, 10]. The output grid (duration /
        output_interval samples of the state and diagnostics) must fit in ``MAX_OUTPUT_BYTES``.
    max_steps : int
        Step budget of the whole run, valid [10, 1e8].
    wall_time_limit : float
        Wall-clock budget [s], valid (0, 1e5]; the run stops with status 8 beyond it (checked
        between chunks of integration sized to last about 0.2 s each).
    jacobian_refresh : int
        Refresh the Jacobian at least every this many accepted steps, valid [1, 10000].
    """

    method: str = "trbdf2"
    rtol: float = 1e-6
    atol_position: float = 1e-5
    atol_velocity: float = 1e-5
    atol_angle: float = 1e-7
    initial_step: float = 1e-3
    max_step: float = 1.0
    output_interval: float = 0.1
    max_steps: int = 5_000_000
    wall_time_limit: float = 300.0
    jacobian_refresh: int = 50

    def __post_init__(self) -> None:
        if self.method not in METHODS:
            raise ValueError(f"SolverOptions.method = {self.method!r}; valid options {METHODS}")
        for name, lo, hi in (
            ("rtol", 1e-10, 1e-2),
            ("atol_position", 1e-12, 1.0),
            ("atol_velocity", 1e-12, 1.0),
            ("atol_angle", 1e-12, 1.0),
            ("initial_step", 1e-9, 10.0),
            ("max_step", 1e-6, 100.0),
            ("output_interval", 1e-3, 10.0),
            ("max_steps", 10, 1e8),
            ("wall_time_limit", 1e-3, 1e5),
            ("jacobian_refresh", 1, 1e4),
        ):
            v = getattr(self, name)
            if not isinstance(v, (int, float)) or not math.isfinite(v) or v < lo or v > hi:
                raise ValueError(
                    f"SolverOptions.{name} = {v!r} is outside the valid range [{lo:g}, {hi:g}]"
                )
