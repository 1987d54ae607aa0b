"""Monte Carlo over the model's uncertain inputs: 5-95 % bands and the probability of meeting
each constraint for a built aerostat.

The hull volume, fineness ratio, fins and tether type of the design are held; the inputs below
are drawn per sample from a normal distribution about the design's value (relative or absolute
one-sigma spread), clipped to the input's valid range, and the aerostat is re-evaluated through
the batch evaluator (:func:`aerostat_core.model.airframe.build_airframe` + :func:`evaluate` and
:func:`aerostat_core.model.constraints.constraint_state`, which broadcast over sample arrays).

Default spreads (one sigma) and their sources:

* hull zero-lift (axial) drag C_DV: 15 % relative, as a factor on Hoerner's C_DV(f, Re) at every
  speed - the scatter of measured streamlined-body drag about Hoerner's correlation
  (Hoerner 1965, *Fluid-Dynamic Drag*, ch. 6);
* hull cross-flow drag (C_dc)_h: 20 % relative - the least known term of the Jones & DeLaurier
  model (Jones & DeLaurier 1983, J. Aircraft 20(2); values 0.25-0.45 are fitted to different
  hulls; docs/methods.md §1.7 uses 0.32);
* fin zero-lift drag C_D0: 25 % relative - flat-plate skin friction plus seams and rigging,
  Hoerner 1965 ch. 2 (no aerostat fin measurement found);
* fabric areal density: 5 % relative, hull and fins together (one fabric lot) - the +-5 % weight
  tolerance on coated-fabric data sheets;
* lifting-gas purity: 0.01 absolute, at most 1 - balloon-grade helium is supplied at 97.5-99 %
  and the purity falls between top-ups (Khoury 2012, *Airships and Aerostats*, ch. 4);
* tether normal drag coefficient C_dn: 10 % relative - round cable in cross-flow, 1.0-1.2
  (Hoerner 1965 ch. 3; aerostat_core.structures.materials);
* wind-profile exponent: 0.04 absolute, in [0, 0.6] - the measured 1/7 power-law exponent
  ranges 0.1-0.25 over open terrain with stability (Touma 1977, J. Appl. Meteor. 16, 1303). It
  acts only when the configuration's wind profile is ``"power"`` (a uniform profile has none).

Random numbers come from ``numpy.random.SeedSequence(seed)``, one child per block of ``chunk``
samples, so the result depends on (seed, n, chunk) only, never on where the blocks run
(:mod:`aerostat_core.studies.scale`).
"""

from __future__ import annotations

import copy
from dataclasses import dataclass, replace

import numpy as np

from aerostat_core.base.validation import check_int, check_number
from aerostat_core.model import budget
from aerostat_core.model.airframe import build_airframe
from aerostat_core.model.constraints import NAMES, VECTORISED_NAMES, constraint_state
from aerostat_core.model.design import Design, design
from aerostat_core.model.inputs import RULE_FIELDS, Configuration, Requirement
from aerostat_core.model.performance import evaluate
from aerostat_core.model.presets import rules_configuration
from aerostat_core.model.rules import RULE_NAMES
from aerostat_core.model.statics import axial_drag_coefficient


@dataclass(frozen=True)
class Uncertainty:
    """One uncertain input.

    name : key; label : display name; unit : of the input;
    paths : configuration attributes it sets, e.g. (("aero", "hull_crossflow_drag"),)
        (``("hull_axial_drag_factor",)`` is the factor on Hoerner's C_DV);
    sigma : one-sigma spread; relative : ``sigma`` is a fraction of the design value (else
    absolute, in ``unit``); lo, hi : valid range the samples are clipped to; source : where the
    spread comes from.
    """

    name: str
    label: str
    unit: str
    paths: tuple
    sigma: float
    relative: bool
    lo: float
    hi: float
    source: str


