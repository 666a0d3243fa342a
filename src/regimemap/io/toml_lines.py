"""Where a key is set in a TOML text: :func:`key_line`, for messages that name the line.

tomllib parses a file but gives no positions; the design file's readers
(:mod:`regimemap.lifetime.file`) name the line of the key they refuse.
The standard library only (``re``).
"""

from __future__ import annotations

import re

__all__ = ["key_line", "key_text"]

_BARE_KEY = r"(?:[A-Za-z0-9_-]+|\"(?:[^\"\\]|\\.)*\"|'[^']*')"
_DOTTED = re.compile(rf"\s*({_BARE_KEY}(?:\s*\.\s*{_BARE_KEY})*)\s*")
_HEADER = re.compile(rf"^\s*\[\[?{_DOTTED.pattern}\]\]?")
_ASSIGN = re.compile(rf"^{_DOTTED.pattern}=")


def _key_path(dotted: str) -> tuple[str, ...]:
    parts = re.findall(_BARE_KEY, dotted)
    return tuple(p[1:-1] if p[:1] in "\"'" else p for p in parts)


def key_line(text: str, table: str, key: str | None = None) -> int | None:
    """The line (from 1) where ``key`` of ``table`` (``"lifetime.errors"``) is set in TOML ``text``.

    tomllib gives no positions, so the text is scanned: table headers
    (``[lifetime.errors]``), keys (``shape = 3``) and dotted keys
    (``errors.force = [0.9, 0.1]`` under ``[lifetime]``).  A key set inside an
    inline table gives the line of that table; with ``key`` None, or a key not
    found, the line of the table's header (None if there is none).  Lines in
    multi-line strings are not told apart from keys.
    """
    want = (*_key_path(table), *(() if key is None else (key,)))
    head = _key_path(table)
    current: tuple[str, ...] = ()
    inline = header = None
    for n, line in enumerate(text.splitlines(), start=1):
        m = _HEADER.match(line)
        if m:
            current = _key_path(m.group(1))
            if current == want:  # [lifetime.errors] for the key "errors" of [lifetime]
                return n
            if current == head and header is None:
                header = n
            continue
        m = _ASSIGN.match(line)
        if not m:
            continue
        path = current + _key_path(m.group(1))
        if path == want:
            return n
        if inline is None and key is not None and want[:len(path)] == path:
            inline = n  # the key sits in an inline table, or in the table set by this dotted key
        if header is None and path[:len(head)] == head and len(path) > len(head):
            header = n  # a table made of dotted keys (lifetime.years = 50)
    return inline if inline is not None else header


_VALUE = re.compile(r"""=\s*((?:"(?:[^"\\]|\\.)*"|'[^']*'|[^#"'])*?)\s*(?:#.*)?$""")


def key_text(text: str, table: str, key: str) -> str | None:
    """The value of ``key`` in ``table`` as the TOML ``text`` writes it (``"10.1"``, ``"2312"``).

    The text after ``=`` on the key's line (:func:`key_line`), without its
    comment; None when the key is not set on a line of its own (an inline
    table, a value over several lines).

    Examples
    --------
    >>> key_text("[site]\\ndepth = 10.10   # h\\n", "site", "depth")
    '10.10'
    """
    n = key_line(text, table, key)
    if n is None:
        return None
    line = text.splitlines()[n - 1]
    if not re.match(rf"^\s*{re.escape(key)}\s*=", line):
        return None
    m = _VALUE.search(line)
    value = m.group(1).strip() if m else ""
    return value or None
