"""Envelope structure: the internal pressure the hull needs, the membrane stresses it makes and
the fabric strength that carries them (issue 13 item 4; docs/methods.md §1.14).

Where the rules come from: the membrane loads are thin-shell statics; the pressure factor 1.2
and the safety factor 4 have no primary source found (docs/methods.md S18) and are inputs with
those defaults (constants.PRESSURE_DYNAMIC_FACTOR, constants.ENVELOPE_SAFETY_FACTOR).
"""

from __future__ import annotations

import functools

import numpy as np


def required_pressure(q, rho_air, rho_gas, g, diameter, factor):
    """Internal pressure needed at the top of the hull [Pa].

    .. math::

        p_{req} = k_p\\, q + (\\rho_{air} - \\rho_{gas})\\, g\\, d

    p_req = factor q + (rho_air - rho_gas) g d: at least ``factor`` times the dynamic pressure
    at the lowest point of the hull (nose dimpling), plus the hydrostatic gas head, by which
    the pressure difference across the fabric grows from the bottom to the top.

    Parameters
    ----------
    q : array_like
        Dynamic pressure 0.5 rho U^2 [Pa].
    rho_air, rho_gas : array_like
        Air and lifting-gas densities [kg/m3].
    g : float
        [m/s2].
    diameter : array_like
        Hull maximum diameter [m].
    factor : float
        p / q rule [-] (constants.PRESSURE_DYNAMIC_FACTOR, 1.2).

    Notes
    -----
    Valid for a non-rigid, streamlined hull trimmed at small angle of attack (the stagnation
    pressure on the nose is about q); gusts and pitch raise the local pressure, which the
    factor and the fabric safety factor cover. Sources: the head term is the hydrostatics of a
    gas column of height d; the factor 1.2 is the rule of thumb quoted in issue 13, for which
    no primary source was found (constants.PRESSURE_DYNAMIC_FACTOR, docs/methods.md S18), so it
    is an engineering margin over the stagnation pressure q.

    Examples
    --------
    1.2 x 100 Pa + (1.2 - 0.2) x 10 x 4 = 160 Pa (by hand):

    >>> round(float(required_pressure(100.0, 1.2, 0.2, 10.0, 4.0, 1.2)), 1)
    160.0
    """
    head = (np.asarray(rho_air) - np.asarray(rho_gas)) * g * np.asarray(diameter)
    return factor * np.asarray(q, float) + head


def membrane_loads(pressure, radius, moment=0.0):
    """Hoop and longitudinal membrane loads of a pressurised hull section [N/m].

    .. math::

        N_{hoop} = p\\, r, \\qquad N_{long} = \\frac{p\\, r}{2} + \\frac{|M|}{\\pi r^2}

    N_hoop = p r; N_long = p r/2 + |M|/(pi r^2) (thin-walled cylinder of radius r with a
    bending moment M about the section: the hoop and axial membrane loads of a closed pressure
    vessel, and the peak axial load M/(pi r^2) of a thin circular section in bending, of
    second moment pi r^3 per unit wall thickness). Source: thin-shell statics, derived here;
    no airship text was available to cross-check it.

    Valid for a thin membrane (fabric thickness << r), away from the nose and tail caps and the
    fin and confluence-line attachments (local patches carry those loads).

    Parameters
    ----------
    pressure : array_like
        Pressure difference across the fabric [Pa].
    radius : array_like
        Section radius [m] (the hull's maximum radius is the critical section for hoop load).
    moment : array_like
        Bending moment at the section [N m].

    Returns
    -------
    n_hoop, n_long : ndarray
        Hoop and longitudinal membrane loads [N/m].

    Examples
    --------
    200 Pa in a 2 m radius: p r = 400 N/m, p r/2 = 200 N/m (by hand):

    >>> [float(x) for x in membrane_loads(200.0, 2.0)]
    [400.0, 200.0]
    """
    p, r = np.asarray(pressure, float), np.asarray(radius, float)
    return p * r, 0.5 * p * r + np.abs(np.asarray(moment, float)) / (np.pi * r**2)


