"""Texts that stay legible: where labels go, and the passes that keep them apart.

The placement model, without matplotlib (:mod:`.placement`); the texts of a map
(:mod:`.labels`); boxes of drawn texts (:mod:`.textboxes`); the one placer, the free space of
a figure and the search for a label's first free place (:mod:`.placer`); labels placed once a
figure is laid out (:mod:`.labelplacer`); the tidy pass of a map figure (:mod:`.tidy`) and the
places of each kind of map label (:mod:`.relabel`).
"""
