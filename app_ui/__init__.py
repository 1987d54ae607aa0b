"""UI layer of the aerostat design app: session state, cached engine calls, input widgets and
plot builders. The only package that imports both Streamlit and :mod:`aerostat_core`; it holds
no physics (that lives in the engine) and no page layout (that lives in ``pages/``)."""
