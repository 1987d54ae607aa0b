"""Helpers for the AppTest tests: read plotted data, tables and messages; drive the form."""

from __future__ import annotations

import base64
import json
import re
from html.parser import HTMLParser
from typing import Any, NamedTuple

import numpy as np
import pandas as pd
from streamlit.testing.v1 import AppTest

DESIGN_PAGE = "pages/1_Design.py"
COMPARE_PAGE = "pages/2_Compare.py"
METHOD_PAGE = "pages/6_Method.py"


def chart(at: AppTest, key: str) -> dict:
    """The plotly figure JSON (data + layout) of the chart with this key."""
    for el in at.get("plotly_chart"):
        if getattr(el, "key", None) == key:
            return json.loads(el.proto.spec)
    keys = [getattr(el, "key", None) for el in at.get("plotly_chart")]
    raise KeyError(f"no plotly chart with key {key!r}; charts: {keys}")


def chart_keys(at: AppTest) -> list[str]:
    return [getattr(el, "key", None) for el in at.get("plotly_chart")]


def trace(fig: dict, name: str) -> dict:
    """The first trace with this name."""
    for t in fig["data"]:
        if t.get("name") == name:
            return t
    raise KeyError(f"no trace {name!r}; traces: {[t.get('name') for t in fig['data']]}")


def values(tr: dict, axis: str) -> np.ndarray:
    """A trace's data along ``axis`` as floats (plain lists or plotly's typed-array encoding)."""
    v = tr[axis]
    if isinstance(v, dict) and "bdata" in v:
        arr = np.frombuffer(base64.b64decode(v["bdata"]), dtype=np.dtype(v["dtype"]))
        shape = v.get("shape")
        if isinstance(shape, str):  # plotly writes "37, 62"
            shape = tuple(int(n) for n in shape.split(","))
        return arr.reshape(shape) if shape else arr
    return np.array([np.nan if x is None else x for x in v], dtype=float)


def shown_table(at: AppTest, first_column: str) -> pd.DataFrame:
    """The texts a static table (``st.table`` of a styler) shows, by its first column."""
    import pyarrow as pa

    for t in at.table:
        if len(t.value.columns) and t.value.columns[0] == first_column:
            data = t.proto.arrow_data
            if data.HasField("styler"):
                return pa.ipc.open_stream(data.styler.display_values).read_all().to_pandas()
            return t.value.astype(str)
    raise KeyError(f"no static table starting with {first_column!r}")


_MD_ESCAPE = re.compile(r"\\([!-/:-@\[-`{-~])")


def _as_read(df: pd.DataFrame) -> pd.DataFrame:
    """A static table's headers as the reader sees them: st.table renders Markdown, so the
    pages backslash-escape user text (case names) there; the escapes are not shown."""
    return df.rename(columns=lambda c: _MD_ESCAPE.sub(r"\1", c) if isinstance(c, str) else c)


_MD_CELL = re.compile(r"(?<!\\)\|")


def markdown_tables(at: AppTest) -> list[pd.DataFrame]:
    """The Markdown (GFM) tables of the page as the reader sees them: every cell a text with
    its backslash escapes read (the Geometry tab's table is Markdown, not ``st.table``)."""
    out = []
    for md in at.markdown:
        lines = [ln.strip() for ln in str(md.value).strip().splitlines()]
        if len(lines) < 2 or not lines[0].startswith("|") or not set(lines[1]) <= set("|:- "):
            continue
        rows = [
            [_MD_ESCAPE.sub(r"\1", c.strip()).replace("\u2060", "") for c in _MD_CELL.split(ln)[1:-1]]
            for ln in lines
            if ln.startswith("|")
        ]
        out.append(pd.DataFrame(rows[2:], columns=rows[0]))
    return out


def html_tables(at: AppTest) -> list[pd.DataFrame]:
    """The HTML tables of the page's ``st.html`` elements as the reader sees them: every cell
    a text (the Geometry tab's table is HTML, not ``st.table``)."""
    import html as _html
    import xml.etree.ElementTree as ET

    out = []
    for el in at.get("html"):
        body = str(el.proto.body)
        for found in re.findall(r"<table.*?</table>", body, flags=re.S):
            root = ET.fromstring(found)
            rows = [
                ["".join(c.itertext()) for c in tr if c.tag in ("th", "td")]
                for tr in root.iter("tr")
            ]
            rows = [[_html.unescape(c) for c in r] for r in rows]
            out.append(pd.DataFrame(rows[1:], columns=rows[0]))
    return out


def _tables(at: AppTest) -> list:
    return (
        [df.value for df in at.dataframe]
        + [_as_read(df.value) for df in at.table]
        + markdown_tables(at)
        + html_tables(at)
    )


