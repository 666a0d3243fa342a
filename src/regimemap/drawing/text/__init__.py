"""Texts that stay legible: where labels go, and the passes that keep them apart.

The placement model, without matplotlib (:mod:`.placement`); the texts of a map
(:mod:`.labels`); boxes of drawn texts (:mod:`.textboxes`); labels placed once a
figure is laid out (:mod:`.labelplacer`); the tidy pass of a map figure
(:mod:`.tidy`) and its moves of one label (:mod:`.relabel`).
"""
