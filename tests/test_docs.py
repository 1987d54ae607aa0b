"""The design documents in docs/ resolve, and the import rules of docs/architecture.md hold.

* Every citation of ``methods.md``, ``dynamics.md``, ``validation.md`` or ``architecture.md``
  in the code names the file by its repository path (``docs/methods.md``), and every section
  number or label it gives (``§1.7``, ``G9``, ``V4``, ``R1``, ``D7``; ranges such as ``G4-G6``)
  is the first word of a heading of that document.
* Headings carry each label once, and the documents' own links to headings resolve (GitHub's
  anchor rules).
* The import rules of docs/architecture.md §4, checked on the parsed imports of every file.
"""

from __future__ import annotations

import ast
import re
import sys
from collections import defaultdict
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
DOCS = ROOT / "docs"
DOC_NAMES = ("methods", "dynamics", "validation", "architecture")
#: Folders (and files) whose citations must resolve.
CITING = ("aerostat_core", "app_ui", "pages", "benchmarks", "tests", "app.py")

# A citation: an optional path, the document, then labels separated by commas, spaces, comment
# marks, slashes or an opening parenthesis ("docs/dynamics.md §1.6 (D1, D7)", "S2/S4").
_LABEL = r"(?:§\d+(?:\.\d+)*|[A-Z]\d+(?:-[A-Z]?\d+)?)(?![\w.]\w)"
_CITATION = re.compile(
    r"(?P<path>[\w./-]*?)\b(?P<doc>" + "|".join(DOC_NAMES) + r")\.md\b"
    r"(?P<labels>(?:[\s,#(/]*(?:sources?\s+)?" + _LABEL + r")*)"
)
_ONE_LABEL = re.compile(_LABEL)
_HEADING = re.compile(r"^#{1,6}\s+(§\d+(?:\.\d+)*|[A-Z]\d+)(?=[\s·:]|$)")


def _python_files(*places: str) -> list[Path]:
    files: list[Path] = []
    for place in places:
        p = ROOT / place
        files += [p] if p.is_file() else sorted(p.rglob("*.py"))
    return [f for f in files if f.resolve() != Path(__file__).resolve()]


def _expand(label: str) -> list[str]:
    """``G4-G6`` -> G4, G5, G6; anything else unchanged."""
    m = re.fullmatch(r"([A-Z])(\d+)-[A-Z]?(\d+)", label)
    if not m:
        return [label]
    return [f"{m[1]}{k}" for k in range(int(m[2]), int(m[3]) + 1)]


def citations() -> list[tuple[str, str, str, list[str]]]:
    """(file:line, path prefix, document, labels) for every citation in the code."""
    found = []
    for f in _python_files(*CITING):
        text = f.read_text(encoding="utf-8")
        for m in _CITATION.finditer(text):
            line = text.count("\n", 0, m.start()) + 1
            labels = [x for lab in _ONE_LABEL.findall(m["labels"]) for x in _expand(lab)]
            found.append((f"{f.relative_to(ROOT)}:{line}", m["path"], m["doc"], labels))
    return found


def headings(doc: str) -> list[str]:
    """Section numbers and labels that open a heading of docs/<doc>.md, in order."""
    out = []
    in_code = False
    for line in (DOCS / f"{doc}.md").read_text(encoding="utf-8").splitlines():
        if line.startswith("```"):
            in_code = not in_code
        m = None if in_code else _HEADING.match(line)
        if m:
            out.append(m[1])
    return out


def test_every_document_exists_and_labels_are_unique() -> None:
    for doc in DOC_NAMES:
        labels = headings(doc)
        assert labels, f"docs/{doc}.md has no numbered headings"
        dupes = sorted({x for x in labels if labels.count(x) > 1})
        assert not dupes, f"docs/{doc}.md: labels used by more than one heading: {dupes}"


def test_the_parser_sees_the_citation_forms_the_code_uses() -> None:
    text = (
        "docs/methods.md §1.12, G4-G6, G14 and docs/dynamics.md §1.6 (D1, D7); "
        "(docs/methods.md\n    # §1.7, sources S1, S6) docs/dynamics.md V4: see docs/methods.md"
    )
    got = [
        (m["doc"], [x for lab in _ONE_LABEL.findall(m["labels"]) for x in _expand(lab)])
        for m in _CITATION.finditer(text)
    ]
    assert got == [
        ("methods", ["§1.12", "G4", "G5", "G6", "G14"]),
        ("dynamics", ["§1.6", "D1", "D7"]),
        ("methods", ["§1.7", "S1", "S6"]),
        ("dynamics", ["V4"]),
        ("methods", []),
    ]


