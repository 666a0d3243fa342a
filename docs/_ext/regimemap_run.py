"""The ``regimemap-run`` and ``regimemap-file`` directives: commands run when the pages are built.

``regimemap-run``
    Runs ``regimemap`` commands (one a line, ``> FILE`` to send the output to
    a file) in a folder of the page's own and shows each command with what it
    printed.  A command that fails is a build warning, so a broken example
    fails ``make docs``.  :func:`run_command` runs one such line (the pages'
    ``testsetup`` blocks use it, as ``regimemap_docs.run_command``, to make the
    files their doctests read).
``regimemap-file NAME``
    A file (a CSV of points, a pulse) written into the folder of the page's
    commands, for the commands after it, and shown.

Set up by ``regimemap_docs``.
"""

from __future__ import annotations

import os
import shlex
import shutil
import tempfile
from pathlib import Path
from typing import Any

from docutils import nodes
from docutils.parsers.rst import directives
from sphinx.application import Sphinx
from sphinx.util import logging
from sphinx.util.docutils import SphinxDirective

logger = logging.getLogger(__name__)

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
    when none exists the commands are shown, marked as not run, and not run), ``:exit-code: N``
    (the exit status every command is expected to end with, 0 by default: ``--check`` of a
    design that fails exits 1; any other status is a warning).
    """

    has_content = True
    option_spec = {"hide-output": directives.flag, "max-lines": directives.nonnegative_int,
                   "output-language": directives.unchanged, "copy-first": directives.unchanged,
                   "exit-code": directives.nonnegative_int}

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
            if result.exit_code != self.options.get("exit-code", 0):
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


def setup(app: Sphinx) -> dict[str, Any]:
    app.add_directive("regimemap-run", RunCommands)
    app.add_directive("regimemap-file", WriteFile)
    app.connect("build-finished", _remove_run_folders)
    return {"version": "1", "parallel_read_safe": True, "parallel_write_safe": True}
