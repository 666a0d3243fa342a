"""Outcome maps drawn: what a pulse does to the block over two swept inputs.

The figure (:mod:`.figure`), what it returns (:mod:`.artists`), its words
(:mod:`.words`) and the placement of its texts (:mod:`.text`).
"""