#: The default uncertainties (module docstring gives the sources).
DEFAULT_UNCERTAINTIES: tuple[Uncertainty, ...] = (
    Uncertainty(
        "hull_axial_drag",
        "Hull zero-lift drag C_DV (factor on Hoerner)",
        "-",
        (("hull_axial_drag_factor",),),
        0.15,
        True,
        0.3,
        3.0,
        "Hoerner 1965, Fluid-Dynamic Drag ch. 6: scatter about the correlation",
    ),
    Uncertainty(
        "hull_crossflow_drag",
        "Hull cross-flow drag (C_dc)_h",
        "-",
        (("aero", "hull_crossflow_drag"),),
        0.20,
        True,
        0.0,
        2.0,
        "Jones & DeLaurier 1983: least known term, 0.25-0.45 fitted to hulls",
    ),
    Uncertainty(
        "fin_zero_lift_drag",
        "Fin zero-lift drag C_D0",
        "-",
        (("aero", "fin_zero_lift_drag"),),
        0.25,
        True,
        0.0,
        0.1,
        "Hoerner 1965 ch. 2: flat-plate friction plus seams",
    ),
    Uncertainty(
        "fabric_areal_density",
        "Fabric areal density",
        "kg/m2",
        (("hull_fabric", "areal_density"), ("fin_fabric", "areal_density")),
        0.05,
        True,
        1e-3,
        2.0,
        "coated-fabric data sheets: +-5 % weight tolerance",
    ),
    Uncertainty(
        "purity",
        "Lifting-gas purity",
        "-",
        (("gas", "purity"),),
        0.01,
        False,
        0.5,
        1.0,
        "balloon-grade helium 97.5-99 %, falls between top-ups (Khoury 2012 ch. 4)",
    ),
    Uncertainty(
        "tether_drag",
        "Tether normal drag C_dn",
        "-",
        (("tether", "normal_drag_coefficient"),),
        0.10,
        True,
        0.05,
        3.0,
        "round cable in cross-flow 1.0-1.2 (Hoerner 1965 ch. 3)",
    ),
    Uncertainty(
        "wind_profile_exponent",
        "Wind-profile exponent",
        "-",
        (("wind_profile", "exponent"),),
        0.04,
        False,
        0.0,
        0.6,
        "1/7 law exponent 0.1-0.25 over open terrain (Touma 1977)",
    ),
)
#: Names of the default uncertainties.
UNCERTAINTY_NAMES = tuple(u.name for u in DEFAULT_UNCERTAINTIES)

#: Largest Monte Carlo size in one call (10^8 samples go through a cluster in blocks).
MAX_SAMPLES = 1_000_000_000
#: Default samples per block.
DEFAULT_CHUNK = 2000
#: Percentiles of the bands [%].
PERCENTILES = (5.0, 50.0, 95.0)


def _nominal(cfg: Configuration, path: tuple) -> float:
    if path == ("hull_axial_drag_factor",):
        return 1.0
    obj = cfg
    for p in path:
        obj = getattr(obj, p)
    return float(obj)


def _with(obj, path: tuple, value):
    """Copy of frozen dataclass ``obj`` with the attribute at ``path`` set to ``value`` (an array
    of samples: the dataclass's scalar check is bypassed on purpose, the samples are clipped to
    the same valid range)."""
    new = copy.copy(obj)
    if len(path) == 1:
        object.__setattr__(new, path[0], value)
    else:
        object.__setattr__(new, path[0], _with(getattr(obj, path[0]), path[1:], value))
    return new


def draw(
    cfg: Configuration, specs, n: int, rng: np.random.Generator, spread: float = 1.0
) -> dict[str, np.ndarray]:
    """Samples of every uncertain input, {name: array (n,)}; ``spread`` scales every sigma."""
    out = {}
    for u in specs:
        nom = _nominal(cfg, u.paths[0])
        s = u.sigma * spread * (abs(nom) if u.relative else 1.0)
        z = rng.standard_normal(n)
        out[u.name] = np.clip(nom + s * z, u.lo, u.hi)
    return out


