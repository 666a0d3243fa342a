"""Small HTML tables for the rich display of results in Jupyter (``_repr_html_``).

The result objects of every layer (a point's classification, a map, a caisson
analysis, a lifetime) show themselves in a notebook as a short table made
here.  The standard library only (no numpy: numbers are duck-typed), and in
the lowest layer so that any layer may use it.  Every text is escaped with
:func:`html.escape`.

>>> table = html_table([("mode", "RO", "rock about O"), ("fx", 0.25252, "")],
...                    caption="k = 0.5, mu = 0.8 <here>")
>>> "<caption>k = 0.5, mu = 0.8 &lt;here&gt;</caption>" in table
True
>>> '<th style="text-align:left">fx</th><td style="text-align:right">0.2525</td>' in table
True
"""

from __future__ import annotations

import numbers
from collections.abc import Iterable, Sequence
from html import escape

from .numbers import number

__all__ = ["cell_text", "html_table"]


def cell_text(value: object) -> str:
    """A cell's text: None as a dash, booleans as yes/no, numbers by :func:`number`.

    numpy numbers and 0-d arrays are numbers here too (duck-typed, without numpy).
    """
    if value is None:
        return "\u2013"
    if isinstance(value, bool) or type(value).__name__ == "bool_":
        return "yes" if value else "no"
    if isinstance(value, numbers.Integral):
        return str(int(value))
    if isinstance(value, numbers.Real):
        return number(float(value))
    if getattr(value, "ndim", None) == 0 and hasattr(value, "item"):
        return cell_text(value.item())
    return str(value)


def html_table(rows: Iterable[Sequence[object]], *, caption: str = "",
               header: Sequence[str] = ()) -> str:
    """A small HTML table: the first cell of a row is its name, the others its values.

    Parameters
    ----------
    rows : iterable of sequences
        One sequence of cells per row (texts, numbers, None ...), see :func:`cell_text`.
    caption : str
        The table's caption (plain text).
    header : sequence of str
        Column titles; none by default.

    Returns
    -------
    str
        HTML, every text escaped.
    """
    out = ['<table class="regimemap">']
    if caption:
        out.append(f"<caption>{escape(caption)}</caption>")
    if header:
        out.append("<thead><tr>" + "".join(f"<th>{escape(str(h))}</th>" for h in header)
                   + "</tr></thead>")
    out.append("<tbody>")
    for row in rows:
        cells = [escape(cell_text(c)) for c in row]
        if not cells:
            continue
        head, rest = cells[0], cells[1:]
        tds = "".join(
            f'<td style="text-align:{"right" if i == 0 else "left"}">{c}</td>'
            for i, c in enumerate(rest))
        out.append(f'<tr><th style="text-align:left">{head}</th>{tds}</tr>')
    out.append("</tbody>")
    out.append("</table>")
    return "\n".join(out)
