"""The figures' look, defined once: colours, fonts, margins and legend places of every page.

Plain dicts (no plotly or Streamlit import), so a figure module takes what it needs and a change
of colour or font happens here only. No plotly template: ``st.plotly_chart`` applies the app's
Streamlit theme on top of these.
"""

from __future__ import annotations

from typing import Any

#: The design's own colour (main line, bars).
ACCENT = "#1f5fa8"
#: Limits and whatever breaks them (limit lines, red crosses).
LIMIT_COLOUR = "#d62728"
#: Second and third series of a figure (the palette's next colours).
SECOND = "#e69f00"
THIRD = "#009e73"
NEUTRAL = "#7f7f7f"
#: Qualitative palette for several cases / wind speeds (colour-blind friendly, Okabe-Ito based).
PALETTE = (
    ACCENT,
    SECOND,
    THIRD,
    "#cc79a7",
    "#56b4e9",
    "#d55e00",
    NEUTRAL,
    "#b8a200",
    "#000000",
)
FONT = dict(family="sans-serif", size=13)
TITLE_SIZE = 15
MARGIN = dict(l=60, r=20, t=50, b=50)
#: Legend below the plot, clear of the x-axis title (the axis title sits at about -0.12).
LEGEND_BELOW = dict(orientation="h", y=-0.22)
#: Legend right of the plot (figures with several panels or long names).
LEGEND_RIGHT = dict(orientation="v", x=1.02, xanchor="left", y=1.0, yanchor="top")


#: Characters of a title line: a half-width chart at 1024 px is about 350 px wide, where a
#: 15 px title of more than ~45 characters ran off the figure and was cut.
TITLE_CHARS = 45


def wrap_title(title: str, width: int = TITLE_CHARS) -> str:
    """A figure title broken into lines of at most ``width`` characters (at spaces, with
    plotly's ``<br>``), so a long title is never cut at the figure's edge.

    >>> wrap_title("Total mass over fineness ratio × fin position (hull re-sized)", 30)
    'Total mass over fineness ratio<br>× fin position (hull re-sized)'
    """
    lines: list[str] = []
    for word in str(title).split(" "):
        if lines and len(lines[-1]) + 1 + len(word) <= width:
            lines[-1] += " " + word
        else:
            lines.append(word)
    return "<br>".join(lines)


def base_layout(title: str, **layout: Any) -> dict[str, Any]:
    """The common layout of a figure: title (wrapped, with room above the plot for every line),
    font, margins and a legend below the plot; ``layout`` overrides or adds keys."""
    text = wrap_title(title)
    lines = text.count("<br>") + 1
    lay: dict[str, Any] = dict(
        title=dict(text=text, font=dict(size=TITLE_SIZE)),
        font=FONT,
        margin=MARGIN,
        legend=LEGEND_BELOW,
    )
    lay.update(layout)
    margin = dict(lay.get("margin") or MARGIN)
    margin["t"] = max(int(margin.get("t", MARGIN["t"])), 30 + 20 * lines)
    lay["margin"] = margin
    return lay


#: Sidebar width at first paint [px]: Streamlit's default 300 px left a 1024 px window 724 px
#: for the page, where the Design page's tabs scrolled sideways and labels broke mid-word.
SIDEBAR_WIDTH = 220

#: The app's few CSS rules (layout only; colours come from .streamlit/config.toml).
#: * the sidebar 220 px wide, the page's side padding 1.5 rem (5 rem left a 1024 px window a
#:   125 px wide input column), a smaller page title and headline numbers: the verdict and the
#:   ten key numbers of the Design page above the fold at 1024 x 768;
#: * tab bars wrap onto a second line instead of scrolling sideways (every tab in sight; the
#:   sliding underline, placed for one line, is replaced by the selected tab's own);
#: * labels and table cells break between words, never inside one ("Ope-rational");
#: * the headline numbers (app_ui/headline.py) in a row that wraps a number whole onto the next
#:   line, a label's help shown on hover under a dotted underline;
#: * a button's or a check box's label wraps instead of ending in an ellipsis ("Load thesis
#:   b…", "Sav…", "Ramp and h…").
PAGE_CSS = f"""
<style>
section[data-testid="stSidebar"] {{ width: {SIDEBAR_WIDTH}px !important;
  min-width: {SIDEBAR_WIDTH}px !important; }}
[data-testid="stTabs"] [role="tablist"] {{ flex-wrap: wrap; overflow-x: visible; row-gap: 0.25rem; }}
[data-testid="stTabs"] [role="tablist"] [data-baseweb="tab-highlight"],
[data-testid="stTabs"] [role="tablist"] [data-baseweb="tab-border"] {{ display: none; }}
[data-testid="stTabs"] [role="tab"][aria-selected="true"] {{ box-shadow: inset 0 -3px 0 {ACCENT}; }}
[data-testid="stWidgetLabel"] p, .aerostat-hl .hl-label, [data-testid="stTable"] th,
[data-testid="stTable"] td {{ word-break: normal; overflow-wrap: normal; hyphens: manual; }}
button [data-testid="stMarkdownContainer"],
[data-testid="stWidgetLabel"] [data-testid="stMarkdownContainer"] {{ overflow: visible;
  text-overflow: clip; white-space: normal; }}
button [data-testid="stMarkdownContainer"] p {{ white-space: normal; text-align: left; }}
[data-testid="stMainBlockContainer"] {{ padding: 1.5rem 1.5rem 4rem 1.5rem; }}
[data-testid="stMain"] h1 {{ font-size: 1.75rem; padding: 0 0 0.5rem 0; }}
.aerostat-hl {{ display: flex; flex-wrap: wrap; gap: 0.25rem 1.5rem; position: relative; }}
.aerostat-hl > div {{ max-width: 100%; }}
.aerostat-hl [data-help]:focus {{ outline: 2px solid {ACCENT}; outline-offset: 2px; }}
/* The focused number's help, under the block rather than under the number: a number near the
   page's right edge would push a note anchored to it off the page. */
.aerostat-hl [data-help]:focus::after {{ content: attr(data-help); position: absolute; z-index: 10;
  left: 0; top: 100%; width: 28rem; max-width: calc(100% - 1.2rem - 2px); padding: 0.4rem 0.6rem;
  font-size: 0.8rem; background: #ffffff; border: 1px solid rgba(49, 51, 63, 0.2);
  border-radius: 0.4rem; }}
.aerostat-hl .hl-note {{ flex-basis: 100%; font-size: 0.875rem; opacity: 0.6; margin: 0.25rem 0 0 0; }}
.aerostat-hl .hl-label {{ font-size: 0.875rem; line-height: 1.4; }}
.aerostat-hl [title] .hl-label {{ text-decoration: underline dotted; text-underline-offset: 3px;
  cursor: help; }}
.aerostat-hl .hl-value {{ font-size: 1.6rem; line-height: 1.3; white-space: nowrap; }}
.aerostat-hl .hl-delta {{ display: inline-block; font-size: 0.875rem; line-height: 1.4;
  padding: 0 0.4rem; border-radius: 0.5rem; white-space: nowrap; }}
</style>
"""