def table_with(at: AppTest, first_column: str, column: str) -> pd.DataFrame:
    """The dataframe or static table whose first column is ``first_column`` and that has
    ``column`` (pages show a wide table as several by theme)."""
    for df in _tables(at):
        cols = list(df.columns)
        if cols[:1] == [first_column] and column in cols:
            return df
    raise KeyError(f"no table starting with {first_column!r} with column {column!r}")


def table(at: AppTest, first_column: str) -> pd.DataFrame:
    """The dataframe (or static table) element whose first column has this name."""
    elements = _tables(at)
    for df in elements:
        if len(df.columns) and df.columns[0] == first_column:
            return df
    cols = [df.columns[0] for df in elements if len(df.columns)]
    raise KeyError(f"no table starting with {first_column!r}; tables start with {cols}")


class Shown(NamedTuple):
    """One headline number as the reader sees it (app_ui/headline.py)."""

    label: str
    value: str
    help: str
    delta: str
    tone: str


class _HeadlineParser(HTMLParser):
    def __init__(self) -> None:
        super().__init__()
        self.items: list[dict[str, str]] = []
        self._field: str | None = None

    def handle_starttag(self, tag: str, attrs: list) -> None:
        a = dict(attrs)
        tid = a.get("data-testid", "")
        if tid == "headline":
            self.items.append({"help": a.get("title") or "", "label": "", "value": "",
                               "delta": "", "tone": ""})
        elif tid.startswith("headline-") and tid != "headline-note" and self.items:
            self._field = tid.removeprefix("headline-")
            if self._field == "delta":
                self.items[-1]["tone"] = a.get("data-tone", "")

    def handle_endtag(self, tag: str) -> None:
        self._field = None

    def handle_data(self, data: str) -> None:
        if self._field and self.items:
            self.items[-1][self._field] += data


def metrics(at: AppTest) -> list[Shown]:
    """Every headline number of the page, in order (the ``st.html`` blocks of
    :func:`app_ui.show.headlines`), as text unescaped."""
    out: list[Shown] = []
    for el in at.get("html"):
        body = str(el.proto.body)
        if 'data-testid="headline"' in body:
            p = _HeadlineParser()
            p.feed(body)
            out += [Shown(**d) for d in p.items]
    return out


def metric(at: AppTest, label: str) -> str:
    shown = metrics(at)
    for m in shown:
        if m.label == label:
            return m.value
    raise KeyError(f"no metric {label!r}; metrics: {[m.label for m in shown]}")


def metric_float(at: AppTest, label: str) -> float:
    return float(metric(at, label).replace(",", ""))


_MD_ESCAPE = re.compile(r"\\([!-/:-@\[-`{-~])")


def messages(at: AppTest, kind: str) -> list[str]:
    """Texts of st.error / st.warning / st.success / st.info elements, with the Markdown
    escapes of :func:`app_ui.widgets.plain` removed (the text the user reads)."""
    return [_MD_ESCAPE.sub(r"\1", str(e.value)) for e in getattr(at, kind)]


def raw_messages(at: AppTest, kind: str) -> list[str]:
    """The Markdown source of the message elements (escapes included)."""
    return [str(e.value) for e in getattr(at, kind)]


def open_groups(at: AppTest, *keys: str) -> AppTest:
    """Open the design-form groups holding these widget keys (a closed group draws no widgets:
    lazy expanders), with one run when any was closed."""
    from app_ui.form_fields import LAYOUT, group_key

    closed = [
        g
        for g, held in LAYOUT.items()
        if set(held) & set(keys)
        and not (group_key(g) in at.session_state and at.session_state[group_key(g)])
    ]
    for g in closed:
        at.session_state[group_key(g)] = True
    if closed:
        at.run()
    return at


def submit(at: AppTest, **widget_values: Any) -> AppTest:
    """Set form widgets by key (number inputs, radios, selectboxes) and press Update design
    (opening the form groups that hold them first)."""
    open_groups(at, *widget_values)
    for key, value in widget_values.items():
        widget = _widget(at, key)
        if widget.type == "text_input" and isinstance(value, (int, float)):
            value = f"{value:g}"  # the form's number boxes are text boxes
        widget.set_value(value)
    at.button(key="in_submit").click()
    at.run()
    return at


def field_value(at: AppTest, key: str) -> float | None:
    """The number shown in a design-form box (text boxes: "12,5" reads as 12.5)."""
    open_groups(at, key)
    text = _widget(at, key).value
    return None if not str(text).strip() else float(str(text).replace(",", "."))