def test_code_citations_resolve_to_sections_in_docs() -> None:
    known = {doc: set(headings(doc)) for doc in DOC_NAMES}
    cites = citations()
    assert len(cites) > 50, "the citation parser found almost nothing: is the pattern broken?"
    wrong_path = [f"{where}: {path}{doc}.md" for where, path, doc, _ in cites if path != "docs/"]
    assert not wrong_path, "cite the documents by their path docs/<name>.md:\n" + "\n".join(
        wrong_path
    )
    missing = [
        f"{where}: docs/{doc}.md {label}"
        for where, _, doc, labels in cites
        for label in labels
        if label not in known[doc]
    ]
    assert not missing, "cited sections with no heading in docs/:\n" + "\n".join(missing)


def _slug(heading: str) -> str:
    """GitHub's anchor of a heading: lower case, punctuation dropped, spaces to hyphens."""
    text = heading.strip().lower()
    text = "".join(ch for ch in text if ch.isalnum() or ch in " -_")
    return text.replace(" ", "-")


def test_links_between_documents_resolve() -> None:
    anchors = {}
    for doc in DOC_NAMES:
        lines = (DOCS / f"{doc}.md").read_text(encoding="utf-8").splitlines()
        anchors[doc] = {_slug(re.sub(r"^#+\s*", "", x)) for x in lines if x.startswith("#")}
    broken = []
    for doc in DOC_NAMES:
        text = (DOCS / f"{doc}.md").read_text(encoding="utf-8")
        for target, anchor in re.findall(r"\]\((?:([a-z]+)\.md)?#([^)\s]+)\)", text):
            if anchor not in anchors[target or doc]:
                broken.append(f"docs/{doc}.md -> {target or doc}.md#{anchor}")
        for target in re.findall(r"\]\(([\w./-]+\.md)[)#]", text):
            if not (DOCS / target).is_file():
                broken.append(f"docs/{doc}.md -> {target}")
    assert not broken, "broken links:\n" + "\n".join(broken)


# --- import rules (docs/architecture.md §4) --------------------------------------------------

STDLIB = set(sys.stdlib_module_names)
CORE_THIRD_PARTY = {
    "numpy", "scipy", "numba", "pymoo", "moordyn", "ezdxf", "stl", "matplotlib", "dask",
    "distributed", "pandas",
}
UI_THIRD_PARTY = {"streamlit", "plotly", "pandas", "numpy", "sqlalchemy"}
PAGE_THIRD_PARTY = {"streamlit", "pandas"}
#: The library modules a page may import (docs/architecture.md §2.3).
PAGE_FACES = (
    "aerostat_core",
    "aerostat_core.model.io",
    "aerostat_core.output.report",
    "aerostat_core.studies.reference",
    "aerostat_core.optimize",
    "aerostat_core.model.budget",
    "aerostat_core.base.validation",
    "aerostat_core.studies.fielded",
)


def _module_name(path: Path) -> str:
    parts = list(path.relative_to(ROOT).with_suffix("").parts)
    if parts[-1] == "__init__":
        parts = parts[:-1]
    return ".".join(parts)


def _is_module(name: str) -> bool:
    p = ROOT.joinpath(*name.split("."))
    return p.with_suffix(".py").is_file() or (p / "__init__.py").is_file()


def _imports(path: Path, module_level_only: bool = False) -> set[str]:
    """Absolute names of the modules a file imports (relative imports resolved; ``from X
    import y`` counts as X.y when that is a module of the repository)."""
    tree = ast.parse(path.read_text(encoding="utf-8"))
    package = _module_name(path)
    if path.name != "__init__.py":
        package = package.rpartition(".")[0]
    if module_level_only:
        nodes = []
        todo = list(tree.body)
        while todo:  # statements at module level, also inside if/try blocks
            node = todo.pop()
            nodes.append(node)
            if not isinstance(node, ast.FunctionDef | ast.AsyncFunctionDef | ast.ClassDef):
                todo += [c for c in ast.iter_child_nodes(node) if isinstance(c, ast.stmt)]
    else:
        nodes = list(ast.walk(tree))
    out: set[str] = set()
    for node in nodes:
        if isinstance(node, ast.Import):
            out |= {a.name for a in node.names}
        elif isinstance(node, ast.ImportFrom):
            if node.level:
                base = package.split(".")[: len(package.split(".")) - (node.level - 1)]
                target = ".".join(base + ([node.module] if node.module else []))
            else:
                target = node.module or ""
            subs = {f"{target}.{a.name}" for a in node.names}
            subs = {s for s in subs if _is_module(s)}
            out |= subs if subs and len(subs) == len(node.names) else subs | {target}
    return out


