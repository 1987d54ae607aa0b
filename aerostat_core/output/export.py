"""Geometry for the people who build the aerostat: STL meshes and gore cutting patterns.

* :func:`hull_mesh` / :func:`fin_meshes` / :func:`stl_bytes`: a watertight triangle mesh of the
  hull (surface of revolution of the shape's profile, outward normals) and of every fin (the
  engine's trapezoidal planform as a slab), written as binary STL with numpy-stl. The thesis
  checked mass and CG against a SolidWorks model (Appendix E); tests/core/test_export.py re-reads
  the mesh and recovers the hull's volume, area and centre of volume within 0.5 %.
* :func:`gore_pattern`: flat patterns of N identical gores. A gore spans 2 pi / N of azimuth, so
  along the meridian arc length s its half-width is w(s) = pi r(s) / N (the arc of the circle of
  radius r it covers, halved); the N gores add up to the hull area,
  N int 2 w ds = 2 pi int r ds = S. The cut line adds a seam allowance outside the seam line.
  Fin patterns: two faces per fin, the planform trapezoid. Written as DXF (ezdxf), SVG and a CSV
  of half-widths along the seam.

Units: metres in the meshes, DXF (``$INSUNITS`` = metres) and CSV; millimetres in the SVG.
"""

from __future__ import annotations

import io
import math
from dataclasses import dataclass

import numpy as np

from aerostat_core.geometry.fins import ARRANGEMENT_ANGLES_DEG
from aerostat_core.model.design import Design

#: Fin slab thickness in the STL / root chord [-]. ASSUMED: inflated fins of t/c 0.12-0.20
#: (docs/methods.md §1.5); the engine models the fin as a flat planform.
FIN_THICKNESS_RATIO = 0.12


def _f(x) -> float:
    return float(np.asarray(x, dtype=float).reshape(-1)[0])


def _stations(d: Design, n: int) -> tuple[np.ndarray, np.ndarray]:
    """Cosine-spaced stations xi [m] (denser at nose and tail) and radii r(xi) [m]."""
    h = d.airframe.hull
    length = _f(h.length)
    xi = 0.5 * length * (1.0 - np.cos(np.linspace(0.0, np.pi, n)))
    r = np.asarray(h.radius_at(xi), dtype=float).reshape(-1)
    r[0] = r[-1] = 0.0
    return xi, r


def hull_mesh(d: Design, n_stations: int = 161, n_azimuth: int = 144) -> np.ndarray:
    """Triangles (n, 3, 3) [m] of the hull surface: body frame, x aft from the nose, y starboard,
    z up; nose and tail closed by single vertices; outward normals (right-hand rule)."""
    xi, r = _stations(d, n_stations)
    phi = np.linspace(0.0, 2.0 * np.pi, n_azimuth, endpoint=False)
    ring = np.stack(
        [
            np.broadcast_to(xi[:, None], (xi.size, phi.size)),
            r[:, None] * np.cos(phi),
            r[:, None] * np.sin(phi),
        ],
        axis=-1,
    )
    j0 = np.arange(phi.size)
    j1 = (j0 + 1) % phi.size
    a, b = ring[:-1][:, j0], ring[:-1][:, j1]
    c, e = ring[1:][:, j0], ring[1:][:, j1]
    t1 = np.stack([a, b, e], axis=2)[1:]  # skip degenerate triangles at the nose apex
    t2 = np.stack([a, e, c], axis=2)[:-1]  # and at the tail apex
    return np.concatenate([t1.reshape(-1, 3, 3), t2.reshape(-1, 3, 3)], axis=0)


