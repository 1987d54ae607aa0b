"""Keep numba's on-disk cache of the dynamics kernels consistent with their sources.

numba (``cache=True``) keys a cached function on its own file's time stamp only, so a kernel that
calls a kernel of another module keeps running the *old* callee after that module is edited (e.g.
after ``git pull``). :func:`ensure_fresh_cache` hashes every kernel module and deletes this
package's cache files when the hash changed, before anything is compiled or loaded. It runs once
per process, when the first :class:`~.system.DynamicSystem` is built (importing the package has no
side effects).
"""

from __future__ import annotations

import hashlib
import os
from pathlib import Path

#: Modules whose numba kernels call each other.
KERNEL_MODULES = ("layout.py", "wind.py", "tether.py", "sixdof_layout.py", "sixdof_wind.py",
                  "sixdof_kernel.py", "kernel.py",
                  "solver.py")
_DONE: list[bool] = []


def _cache_dirs(here: Path) -> list[Path]:
    dirs = [here / "__pycache__"]
    env = os.environ.get("NUMBA_CACHE_DIR")
    if env:
        dirs += [p for p in Path(env).glob("**/dynamics") if p.is_dir()]
    return dirs


def ensure_fresh_cache(force: bool = False) -> bool:
    """Delete stale kernel caches (once per process unless ``force``); True when something was
    deleted."""
    if _DONE and not force:
        return False
    _DONE.append(True)
    here = Path(__file__).resolve().parent
    h = hashlib.sha256()
    for name in KERNEL_MODULES:
        try:
            h.update((here / name).read_bytes())
        except OSError:
            return False
    digest = h.hexdigest()
    removed = False
    for d in _cache_dirs(here):
        stamp = d / "kernels.sha256"
        try:
            if stamp.read_text().strip() == digest:
                continue
        except OSError:
            pass
        if not d.is_dir():
            continue
        for f in list(d.glob("*.nbi")) + list(d.glob("*.nbc")):
            try:
                f.unlink()
                removed = True
            except OSError:
                pass
        try:
            stamp.write_text(digest)
        except OSError:
            pass
    return removed