def _top(name: str) -> str:
    return name.split(".")[0]


def _violations(files, allowed) -> list[str]:
    return sorted(
        f"{f.relative_to(ROOT)} imports {name}"
        for f in files
        for name in _imports(f)
        if not allowed(name)
    )


def test_core_imports_only_the_standard_library_and_its_numeric_stack() -> None:
    bad = _violations(
        _python_files("aerostat_core"),
        lambda n: _top(n) in STDLIB | CORE_THIRD_PARTY | {"aerostat_core"},
    )
    assert not bad, "aerostat_core must not import UI or other packages:\n" + "\n".join(bad)


#: The packages of aerostat_core, bottom-up (docs/architecture.md §1): a module may import its own
#: package and the packages below it, never one above. Function-level imports count too: an
#: import hidden in a function body is still a dependency.
LADDER = (
    "base", "atmosphere", "geometry", "aerodynamics", "structures", "tether", "model",
    "optimize", "dynamics", "studies", "output", "cli",
)
#: The faces at the top of the library: they may import every package.
FACES = ("aerostat_core", "aerostat_core.__main__")


def _package_of(module: str) -> str | None:
    parts = module.split(".")
    return parts[1] if len(parts) > 1 and parts[0] == "aerostat_core" and parts[1] in LADDER else None


def _core_modules() -> dict[str, Path]:
    return {_module_name(f): f for f in _python_files("aerostat_core")}


def test_every_core_module_lives_in_a_package_of_the_ladder() -> None:
    loose = sorted(m for m in _core_modules() if m not in FACES and _package_of(m) is None)
    assert not loose, "modules outside the packages of docs/architecture.md §1: " + ", ".join(loose)


def test_no_package_imports_a_package_above_it() -> None:
    bad = []
    for me, f in _core_modules().items():
        mine = _package_of(me)
        if mine is None:
            continue
        for name in _imports(f):
            if _top(name) != "aerostat_core":
                continue
            theirs = _package_of(name)
            if theirs is None:
                bad.append(f"{f.relative_to(ROOT)} imports the top-level face {name}")
            elif LADDER.index(theirs) > LADDER.index(mine):
                bad.append(f"{f.relative_to(ROOT)} ({mine}) imports {name} ({theirs}, above)")
    assert not bad, "upward imports (docs/architecture.md §1):\n" + "\n".join(sorted(bad))


def test_static_engine_never_imports_the_dynamics() -> None:
    static = [
        f for m, f in _core_modules().items()
        if _package_of(m) in LADDER[: LADDER.index("dynamics")]
    ]
    bad = _violations(static, lambda n: not n.startswith("aerostat_core.dynamics"))
    assert not bad, "\n".join(bad)


@pytest.mark.parametrize("module_level_only", [True, False], ids=["module-level", "all-imports"])
def test_no_import_cycles_in_the_core(module_level_only: bool) -> None:
    """No circle of imports between core modules, counting imports inside functions as well
    (a function-level import that dodges an import-time cycle still makes a circle)."""
    graph: dict[str, set[str]] = defaultdict(set)
    for f in _python_files("aerostat_core"):
        me = _module_name(f)
        deps = {n for n in _imports(f, module_level_only=module_level_only) if _is_module(n)}
        # a package's __init__ that only documents the package is no edge back to its modules
        graph[me] = {n for n in deps if n.startswith("aerostat_core") and n != me}
    state: dict[str, int] = {}
    cycle: list[str] = []

    def visit(node: str, stack: list[str]) -> bool:
        state[node] = 1
        for nxt in sorted(graph.get(node, ())):
            if state.get(nxt) == 1:
                cycle.extend(stack[stack.index(nxt) :] + [node, nxt] if nxt in stack else [nxt])
                return True
            if nxt not in state and visit(nxt, stack + [node]):
                return True
        state[node] = 2
        return False

    for node in sorted(graph):
        if node not in state and visit(node, []):
            break
    assert not cycle, "import cycle: " + " -> ".join(cycle)