def allowable_pressure(strength, safety_factor, radius, moment=0.0):
    """Largest pressure the fabric carries with the safety factor [Pa].

    .. math::

        p_{allow} = \\min\\left(\\frac{F}{SF\\, r},\\;
        \\frac{2}{r}\\left(\\frac{F}{SF} - \\frac{|M|}{\\pi r^2}\\right)\\right)

    From N_hoop and N_long <= F/SF: p <= F/(SF r) and p <= 2 (F/SF - |M|/(pi r^2))/r.

    Parameters
    ----------
    strength : float
        Fabric tensile strength F [N/m] (the weaker warp/fill direction).
    safety_factor : float
        [-] (default 4, constants.ENVELOPE_SAFETY_FACTOR: attributed to Carichner & Nicolai,
        unverified).
    radius : array_like
        [m].
    moment : array_like
        [N m].

    Notes
    -----
    Valid with the thin-membrane loads of :func:`membrane_loads`; a bending moment larger than
    pi r^2 F/SF makes the allowable pressure negative (the hull creases whatever the pressure).
    Source: thin-shell statics (:func:`membrane_loads`); docs/methods.md §1.14.
    """
    r = np.asarray(radius, float)
    n = float(strength) / float(safety_factor)
    hoop = n / r
    long = 2.0 * (n - np.abs(np.asarray(moment, float)) / (np.pi * r**2)) / r
    return np.minimum(hoop, long)


# --- the hull as a pressurised beam (issue 22 item 5; docs/methods.md §1.17) ---------------
#: Stations along the hull of the beam model (the shear and moment integrals).
BEAM_STATIONS = 25
#: Share of the hull length over which the confluence lines spread the tether's pull [-], a hat
#: centred on the centre of buoyancy: engineering choice (the patch lines of tactical aerostats
#: span about a third of the hull; a point load would be the conservative limit).
CONFLUENCE_SPAN = 1.0 / 3.0
#: Sections checked for wrinkling: radius at least this share of the largest [-].
WRINKLE_MIN_RADIUS = 0.5


def wrinkling_moment(pressure, radius):
    r"""Bending moment at which a pressurised circular envelope section starts to wrinkle [N m].

    M_w = pi p r^3 / 2: the axial membrane tension of the pressure, p r / 2 per unit length of
    circumference, is cancelled on the compression side by the bending load M / (pi r^2) (thin
    circular section of second moment pi r^3 per unit wall thickness). Past M_w that side
    carries no tension and the fabric folds; the collapse moment of a fabric tube is about twice
    this (Comer & Levy 1963, AIAA J. 1(7)), so M_w is the onset, the design value. Source:
    Carichner & Nicolai (2013), *Fundamentals of Aircraft and Airship Design* vol. 2, envelope
    structure (the wrinkling criterion of non-rigid airship practice, Burgess 1927 *Airship
    Design* ch. 9).

    .. math:: M_w = \frac{\pi p r^3}{2}

    Valid for a thin circular section of an inflated envelope (p >= 0, r > 0), up to the onset
    of wrinkling.

    Parameters
    ----------
    pressure : array_like
        Pressure difference across the fabric at the section [Pa], >= 0.
    radius : array_like
        Section radius [m], > 0.

    Examples
    --------
    >>> round(float(wrinkling_moment(200.0, 2.0)), 1)  # pi 200 8 / 2
    2513.3
    """
    return 0.5 * np.pi * np.asarray(pressure, float) * np.asarray(radius, float) ** 3


