"""Sphinx extension of the regimemap documentation: pages generated from the code at build time.

Directives
----------
``regimemap-api PACKAGE``
    The API reference of one public package: a table of the names of its
    ``__all__`` (each linked to where it is defined), then every public
    submodule with the members of its own ``__all__`` that it defines
    (autodoc).  The package's lazy names (PEP 562) are resolved here, so
    autodoc documents the real objects, once each, at their home.
``regimemap-design-keys``
    Every table and key of the caisson design file, with what the reader
    accepts (range and unit), whether it is required and its default, read
    from the tables :mod:`regimemap.io.design` validates against (``_SPEC``,
    ``LIFETIME_KEYS``, ``ERROR_FACTORS``) and the defaults of its dataclasses.
``regimemap-run``
    Runs ``regimemap`` commands (one a line, ``> FILE`` to send the output to
    a file) in a folder of the page's own and shows each command with what it
    printed.  A command that fails is a build warning, so a broken example
    fails ``make docs``.  :func:`run_command` runs one such line (the pages'
    ``testsetup`` blocks use it to make the files their doctests read).
``regimemap-file NAME``
    A file (a CSV of points, a pulse) written into the folder of the page's
    commands, for the commands after it, and shown.

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

import ast
import dataclasses
import importlib
import inspect
import os
import pkgutil
import re
import shlex
import shutil
import tempfile
import types
import weakref
from pathlib import Path
from typing import Any

from docutils import nodes
from docutils.parsers.rst import directives
from sphinx.application import Sphinx
from sphinx.util import logging
from sphinx.util.docutils import SphinxDirective

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


# -- the API reference ------------------------------------------------------------------------

def _public_submodules(package: Any) -> list[Any]:
    if not hasattr(package, "__path__"):
        return []
    out = []
    for info in sorted(pkgutil.iter_modules(package.__path__), key=lambda i: i.name):
        if info.name.startswith("_"):
            continue
        module = importlib.import_module(f"{package.__name__}.{info.name}")
        out.append(module)
        # a subpackage without a public API of its own (drawing's rooms): its modules here too
        if info.ispkg and not hasattr(module, "__all__"):
            out += _public_submodules(module)
    return out


_DEFINED: dict[str, set[str]] = {}


def _defined_names(module: Any) -> set[str]:
    """Names a module binds at its top level itself (def, class, assignment), not by import."""
    name = module.__name__
    if name not in _DEFINED:
        tree = ast.parse(inspect.getsource(module))
        names: set[str] = set()
        for node in tree.body:
            if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)):
                names.add(node.name)
            elif isinstance(node, ast.Assign):
                for target in node.targets:
                    for t in ast.walk(target):
                        if isinstance(t, ast.Name):
                            names.add(t.id)
            elif isinstance(node, ast.AnnAssign) and isinstance(node.target, ast.Name):
                names.add(node.target.id)
        _DEFINED[name] = names
    return _DEFINED[name]


def _home(obj: Any, name: str, candidates: list[Any]) -> str | None:
    """The module that defines ``obj`` (known as ``name``), among ``candidates`` first."""
    for module in candidates:
        if name in _defined_names(module) and getattr(module, name, None) is obj:
            return str(module.__name__)
    mod = getattr(obj, "__module__", None)
    if isinstance(mod, str) and mod.startswith("regimemap"):
        module = importlib.import_module(mod)
        if name in _defined_names(module):
            return mod
    return None


def _all_modules() -> list[Any]:
    import regimemap

    out = []
    for info in pkgutil.walk_packages(regimemap.__path__, "regimemap."):
        if any(part.startswith("_") for part in info.name.split(".")):
            continue
        out.append(importlib.import_module(info.name))
    return out


def _role(obj: Any) -> str:
    if inspect.isclass(obj):
        return "class"
    if inspect.isroutine(obj):
        return "func"
    if inspect.ismodule(obj):
        return "mod"
    return "data"


def _summary(obj: Any, home: str | None, name: str) -> str:
    if _role(obj) == "data":
        from sphinx.pycode import ModuleAnalyzer

        if home is None:
            return ""
        docs = ModuleAnalyzer.for_module(home).find_attr_docs()
        lines = docs.get(("", name), [])
        text = " ".join(line.strip() for line in lines if line.strip())
    else:
        doc = inspect.getdoc(obj) or ""
        text = " ".join(doc.strip().split("\n\n")[0].split())
    return _escape_pipes(text)


def _is_alias(obj: Any) -> bool:
    """A type alias (``Interval = tuple[np.ndarray, np.ndarray]``), which autodoc cannot sign."""
    return isinstance(obj, types.GenericAlias) or type(obj).__module__ == "typing" or (
        type(obj).__name__ in ("UnionType", "TypeAliasType"))


def _alias_lines(module: Any, name: str) -> list[str]:
    from sphinx.pycode import ModuleAnalyzer

    source = inspect.getsource(module)
    value = ""
    for node in ast.parse(source).body:
        target = node.targets[0] if isinstance(node, ast.Assign) and len(node.targets) == 1 else (
            node.target if isinstance(node, ast.AnnAssign) else None)
        if isinstance(target, ast.Name) and target.id == name and node.value is not None:
            value = " ".join((ast.get_source_segment(source, node.value) or "").split())
    doc = ModuleAnalyzer.for_module(module.__name__).find_attr_docs().get(("", name), [])
    # not indexed: two modules may name an alias alike (Box), and an annotation that names
    # it would then find two targets
    out = [f".. py:data:: {name}", f"   :module: {module.__name__}", "   :no-index:"]
    if value:
        out.append(f"   :value: {value}")
    out.append("")
    out += [f"   {line}" for line in doc if line.strip()] or ["   A type alias."]
    return out + [""]


class PublicApi(SphinxDirective):
    """``.. regimemap-api:: regimemap.maps`` (options ``:no-modules:``)."""

    required_arguments = 1
    option_spec = {"no-modules": directives.flag}

    def run(self) -> list[nodes.Node]:
        name = self.arguments[0]
        package = importlib.import_module(name)
        submodules = _public_submodules(package)
        everywhere = _all_modules()
        public = list(getattr(package, "__all__", []))
        lines: list[str] = []
        here: list[tuple[str, str]] = []  # documented on this page under the package's name
        rows: list[str] = []
        for public_name in public:
            obj = getattr(package, public_name)
            home = _home(obj, public_name, submodules + everywhere)
            role = _role(obj)
            if home is None:
                here.append((public_name, role))
                target = f"{name}.{public_name}"
            else:
                target = f"{home}.{public_name}"
            summary = _summary(obj, home, public_name)
            rows += [f"   * - :py:{'obj' if role == 'data' else role}:`{public_name} <{target}>`",
                     f"     - {summary}" if summary else "     -"]
        if rows:
            lines += ["Public names", "-" * 12, "",
                      f"``{name}.__all__``: what ``from {name} import ...`` gives; each name is "
                      "linked to the module that defines it.", "",
                      ".. list-table::", "   :class: regimemap-api-summary", "   :widths: 28 72", ""]
            lines += rows + [""]
        for public_name, role in here:
            directive = {"class": "autoclass", "func": "autofunction"}.get(role, "autodata")
            lines += [f".. {directive}:: {name}.{public_name}", ""]
        if "no-modules" not in self.options:
            for module in submodules:
                defined = _defined_names(module)
                members = [n for n in getattr(module, "__all__", []) if n in defined]
                aliases = [n for n in members if _is_alias(getattr(module, n))]
                members = [n for n in members if n not in aliases]
                title = module.__name__
                lines += [title, "-" * len(title), "", f".. automodule:: {module.__name__}"]
                lines += [f"   :members: {', '.join(members)}"] if members else ["   :no-members:"]
                lines += [""]
                for alias in aliases:
                    lines += _alias_lines(module, alias)
        return self.parse_text_to_nodes("\n".join(lines), allow_section_headings=True)


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
        from regimemap.io import design
        from regimemap.io.design_keys import DESIGN_KEYS as spec
        classes = {"site": design.SiteSpec, "wave": design.WaveSpec, "caisson": design.CaissonSpec}
        lines: list[str] = []
        for table, keys in spec.items():
            defaults = _defaults(classes[table]) if table in classes else {}
            lines += self._table(f"[{table}]", [
                (key, "required" if getattr(k, "required", True) else "optional", k.accepted,
                 _default_text(defaults.get(key)))
                for key, k in keys.items()])
        from regimemap.io.design_lifetime_keys import LIFETIME_TABLES as lifetime_tables

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


# -- commands run at build time ---------------------------------------------------------------

def _run_folder(app: Sphinx, docname: str) -> Path:
    folders: dict[str, str] = app.__dict__.setdefault("_regimemap_run_folders", {})
    if docname not in folders:
        folders[docname] = tempfile.mkdtemp(prefix="regimemap-docs-")
    return Path(folders[docname])


def run_command(command: str, folder: str | os.PathLike[str] = ".") -> Any:
    """Run one ``regimemap ...`` command line in ``folder``, as :class:`RunCommands` does.

    ``# ...`` ends the command (a comment), ``> FILE`` sends its standard output
    to FILE in ``folder``.  Returns click's ``Result``; raises ``ValueError`` for
    a line that is not a regimemap command.  The doctests of a page call it from
    a ``testsetup`` to make the files that the page's commands write (the
    doctest build does not run the commands of the pages).
    """
    from click.testing import CliRunner

    from regimemap.cli import cli

    words, target = _command_words(command)
    old = os.getcwd()
    try:
        os.chdir(folder)
        result = CliRunner().invoke(cli, words[1:], prog_name="regimemap", catch_exceptions=True)
        if target is not None and result.exit_code == 0:
            Path(target).write_text(result.stdout, encoding="utf-8")
    finally:
        os.chdir(old)
    return result


def _command_words(command: str) -> tuple[list[str], str | None]:
    """The words of a ``regimemap ...`` line (comment removed) and the file after ``>``, if any."""
    words = shlex.split(command, comments=True)
    target = None
    if ">" in words:
        at = words.index(">")
        target, words = words[at + 1], words[:at]
    if not words or words[0] != "regimemap":
        raise ValueError(f"regimemap-run runs regimemap commands only, got {command!r}")
    return words, target


class RunCommands(SphinxDirective):
    """``.. regimemap-run::`` with one ``regimemap ...`` command a line.

    Each command is shown in a console block, what it printed in a block of its
    own.  A command may end with a ``# comment`` (shown, not run).  Options:
    ``:hide-output:`` (show the commands only), ``:max-lines: N`` (the first N
    lines of each output, then ``...``), ``:output-language:`` (the highlighting
    of the outputs, ``text`` by default), ``:copy-first: NAME PATH [PATH ...]`` (copy
    the first of the PATHs that exists -- relative to the repository, such as the
    shared data beside a clone -- to NAME in the folder before the commands run;
    when none exists the commands are shown, marked as not run, and not run).
    """

    has_content = True
    option_spec = {"hide-output": directives.flag, "max-lines": directives.nonnegative_int,
                   "output-language": directives.unchanged, "copy-first": directives.unchanged}

    def _copy_first(self, folder: Path) -> bool:
        name, *paths = self.options["copy-first"].split()
        root = Path(self.env.app.srcdir).parent
        for path in paths:
            if (root / path).is_file():
                shutil.copyfile(root / path, folder / name)
                return True
        logger.info("regimemap-run: none of %s exists: the commands are not run", ", ".join(paths))
        return False

    def run(self) -> list[nodes.Node]:
        folder = _run_folder(self.env.app, self.env.docname)
        if "copy-first" in self.options and not self._copy_first(folder):
            text = "\n".join(f"$ {c.strip()}" for c in self.content if c.strip())
            block = nodes.literal_block(text, text)
            block["language"] = "console"
            note = nodes.paragraph(text=f"(Not run here: {self.options['copy-first'].split()[1]} is absent.)")
            return [block, note]
        blocks: list[tuple[str, list[str]]] = []  # (language, lines)
        for command in (line.strip() for line in self.content):
            if not command:
                continue
            try:
                _, target = _command_words(command)
            except ValueError as exc:
                raise self.error(str(exc)) from None
            result = run_command(command, folder)
            if result.exit_code != 0:
                why = result.stderr.strip() or repr(result.exception)
                logger.warning("regimemap-run: %r exited with %s: %s", command, result.exit_code, why,
                               location=self.get_location())
            if blocks and blocks[-1][0] == "console":
                blocks[-1][1].append(f"$ {command}")
            else:
                blocks.append(("console", [f"$ {command}"]))
            out = result.stdout.rstrip("\n").splitlines()
            if target is None and "hide-output" not in self.options and out:
                limit = self.options.get("max-lines")
                if limit is not None and len(out) > limit:
                    out = out[:limit] + ["..."]
                blocks.append((self.options.get("output-language", "text"), out))
        result_nodes: list[nodes.Node] = []
        for language, text_lines in blocks:
            text = "\n".join(text_lines)
            block = nodes.literal_block(text, text)
            block["language"] = language
            block["classes"].append("regimemap-run-" + ("command" if language == "console" else "output"))
            self.set_source_info(block)
            result_nodes.append(block)
        return result_nodes


class WriteFile(SphinxDirective):
    """``.. regimemap-file:: NAME``: a file of the page's example folder, shown and written.

    The content is written to NAME in the folder where the page's
    ``regimemap-run`` commands run (so that a later command reads it) and shown
    as ``cat > NAME`` would make it.  Option ``:language:`` (``text`` by default).
    """

    has_content = True
    required_arguments = 1
    option_spec = {"language": directives.unchanged}

    def run(self) -> list[nodes.Node]:
        name = self.arguments[0]
        if Path(name).name != name:
            raise self.error(f"regimemap-file writes a file of the page's folder, got {name!r}")
        text = "\n".join(self.content) + "\n"
        (_run_folder(self.env.app, self.env.docname) / name).write_text(text, encoding="utf-8")
        command = f"$ cat {name}"
        shown = nodes.literal_block(command, command)
        shown["language"] = "console"
        shown["classes"].append("regimemap-run-command")
        body = nodes.literal_block(text.rstrip("\n"), text.rstrip("\n"))
        body["language"] = self.options.get("language", "text")
        body["classes"].append("regimemap-run-output")
        for block in (shown, body):
            self.set_source_info(block)
        return [shown, body]


def _remove_run_folders(app: Sphinx, exception: Exception | None) -> None:
    for folder in app.__dict__.get("_regimemap_run_folders", {}).values():
        shutil.rmtree(folder, ignore_errors=True)


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
    app.add_directive("regimemap-api", PublicApi)
    app.add_directive("regimemap-design-keys", DesignKeys)
    app.add_directive("regimemap-run", RunCommands)
    app.add_directive("regimemap-file", WriteFile)
    app.connect("missing-reference", _missing_reference)
    app.connect("autodoc-process-docstring", _plain_pipes, priority=600)
    app.connect("autodoc-skip-member", _skip_foreign)
    for part in ("description", "usage", "options", "arguments", "envars", "epilog"):
        event = f"sphinx-click-process-{part}"
        if event in app.events.events:
            app.connect(event, _plain_pipes_click)
    app.connect("doctree-read", _docstring_doctests)
    app.connect("build-finished", _remove_run_folders)
    app.connect("build-finished", _copy_mathjax)
    return {"version": "1", "parallel_read_safe": True, "parallel_write_safe": True}

