"""Edits typed into the Design form but not applied are never dropped without a word.

The form applies on Enter (``enter_to_submit``) and on "Update design". Until then its values
live only in the browser, so a small script in the page marks the form as edited on the first
keystroke and, while it is, asks before a page switch from the sidebar or a reload/close drops
the edits (the browser's own confirmation). Applying clears the mark. The script only reads the
page: no user text goes into it.
"""

from __future__ import annotations

import streamlit as st

#: The button that applies the form (its label is the form's own).
APPLY_LABEL = "Update design"
QUESTION = (
    "Your changes to the design inputs are not applied yet (press Enter or Update design). "
    "Leave this page and drop them?"
)

_SCRIPT = """<script>(() => {
  if (window.__aerostatUnapplied) return;
  window.__aerostatUnapplied = true;
  let dirty = false;
  const inDesignForm = (el) => {
    const form = el && el.closest && el.closest('[data-testid="stForm"]');
    return !!form && [...form.querySelectorAll("button")].some(
      (b) => (b.innerText || "").includes(%(apply)s));
  };
  document.addEventListener("input", (e) => { if (inDesignForm(e.target)) dirty = true; }, true);
  document.addEventListener("change", (e) => { if (inDesignForm(e.target)) dirty = true; }, true);
  document.addEventListener("keydown", (e) => {
    if (e.key === "Enter" && inDesignForm(e.target)) dirty = false;  // Enter applies
  }, true);
  document.addEventListener("click", (e) => {
    const button = e.target.closest && e.target.closest("button");
    if (button && (button.innerText || "").includes(%(apply)s)) { dirty = false; return; }
    const link = e.target.closest && e.target.closest('[data-testid="stSidebarNav"] a');
    if (link && dirty) {
      if (window.confirm(%(question)s)) { dirty = false; }
      else { e.preventDefault(); e.stopPropagation(); }
    }
  }, true);
  window.addEventListener("beforeunload", (e) => {
    if (dirty) { e.preventDefault(); e.returnValue = ""; }
  });
})();</script>"""


def guard() -> None:
    """Add the script to the page (once per browser tab; it follows the form by its button)."""
    import json

    st.html(
        _SCRIPT % {"apply": json.dumps(APPLY_LABEL), "question": json.dumps(QUESTION)},
        unsafe_allow_javascript=True,
        width="content",
    )
