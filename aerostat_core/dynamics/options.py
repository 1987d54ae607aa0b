"""Integrator settings and the driver's status codes (shared by :mod:`.simulate` and
:mod:`.results`)."""

from __future__ import annotations

from dataclasses import dataclass

from aerostat_core.base.fields import choice, integer, number, validate

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

    method: str = choice("trbdf2", "Integration method", METHODS)
    rtol: float = number(1e-6, "Relative tolerance", "", 1e-10, 1e-2)
    atol_position: float = number(1e-5, "Absolute tolerance, positions", "m", 1e-12, 1.0)
    atol_velocity: float = number(1e-5, "Absolute tolerance, velocities", "m/s", 1e-12, 1.0)
    atol_angle: float = number(1e-7, "Absolute tolerance, angles", "rad", 1e-12, 1.0)
    initial_step: float = number(1e-3, "Initial step", "s", 1e-9, 10.0)
    max_step: float = number(1.0, "Largest step", "s", 1e-6, 100.0)
    output_interval: float = number(0.1, "Output interval", "s", 1e-3, 10.0)
    max_steps: int = integer(5_000_000, "Step budget", 10, 10**8)
    wall_time_limit: float = number(300.0, "Wall-clock budget", "s", 1e-3, 1e5)
    jacobian_refresh: int = integer(50, "Steps between Jacobian refreshes", 1, 10**4)

    def __post_init__(self) -> None:
        validate(self)
