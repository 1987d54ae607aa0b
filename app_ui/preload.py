"""Load the browser's heavy chart and grid code after the first result is on screen.

A fresh browser fetches Streamlit's element code on first use: the plotly chart bundle is
4.7 MB of JavaScript and the data grid about 1 MB. Drawn on the first tab, they held the first
result back by about 3 s on 2 busy cores; drawn on the next tab, they made that tab switch slow
instead. So the Design page's first tab uses a static drawing and static tables, and its last
element asks the browser to import those two bundles when it is idle: the same module URLs the
app imports, so the tab switch finds them evaluated. Nothing here touches user data; the script
is a constant apart from the bundle names found in the installed Streamlit.
"""

from __future__ import annotations

import functools
import json
from pathlib import Path

import streamlit as st

#: Streamlit's lazily loaded element bundles worth warming (file-name prefixes).
#: The static table's bundle (its Arrow code is the grid's, loaded just before it) and the
#: multiselect (Tether profiles tab): the first tab has neither, so a later tab switch fetched them.
BUNDLES = ("PlotlyChart", "DataFrame", "Table", "Multiselect")


@functools.cache
def bundle_urls() -> tuple[str, ...]:
    """Paths (relative to the app's base URL) of the installed Streamlit's bundles of
    :data:`BUNDLES`; empty when the layout of the package is not the expected one."""
    js = Path(st.__file__).parent / "static" / "static" / "js"
    return tuple(f"static/js/{p.name}" for b in BUNDLES for p in sorted(js.glob(f"{b}.*.js")))


def warm_bundles() -> None:
    """Place at the end of the first page: once its first result is drawn and the browser is
    idle, import the chart and grid bundles (at most once per browser tab; after 20 s at the
    latest, for a page that shows no result). ``window.__aerostatWarmed`` is true once they
    are loaded (benchmarks/bench_app.py reads it)."""
    urls = bundle_urls()
    if not urls:
        return
    script = (
        "<script>(() => {"
        "if (window.__aerostatWarm) return; window.__aerostatWarm = true;"
        f"const urls = {json.dumps(list(urls))};"
        # one after the other (the chart bundle first): two at once made both late
        "const go = () => urls.reduce((p, u) => p.then(() => import("
        "new URL(u, document.baseURI).href)).catch(() => {}), Promise.resolve())"
        ".then(() => { window.__aerostatWarmed = true; });"
        # Only once the first result is on screen and the script has finished: this element
        # is drawn before the browser has loaded the code of the elements above it, and the
        # chart bundle's 4.7 MB evaluated then held the first result back (by seconds on 2
        # busy cores); then when the browser is idle.
        "const ready = () => document.querySelector('[data-testid=\"headline\"]') && "
        "document.querySelector('[data-test-script-state=\"notRunning\"]') && "
        "!document.querySelector('[data-testid=\"stSkeleton\"]');"
        "const idle = window.requestIdleCallback || ((f) => setTimeout(f, 0));"
        "const t0 = Date.now();"
        "const wait = () => (ready() || Date.now() - t0 > 20000) "
        "? setTimeout(() => idle(go, {timeout: 2000}), 500) : setTimeout(wait, 200);"
        "wait();"
        "})();</script>"
    )
    st.html(script, unsafe_allow_javascript=True)
