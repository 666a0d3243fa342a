"""Every example of README.md runs (shell blocks with the installed `regimemap`, Python blocks).

One test per block, so that pytest-xdist spreads them over the cores.  A block
that reads a file an earlier block writes (``regimemap lifetime goda.toml``
after ``regimemap caisson --example > goda.toml``) runs in the same test, after
that block, in the same folder: the blocks are grouped by the files they pass on.

The README is the landing page: the rest of the examples live in the
documentation site (docs/guide/), where ``make docs`` runs them (the pages'
``regimemap-run`` commands in the html build, their Python in the doctest
build; docs/guide/development.md says which runs where).
"""

from __future__ import annotations

import os
import re
import subprocess
import sys
from pathlib import Path

import pytest

README = Path(__file__).resolve().parents[1] / "README.md"
BIN = str(Path(sys.executable).parent)


def _blocks() -> list[tuple[str, str]]:
    out = []
    for lang, body in re.findall(r"```(\w+)\n(.*?)```", README.read_text(encoding="utf-8"), re.S):
        if lang == "console":
            cmds = [line[2:].split("  #")[0] for line in body.splitlines() if line.startswith("$ ")]
            body = "\n".join(c for c in cmds if not c.startswith("make "))
            lang = "sh"
        elif lang in ("sh", "bash"):
            if "make figures" in body or "make test" in body:
                continue  # the README's set-up commands: CI runs `make test` itself
            body = body.replace(".venv/bin/", "")
        elif lang != "python":
            continue
        if body.strip():
            out.append((lang, body))
    return out


BLOCKS = _blocks()

#: A file name in a block (``map.npz``, ``goda.toml``, ``caissons.csv`` ...).
_FILE = r"(?<![\w.-])[\w.-]+\.(?:csv|npz|json|toml|png|svg|pdf|gif|txt)(?![\w.-])"
#: ... that the block writes: after -o, --plot, --animate, a shell redirection, or saved by Python.
_WRITES = re.compile(rf"(?:(?:-o|--output|--plot|--animate|>)\s+|(?:save_figure|savefig)\([^)]*?[\"'])({_FILE})")


def _writes(body: str) -> set[str]:
    return set(_WRITES.findall(body))


def _reads(body: str) -> set[str]:
    return set(re.findall(_FILE, body)) - _writes(body)


def groups(blocks: list[tuple[str, str]]) -> list[list[int]]:
    """Indices of the blocks, grouped: a block joins the group of the last earlier block that
    writes a file it reads (and so all of that block's own prerequisites); groups in README order."""
    parent = list(range(len(blocks)))

    def root(i: int) -> int:
        while parent[i] != i:
            i = parent[i]
        return i

    for i, (_, body) in enumerate(blocks):
        for name in _reads(body):
            writers = [j for j in range(i) if name in _writes(blocks[j][1])]
            if writers:
                parent[root(i)] = root(writers[-1])
    out: dict[int, list[int]] = {}
    for i in range(len(blocks)):
        out.setdefault(root(i), []).append(i)
    return sorted(out.values())


GROUPS = groups(BLOCKS)


def _group_id(group: list[int]) -> str:
    return "+".join(f"{i}-{BLOCKS[i][0]}" for i in group)


#: The five commands of the README's tour.
TOUR = ("plot", "classify", "caisson", "simulate", "lifetime")


def test_readme_has_examples():
    langs = {lang for lang, _ in BLOCKS}
    assert {"sh", "python"} <= langs and len(BLOCKS) >= 6
    commands = {m for _, body in BLOCKS for m in re.findall(r"^regimemap (\w+)", body, re.M)}
    assert set(TOUR) <= commands, f"the tour lacks {set(TOUR) - commands}"


def test_readme_links_resolve():
    """Every relative link and image of the README names a file of the repository."""
    text = README.read_text(encoding="utf-8")
    targets = re.findall(r"\]\(([^)#\s]+)(?:#[^)]*)?\)", text)
    local = [t for t in targets if "://" not in t]
    assert local, "the README links into the docs"
    missing = [t for t in local if not (README.parent / t).exists()]
    assert not missing, f"README links to missing files: {missing}"


def test_blocks_that_read_files_run_after_the_blocks_that_write_them():
    """The grouping (checked on a made-up README): a reader joins its writer, in order; others alone."""
    made_up = [("sh", "regimemap export -o map.npz"), ("python", "np.load('map.npz')"),
               ("sh", "cat > c.csv <<'EOF'\nk,mu\nEOF"), ("sh", "regimemap plot -o map.svg"),
               ("python", "read_points_csv('c.csv')"), ("sh", "regimemap outcome -o map.npz"),
               ("python", "np.load('map.npz')")]
    assert groups(made_up) == [[0, 1], [2, 4], [3], [5, 6]]


@pytest.mark.subprocess  # the installed regimemap, python -c
@pytest.mark.slow  # seconds a block
@pytest.mark.parametrize("group", GROUPS, ids=_group_id)
@pytest.mark.deep
def test_readme_examples_run(group, tmp_path):
    """The blocks of one group run in order in one folder of their own."""
    env = dict(os.environ, PATH=BIN + os.pathsep + os.environ.get("PATH", ""), MPLBACKEND="Agg")
    for i in group:
        lang, body = BLOCKS[i]
        cmd = [sys.executable, "-c", body] if lang == "python" else ["bash", "-e", "-c", body]
        r = subprocess.run(cmd, cwd=tmp_path, env=env, capture_output=True, text=True, timeout=300)
        assert r.returncode == 0, f"README example {i} failed:\n{body}\n--- stderr ---\n{r.stderr[-2000:]}"
