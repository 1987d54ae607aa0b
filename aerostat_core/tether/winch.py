"""Winch and ground handling (thesis §2.2.4): line pull, motor power, drum size, reel time."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True)
class Winch:
    """Winch sized for a tether (SI).

    pull : line pull [N]; speed : reel speed [m/s]; power : motor (input) power [W];
    drum_diameter [m]; drum_length : drum width between flanges [m]; layers : tether layers on
    the drum; reel_time : time to reel the whole tether in [s].
    """

    pull: float
    speed: float
    power: float
    drum_diameter: float
    drum_length: float
    layers: int
    reel_time: float


def size_winch(
    pull: float,
    speed: float,
    efficiency: float,
    tether_length: float,
    tether_diameter: float,
    bend_radius_ratio: float,
    layers: int,
) -> Winch:
    """Winch for a line pull, reel speed and stored tether.

    P = T v / eta; drum core diameter D = 2 R_min = 2 (R_min/d) d; a drum of width W holding n
    layers stores L = pi (W/d) n (D + n d) (layer i on diameter D + (2i - 1) d), so
    W = L d/(pi n (D + n d)); reel-in time t = L/v.

    Parameters
    ----------
    pull : float
        Largest tether tension at the winch over the wind envelope, survival included [N].
    speed : float
        Reel-in/out speed [m/s] (thesis §2.2.4: about 60 ft/min = 0.3048 m/s for DC winches).
    efficiency : float
        Motor x drive efficiency (0, 1].
    tether_length : float
        Stored tether [m].
    tether_diameter : float
        [m].
    bend_radius_ratio : float
        Tether minimum bend radius / diameter [-].
    layers : int
        Layers wound on the drum, >= 1.

    Notes
    -----
    Steady reeling (no acceleration or drum inertia), tension taken equal on every layer; a
    level-wind packs the layers at pitch d. Sources: thesis §2.2.4 (reel speed, drum sized by the
    bend radius, motor power from pull and speed); drum capacity from the wound geometry.

    Examples
    --------
    >>> w = size_winch(1000.0, 0.3048, 0.75, 300.0, 0.005, 10.0, 10)
    >>> round(w.power, 1), round(w.drum_diameter, 3), round(w.reel_time)
    (406.4, 0.1, 984)
    """
    d = float(tether_diameter)
    drum = 2.0 * bend_radius_ratio * d
    n = int(layers)
    width = tether_length * d / (np.pi * n * (drum + n * d))
    return Winch(
        pull=float(pull),
        speed=float(speed),
        power=float(pull) * speed / efficiency,
        drum_diameter=drum,
        drum_length=float(width),
        layers=n,
        reel_time=tether_length / speed,
    )
