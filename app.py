"""Aerostat design app: page config, shared session state and navigation.

Run with ``make run`` (or ``streamlit run app.py``). Pages live in ``pages/``; every page of
:data:`PAGES` must exist: a missing file is a broken install, shown as an error naming the file
(the other pages still work), and the tests fail on it (tests/app/test_pages.py, the browser
smoke test counts the navigation links).
"""

from pathlib import Path

import streamlit as st

from app_ui import show, theme, workspace_ui
from app_ui.errors import report_unexpected

HERE = Path(__file__).resolve().parent

#: (file, title, icon) in navigation order; the first is the default page.
PAGES = (
    ("pages/1_Design.py", "Design", ":material/design_services:"),
    ("pages/2_Compare.py", "Compare", ":material/compare:"),
    ("pages/3_Sensitivity.py", "Sensitivity", ":material/tune:"),
    ("pages/4_Optimise.py", "Optimise", ":material/auto_graph:"),
    ("pages/5_Dynamics.py", "Dynamics", ":material/airwave:"),
    ("pages/6_Method.py", "Method", ":material/menu_book:"),
    ("pages/7_Shapes.py", "Shapes", ":material/category:"),
)

st.set_page_config(
    page_title="Aerostat design",
    page_icon=":material/cloud:",
    layout="wide",
    initial_sidebar_state=theme.SIDEBAR_WIDTH,
)
st.html(theme.PAGE_CSS)
# Binds this session to the workspace in the URL (?ws=...) and loads its saved cases; a bare
# address offers the browser's recent workspaces back.
workspace_ui.attach()

MISSING = [path for path, _, _ in PAGES if not (HERE / path).is_file()]
pages = [
    st.Page(str(HERE / path), title=title, icon=icon, default=(i == 0))
    for i, (path, title, icon) in enumerate(PAGES)
    if path not in MISSING
]
with st.sidebar:
    show.unit_switch()  # one switch for every page and the report (exports stay SI)
    st.caption("Tethered aerostat design · Mahmood (2020) method, rebuilt from public sources")
workspace_ui.status()  # where the work is kept; database outages; unsaved cases
if MISSING:
    st.error(f"This installation is incomplete: page file(s) missing: {', '.join(MISSING)}.",
             icon=":material/error:")
try:
    st.navigation(pages).run()
except Exception as exc:  # noqa: BLE001 - the error boundary: never a traceback on screen
    report_unexpected(exc)