def beam_moment(x, load, point_loads=(), couples=()):
    r"""Bending moment along a free-free beam in equilibrium [N m] (pure function).

    V(x) = int_0^x w dx' + sum_i P_i H(x - x_i); M(x) = int_0^x V dx' + sum_j C_j H(x - x_j),
    by the trapezoid rule on the stations ``x``. Loads from a simplified distribution do not
    close exactly: the force residual is the caller's (it sets the reaction), and the moment
    residual at the tail, M(L), is removed as a linear ramp M(x) - M(L) x / L (the "closing"
    of airship load curves, Burgess 1927 ch. 9), so M(0) = M(L) = 0.

    .. math:: V(x) = \int_0^x w\,dx' + \sum_i P_i H(x - x_i), \quad
              M(x) = \int_0^x V\,dx' + \sum_j C_j H(x - x_j)

    Valid for a slender free-free beam in static equilibrium (stations increasing from the
    nose). Source: Burgess (1927) *Airship Design* ch. 9; docs/methods.md §1.17.

    Parameters
    ----------
    x : ndarray, shape (N, ...)
        Stations from the nose [m], increasing along the first axis.
    load : ndarray, shape (N, ...)
        Distributed load normal to the axis [N/m] (positive up).
    point_loads : sequence of (P, x_P)
        Point loads [N] (positive up) at stations [m] (arrays broadcast with x[0]).
    couples : sequence of (C, x_C)
        Point couples [N m] (nose-up positive) at stations [m].

    Returns
    -------
    ndarray, shape of ``x``

    Examples
    --------
    A uniform load w on a beam of length L held by a point load -wL at mid-length: the largest
    moment is w L^2 / 8.

    >>> x = np.linspace(0.0, 2.0, 201)
    >>> m = beam_moment(x, np.ones_like(x), [(-2.0, 1.0)])
    >>> round(float(np.abs(m).max()), 4)
    0.5
    """
    x = np.asarray(x, float)
    dx = np.diff(x, axis=0)
    w = np.asarray(load, float)
    v = np.concatenate([np.zeros_like(w[:1]), np.cumsum(0.5 * (w[1:] + w[:-1]) * dx, axis=0)])
    m = np.concatenate([np.zeros_like(v[:1]), np.cumsum(0.5 * (v[1:] + v[:-1]) * dx, axis=0)])
    for p, xp in point_loads:
        m = m + np.asarray(p, float) * np.maximum(x - np.asarray(xp, float), 0.0)
    for c, xc in couples:
        m = m + np.asarray(c, float) * (x >= np.asarray(xc, float))
    span = x[-1] - x[0]
    return m - m[-1] * (x - x[0]) / np.where(span > 0, span, 1.0)