def sampled_configuration(cfg: Configuration, specs, samples: dict, axial=None) -> Configuration:
    """``cfg`` carrying sample arrays of shape (n, 1) (``axial``: C_DV array for
    ``aero.hull_axial_drag``, broadcasting with the evaluation's shape)."""
    c = cfg
    for u in specs:
        for path in u.paths:
            if path == ("hull_axial_drag_factor",):
                continue
            c = _with(c, path, samples[u.name][:, None])
    if axial is not None:
        c = _with(c, ("aero", "hull_axial_drag"), axial)
    return c


def sample_block(
    req: Requirement,
    cfg: Configuration,
    volume: float,
    specs,
    seed,
    n: int,
    speeds,
    spread: float = 1.0,
) -> dict[str, np.ndarray]:
    """Evaluate ``n`` samples (the unit of work :mod:`aerostat_core.studies.scale` maps).

    Parameters
    ----------
    req : Requirement
        Resolved.
    cfg : Configuration
        The design's configuration (hull volume held at ``volume`` [m3]).
    specs : sequence of Uncertainty
    seed : numpy.random.SeedSequence
        This block's seed.
    n : int
    speeds : ndarray, shape (W,)
        Band speeds [m/s], > 0.
    spread : float
        Factor on every sigma.

    Returns
    -------
    dict
        ``blow_by``, ``tension`` (top tension) [m, N], shape (n, W); ``blow_by_design``,
        ``tension_design`` at the design wind, ``free_lift`` [kg], shape (n,); ``met`` (n, K)
        for the constraints of the table; the drawn inputs under their names.
    """
    rng = np.random.default_rng(seed)
    s = draw(cfg, specs, n, rng, spread)
    vol = np.full((n, 1), float(volume))
    # Hoerner's C_DV of the design at each speed (depends on Re only), times the drawn factor
    af0 = build_airframe(req, cfg, float(volume))
    factor = s.get("hull_axial_drag", np.ones(n))[:, None]
    if cfg.aero.hull_axial_drag is None:
        base_w = axial_drag_coefficient(af0, cfg.aero, speeds)
        base_c = axial_drag_coefficient(
            af0, cfg.aero, np.array([req.design_wind, req.survival_wind])
        )
    else:
        base_c = np.full(2, float(cfg.aero.hull_axial_drag))
        base_w = np.full(np.shape(speeds), float(cfg.aero.hull_axial_drag))
    c_w = sampled_configuration(cfg, specs, s, axial=factor * base_w)
    af = build_airframe(req, c_w, vol)
    ev = evaluate(req, c_w, af, speeds)
    c_c = sampled_configuration(cfg, specs, s, axial=(factor[None] * base_c.reshape(2, 1, 1)))
    st = constraint_state(req, c_c, af)
    ev_c = st.evaluation
    # copies, not views: a view (tension_top is the last station of the whole tether march)
    # would keep every segment of the block alive while the samples are kept (100 000 kept
    # samples peaked at 618 MB with views)
    out = {
        "blow_by": np.array(np.asarray(ev.tether.blow_by, float).reshape(n, -1)),
        "tension": np.array(np.asarray(ev.tether.tension_top, float).reshape(n, -1)),
        "blow_by_design": np.array(np.asarray(ev_c.tether.blow_by, float)[0].reshape(n)),
        "tension_design": np.array(np.asarray(ev_c.tether.tension_top, float)[0].reshape(n)),
        "free_lift": np.array((np.asarray(af.free_lift, float) / af.g).reshape(n)),
        "met": np.array(np.asarray(st.met, bool).reshape(n, len(NAMES))),
    }
    out.update({k: v for k, v in s.items()})
    return out


def band_speeds(req: Requirement, n: int = 10) -> np.ndarray:
    """n speeds from wind_max/n to wind_max [m/s] (zero wind has no drag and no band)."""
    return np.linspace(req.wind_max / n, req.wind_max, n)


