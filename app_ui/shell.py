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
import types
from pathlib import Path

from streamlit.runtime.pages_manager import PagesManager
from streamlit.runtime.scriptrunner_utils.exceptions import StopException
from streamlit.runtime.scriptrunner_utils.script_run_context import get_script_run_ctx

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


def _run_app(ctx) -> None:
    """Run ``app.py`` in this script run as Streamlit runs an entry script: its cached byte
    code in a fresh ``__main__`` module (no process-wide ``sys.modules`` or ``sys.argv`` swap,
    which ``runpy`` would make under the other sessions' feet), with the entry script's page
    hash active, so the app's own widgets keep the identity they have in every later run."""
    code = ctx.pages_manager.get_page_script_byte_code(str(APP))
    module = types.ModuleType("__main__")
    module.__dict__["__file__"] = str(APP)
    with ctx.run_with_active_hash(ctx.pages_manager.main_script_hash):
        exec(code, module.__dict__)  # noqa: S102 - the app's own entry script


def run_inside_the_app() -> None:
    """Run ``app.py`` (and through it this page) when Streamlit has started this page's file
    on its own, then end this bare run.

    Call it first in every page of ``pages/``, before it draws anything. ``app.py`` is run in
    this same script run rather than by a rerun, so the event that started the run (a pressed
    button) is not lost; its ``st.navigation`` resolves this page by its address, as it would
    for any later run, and ends the folder mode for the process. A page run as the entry
    script itself (``streamlit run pages/6_Method.py``, an AppTest of one page file) is left
    alone: there is no app around it to run. The bare run then ends by
    :class:`StopException` itself, not ``st.stop()``, which would also drop a fragment rerun
    queued meanwhile (a click inside a fragment during this first, slow run). Under
    ``app.py`` (every run but those) this does nothing.
    """
    ctx = get_script_run_ctx()
    if (ctx is None  # no script run (a bare import)
            or Path(ctx.pages_manager.main_script_path).resolve() != APP  # the page is the entry
            or inside_the_app()):
        return
    PagesManager.uses_pages_directory = False  # as st.navigation does, for the later runs
    _run_app(ctx)
    raise StopException()