def envelope_loads(af, cfg, ev, stations: int = BEAM_STATIONS) -> dict:
    r"""Pressure, membrane loads, bending and wrinkling moments of the envelope, the hull taken as
    a pressurised beam at the trim of an evaluation (Carichner & Nicolai 2013 vol. 2; Burgess
    1927 ch. 9; docs/methods.md §1.17).

    Loads normal to the hull axis, along ``stations`` stations from nose to tail:

    * net buoyancy of the gas (rho_air - rho_gas) g A(x) cos(alpha), A the section area;
    * the envelope fabric weight, the hull item mass spread over the perimeter 2 pi r(x);
    * the fins, payload and every other item as point weights at their stations;
    * the aerodynamic load along the hull in the shapes of Jones & DeLaurier: the potential-flow
      (Munk) part, proportional to sin(2 alpha) dA/dx, ahead of the viscous cut-off station, the
      cross-flow part, proportional to r(x), aft of it; the two scaled so that their force and
      moment are the model's own hull normal force and couple (Jones & DeLaurier forces,
      what the trim balanced);
    * the fin lift (aerodynamics.fin_lift_drag) at the fin aerodynamic centre;
    * the confluence lines: the tether's pull enters the hull along the patch line of the
      lines (a hat of base :data:`CONFLUENCE_SPAN` of the hull length on the centre of
      buoyancy; the confluence point itself lies below the hull, often ahead of the nose). Its
      resultant is what closes the balance of all the other loads: a uniform part, the force,
      and a linear part, the moment (the fore and aft lines pull unequally, and their
      horizontal pull acts below the axis, so that the resultant passes through the confluence
      point). So M(0) = M(L) = 0 without a closing ramp.

    The hull's pressure (at the top) is the largest of what it needs against nose dimpling
    (:func:`required_pressure`), what keeps the governing section from wrinkling (the pressure
    whose M_w is the bending moment there, times the same factor, plus the gas head from the
    section's centre to the top) and the gas superpressure: the pressure is chosen to prevent
    wrinkling and the fabric is then sized for it (Carichner & Nicolai 2013). Whether the fabric
    can carry a pressure that high is the constraint table's wrinkling row
    (:func:`aerostat_core.model.mission.structure_quantities`). The governing section is where
    |M| / r^3 is largest among the sections of radius at least :data:`WRINKLE_MIN_RADIUS` of the
    largest (the nose and tail caps carry their loads as shells of double curvature, not as a
    beam).

    .. math:: N_x = \frac{p r}{2} + \frac{|M(x)|}{\pi r^2}, \quad
              p \ge \frac{2 M}{\pi r^3} + \rho_g g\,r

    Valid for a streamlined, pressurised hull at incidences where the trim of ``ev`` holds.
    Source: Carichner & Nicolai (2013) vol. 2; Burgess (1927) ch. 9; docs/methods.md §1.17.

    Parameters
    ----------
    af : Airframe
    cfg : Configuration
        ``cfg.aero`` (efficiency, cross-flow drag), ``cfg.mission.pressure_dynamic_factor``,
        ``cfg.gas.superpressure``.
    ev : Evaluation
        Trim and tether at the speed(s) of interest (arrays broadcast over designs and speeds).
    stations : int
        Stations of the integrals [-], >= 11.

    Returns
    -------
    dict of ndarray (the broadcast shape of designs and speeds)
        ``pressure`` [Pa] (top of the hull, the largest of the three needs),
        ``pressure_dimpling``, ``pressure_wrinkling`` [Pa] (the two needs), ``hoop_load``
        p r_max [N/m], ``longitudinal_load`` [N/m] (largest p r/2 + |M|/(pi r^2) along the
        hull), ``bending_moment`` [N m] (largest |M(x)|), ``wrinkling_moment`` [N m]
        (pi p r^3 / 2 at the governing section, at the section's mean pressure),
        ``moment_at_governing`` [N m], ``governing_station`` [m from the nose],
        ``governing_radius`` [m], ``head`` [Pa] (gas head from the axis to the top).

    Notes
    -----
    The loop along the stations runs compiled (:func:`aerostat_core.structures.beam_kernel.
    envelope_beam`, every design and speed in one call); :func:`_envelope_loads_plain` is the
    same arithmetic in numpy, kept as the reference definition (tests/core/test_fast_paths.py
    checks the two agree).
    """
    from aerostat_core.geometry.shapes import SHAPE_INFO

    h, g = af.hull, af.g
    alpha = np.asarray(ev.equilibrium.alpha, float)
    speed = np.asarray(ev.speed, float)
    q = 0.5 * af.air_density * speed**2
    shape = np.broadcast_shapes(np.shape(alpha), np.shape(q), np.shape(h.length))
    t, wts = _stations(max(int(stations), 11), len(shape))
    ns = wts.size
    length = np.asarray(h.length, float)
    x = t * length
    r = h.radius_at(x)
    ca = np.cos(alpha)
    drho = af.air_density - af.gas_density
    streamlined = SHAPE_INFO[h.shape].streamlined
    lift_h = hull_moment = sin2a = 0.0
    if streamlined:
        lift_h, hull_moment, fin_lift = _aero_loads(af, cfg, q, alpha)
        sin2a = np.sin(2.0 * alpha)
    points = _item_weights(af, g, ca)
    if streamlined:
        points.append((fin_lift * ca, af.fins.xi_ac))
    factor = cfg.mission.pressure_dynamic_factor
    p_dimple = required_pressure(q, af.air_density, af.gas_density, g, h.diameter, factor)
    cols = [length, h.b, af.xi_m, h.xi_cb, af.cutoff_station, drho, ca,
            af.mass.items["hull"], sin2a, lift_h, hull_moment, p_dimple]
    npt = len(points)
    cols += [p for p, _ in points] + [xp for _, xp in points]
    full = np.broadcast_shapes(shape, np.shape(x)[1:], np.shape(r)[1:],
                               *(np.shape(a) for a in cols))
    n = int(np.prod(full, dtype=int))
    # every per-column input broadcast into one C-ordered buffer (one assignment each)
    buf = np.empty((len(cols),) + full)
    for i, a in enumerate(cols):
        buf[i] = a
    c = buf.reshape(len(cols), n)
    xs = np.empty((2, ns) + full)
    xs[0], xs[1] = x, r
    xs = xs.reshape(2, ns, n)
    out = _envelope_beam()(
        xs[0], xs[1], wts, *c[:6], float(g), *c[6:11], c[12:12 + npt], c[12 + npt:],
        bool(streamlined), float(CONFLUENCE_SPAN), float(WRINKLE_MIN_RADIUS), c[11],
        float(factor), float(cfg.gas.superpressure))
    m_gov, r_gov, x_gov, p_wrinkle, p_top, n_long, bend = (a.reshape(full) for a in out)
    head = drho * g * h.b  # top of the hull less the section's mean
    return {
        "pressure": np.broadcast_to(p_top, shape),
        "pressure_dimpling": np.broadcast_to(p_dimple, shape),
        "pressure_wrinkling": np.broadcast_to(p_wrinkle, shape),
        "hoop_load": np.broadcast_to(p_top * h.b, shape),
        "longitudinal_load": n_long,
        "bending_moment": bend,
        "wrinkling_moment": wrinkling_moment(np.maximum(p_top - head, 0.0), r_gov),
        "moment_at_governing": m_gov,
        "governing_station": x_gov,
        "governing_radius": r_gov,
        "head": np.broadcast_to(head, shape),
    }


