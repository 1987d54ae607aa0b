"""3-DOF dynamics of a tethered aerostat in varying, gust and turbulent wind (dynamics.md)."""

from ._cache import ensure_fresh_cache

ensure_fresh_cache()