def test_architecture_names_every_module() -> None:
    """docs/architecture.md §1 is the map: every module of aerostat_core is named there by its
    path (``model/sizing.py``), so a newcomer finds each room from the document."""
    text = (DOCS / "architecture.md").read_text(encoding="utf-8")
    missing = sorted(
        str(f.relative_to(ROOT / "aerostat_core"))
        for f in _python_files("aerostat_core")
        if f.name != "__init__.py" and str(f.relative_to(ROOT / "aerostat_core")) not in text
    )
    assert not missing, "modules docs/architecture.md does not name: " + ", ".join(missing)


def test_no_module_imports_another_modules_private_names() -> None:
    """``from aerostat_core.x import _name`` (or ``module._name`` of an imported project module)
    couples a module to another's internals; helpers shared between modules are public. Checked
    for the library, the UI rooms and the pages."""
    bad = []
    files = [*_python_files("aerostat_core"), *_python_files("app_ui"), *_python_files("pages")]
    for f in files:
        tree = ast.parse(f.read_text(encoding="utf-8"))
        package = _module_name(f) if f.name == "__init__.py" else _module_name(f).rpartition(".")[0]
        core_aliases = set()
        for node in ast.walk(tree):
            if isinstance(node, ast.ImportFrom):
                if node.level:
                    base = package.split(".")[: len(package.split(".")) - (node.level - 1)]
                    target = ".".join(base + ([node.module] if node.module else []))
                else:
                    target = node.module or ""
                if _top(target) not in ("aerostat_core", "app_ui"):
                    continue
                for a in node.names:
                    if a.name.startswith("_") and not a.name.startswith("__"):
                        bad.append(f"{f.relative_to(ROOT)}:{node.lineno} imports {target}.{a.name}")
                    elif _is_module(f"{target}.{a.name}"):
                        core_aliases.add(a.asname or a.name)
            elif isinstance(node, ast.Import):
                core_aliases |= {
                    a.asname or a.name
                    for a in node.names
                    if _top(a.name) in ("aerostat_core", "app_ui")
                }
        for node in ast.walk(tree):
            if (
                isinstance(node, ast.Attribute)
                and isinstance(node.value, ast.Name)
                and node.value.id in core_aliases
                and node.attr.startswith("_")
                and not node.attr.startswith("__")
            ):
                bad.append(f"{f.relative_to(ROOT)}:{node.lineno} uses {node.value.id}.{node.attr}")
    assert not bad, "\n".join(bad)


def test_ui_layer_imports_the_core_and_ui_libraries_only() -> None:
    bad = _violations(
        _python_files("app_ui"),
        lambda n: _top(n) in STDLIB | UI_THIRD_PARTY | {"aerostat_core", "app_ui"},
    )
    assert not bad, "\n".join(bad)


def test_pages_use_the_ui_layer_and_only_the_public_faces_of_the_core() -> None:
    def allowed(name: str) -> bool:
        if _top(name) == "aerostat_core":
            return any(name == f or name.startswith(f + ".") for f in PAGE_FACES[1:]) or (
                name == "aerostat_core"
            )
        return _top(name) in STDLIB | PAGE_THIRD_PARTY | {"app_ui"}

    bad = _violations(_python_files("pages"), allowed)
    assert not bad, (
        "pages may import app_ui and the core's faces (docs/architecture.md §2.3):\n"
        + "\n".join(bad)
    )


def test_app_entry_point_imports_streamlit_and_the_ui_layer_only() -> None:
    bad = _violations(
        _python_files("app.py"), lambda n: _top(n) in STDLIB | {"streamlit", "app_ui"}
    )
    assert not bad, "\n".join(bad)


@pytest.mark.parametrize("package", ["tests", "benchmarks"])
def test_nothing_outside_tests_and_benchmarks_imports_them(package: str) -> None:
    others = [
        p for p in ("aerostat_core", "app_ui", "pages", "benchmarks", "app.py") if p != package
    ]
    bad = _violations(_python_files(*others), lambda n: _top(n) != package)
    assert not bad, "\n".join(bad)


def test_method_page_shows_the_design_documents() -> None:
    from streamlit.testing.v1 import AppTest

    at = AppTest.from_file(str(ROOT / "pages" / "6_Method.py"), default_timeout=120).run()
    assert not at.exception
    assert any(e.label.startswith("Design documents (docs/)") for e in at.expander)
    for doc in DOC_NAMES:
        at.radio(key="method_doc").set_value(f"docs/{doc}.md").run()
        assert not at.exception
        first_line = (DOCS / f"{doc}.md").read_text(encoding="utf-8").splitlines()[0]
        assert any(first_line in str(m.value) for m in at.markdown), doc