def _aero_loads(af, cfg, q, alpha):
    """The model's own hull normal force N_h = N_i + N_c [N], hull couple M_i + M_c [N m]
    (Jones & DeLaurier: potential flow and cross-flow, aerodynamics.forces) and fin lift [N]
    at dynamic pressure ``q`` [Pa] and angle of attack ``alpha`` [rad]: what the trim
    balanced, and what the beam's distributed aerodynamic load must add up to."""
    from aerostat_core.aerodynamics.forces import fin_lift_drag, hull_crossflow, hull_inviscid

    h, ae, fn = af.hull, cfg.aero, af.fins
    n_i, _, m_i = hull_inviscid(q, alpha, h.k2 - h.k1, ae.hull_efficiency, af.i1, af.i3)
    n_c, m_c = hull_crossflow(q, alpha, ae.hull_crossflow_drag, af.j1, af.j2)
    fin_lift = fin_lift_drag(q, alpha, fn.lift_slope, ae.fin_efficiency,
                             np.radians(ae.fin_stall_angle_deg), fn.lifting_area,
                             fn.area_total, ae.fin_zero_lift_drag, fn.aspect_ratio,
                             fn.oswald)[0]
    return n_i + n_c, m_i + m_c, fin_lift


def _item_weights(af, g, ca):
    """The carried items as point loads normal to the axis: [(-m g cos(alpha) [N], x [m])],
    the items at one station (payload, miscellaneous, battery and ballonet under the centre of
    buoyancy) summed into one load; the hull, gas and tether are distributed, not points."""
    positions = af.mass.positions
    at: dict = {}
    for k, m in af.mass.items.items():
        if k in ("hull", "lifting gas", "tether") or k not in positions:
            continue
        xk = positions[k][0]
        key = id(xk)
        at[key] = (at[key][0] + np.asarray(m), xk) if key in at else (np.asarray(m), xk)
    return [(-m * g * ca, xk) for m, xk in at.values()]


