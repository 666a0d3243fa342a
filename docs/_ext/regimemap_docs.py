"""Sphinx extension of the regimemap documentation: what Sphinx's own extensions do not do.

The API pages are autosummary's, autodoc's and numpydoc's (``regimemap_api``
computes the entries autosummary's template cannot find alone).  What is left
here, none of which autosummary, autodoc, numpydoc, sphinx-click or
sphinx-gallery does: the design-file reference from the reader's own tables;
commands run at build time (``regimemap_run``); an image scraper for Figures
made without pyplot; ``|`` of formulas in docstrings and click's help kept as
text rather than read as reST substitutions; a warning for a broken Python
cross-reference in the hand-written pages only; the docstrings' doctests run
in their module's namespace; MathJax copied from an installed package so that
the site reads offline.

Directives
----------
``regimemap-design-keys``
    Every table and key of the caisson design file, with what the reader
    accepts (range and unit), whether it is required and its default, read
    from the tables :mod:`regimemap.caisson.file` validates against (``_SPEC``,
    ``LIFETIME_KEYS``, ``ERROR_FACTORS``) and the defaults of its dataclasses.
``regimemap-study-keys``
    Every key of the study file (``regimemap study``), from the declarations its reader
    reads (:mod:`regimemap_study_keys`).
``regimemap-run``, ``regimemap-file NAME``
    Commands run when the pages are built, and the files they read: in
    ``regimemap_run`` (set up from here; :func:`run_command` is importable
    from here too, for the pages' ``testsetup`` blocks).

Gallery
-------
:func:`figure_scraper` is the sphinx-gallery image scraper: regimemap draws on
matplotlib ``Figure`` objects without pyplot, so the scraper saves the Figures
that an example's code block left in its global variables.

Cross-references
----------------
A Python cross-reference that does not resolve in a page written for the site
(the index, the guide, the gallery) is a warning (``nitpicky`` stays off for
the docstrings, whose types name numpy's and matplotlib's classes).
"""

from __future__ import annotations

import dataclasses
import importlib
import re
import shutil
import weakref
from pathlib import Path
from typing import Any

from docutils import nodes
from regimemap_run import run_command
from sphinx.application import Sphinx
from sphinx.util import logging
from sphinx.util.docutils import SphinxDirective

__all__ = ["MATHJAX_DIR", "MATHJAX_FILE", "figure_scraper", "local_mathjax", "run_command"]

logger = logging.getLogger(__name__)

# -- the gallery's image scraper --------------------------------------------------------------

_SCRAPED: weakref.WeakSet[Any] = weakref.WeakSet()


def _figures_in(value: Any) -> list[Any]:
    from matplotlib.figure import Figure

    if isinstance(value, Figure):
        return [value]
    if isinstance(value, dict):
        return [v for v in value.values() if isinstance(v, Figure)]
    if isinstance(value, (list, tuple)):
        return [v for v in value if isinstance(v, Figure)]
    return []


def figure_scraper(block: Any, block_vars: dict[str, Any], gallery_conf: dict[str, Any],
                   **kwargs: Any) -> str:
    """Save the matplotlib Figures a code block left in the example's globals (in their order).

    A Figure held in a variable (or in a dict, list or tuple held in one) is
    saved once, the first time a block ends with it, at its own size and
    resolution: what ``regimemap.drawing.save_figure`` writes.
    """
    from sphinx_gallery.scrapers import figure_rst

    found: list[Any] = []
    for value in list(block_vars["example_globals"].values()):
        for fig in _figures_in(value):
            if fig not in _SCRAPED and all(fig is not f for f in found):
                found.append(fig)
    paths = []
    for fig, path in zip(found, block_vars["image_path_iterator"]):
        fig.savefig(path, dpi=fig.dpi)
        _SCRAPED.add(fig)
        paths.append(path)
    return figure_rst(paths, gallery_conf["src_dir"])


# -- the design-file reference ----------------------------------------------------------------

def _default_text(value: Any) -> str:
    if value is dataclasses.MISSING or value is None:
        return ""
    if isinstance(value, bool):
        return "``true``" if value else "``false``"
    if isinstance(value, str):
        return f'``"{value}"``'
    return f"``{value!r}``"


def _defaults(spec_class: Any) -> dict[str, Any]:
    out: dict[str, Any] = {}
    for f in dataclasses.fields(spec_class):
        if f.default is not dataclasses.MISSING:
            out[f.name] = f.default
        elif f.default_factory is not dataclasses.MISSING:
            out[f.name] = f.default_factory()
    return out


def _cell(text: str) -> str:
    return " ".join(str(text).split()).replace("*", r"\*").replace("|", r"\|")


