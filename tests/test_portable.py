"""The same numbers on every machine: ``make test-portable``'s levels and the caches that depend on them.

numpy picks, per loop, the highest of its compiled CPU targets the CPU has (docs/guide/development.md,
"Reproducibility").  ``tests/cpu_levels.py`` runs the tests marked ``portable`` once per level of
this CPU with ``NPY_DISABLE_CPU_FEATURES``: its choice of levels is checked here on made-up CPUs
(AVX-512, AVX2 only, baseline only, a numpy that cannot list its loops), and on this one that each
level is accepted by numpy and moves its loops.  The outcome-map cache of ``make figures`` keys on
the same levels, so a map computed on other loops is never drawn as this machine's.
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

from tests import cpu_levels

X86 = ["X86_V3", "X86_V4", "AVX512_ICL", "AVX512_SPR"]
ALL = {"X86_V3": True, "X86_V4": True, "AVX512_ICL": True, "AVX512_SPR": False}
USED = {"X86_V3", "X86_V4", "AVX512_SPR"}  # numpy 2.4's loops: none compiled for AVX512_ICL


def _levels(monkeypatch, dispatch, features, used):
    monkeypatch.setattr(cpu_levels, "_features", lambda: (dispatch, features, used))
    return cpu_levels.levels()


def test_an_avx512_machine_drops_x86_v4_then_x86_v3(monkeypatch):
    todo, notes = _levels(monkeypatch, X86, ALL, USED)
    assert todo == [["X86_V4", "AVX512_ICL"], ["X86_V3", "X86_V4", "AVX512_ICL"]]
    assert any(n.startswith("AVX512_SPR: not on this CPU") for n in notes)
    assert any(n.startswith("AVX512_ICL: no ufunc loop") for n in notes)


def test_an_avx2_machine_runs_the_baseline_only_and_names_what_it_lacks(monkeypatch):
    todo, notes = _levels(monkeypatch, X86, dict.fromkeys(X86, False) | {"X86_V3": True}, USED)
    assert todo == [["X86_V3"]]
    assert sorted(n.split(":")[0] for n in notes) == ["AVX512_ICL", "AVX512_SPR", "X86_V4"]


def test_a_baseline_only_machine_has_nothing_to_compare(monkeypatch, capsys):
    monkeypatch.delenv("NPY_DISABLE_CPU_FEATURES", raising=False)  # restored after the test
    monkeypatch.setattr(cpu_levels, "_features", lambda: (["ASIMDHP", "ASIMDDP"], {}, set()))
    assert cpu_levels.levels()[0] == []
    assert cpu_levels.main([]) == 0
    assert "nothing to compare" in capsys.readouterr().out


def test_a_numpy_that_cannot_list_its_loops_drops_every_level(monkeypatch):
    todo, _ = _levels(monkeypatch, X86, ALL, None)
    assert todo == [["AVX512_ICL"], ["X86_V4", "AVX512_ICL"], ["X86_V3", "X86_V4", "AVX512_ICL"]]


def test_only_the_files_that_mark_portable_tests_are_collected():
    files = cpu_levels.marked_files()
    assert "tests/lifetime/test_vectorised.py" in files and "tests/test_portable.py" not in files
    root = Path(cpu_levels.__file__).resolve().parents[1]
    assert all(cpu_levels.MARK in (root / f).read_text(encoding="utf-8") for f in files)


# -- on this CPU ------------------------------------------------------------------------------------

_PROBE = """
import json
from numpy.lib import introspect
from regimemap.motion.record_outcome import _cache_key
info = introspect.opt_func_info(func_name="exp|log|sin|power", signature="float64")
print(json.dumps({"loops": sorted({s["current"] for f in info.values() for s in f.values()}),
                  "key": _cache_key("D.1")}))
"""


def _probe(disabled: str | None) -> dict[str, object]:
    env = {k: v for k, v in os.environ.items() if k != "NPY_DISABLE_CPU_FEATURES"}
    if disabled is not None:
        env["NPY_DISABLE_CPU_FEATURES"] = disabled
    # -W error::ImportWarning: a name numpy does not accept would stop the import
    r = subprocess.run([sys.executable, "-W", "error::ImportWarning", "-c", _PROBE], env=env,
                       capture_output=True, text=True, check=True)
    out: dict[str, object] = json.loads(r.stdout)
    return out


@pytest.fixture(scope="module")
def this_cpu():
    pytest.importorskip("numpy.lib.introspect")
    todo = subprocess.run(
        [sys.executable, "-c", "from tests import cpu_levels; import json; print(json.dumps(cpu_levels.levels()[0]))"],
        env={k: v for k, v in os.environ.items() if k != "NPY_DISABLE_CPU_FEATURES"},
        capture_output=True, text=True, check=True)
    levels = json.loads(todo.stdout)
    if not levels:
        pytest.skip("numpy runs its baseline loops only on this CPU")
    return levels


@pytest.mark.subprocess
def test_each_level_is_accepted_and_moves_the_loops_and_the_cache_key(this_cpu):
    full = _probe(None)
    seen = [full]
    for disabled in this_cpu:
        got = _probe(" ".join(disabled))
        assert not set(got["loops"]) & set(disabled), (disabled, got)
        assert got["key"] != full["key"]
        assert _probe(" ".join(disabled))["key"] == got["key"]  # the same loops, the same key
        seen.append(got)
    assert len({s["key"] for s in seen}) == len(seen)