def _widget(at: AppTest, key: str):
    for kind in ("number_input", "radio", "selectbox", "text_input", "multiselect", "toggle"):
        elements = getattr(at, kind)
        for el in elements:
            if getattr(el, "key", None) == key:
                return el
    raise KeyError(key)


def show_tab(at: AppTest, label: str, key: str = "design_tab") -> AppTest:
    """Open a lazy result tab (st.tabs with on_change="rerun": only the open tab runs)."""
    at.session_state[key] = label
    at.run()
    return at


def goto(at: AppTest, page: str) -> AppTest:
    at.switch_page(page)
    at.run()
    return at


def mass_bars(at: AppTest) -> dict[str, float]:
    """The Mass tab's static bar chart (an SVG): {item: mass [kg]} as drawn."""
    import xml.etree.ElementTree as ET

    for el in at.get("image"):
        for img in el.proto.imgs:
            if not img.url.startswith("data:image/svg+xml;base64,"):
                continue
            body = base64.b64decode(img.url.split(",", 1)[1]).decode("utf-8")
            if 'data-testid="mass-bars"' in body:
                root = ET.fromstring(body)
                return {
                    g.get("data-item"): float(g.get("data-mass-kg"))
                    for g in root.iter("{http://www.w3.org/2000/svg}g")
                    if g.get("data-item")
                }
    raise KeyError("no mass bar chart on the page")


def svg_images(at: AppTest) -> list[str]:
    """The SVG markup of every image on the page (``st.image`` of an SVG: a base64 data URL)."""
    return [
        base64.b64decode(img.url.split(",", 1)[1]).decode("utf-8")
        for el in at.get("image")
        for img in el.proto.imgs
        if img.url.startswith("data:image/svg+xml;base64,")
    ]


def perf_charts(at: AppTest) -> dict:
    """The Performance tab's static charts: {key ("perf_blow_by" ...): parsed SVG root}."""
    import xml.etree.ElementTree as ET

    roots = [ET.fromstring(body) for body in svg_images(at) if "data-chart=" in body]
    return {r.get("data-chart"): r for r in roots}


def svg_series(root, key: str) -> tuple[np.ndarray, np.ndarray]:
    """(x, y) of a line of a static chart (:mod:`app_ui.perf_view`), in the units it shows."""
    for g in root.iter("{http://www.w3.org/2000/svg}g"):
        if g.get("data-series") == key:
            return (
                np.array(g.get("data-x").split(), float),
                np.array(g.get("data-y").split(), float),
            )
    raise KeyError(f"no series {key!r} in chart {root.get('data-chart')!r}")


def svg_limit_points(root) -> np.ndarray:
    """x of the red crosses of a static chart (the speeds that break an operating limit)."""
    return np.array(
        [
            float(g.get("data-x"))
            for g in root.iter("{http://www.w3.org/2000/svg}g")
            if g.get("data-limit-point")
        ]
    )


def svg_limit_lines(root) -> dict[str, float]:
    """{name: value} of the requirement lines of a static chart, in the units it shows."""
    return {
        e.get("data-limit"): float(e.get("data-value"))
        for e in root.iter("{http://www.w3.org/2000/svg}line")
        if e.get("data-limit")
    }


def side_view(at: AppTest) -> dict:
    """The Design page's static side view (an SVG drawn to scale): its scale [px/m], the hull
    outline's extent in metres, and the marked points {key: (xi, z)} [m]."""
    import xml.etree.ElementTree as ET

    for el in at.get("image"):  # st.image of an SVG string: a base64 data URL
        urls = [img.url for img in el.proto.imgs]
        svg = [u for u in urls if u.startswith("data:image/svg+xml;base64,")]
        if not svg:
            continue
        body = base64.b64decode(svg[0].split(",", 1)[1]).decode("utf-8")
        if 'data-testid="side-view"' not in body:
            continue
        root = ET.fromstring(body)
        ns = "{http://www.w3.org/2000/svg}"
        scale = float(root.get("data-scale"))
        hull = next(e for e in root.iter(f"{ns}polygon") if e.get("data-part") == "hull")
        xy = np.array([[float(v) for v in p.split(",")] for p in hull.get("points").split()])
        points = {
            g.get("data-point"): (float(g.get("data-xi")), float(g.get("data-z")))
            for g in root.iter(f"{ns}g")
            if g.get("data-point")
        }
        parts = [e.get("data-part") for e in root.iter() if e.get("data-part")]
        return {
            "scale": scale,
            "hull_length": float(np.ptp(xy[:, 0])) / scale,
            "hull_height": float(np.ptp(xy[:, 1])) / scale,
            "points": points,
            "parts": parts,
        }
    raise KeyError("no side view on the page")
