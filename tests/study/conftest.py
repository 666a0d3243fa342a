"""The study tests' files: a study's text, built from its tables, and the fixture that writes it.

A study's text is :func:`study_head` (its seed, trials and base), then its tables, each after a
blank line (:func:`section_table`, :func:`scenario_table`), as the tests' files have always been
written (their line numbers are asserted).  :data:`SITE` is the site of a section on the example design's
(8 m of water, the armour 4.5 m and the base 5.5 m deep).
"""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

import pytest

#: The keys of a section's site: 8 m of water, the armour 4.5 m and the base 5.5 m deep.
SITE = ("depth = 8.0", "armour_depth = 4.5", "base_depth = 5.5")


def study_head(seed: int, trials: int) -> str:
    """The top of a study: its seed, trials and base file (``goda.toml``)."""
    return f'seed = {seed}\ntrials = {trials}\nbase = "goda.toml"\n'


def section_table(name: str, chainage: float, *keys: str) -> str:
    """A ``[[section]]`` table after a blank line: its name, chainage and ``keys`` (a line each)."""
    return f'\n[[section]]\nname = "{name}"\nchainage = {chainage}\n' + "".join(f"{key}\n" for key in keys)


def scenario_table(name: str, *keys: str) -> str:
    """A ``[[scenario]]`` table after a blank line: its name and ``keys`` (a line each)."""
    return f'\n[[scenario]]\nname = "{name}"\n' + "".join(f"{key}\n" for key in keys)


@pytest.fixture
def write_study(goda: Path) -> Callable[..., Path]:
    """``write_study(text, name="study.toml")``: ``text`` as ``tmp_path/name``, next to its base,
    Goda's caisson (``tmp_path/goda.toml``, the ``goda`` fixture); the study file's path."""

    def write(text: str, name: str = "study.toml") -> Path:
        path = goda.parent / name
        path.write_text(text)
        return path

    return write
