"""A study task whose sliding is infinite (a crest under 20 m of water) raises, quietly, and stores nothing."""

from __future__ import annotations

import warnings
from dataclasses import replace

import pytest

from regimemap.caisson.file import example_design_text
from regimemap.lifetime import YearTrend
from regimemap.lifetime.finite import NonFiniteResult
from regimemap.study.file import parse_study
from regimemap.study.run import study_tasks
from regimemap.study.run_tasks import run_task

STUDY = """seed = 3
trials = 40
base = "goda.toml"

[[section]]
name = "trunk"
chainage = 0.0
depth = 8.0
armour_depth = 4.5
base_depth = 5.5
widths = [12.0, 15.0]

[[scenario]]
name = "rise"
rate = 0.01
"""


@pytest.mark.slow
def test_an_infinite_sliding_is_refused_without_a_numpy_warning(tmp_path):
    (tmp_path / "goda.toml").write_text(example_design_text())
    study = parse_study(STUDY, str(tmp_path / "study.toml"))
    ((_, task),) = list(study_tasks(study))
    assert task.label == f"{tmp_path / 'study.toml'}: section 'trunk', scenario 'rise'"
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # a RuntimeWarning would be raised instead
        ok = run_task(task)
        assert len(ok["esd"]) == 2
        # what the scenario check refuses, forced past it: 20 m of rise in every year
        drowned = replace(task, model=task.model.with_(trend=YearTrend((20.0,) * 50, (1.0,) * 50, (1.0,) * 50)))
        with pytest.raises(NonFiniteResult, match=r"section 'trunk', scenario 'rise', width 12 m: the lifetime "
                                                  r"sliding is not finite \(inf in \d+ of 40 values"):
            run_task(drowned)