@dataclass(frozen=True)
class MonteCarloResult:
    """Bands and probabilities of a Monte Carlo run.

    speeds : (W,) [m/s]; blow_by, tension : (3, W) the 5/50/95 % percentiles [m, N];
    free_lift : (3,) [kg] (static: the same at every wind); blow_by_design, tension_design : (3,)
    at the design wind; p_met : {constraint: probability}; p_feasible : every constraint met;
    n, seed, chunk; design_wind [m/s]; specs : the uncertainties used (after ``spread``);
    samples : the raw block outputs concatenated (dict of arrays; empty when the blocks were
    reduced to histograms, ``keep_samples=False``).
    """

    speeds: np.ndarray
    blow_by: np.ndarray
    tension: np.ndarray
    free_lift: np.ndarray
    blow_by_design: np.ndarray
    tension_design: np.ndarray
    p_met: dict
    p_feasible: float
    n: int
    seed: int
    chunk: int
    design_wind: float
    specs: tuple
    samples: dict

    def summary(self) -> dict:
        """The CLI keys: ``blow_by_p05_m``, ``blow_by_p95_m``, ``tension_p05_N``,
        ``tension_p95_N``, ``free_lift_p05_kg``, ``free_lift_p95_kg`` (at the design wind),
        their medians, the probability of meeting each constraint and the sample count."""
        return {
            "blow_by_p05_m": float(self.blow_by_design[0]),
            "blow_by_p50_m": float(self.blow_by_design[1]),
            "blow_by_p95_m": float(self.blow_by_design[2]),
            "tension_p05_N": float(self.tension_design[0]),
            "tension_p50_N": float(self.tension_design[1]),
            "tension_p95_N": float(self.tension_design[2]),
            "free_lift_p05_kg": float(self.free_lift[0]),
            "free_lift_p50_kg": float(self.free_lift[1]),
            "free_lift_p95_kg": float(self.free_lift[2]),
            "probability_met": dict(self.p_met),
            "probability_feasible": self.p_feasible,
            "monte_carlo_samples": self.n,
            "monte_carlo_seed": self.seed,
        }

    def band_rows(self) -> list[dict]:
        """One row per band speed: wind, 5/50/95 % blow-by [m] and tension [N]."""
        rows = []
        for j, u in enumerate(self.speeds):
            rows.append(
                {
                    "wind_speed_m_s": float(u),
                    **{
                        f"blow_by_p{int(p):02d}_m": float(self.blow_by[i, j])
                        for i, p in enumerate(PERCENTILES)
                    },
                    **{
                        f"tension_p{int(p):02d}_N": float(self.tension[i, j])
                        for i, p in enumerate(PERCENTILES)
                    },
                }
            )
        return rows


