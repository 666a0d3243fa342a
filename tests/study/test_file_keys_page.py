"""The study file's reference page is generated from the declarations the study reader reads."""

from __future__ import annotations

import importlib
import re
import sys
from pathlib import Path

import pytest

from regimemap.caisson.file_keys import DESIGN_KEYS, WIDTH_RANGE
from regimemap.io.toml_keys import Key
from regimemap.lifetime.file_keys import LIFETIME_KEYS
from regimemap.study import file_sections as study_sections

DOCS = Path(__file__).resolve().parents[2] / "docs"


@pytest.fixture
def page_module(monkeypatch):
    monkeypatch.syspath_prepend(str(DOCS / "_ext"))
    sys.modules.pop("regimemap_study_keys", None)
    return importlib.import_module("regimemap_study_keys")


def _rows(rst: str, title: str) -> dict[str, str]:
    """The ``key -> accepted`` rows of the list-table under ``title``."""
    part = rst.split(f"\n{title}\n", 1)[1] if not rst.startswith(title) else rst[len(title):]
    part = re.split(r"\n\S[^\n]*\n~+\n", part, maxsplit=1)[0]
    return dict(re.findall(r"   \* - ``(.+?)``\n     - (.+)", part))


def _accepted(keys: dict) -> dict[str, str]:
    return {k: spec.accepted for k, spec in keys.items()}


def test_every_key_of_every_part_is_on_the_page_with_what_it_accepts(page_module):
    rst = page_module.study_keys_rst()
    top = _rows(rst, "The top level")
    assert {k: top[k] for k in study_sections.STUDY_KEYS} == _accepted(study_sections.STUDY_KEYS)
    assert {f"[{t}]" for t in study_sections.DESIGN_TABLES} <= set(top)
    assert _rows(rst, "[[section]]") == _accepted(study_sections.SECTION_KEYS)
    assert _rows(rst, "[[scenario]]") == _accepted(study_sections.SCENARIO_KEYS)
    section_intro = rst.split("\n[[section]]\n", 1)[1].split(".. list-table::")[0]
    changed = section_intro.split("``[lifetime]``: ")[1].split(" -- ")[0].split(", ")
    fixed = section_intro.split("The study fixes ")[1].split(" of ``[lifetime]``")[0].split(", ")
    assert changed == [f"``{k}``" for k in LIFETIME_KEYS if k not in study_sections.STUDY_WIDE]
    assert fixed == [f"``{k}``" for k in study_sections.STUDY_WIDE]
    for key in DESIGN_KEYS["site"]:
        assert f"``{key}``" in section_intro.split("``[caisson]``")[0]
    limits = _rows(rst, "The sea level of every service year")
    assert set(limits) == {"hc - rise", "d + rise", "h' + rise", "h + rise"}
    assert DESIGN_KEYS["caisson"]["crest"].accepted in limits["hc - rise"]
    assert f"{WIDTH_RANGE[0]:g} <= width <= {WIDTH_RANGE[1]:g}" in rst


def test_a_new_declared_key_appears_on_the_page(page_module, monkeypatch):
    monkeypatch.setitem(study_sections.SCENARIO_KEYS, "surge_factor",
                        Key("a table {year = factor > 0} on surges", kind="table"))
    assert _rows(page_module.study_keys_rst(), "[[scenario]]")["surge_factor"] == (
        "a table {year = factor > 0} on surges")


def test_the_page_is_in_the_guide_and_uses_the_directive():
    page = (DOCS / "guide" / "study-file.rst").read_text(encoding="utf-8")
    assert ".. regimemap-study-keys::" in page and "regimemap study --example" in page
    toctree = (DOCS / "guide" / "index.md").read_text(encoding="utf-8").split("```{toctree}")[1]
    assert "\nstudy-file\n" in toctree
    ext = (DOCS / "_ext" / "regimemap_docs.py").read_text(encoding="utf-8")
    assert 'app.add_directive("regimemap-study-keys", StudyKeys)' in ext
