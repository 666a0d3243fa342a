from __future__ import annotations

import pytest

from regimemap import MAP_MODES, Mode


def test_labels_and_codes():
    assert [m.label for m in MAP_MODES] == ["RE", "SL", "RO", "SRO-", "SRO+", "SRO'-"]
    assert Mode.RO_PRIME.label == "RO'" and Mode.SRO_PRIME_PLUS.label == "SRO'+"
    assert len({int(m) for m in Mode}) == len(Mode)
    assert all(0 <= int(m) < 255 for m in Mode)


def test_from_label():
    assert Mode.from_label("sro'-") is Mode.SRO_PRIME_MINUS
    assert Mode.from_label("SRO_MINUS") is Mode.SRO_MINUS
    with pytest.raises(ValueError, match="known modes"):
        Mode.from_label("XX")


def test_tex_is_mathtext():
    assert all(m.tex.startswith("$") and m.tex.endswith("$") for m in Mode)