def fin_meshes(d: Design) -> np.ndarray:
    """Triangles (n, 3, 3) [m] of all fins: each the engine's planform (root LE and TE on the
    hull surface, swept tip) as a slab FIN_THICKNESS_RATIO x root chord thick; empty for
    finless (bluff) hulls."""
    f, h = d.airframe.fins, d.airframe.hull
    rc = _f(f.root_chord)
    if rc <= 0.0 or _f(f.area_total) <= 0.0:
        return np.zeros((0, 3, 3))
    le, tc, span = _f(f.xi_root_le), _f(f.tip_chord), _f(f.span)
    tan_le = math.tan(_f(f.sweep_le))
    r_le, r_te = _f(h.radius_at(le)), _f(h.radius_at(le + rc))
    r_tip = _f(h.radius_at(le + 0.5 * rc)) + span
    tip_le = le + span * tan_le
    quad = [(le, r_le), (le + rc, r_te), (tip_le + tc, r_tip), (tip_le, r_tip)]
    half_t = 0.5 * FIN_THICKNESS_RATIO * rc
    faces = [(0, 1, 2), (0, 2, 3)]
    out = []
    for ang in np.radians(ARRANGEMENT_ANGLES_DEG[d.configuration.fins.arrangement]):
        radial = np.array([0.0, math.cos(ang), math.sin(ang)])
        normal = np.array([0.0, -math.sin(ang), math.cos(ang)])
        top = np.array([[x, 0, 0] + rr * radial + half_t * normal for x, rr in quad])
        bot = np.array([[x, 0, 0] + rr * radial - half_t * normal for x, rr in quad])
        tris = [top[list(t)] for t in faces] + [bot[[t[0], t[2], t[1]]] for t in faces]
        for k in range(4):  # side walls
            k2 = (k + 1) % 4
            tris.append(np.array([bot[k], bot[k2], top[k2]]))
            tris.append(np.array([bot[k], top[k2], top[k]]))
        tri = np.array(tris)
        # orient every triangle outward from the slab centre
        centre = 0.5 * (top.mean(axis=0) + bot.mean(axis=0))
        nrm = np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0])
        flip = np.einsum("ij,ij->i", nrm, tri.mean(axis=1) - centre) < 0
        tri[flip] = tri[flip][:, [0, 2, 1]]
        out.append(tri)
    return np.concatenate(out, axis=0)


def stl_bytes(triangles: np.ndarray, name: str = "aerostat") -> bytes:
    """Binary STL of triangles (n, 3, 3) [m] (numpy-stl)."""
    from stl import mesh

    m = mesh.Mesh(np.zeros(triangles.shape[0], dtype=mesh.Mesh.dtype))
    m.vectors[:] = triangles
    m.update_normals()
    buf = io.BytesIO()
    m.save(name, fh=buf, mode=mesh.stl.Mode.BINARY)
    return buf.getvalue()


def design_stl(d: Design, part: str = "all") -> bytes:
    """Binary STL of the hull (``part="hull"``), the fins (``"fins"``) or both (``"all"``)."""
    if part not in ("all", "hull", "fins"):
        raise ValueError(f"STL part = {part!r} is not one of: all, hull, fins")
    parts = []
    if part in ("all", "hull"):
        parts.append(hull_mesh(d))
    if part in ("all", "fins"):
        parts.append(fin_meshes(d))
    tris = np.concatenate([p for p in parts if len(p)], axis=0)
    return stl_bytes(tris, f"aerostat {part} ({d.airframe.hull.shape})")


def mesh_properties(data: bytes) -> dict:
    """Volume [m3], surface area [m2] and centre of volume (x, y, z) [m] of an STL (re-read with
    numpy-stl): the check the thesis made with SolidWorks."""
    from stl import mesh

    m = mesh.Mesh.from_file("mesh.stl", fh=io.BytesIO(data))
    volume, cog, _ = m.get_mass_properties()
    return {"volume": float(volume), "area": float(np.sum(m.areas)), "centre": np.asarray(cog)}


# --- gore and fin patterns ----------------------------------------------------------------
@dataclass(frozen=True)
class GorePattern:
    """Flat patterns [m].

    n_gores : int; seam_allowance [m];
    s : arc length along the seam from the nose [m]; xi : hull station there [m]; radius [m];
    half_width : w(s) = pi r / N [m];
    seam_outline, cut_outline : closed polygons (k, 2) of one gore (x = s, y across);
    fin_outlines, fin_cut_outlines : one planform polygon per fin face (4 corners, closed);
    hull_area [m2] (the engine's), pattern_area [m2] (N gore seam polygons, shoelace),
    fin_pattern_area [m2] (all fin faces).
    """

    n_gores: int
    seam_allowance: float
    s: np.ndarray
    xi: np.ndarray
    radius: np.ndarray
    half_width: np.ndarray
    seam_outline: np.ndarray
    cut_outline: np.ndarray
    fin_outlines: tuple
    fin_cut_outlines: tuple
    hull_area: float
    pattern_area: float
    fin_pattern_area: float

    def rows(self) -> list[dict]:
        """CSV rows: station along the seam and half-widths (seam line and cut line)."""
        return [
            {
                "s_m": float(a),
                "xi_m": float(x),
                "radius_m": float(r),
                "half_width_m": float(w),
                "cut_half_width_m": float(w + self.seam_allowance),
            }
            for a, x, r, w in zip(self.s, self.xi, self.radius, self.half_width)
        ]


