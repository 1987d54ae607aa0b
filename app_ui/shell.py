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

import inspect
import runpy
from pathlib import Path

import streamlit as st
from streamlit.runtime.pages_manager import PagesManager

#: The app's entry script.
APP = Path(__file__).resolve().parents[1] / "app.py"


def inside_the_app() -> bool:
    """True when this call runs under ``app.py`` (one of its frames is on the stack).

    Asked of the running script itself, not of Streamlit's process-wide mode flag: on a freshly
    started server several sessions start at once, and a session that Streamlit began in the
    folder mode must still be caught after another session's run has ended that mode.
    """
    frame = inspect.currentframe()
    while frame is not None:
        name = frame.f_code.co_filename
        if name.endswith(APP.name) and Path(name).resolve() == APP:
            return True
        frame = frame.f_back
    return False


def run_inside_the_app() -> None:
    """Run ``app.py`` (and through it this page) when Streamlit has started this page's file
    on its own, then end this bare run.

    Call it first in every page of ``pages/``, before it draws anything. ``app.py`` is run in
    this same script run rather than by a rerun, so the event that started the run (a pressed
    button) is not lost; its ``st.navigation`` resolves this page by its address, as it would
    for any later run, and ends the folder mode for the process. Under ``app.py`` (every run
    but those) this does nothing.
    """
    if inside_the_app():
        return
    PagesManager.uses_pages_directory = False  # as st.navigation does, for the later runs
    runpy.run_path(str(APP), run_name="__main__")
    st.stop()
