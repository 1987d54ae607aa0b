"""Aerostat design app: page config, shared session state and navigation.

Run with ``make run`` (or ``streamlit run app.py``). Pages live in ``pages/``; a page is listed
only when its file exists, so pages written by other engineers appear as they land.
"""

from pathlib import Path

import streamlit as st

from app_ui import show, theme
from app_ui.errors import report_unexpected
from app_ui.state import STORE_ERR_KEY, attach_workspace

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
# Binds this session to the workspace in the URL (?ws=...) and loads its saved cases.
attach_workspace()

pages = [
    st.Page(str(HERE / path), title=title, icon=icon, default=(i == 0))
    for i, (path, title, icon) in enumerate(PAGES)
    if (HERE / path).is_file()
]
with st.sidebar:
    show.unit_switch()  # one switch for every page and the report (exports stay SI)
    st.caption("Tethered aerostat design · Mahmood (2020) method, rebuilt from public sources")
    st.caption(
        "Your inputs and saved cases are kept in this workspace: bookmark or share this page's "
        "address to come back to them."
    )
store_error = st.session_state.get(STORE_ERR_KEY)
if store_error:
    st.warning(store_error, icon=":material/database:")
try:
    st.navigation(pages).run()
except Exception as exc:  # noqa: BLE001 - the error boundary: never a traceback on screen
    report_unexpected(exc)
