"""A study task whose sliding is infinite (a crest under 20 m of water) raises, quietly, and stores nothing."""

from __future__ import annotations

import warnings
from dataclasses import replace

import pytest

from regimemap.lifetime import YearTrend
from regimemap.lifetime.finite import NonFiniteResult
from regimemap.study.file import parse_study
from regimemap.study.run import study_tasks
from regimemap.study.run_tasks import run_task

from .conftest import SITE, scenario_table, section_table, study_head

STUDY = (study_head(3, 40) + section_table("trunk", 0.0, *SITE, "widths = [12.0, 15.0]")
         + scenario_table("rise", "rate = 0.01"))


@pytest.mark.slow
@pytest.mark.usefixtures("goda")  # the study's base, tmp_path/goda.toml
def test_an_infinite_sliding_is_refused_without_a_numpy_warning(tmp_path):
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
