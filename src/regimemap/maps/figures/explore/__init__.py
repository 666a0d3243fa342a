"""``regimemap explore``: the regime map, live, with sliders and a click.

The window (:mod:`.explorer`), its layout and widgets (:mod:`.layout`), the
artists drawn from bitmaps (:mod:`.images`) and its words and numbers
(:mod:`.text`).
"""
