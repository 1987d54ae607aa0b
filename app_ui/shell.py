"""Every page runs inside ``app.py``: its style, workspace, unit switch and navigation.

Streamlit (1.67) keeps its first multipage mode for an app that has a ``pages/`` folder: until
some session of the server process has called ``st.navigation``, a request for a page's own
address (``/Method``: a bookmark, a reload, a browser reconnecting after a server restart) runs
that page's file alone, under a navigation built from the folder's file names. ``app.py`` does
not run, so the page has no style sheet, no workspace bound to ``?ws=``, no unit switch, and
the sidebar lists "app" and the bare file names. :func:`run_inside_the_app` runs ``app.py`` in
that case, whose ``st.navigation`` opens the page the address names and ends the folder mode
for the process.
"""

from __future__ import annotations

import runpy
from pathlib import Path

import streamlit as st
from streamlit.runtime.pages_manager import PagesManager

#: The app's entry script.
APP = Path(__file__).resolve().parents[1] / "app.py"


def run_inside_the_app() -> None:
    """Run ``app.py`` (and through it this page) when Streamlit has started this page's file
    on its own, then end this bare run.

    Call it first in every page of ``pages/``, before it draws anything. ``app.py`` is run in
    this same script run rather than by a rerun, so the event that started the run (a pressed
    button) is not lost; its ``st.navigation`` resolves this page by its address, as it would
    for any later run. In the app's own runs (``app.py`` has called ``st.navigation``, which
    ends the folder mode for the process) this does nothing.
    """
    if not PagesManager.uses_pages_directory:
        return
    PagesManager.uses_pages_directory = False  # what st.navigation does first, before the page
    runpy.run_path(str(APP), run_name="__main__")
    st.stop()
