"""PLACEHOLDER entry point, so that `make run`, the Docker image and the browser smoke tests work
before the real app lands. Replace it whole with the real frame (st.set_page_config, session state,
st.navigation over pages/): see shared/design/engineering.md §1 and §4.
"""

import streamlit as st

st.set_page_config(page_title="Aerostat design", layout="wide")
st.title("Aerostat design")
st.write(
    "Size a tethered aerostat for a payload and an altitude, then check its blow-by, tether "
    "tension and dynamics. The design pages are on their way; meanwhile the command line works: "
    "`python -m aerostat_core design --payload 10 --altitude 300`."
)
