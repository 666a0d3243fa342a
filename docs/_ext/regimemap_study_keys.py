"""The study file's reference (``.. regimemap-study-keys::``), from the declarations its reader reads.

:func:`study_keys_rst` writes the reST of every key of a study file -- the top
level, ``[[section]]``, ``[[scenario]]``, the design tables a section may
change and the limits each scenario's sea level is checked against -- from
:mod:`regimemap.study.file_sections` (``STUDY_KEYS``, ``SECTION_KEYS``,
``SCENARIO_KEYS``, ``OVERRIDABLE``, ``STUDY_WIDE``, ``DESIGN_TABLES``),
:mod:`regimemap.study.file_limits` (``SEA_LEVEL_LIMITS``) and the design file's
declarations (:data:`regimemap.caisson.file_keys.DESIGN_KEYS`,
:data:`regimemap.lifetime.file_keys.LIFETIME_KEYS`), so the page says what
the parser accepts.  regimemap only (no Sphinx): a unit test calls it; the
directive is :mod:`regimemap_docs`'s.
"""

from __future__ import annotations

__all__ = ["study_keys_rst"]


def _cell(text: str) -> str:
    return " ".join(str(text).split()).replace("*", r"\*").replace("|", r"\|")


def _table(title: str, rows: list[tuple[str, str]], intro: str = "", head: str = "key") -> list[str]:
    out = [title, "~" * len(title), ""]
    if intro:
        out += [intro, ""]
    out += [".. list-table::", "   :header-rows: 1", "   :widths: 22 78",
            "   :class: regimemap-study-keys", "", f"   * - {head}", "     - accepted (unit)"]
    for key, accepted in rows:
        out += [f"   * - ``{key}``", f"     - {_cell(accepted)}"]
    return out + [""]


def study_keys_rst() -> str:
    """The reST of the study file's keys: a table per part, then the sea level's limits.

    Returns
    -------
    str
        Sections headed with ``~`` (under the page's ``-`` heading), each a ``list-table``.
    """
    from regimemap.caisson.file_keys import DESIGN_KEYS
    from regimemap.lifetime.file_keys import LIFETIME_KEYS
    from regimemap.study.file_limits import SEA_LEVEL_LIMITS
    from regimemap.study.file_sections import (
        DESIGN_TABLES,
        OVERRIDABLE,
        SCENARIO_KEYS,
        SECTION_KEYS,
        STUDY_KEYS,
        STUDY_WIDE,
    )

    tables = ", ".join(f"``[{t}]``" for t in DESIGN_TABLES)
    lines = _table("The top level", [(k, v.accepted) for k, v in STUDY_KEYS.items()] +
                   [(f"[{t}]", f"the design file's [{t}] table, inline: the base design (over base's)")
                    for t in DESIGN_TABLES],
                   f"The study's own keys, and the design file's tables {tables} "
                   "(:ref:`design-file`) inline or through ``base``.")
    shared = [k for k in STUDY_WIDE if k in LIFETIME_KEYS]
    changed = []
    for table in OVERRIDABLE:
        keys = LIFETIME_KEYS if table == "lifetime" else DESIGN_KEYS[table]
        names = [k for k in keys if not (table == "lifetime" and k in STUDY_WIDE)]
        changed.append(f"``[{table}]``: " + ", ".join(f"``{k}``" for k in names))
    lines += _table("[[section]]", [(k, v.accepted) for k, v in SECTION_KEYS.items()],
                    "One table per section along the breakwater.  Besides these keys, a section changes "
                    "the base design's keys of " + "; ".join(changed) + " -- written bare "
                    "(``depth = 8.0``) or with their table when two tables share the name "
                    "(``caisson.impulsive = false``; ``caisson.width`` for the design's width, a bare "
                    "``width`` being the width simulated); every check of the design file applies.  The "
                    "study fixes " + ", ".join(f"``{k}``" for k in shared) + " of ``[lifetime]`` for "
                    "every section.")
    lines += _table("[[scenario]]", [(k, v.accepted) for k, v in SCENARIO_KEYS.items()],
                    "One table per climate scenario over the service years 1 to ``[lifetime] years``.  "
                    "A table ``{year = value}`` is linear between its years, from today's value at year 0 "
                    "(0 m, a factor 1), and constant after its last year; a scenario with none of the keys "
                    "but its name is today's climate.")
    rows = []
    for table, key, symbol, sign, what in SEA_LEVEL_LIMITS:
        moved = f"{symbol} {'-' if sign < 0 else '+'} rise"
        rule = f"{moved} > 0 and " if key == "crest" else ""
        rows.append((moved, f"{rule}[{table}] {key}: {DESIGN_KEYS[table][key].accepted} -- else it "
                     f"{what.format('S')}"))
    lines += _table("The sea level of every service year", rows,
                    "Before any task runs, the rise of each scenario in each service year is checked "
                    "against each section with the design file's own limits: the rise adds to the depths "
                    "and takes from the crest.  The first service year that fails stops the study with "
                    "exit status 2 and one line naming the file, the scenario's line, the year and the "
                    "section (with a hint when the values read in millimetres or centimetres would pass); "
                    "a sea level that falls is a warning.  A ``wave_height_factor`` must keep each "
                    "section's 50-year H0' (``H0_50``, or its largest annual maximum) within the design "
                    "file's ``[lifetime] H0_50``: " + _cell(LIFETIME_KEYS["H0_50"].accepted) + ".  "
                    "Each width of a section is checked as the "
                    "design file's ``[caisson] width``: " + _cell(DESIGN_KEYS["caisson"]["width"].accepted)
                    + ".", head="risen length")
    return "\n".join(lines)