def _polygon_area(p: np.ndarray) -> float:
    x, y = p[:, 0], p[:, 1]
    return 0.5 * abs(float(np.dot(x, np.roll(y, -1)) - np.dot(y, np.roll(x, -1))))


def _offset(poly: np.ndarray, dist: float) -> np.ndarray:
    """Outward offset of a closed convex-ish polygon (k, 2) by ``dist`` [m], vertex normals from
    the bisector of the neighbouring edges (exact for straight edges, good for smooth curves)."""
    p = poly[:-1] if np.allclose(poly[0], poly[-1]) else poly
    prev, nxt = np.roll(p, 1, axis=0), np.roll(p, -1, axis=0)
    e1 = p - prev
    e2 = nxt - p
    n1 = np.stack([e1[:, 1], -e1[:, 0]], axis=1)
    n2 = np.stack([e2[:, 1], -e2[:, 0]], axis=1)
    n1 /= np.maximum(np.linalg.norm(n1, axis=1, keepdims=True), 1e-300)
    n2 /= np.maximum(np.linalg.norm(n2, axis=1, keepdims=True), 1e-300)
    bis = n1 + n2
    bis /= np.maximum(np.linalg.norm(bis, axis=1, keepdims=True), 1e-300)
    cos_half = np.clip(np.einsum("ij,ij->i", bis, n2), 0.25, 1.0)
    area_sign = np.sign(
        np.dot(p[:, 0], np.roll(p[:, 1], -1)) - np.dot(p[:, 1], np.roll(p[:, 0], -1))
    )
    out = p + area_sign * dist * bis / cos_half[:, None]
    return np.vstack([out, out[:1]])


def gore_pattern(
    d: Design, n_gores: int = 12, seam_allowance: float = 0.02, n_stations: int = 401
) -> GorePattern:
    """Gore and fin cutting patterns of a design.

    Parameters
    ----------
    d : Design
    n_gores : int
        Number of gores N, valid [3, 64].
    seam_allowance : float
        Width added outside the seam line [m], valid [0, 0.2].
    n_stations : int
        Stations along the seam (cosine spaced), valid [21, 5001].

    Notes
    -----
    w(s) = pi r(s)/N with s the meridian arc length; pattern area N int 2 w ds = hull area
    (within the polygon discretisation, < 0.1 % at 401 stations; tests/core/test_export.py).
    """
    if not isinstance(n_gores, (int, np.integer)) or not 3 <= int(n_gores) <= 64:
        raise ValueError(f"n_gores = {n_gores!r} is outside the valid range [3, 64]")
    if not (isinstance(seam_allowance, (int, float)) and 0.0 <= seam_allowance <= 0.2):
        raise ValueError(
            f"seam_allowance = {seam_allowance!r} is outside the valid range [0, 0.2] m"
        )
    if not 21 <= int(n_stations) <= 5001:
        raise ValueError(f"n_stations = {n_stations!r} is outside the valid range [21, 5001]")
    xi, r = _stations(d, int(n_stations))
    s = np.concatenate([[0.0], np.cumsum(np.hypot(np.diff(xi), np.diff(r)))])
    w = np.pi * r / n_gores
    seam = np.vstack([np.stack([s, w], axis=1), np.stack([s[::-1], -w[::-1]], axis=1)[1:-1]])
    seam = np.vstack([seam, seam[:1]])
    cut = _offset(seam, seam_allowance) if seam_allowance > 0 else seam.copy()
    f = d.airframe.fins
    fins, fins_cut = [], []
    if _f(f.area_total) > 0:
        rc, tc, span = _f(f.root_chord), _f(f.tip_chord), _f(f.span)
        x_tip = span * math.tan(_f(f.sweep_le))
        quad = np.array([[0.0, 0.0], [rc, 0.0], [x_tip + tc, span], [x_tip, span], [0.0, 0.0]])
        for _ in range(2 * int(f.count)):  # two faces per fin
            fins.append(quad)
            fins_cut.append(_offset(quad, seam_allowance) if seam_allowance > 0 else quad)
    return GorePattern(
        n_gores=int(n_gores),
        seam_allowance=float(seam_allowance),
        s=s,
        xi=xi,
        radius=r,
        half_width=w,
        seam_outline=seam,
        cut_outline=cut,
        fin_outlines=tuple(fins),
        fin_cut_outlines=tuple(fins_cut),
        hull_area=_f(d.airframe.hull.surface_area),
        pattern_area=n_gores * _polygon_area(seam),
        fin_pattern_area=float(sum(_polygon_area(q) for q in fins)),
    )