@functools.lru_cache(maxsize=16)
def _stations(ns: int, ndim: int):
    """Station fractions 0..1 (shape (ns,) + (1,) * ndim) and trapezoid weights (1/2 at the
    ends) of :func:`envelope_loads`, built once per size (the fractions read-only; the weights
    are only read, by the compiled kernel, which takes writable arrays)."""
    t = np.linspace(0.0, 1.0, ns).reshape((-1,) + (1,) * ndim)
    wts = np.ones(ns)
    wts[0] = wts[-1] = 0.5
    t.flags.writeable = False
    return t, wts


def _envelope_beam():
    """The compiled kernel of :func:`envelope_loads`
    (:func:`aerostat_core.structures.beam_kernel.envelope_beam`), imported on the first call so
    that importing the library does not import numba."""
    from aerostat_core.structures.beam_kernel import envelope_beam

    return envelope_beam


def _envelope_loads_plain(af, cfg, ev, stations: int = BEAM_STATIONS) -> dict:
    """:func:`envelope_loads` in numpy, the reference definition of the compiled kernel (the
    same equations, arguments and result; docs/methods.md §1.17)."""
    from aerostat_core.geometry.shapes import SHAPE_INFO

    h, g = af.hull, af.g
    alpha = np.asarray(ev.equilibrium.alpha, float)
    speed = np.asarray(ev.speed, float)
    q = 0.5 * af.air_density * speed**2
    shape = np.broadcast_shapes(np.shape(alpha), np.shape(q), np.shape(h.length))
    # the geometry once per hull (not per speed): stations, radius, area and its slope
    t = np.linspace(0.0, 1.0, max(int(stations), 11)).reshape((-1,) + (1,) * len(shape))
    length = np.asarray(h.length, float)
    x = t * length
    r = np.broadcast_to(h.radius_at(x), x.shape)
    area = np.pi * r**2
    dx = length / (t.shape[0] - 1)
    wts = np.ones_like(t)
    wts[0] = wts[-1] = 0.5

    def integral(a):  # trapezoid rule on the uniform stations
        return (wts * a).sum(axis=0) * dx

    d_area = np.gradient(area, axis=0) / np.maximum(dx, 1e-12)
    per = 2.0 * np.pi * r
    per_int = np.maximum(integral(per), 1e-12)
    ca = np.cos(alpha)
    drho = af.air_density - af.gas_density
    load = drho * g * area * ca
    load = load - np.asarray(af.mass.items["hull"]) * g * ca * per / per_int
    streamlined = SHAPE_INFO[h.shape].streamlined
    couples = []
    if streamlined:
        # the hull's aerodynamic load along it: the Jones & DeLaurier shapes (potential flow
        # ahead of the cut-off station, cross-flow aft of it), scaled so that their force and
        # moment are the model's own hull lift and couple (what the trim balanced)
        # the model's hull normal force and couple (Jones & DeLaurier), and the fin lift
        lift_h, hull_moment, fin_lift = _aero_loads(af, cfg, q, alpha)
        ahead = x <= af.cutoff_station
        shape_1 = np.where(ahead, np.sin(2.0 * alpha) * d_area, 0.0)
        shape_2 = np.where(ahead, 0.0, 2.0 * r * np.ones_like(alpha))
        arm = x - af.xi_m
        f1, f2 = integral(shape_1), integral(shape_2)
        m1, m2 = integral(shape_1 * arm), integral(shape_2 * arm)
        couple_h = -hull_moment  # the moment of upward loads
        det = f1 * m2 - f2 * m1
        ok = np.abs(det) > 1e-9 * (np.abs(f1 * m2) + np.abs(f2 * m1) + 1e-30)
        safe = np.where(ok, det, 1.0)
        s1 = np.where(ok, (lift_h * m2 - f2 * couple_h) / safe, 0.0)
        s2 = np.where(ok, (f1 * couple_h - m1 * lift_h) / safe, 0.0)
        load = load + s1 * shape_1 + s2 * shape_2
        # where the two shapes cannot carry it (alpha ~ 0), the hull load as a force and couple
        couples.append((np.where(ok, 0.0, hull_moment), af.xi_m))
        hull_point = (np.where(ok, 0.0, lift_h), af.xi_m)
    # the carried items as point weights (those at one station, as the payload, miscellaneous,
    # battery and ballonet under the centre of buoyancy, summed into one load)
    points = _item_weights(af, g, ca)
    if streamlined:
        points.append((fin_lift * ca, af.fins.xi_ac))
        points.append(hull_point)
    # the confluence lines' reaction closes the balance: its force the residual force, spread
    # over their patch line (a hat of base CONFLUENCE_SPAN of the hull length on the centre of
    # buoyancy, where the patches of the lines sit), with a linear part that carries the moment
    # (the fore and aft lines pull unequally so that the resultant passes through the
    # confluence point, as they do to hold the trim)
    patch = np.maximum(1.0 - np.abs(x - h.xi_cb) / (0.5 * CONFLUENCE_SPAN * length), 0.0)
    w0 = np.maximum(integral(patch), 1e-12)
    x_bar = integral(patch * x) / w0
    w2 = np.maximum(integral(patch * (x - x_bar) ** 2), 1e-12)
    force = integral(load) + sum(np.asarray(p) for p, _ in points)
    first = integral(load * x) + sum(np.asarray(p) * np.asarray(xp) for p, xp in points)
    c = sum(np.asarray(cc) for cc, _ in couples) - first + force * x_bar
    load = load - force * patch / w0 + c * (x - x_bar) * patch / w2
    moment = beam_moment(x, load, points, couples)
    rr = np.maximum(r, 1e-3 * h.b)
    head = drho * g * h.b  # top of the hull less the section's mean
    # governing section: the largest |M| / r^3 (the pressure is uniform along the hull)
    ratio = np.where(r >= WRINKLE_MIN_RADIUS * h.b, np.abs(moment) / rr**3, 0.0)
    ratio = np.broadcast_to(ratio, np.broadcast_shapes(ratio.shape, np.shape(moment)))
    k = np.argmax(ratio, axis=0)[None]
    full = np.shape(moment)

    def take(a):
        return np.take_along_axis(np.broadcast_to(a, full), k, axis=0)[0]

    m_gov, r_gov = take(np.abs(moment)), take(rr)
    factor = cfg.mission.pressure_dynamic_factor
    p_dimple = required_pressure(q, af.air_density, af.gas_density, g, h.diameter, factor)
    # the pressure that keeps the governing section from wrinkling, with the same factor
    p_wrinkle = factor * 2.0 * m_gov / (np.pi * r_gov**3) + head
    p_top = np.maximum(np.maximum(p_dimple, p_wrinkle), cfg.gas.superpressure)
    n_long = 0.5 * p_top * rr + np.abs(moment) / (np.pi * rr**2)
    return {
        "pressure": np.broadcast_to(p_top, shape),
        "pressure_dimpling": np.broadcast_to(p_dimple, shape),
        "pressure_wrinkling": np.broadcast_to(p_wrinkle, shape),
        "hoop_load": np.broadcast_to(p_top * h.b, shape),
        "longitudinal_load": n_long.max(axis=0),
        "bending_moment": np.abs(moment).max(axis=0),
        "wrinkling_moment": wrinkling_moment(np.maximum(p_top - head, 0.0), r_gov),
        "moment_at_governing": m_gov,
        "governing_station": take(x),
        "governing_radius": r_gov,
        "head": np.broadcast_to(head, shape),
    }