class DesignKeys(SphinxDirective):
    """``.. regimemap-design-keys::``: every table and key of the design file, from the reader."""

    has_content = False

    def run(self) -> list[nodes.Node]:
        from regimemap.caisson import file as design
        from regimemap.caisson.file_keys import DESIGN_KEYS as spec
        from regimemap.caisson.file_keys import DESIGN_TABLES as classes
        lines: list[str] = []
        for table, keys in spec.items():
            defaults = _defaults(classes[table])
            lines += self._table(f"[{table}]", [
                (key, "required" if getattr(k, "required", True) else "optional", k.accepted,
                 _default_text(defaults.get(key)))
                for key, k in keys.items()])
        from regimemap.lifetime.file_keys import LIFETIME_TABLES as lifetime_tables

        if lifetime_tables:
            spec_defaults = _defaults(design.LifetimeSpec)
            from regimemap.lifetime import DEFAULT_ERRORS

            for table, keys in lifetime_tables.items():
                rows = []
                for key, k in keys.items():
                    if table == "lifetime":
                        default = spec_defaults.get(key)
                        if key == "errors" or isinstance(default, dict):
                            default = None
                    else:
                        factor = getattr(DEFAULT_ERRORS, key, None)
                        default = None if factor is None else f"[{factor.ratio:g}, {factor.cov:g}]"
                    text = (f"``{default}``" if isinstance(default, str)
                            else _default_text(default))
                    rows.append((key, k.kind, k.accepted, text))
                lines += self._table(f"[{table}]", rows, second="kind")
        return self.parse_text_to_nodes("\n".join(lines), allow_section_headings=True)

    @staticmethod
    def _table(title: str, rows: list[tuple[str, str, str, str]], second: str = "required") -> list[str]:
        out = [f"``{title}``", "~" * (len(title) + 4), "",
               ".. list-table::", "   :header-rows: 1", "   :widths: 18 12 55 15",
               "   :class: regimemap-design-keys", "",
               "   * - key", f"     - {second}", "     - accepted (unit)", "     - default"]
        for key, kind, accepted, default in rows:
            out += [f"   * - ``{key}``", f"     - {kind}", f"     - {_cell(accepted)}",
                    f"     - {default}" if default else "     -"]
        return out + [""]


class StudyKeys(SphinxDirective):
    """``.. regimemap-study-keys::``: every key of the study file, from its reader's declarations
    (:func:`regimemap_study_keys.study_keys_rst`)."""

    has_content = False

    def run(self) -> list[nodes.Node]:
        from regimemap_study_keys import study_keys_rst

        return self.parse_text_to_nodes(study_keys_rst(), allow_section_headings=True)


# -- docstrings: plain-text |x| is not a substitution ---------------------------------------

_INLINE_CODE = re.compile(r"(``.+?``|:[\w:.-]+:`[^`]*`|`[^`]*`_?)")


def _escape_pipes(text: str) -> str:
    """``|a|`` written as plain text (an absolute value) is not a reST substitution: escape it."""
    parts = _INLINE_CODE.split(text)
    return "".join(part if i % 2 else part.replace("|", r"\|") for i, part in enumerate(parts))


_DIRECTIVE = re.compile(r"\.\.\s+([\w:-]+)::")
#: Directives whose content is code, not reST: their ``|`` stay as written.
_LITERAL_DIRECTIVES = frozenset({"code-block", "code", "sourcecode", "math", "doctest", "testcode",
                                 "testoutput", "testsetup", "testcleanup", "raw", "parsed-literal",
                                 "literalinclude", "highlight"})


def _escape_lines(lines: list[str]) -> None:
    """Escape, in place, the ``|`` of formulas written as text (``|k'|``, ``|ak+b|``).

    The docstrings and the commands' help are plain text, not reST with
    substitutions: outside literal blocks, doctests, code directives and inline
    literals, ``|`` is an ordinary character.  The bar that starts a line of a
    line block (``| ...``, sphinx-click's rendering of click's ``\\b``
    paragraphs) is kept.
    """
    block_indent: int | None = None   # inside a literal block or a directive: its indent
    after_marker, marker_indent = False, 0
    in_doctest = False
    for i, line in enumerate(lines):
        stripped = line.strip()
        indent = len(line) - len(line.lstrip())
        if not stripped:
            in_doctest = False
            continue
        if block_indent is not None:
            if indent > block_indent:
                continue
            block_indent = None
        if after_marker:
            after_marker = False
            if indent > marker_indent:
                block_indent = marker_indent
                continue
        if in_doctest or stripped.startswith(">>>"):
            in_doctest = True
            continue
        directive = _DIRECTIVE.match(stripped)
        if directive is not None and directive.group(1) in _LITERAL_DIRECTIVES or (
                directive is None and stripped.endswith("::")):
            after_marker, marker_indent = True, indent   # literal content follows
        if stripped.startswith(".. "):
            continue
        if "|" not in line:
            continue
        if stripped == "|" or stripped.startswith("| "):  # a line of a line block
            bar = line.index("|") + 1
            lines[i] = line[:bar] + _escape_pipes(line[bar:])
        else:
            lines[i] = _escape_pipes(line)


def _plain_pipes(app: Sphinx, what: str, name: str, obj: Any, options: Any, lines: list[str]) -> None:
    """``autodoc-process-docstring``: :func:`_escape_lines` on every docstring."""
    _escape_lines(lines)