def monte_carlo(
    d: Design,
    n: int = 10_000,
    seed: int = 0,
    specs=None,
    spread: float = 1.0,
    speeds=None,
    client=None,
    chunk: int = DEFAULT_CHUNK,
    keep_samples: bool | None = None,
) -> MonteCarloResult:
    """Seeded Monte Carlo of the built aerostat ``d`` over the uncertain inputs.

    Parameters
    ----------
    d : Design
    n : int
        Samples, valid [2, 1e9].
    seed : int
        Seed, valid [0, 2^32).
    specs : sequence of Uncertainty, optional
        Default :data:`DEFAULT_UNCERTAINTIES`.
    spread : float
        Factor on every sigma, valid [0, 10] (0: every sample is the design).
    speeds : array_like, optional
        Band speeds [m/s] > 0; default :func:`band_speeds`.
    client : dask.distributed.Client or str, optional
        Map the blocks over a Dask cluster (same result).
    chunk : int
        Samples per block, valid [1, 1e6].
    keep_samples : bool, optional
        Keep every sample (exact percentiles) or reduce each block to histograms
        (:data:`HIST_BINS` bins per output; for runs too large to hold); default: keep up to
        :data:`KEEP_SAMPLES_MAX` samples.

    Returns
    -------
    MonteCarloResult
    """
    from aerostat_core.studies.scale import map_blocks, map_reduce

    n = check_int("monte_carlo", "n", n, 2, MAX_SAMPLES)
    seed = check_int("monte_carlo", "seed", seed, 0, 2**32 - 1)
    chunk = check_int("monte_carlo", "chunk", chunk, 1, 1_000_000)
    spread = check_number("monte_carlo", "spread", spread, 0, 10)
    specs = DEFAULT_UNCERTAINTIES if specs is None else tuple(specs)
    if d.configuration.wind_profile.kind != "power":  # say so where the spread is listed
        specs = tuple(
            replace(u, label=f"{u.label} (no effect: {d.configuration.wind_profile.kind} profile)")
            if u.name == "wind_profile_exponent"
            else u
            for u in specs
        )
    req = d.requirement
    speeds = band_speeds(req) if speeds is None else np.asarray(speeds, float).reshape(-1)
    if speeds.size == 0 or np.any(speeds <= 0) or np.any(speeds > 60):
        raise ValueError("monte_carlo speeds must lie in (0, 60] m/s")
    root = np.random.SeedSequence(seed)

    def block_args():
        # one child seed per block, spawned as the block is made (children are numbered in
        # order, so this equals root.spawn(blocks)): 10^9 samples never hold 10^6 seeds at once
        for start in range(0, n, chunk):
            yield (req, d.configuration, d.volume, specs, root.spawn(1)[0],
                   min(chunk, n - start), speeds, spread)

    keep = n <= KEEP_SAMPLES_MAX if keep_samples is None else bool(keep_samples)
    if client is None:  # in this process: the compute budget (a cluster brings its own)
        budget.check_monte_carlo(d.configuration.tether_segments, speeds.size, n)
    pct = np.array(PERCENTILES)
    if keep:
        blocks = map_blocks(sample_block, list(block_args()), client=client)
        samples = {k: np.concatenate([b[k] for b in blocks]) for k in blocks[0]}
        del blocks
        bands = {k: np.percentile(samples[k], pct, axis=0) for k in BAND_KEYS}
        met_count = samples["met"].sum(axis=0)
        feasible_count = int(samples["met"].all(axis=1).sum())
    else:
        # bins from the first block (run here, so every scheduler uses the same bins), then each
        # block reduced to histograms where it runs and folded in as it arrives: the memory is
        # one block plus one set of histograms at any n
        rest = block_args()
        pilot = sample_block(*next(rest))
        edges = histogram_edges(pilot)
        total = map_reduce(
            sample_reduced,
            ((edges, *a) for a in rest),
            lambda acc, item: add_reduced(acc, item[1]),
            reduce_block(edges, pilot),
            client=client,
        )
        bands = {k: histogram_percentiles(edges[k], total["counts"][k], pct) for k in BAND_KEYS}
        bands = {k: b[:, 0] if pilot[k].ndim == 1 else b for k, b in bands.items()}
        met_count = total["met"]
        feasible_count = int(total["feasible"])
        samples = {}
    return MonteCarloResult(
        speeds=speeds,
        blow_by=bands["blow_by"],
        tension=bands["tension"],
        free_lift=bands["free_lift"],
        blow_by_design=bands["blow_by_design"],
        tension_design=bands["tension_design"],
        p_met={name: float(met_count[k] / n) for k, name in enumerate(NAMES)
               if name in VECTORISED_NAMES},
        p_feasible=feasible_count / n,
        n=n,
        seed=seed,
        chunk=chunk,
        design_wind=float(req.design_wind),
        specs=tuple(replace(u, sigma=u.sigma * spread) for u in specs),
        samples=samples,
    )


#: Outputs with percentile bands (keys of :func:`sample_block`).
BAND_KEYS = ("blow_by", "tension", "free_lift", "blow_by_design", "tension_design")
#: Above this many samples only histograms leave the blocks (a 10^8 run would need ~20 GB of
#: samples, 10^6 peaked at 5.4 GB); below it the samples are kept (about 250 bytes a sample with
#: 10 band speeds) and the percentiles are exact.
KEEP_SAMPLES_MAX = 100_000
#: Histogram bins per output column; the range is the first block's range widened by its span
#: on each side (values beyond go to the end bins), so a bin is ~1/7000 of the spread.
HIST_BINS = 20_000


