"""``regimemap explore``: the regime map, live, with sliders and a click.

The window (:mod:`.explorer`), the callbacks of its widgets and mouse (:mod:`.events`), its
layout and widgets (:mod:`.layout`), the artists drawn from bitmaps (:mod:`.images`) and its
words and numbers (:mod:`.text`).
"""