def _plain_pipes_click(app: Sphinx, ctx: Any, lines: list[str]) -> None:
    """``sphinx-click-process-*``: :func:`_escape_lines` on the commands' help."""
    _escape_lines(lines)


def _skip_foreign(app: Sphinx, what: str, name: str, obj: Any, skip: bool, options: Any) -> bool | None:
    """Leave out members that matplotlib makes for every Artist subclass (``set``)."""
    module = getattr(obj, "__module__", None)
    if isinstance(module, str) and module.startswith("matplotlib"):
        return True
    return None


# -- broken cross-references in the hand-written pages ----------------------------------------

#: Pages whose Python cross-references must all resolve: those written for the site (the
#: docstrings' references to types of numpy, matplotlib ... are not checked).
CHECKED_PAGES = ("index", "notes")
CHECKED_FOLDERS = ("guide/", "auto_examples/")


def _missing_reference(app: Sphinx, env: Any, node: Any, contnode: Any) -> None:
    doc = node.get("refdoc", "")
    if node.get("refdomain") == "py" and (doc in CHECKED_PAGES or doc.startswith(CHECKED_FOLDERS)):
        logger.warning("broken cross-reference %s:%s %r", node.get("refdomain"), node.get("reftype"),
                       node.get("reftarget"), location=node)
    return None


# -- the docstrings' examples run in their module's namespace ----------------------------------

_DOCSTRING_OF = re.compile(r"docstring of ([\w.]+)")


def _module_of(path: str) -> str | None:
    """The longest importable module prefix of a dotted path."""
    parts = path.split(".")
    for n in range(len(parts), 0, -1):
        name = ".".join(parts[:n])
        try:
            importlib.import_module(name)
        except ImportError:
            continue
        return name
    return None


def _docstring_doctests(app: Sphinx, doctree: nodes.document) -> None:
    """Give the ``>>>`` examples of each docstring shown by autodoc a group of their own.

    The group starts from the globals of the docstring's module, as ``python -m
    doctest`` and ``pytest --doctest-modules`` run them (the examples use the
    module's names without importing them); the examples of the hand-written
    pages stay in the page's ``default`` group.
    """
    setups: dict[str, nodes.Node] = {}
    for block in list(doctree.findall(nodes.doctest_block)):
        match = _DOCSTRING_OF.search(block.source or "")
        if match is None:
            continue
        module = _module_of(match.group(1))
        if module is None:
            continue
        group = match.group(1)
        block["groups"] = [group]
        if group not in setups:
            code = (f"import importlib as _importlib\n"
                    f"globals().update(vars(_importlib.import_module({module!r})))")
            setup = nodes.comment(code, code, testnodetype="testsetup", groups=[group])
            setups[group] = setup
            block.parent.insert(block.parent.index(block), setup)


# -- MathJax from the docs' own dependencies, so that the site reads offline ------------------

#: Where the site keeps its copy of MathJax, under ``_static``.
MATHJAX_DIR = "mathjax"
MATHJAX_FILE = "tex-mml-chtml.js"


def local_mathjax() -> Path | None:
    """MathJax 3's ``es5`` folder of the ``django-static-mathjax`` package, if it is installed."""
    import importlib.util

    spec = importlib.util.find_spec("mathjax")
    if spec is None or not spec.submodule_search_locations:
        return None
    es5 = Path(list(spec.submodule_search_locations)[0]) / "static" / "mathjax" / "es5"
    return es5 if (es5 / MATHJAX_FILE).is_file() else None


def _copy_mathjax(app: Sphinx, exception: Exception | None) -> None:
    """Copy MathJax's combined component and its web fonts into ``_static/mathjax``."""
    es5 = local_mathjax()
    if exception is not None or es5 is None or app.builder.format != "html":
        return
    target = Path(app.outdir) / "_static" / MATHJAX_DIR
    (target / "output" / "chtml").mkdir(parents=True, exist_ok=True)
    shutil.copy2(es5 / MATHJAX_FILE, target / MATHJAX_FILE)
    fonts = es5 / "output" / "chtml" / "fonts"
    shutil.copytree(fonts, target / "output" / "chtml" / "fonts", dirs_exist_ok=True)


def setup(app: Sphinx) -> dict[str, Any]:
    app.add_directive("regimemap-design-keys", DesignKeys)
    app.add_directive("regimemap-study-keys", StudyKeys)
    app.setup_extension("regimemap_run")
    app.connect("missing-reference", _missing_reference)
    app.connect("autodoc-process-docstring", _plain_pipes, priority=600)
    app.connect("autodoc-skip-member", _skip_foreign)
    for part in ("description", "usage", "options", "arguments", "envars", "epilog"):
        event = f"sphinx-click-process-{part}"
        if event in app.events.events:
            app.connect(event, _plain_pipes_click)
    app.connect("doctree-read", _docstring_doctests)
    app.connect("build-finished", _copy_mathjax)
    return {"version": "1", "parallel_read_safe": True, "parallel_write_safe": True}