def histogram_edges(block: dict) -> dict:
    """Bin edges per output column from one block's samples: {key: array (columns, bins + 1)}."""
    out = {}
    for k in BAND_KEYS:
        x = np.asarray(block[k], float).reshape(block[k].shape[0], -1)
        lo, hi = x.min(axis=0), x.max(axis=0)
        span = np.maximum(hi - lo, 1e-9 * np.maximum(np.abs(hi), 1.0))
        out[k] = np.linspace(lo - span, hi + span, HIST_BINS + 1, axis=-1)
    return out


def reduce_block(edges: dict, block: dict) -> dict:
    """Histogram counts per output column, constraint-met counts and feasible count of a block."""
    counts = {}
    for k in BAND_KEYS:
        x = np.asarray(block[k], float).reshape(block[k].shape[0], -1)
        e = edges[k]
        c = np.empty((x.shape[1], HIST_BINS), np.int64)
        for j in range(x.shape[1]):
            i = np.clip(np.searchsorted(e[j], x[:, j], side="right") - 1, 0, HIST_BINS - 1)
            c[j] = np.bincount(i, minlength=HIST_BINS)
        counts[k] = c
    met = np.asarray(block["met"], bool)
    return {"counts": counts, "met": met.sum(axis=0), "feasible": int(met.all(axis=1).sum())}


def add_reduced(acc: dict, part: dict) -> dict:
    """Add the histograms and counts of one reduced block (:func:`reduce_block`) into ``acc``
    (in place) and return it."""
    for k in BAND_KEYS:
        acc["counts"][k] += part["counts"][k]
    acc["met"] = acc["met"] + part["met"]
    acc["feasible"] += int(part["feasible"])
    return acc


def sample_reduced(edges: dict, *args) -> dict:
    """:func:`sample_block` reduced to histograms on the worker (:func:`reduce_block`)."""
    return reduce_block(edges, sample_block(*args))


def histogram_percentiles(edges: np.ndarray, counts: np.ndarray, pct) -> np.ndarray:
    """Percentiles ``pct`` [%] from histograms (columns, bins), linear within a bin; the shape
    of ``np.percentile(x, pct, axis=0)`` for the column layout of the samples."""
    cdf = np.cumsum(counts, axis=1) / counts.sum(axis=1, keepdims=True)
    out = np.empty((len(pct), counts.shape[0]))
    for j in range(counts.shape[0]):
        for i, p in enumerate(pct):
            q = p / 100.0
            b = int(np.searchsorted(cdf[j], q, side="left"))
            c0 = cdf[j][b - 1] if b > 0 else 0.0
            f = (q - c0) / max(cdf[j][b] - c0, 1e-300)
            out[i, j] = edges[j][b] + f * (edges[j][b + 1] - edges[j][b])
    return out


def mission_requirement(req: Requirement, rules: str) -> Requirement:
    """The mission of ``req`` (payload, altitude, site, sweep, power, endurance) under rule set
    ``rules``, with every limit (inputs.RULE_FIELDS) left to that rule set."""
    return replace(req, rules=rules, **{k: None for k in RULE_FIELDS})


def rule_set_spread(req: Requirement, n: int = 2000, seed: int = 0, client=None) -> list[dict]:
    """The same mission sized under every rule set, each with its Monte Carlo bands.

    Returns one row per rule set: rules, volume_m3, design_wind_m_s, blow_by_limit_m, the 5/95 %
    blow-by and tension at that rule set's design wind and free lift, the probability that
    every constraint is met, and the nominal feasibility.
    """
    rows = []
    for r in RULE_NAMES:
        dr = design(mission_requirement(req, r), rules_configuration(r))
        mc = monte_carlo(dr, n=n, seed=seed, client=client)
        s = mc.summary()
        rows.append(
            {
                "rules": r,
                "volume_m3": float(dr.volume),
                "total_mass_kg": float(dr.total_mass),
                "design_wind_m_s": float(dr.requirement.design_wind),
                "blow_by_limit_m": float(dr.requirement.blow_by_limit),
                "blow_by_m": float(dr.design_point["blow_by_m"]),
                **{
                    k: s[k]
                    for k in (
                        "blow_by_p05_m",
                        "blow_by_p95_m",
                        "tension_p05_N",
                        "tension_p95_N",
                        "free_lift_p05_kg",
                        "free_lift_p95_kg",
                    )
                },
                "probability_feasible": s["probability_feasible"],
                "feasible": bool(dr.feasible),
            }
        )
    return rows