def _layout(p: GorePattern) -> list[tuple[str, str, np.ndarray]]:
    """(layer, label, polygon) of every outline, laid out side by side [m]: the gore (one
    drawing, cut N times) on top, the fin faces in a row below."""
    width = float(np.max(p.cut_outline[:, 1]) - np.min(p.cut_outline[:, 1]))
    items = [("SEAM", f"gore (cut {p.n_gores})", p.seam_outline), ("CUT", "", p.cut_outline)]
    y0 = -width - 0.5
    x = 0.0
    for k, (q, qc) in enumerate(zip(p.fin_outlines, p.fin_cut_outlines)):
        shift = np.array([x, y0 - float(np.max(qc[:, 1]))])
        items.append(("FIN_SEAM", f"fin face {k + 1}", q + shift))
        items.append(("FIN_CUT", "", qc + shift))
        x += float(np.ptp(qc[:, 0])) + 0.3
    return items


def gore_dxf(p: GorePattern) -> bytes:
    """DXF (ezdxf, R2010, metres) of the gore and fin patterns: layers SEAM, CUT, FIN_SEAM,
    FIN_CUT, with a text label per part."""
    import ezdxf
    from ezdxf import units

    doc = ezdxf.new("R2010")
    doc.units = units.M
    for name, colour in (("SEAM", 1), ("CUT", 7), ("FIN_SEAM", 3), ("FIN_CUT", 7)):
        doc.layers.add(name, color=colour)
    msp = doc.modelspace()
    for layer, label, poly in _layout(p):
        msp.add_lwpolyline(
            [tuple(map(float, q)) for q in poly[:-1]], close=True, dxfattribs={"layer": layer}
        )
        if label:
            c = poly[:-1].mean(axis=0)
            msp.add_text(label, height=0.1, dxfattribs={"layer": layer}).set_placement(
                (float(c[0]), float(c[1]))
            )
    buf = io.StringIO()
    doc.write(buf)
    return buf.getvalue().encode("utf-8")


def gore_svg(p: GorePattern) -> bytes:
    """SVG (millimetres) of the gore and fin patterns: seam lines solid, cut lines dashed."""
    items = _layout(p)
    pts = np.vstack([poly for _, _, poly in items]) * 1000.0
    lo, hi = pts.min(axis=0) - 50.0, pts.max(axis=0) + 50.0
    w, h = hi - lo
    out = [
        f'<svg xmlns="http://www.w3.org/2000/svg" width="{w:.0f}mm" height="{h:.0f}mm" '
        f'viewBox="0 0 {w:.1f} {h:.1f}">'
    ]
    for layer, label, poly in items:
        q = (poly * 1000.0 - lo) * np.array([1.0, -1.0]) + np.array([0.0, h])
        path = " ".join(f"{x:.2f},{y:.2f}" for x, y in q)
        dash = ' stroke-dasharray="20,10"' if "CUT" in layer else ""
        out.append(
            f'<polygon points="{path}" fill="none" stroke="black" stroke-width="2"'
            f"{dash}><title>{layer}</title></polygon>"
        )
        if label:
            c = q[:-1].mean(axis=0)
            out.append(f'<text x="{c[0]:.1f}" y="{c[1]:.1f}" font-size="80">{label}</text>')
    out.append("</svg>")
    return "\n".join(out).encode("utf-8")


def gore_csv(p: GorePattern) -> str:
    """CSV of half-widths along the seam (metres), with a comment header."""
    from aerostat_core.model.io import rows_to_csv

    head = (
        f"# {p.n_gores} gores, seam allowance {p.seam_allowance:g} m, hull area "
        f"{p.hull_area:.4f} m2, pattern area {p.pattern_area:.4f} m2\n"
    )
    return head + rows_to_csv(p.rows())