# --- verdict: probability of meeting the design margins and the operating limits (issue 22) --
def limits_block(req: Requirement, cfg: Configuration, volume: float, specs, seed, n: int,
                 spread: float = 1.0) -> dict:
    """The constraint table of ``n`` samples at the design margins and at the operating limits
    (:func:`aerostat_core.model.verdict.operating_requirement`), from the same draws as
    :func:`sample_block` with the same seed: {"design": met (n, K), "operating": met (n, K)}."""
    from aerostat_core.model.verdict import operating_requirement

    rng = np.random.default_rng(seed)
    s = draw(cfg, specs, n, rng, spread)
    vol = np.full((n, 1), float(volume))
    af0 = build_airframe(req, cfg, float(volume))
    factor = s.get("hull_axial_drag", np.ones(n))[:, None]
    if cfg.aero.hull_axial_drag is None:
        base_c = axial_drag_coefficient(af0, cfg.aero, np.array([req.design_wind,
                                                                 req.survival_wind]))
    else:
        base_c = np.full(2, float(cfg.aero.hull_axial_drag))
    axial = factor[None] * base_c.reshape(2, 1, 1)
    req_op, cfg_op = operating_requirement(req, cfg)
    c_c = sampled_configuration(cfg, specs, s, axial=axial)
    af = build_airframe(req, c_c, vol)
    out = {"design": np.asarray(constraint_state(req, c_c, af).met, bool).reshape(n, len(NAMES))}
    if req_op is req and cfg_op is cfg:
        out["operating"] = out["design"]
    else:
        c_op = sampled_configuration(cfg_op, specs, s, axial=axial)
        out["operating"] = np.asarray(constraint_state(req_op, c_op, af).met,
                                      bool).reshape(n, len(NAMES))
    return out


def limit_probabilities(d: Design, n: int = 1000, seed: int = 0, specs=None,
                        spread: float = 1.0, chunk: int = DEFAULT_CHUNK) -> dict:
    """Probability that the built aerostat ``d`` meets its design margins and, separately, its
    operating limits, over a seeded sample of the uncertain inputs (:data:`DEFAULT_UNCERTAINTIES`;
    the hull volume and every design choice held).

    Parameters
    ----------
    d : Design
    n : int
        Samples, valid [2, 1e7].
    seed : int
        Valid [0, 2^32).

    Returns
    -------
    dict
        ``design``, ``operating`` [-] (every row met), ``design_by_constraint``,
        ``operating_by_constraint`` ({name: probability}), ``n``, ``seed``.
    """
    n = check_int("limit_probabilities", "n", n, 2, 10_000_000)
    seed = check_int("limit_probabilities", "seed", seed, 0, 2**32 - 1)
    specs = DEFAULT_UNCERTAINTIES if specs is None else tuple(specs)
    req = d.requirement
    sizes = [chunk] * (n // chunk) + ([n % chunk] if n % chunk else [])
    seeds = np.random.SeedSequence(seed).spawn(len(sizes))
    met = {"design": np.zeros(len(NAMES)), "operating": np.zeros(len(NAMES))}
    every = {"design": 0, "operating": 0}
    for s, k in zip(seeds, sizes):
        b = limits_block(req, d.configuration, d.volume, specs, s, k, spread)
        for key in met:
            met[key] += b[key].sum(axis=0)
            every[key] += int(b[key].all(axis=1).sum())
    return {
        "design": every["design"] / n,
        "operating": every["operating"] / n,
        "design_by_constraint": {nm: float(met["design"][i] / n) for i, nm in enumerate(NAMES)
                                 if nm in VECTORISED_NAMES},
        "operating_by_constraint": {nm: float(met["operating"][i] / n)
                                    for i, nm in enumerate(NAMES) if nm in VECTORISED_NAMES},
        "n": n,
        "seed": seed,
    }
