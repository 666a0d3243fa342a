"""The results store of a study: one small JSON file per finished task, and a manifest.

A folder holds ``manifest.json`` (the study's hash, its file and the number of
tasks) and ``tasks/<section>-<scenario>-<replicate>.json``, each written to a
temporary file and renamed into place (:func:`regimemap.io.atomic.atomic_open`),
so a task file is either whole or absent: ``kill -9``, a crashed worker or a full
disk lose at most the tasks in flight, never a finished one, and no lock or
database is needed.  One file per task keeps a resumed run to listing a folder,
lets several studies sit side by side, and is read with any tool.  Floats are
stored as Python's shortest repr, which reads back to the same bits.

Opening a store that exists: ``resume`` with the same hash reuses its tasks; a
different hash is refused whether resuming or not (the store is left untouched);
the same hash without ``resume`` is refused, when it holds a task, with the hint to
``--resume`` or to give another ``--store``, so finished tasks are never run again
by accident (an empty store of the study, left by a run that never got going, is
reused).  :func:`replacing_store` replaces a study store (``--overwrite``): the new
run is stored in a folder beside it, which takes the old one's place only when the
run has finished, so an interrupted or failed run leaves the old store whole.
"""

from __future__ import annotations

import contextlib
import json
import os
import shutil
from collections.abc import Iterator, Mapping
from pathlib import Path
from typing import Any

from ..io.atomic import atomic_open
from ..io.json import write_json

__all__ = ["MANIFEST", "StudyStore", "StudyStoreError", "replacing_store", "task_name"]

#: The manifest's file name in the store's folder.
MANIFEST = "manifest.json"
_FORMAT = "regimemap-study-store-1"


class StudyStoreError(ValueError):
    """A store that cannot be used for this study (another study's, or in use without ``resume``)."""


def task_name(section: int, scenario: int, replicate: int) -> str:
    """The file name of a task (``s0003-c01-r0000.json``)."""
    return f"s{section:04d}-c{scenario:02d}-r{replicate:04d}.json"


class StudyStore:
    """A folder of finished tasks of one study (see the module's notes).

    Parameters
    ----------
    folder : str or Path
        The store's folder (created with its parents when missing).
    study_hash : str
        The study's hash, kept in the manifest.
    source : str
        The study file, for the messages.
    tasks : int
        The study's number of tasks.
    resume : bool
        Reuse the tasks of an existing store of the same study.

    Raises
    ------
    StudyStoreError
        The folder holds another study's store, or this study's without ``resume``, or is
        not a store and not empty.
    """

    def __init__(self, folder: str | os.PathLike[str], study_hash: str, source: str, tasks: int,
                 resume: bool = False) -> None:
        self.folder = Path(folder)
        self.tasks_folder = self.folder / "tasks"
        manifest = self.folder / MANIFEST
        if self.folder.exists() and not self.folder.is_dir():
            raise StudyStoreError(f"{self.folder}: not a folder; give --store a folder (created if missing)")
        if manifest.exists():
            try:
                old = json.loads(manifest.read_text(encoding="utf-8"))
            except (OSError, ValueError) as exc:
                raise StudyStoreError(f"{manifest}: not a study store's manifest ({exc}); give another "
                                      "--store") from None
            if old.get("study_hash") != study_hash:
                raise StudyStoreError(
                    f"{self.folder}: the store of another study (its hash {str(old.get('study_hash'))[:12]}, "
                    f"this study's {study_hash[:12]}: {source} has changed); refused, the store is "
                    "untouched: give --overwrite to replace it, or a new --store")
            if not resume and any(self.tasks_folder.glob("*.json")):
                raise StudyStoreError(
                    f"{self.folder}: already holds this study's results; give --resume to finish (or "
                    "reuse) them, --overwrite to run the study again in their place, or a new --store")
        elif self.folder.exists() and any(self.folder.iterdir()):
            raise StudyStoreError(f"{self.folder}: a folder that is not a study store and not empty; "
                                  "give a new --store")
        else:
            self.tasks_folder.mkdir(parents=True, exist_ok=True)
            write_json(manifest, {"format": _FORMAT, "study_hash": study_hash, "study": source,
                                  "tasks": tasks})
        self.tasks_folder.mkdir(parents=True, exist_ok=True)

    def path(self, name: str) -> Path:
        """The file of the task ``name`` (:func:`task_name`)."""
        return self.tasks_folder / name

    def load(self, name: str) -> dict[str, Any] | None:
        """The stored result of a task; None when it is not (whole) in the store."""
        try:
            data: dict[str, Any] = json.loads(self.path(name).read_text(encoding="utf-8"))
        except (OSError, ValueError):
            return None
        return data

    def save(self, name: str, result: Mapping[str, Any]) -> None:
        """Store a task's result, atomically; one that holds ``inf`` or ``nan`` is refused
        (:class:`ValueError`) and nothing is stored."""
        with atomic_open(self.path(name), "w", encoding="utf-8") as f:
            json.dump(result, f, separators=(",", ":"), allow_nan=False)

    def done(self) -> set[str]:
        """The names of the tasks stored."""
        return {p.name for p in self.tasks_folder.glob("*.json")}


def _is_store(folder: Path) -> bool:
    return (folder / MANIFEST).is_file()


@contextlib.contextmanager
def replacing_store(folder: str | os.PathLike[str], study_hash: str, source: str,
                    tasks: int) -> Iterator[StudyStore]:
    """A new, empty store that replaces the study store at ``folder`` when the block ends without
    an error (``--overwrite``); the old store is whole until then.

    The new store is made in ``.NAME.new`` beside ``folder`` (a stale one, left by a run that was
    killed, is removed first); at the end the old store is renamed ``.NAME.old``, the new one
    takes its name, and the old one is removed.  On an error or an interrupt the new folder is
    removed and the old store is left as it was.  A ``folder`` that does not exist is simply
    created; one that is not a study store (no manifest) is refused and left untouched.

    Raises
    ------
    StudyStoreError
        ``folder`` exists and is not a study store (or not a folder).
    """
    target = Path(folder)
    if not target.exists():
        yield StudyStore(target, study_hash, source, tasks)
        return
    if not target.is_dir() or not _is_store(target):
        raise StudyStoreError(f"{target}: not a study store (no {MANIFEST}); --overwrite replaces only a "
                              "study store: give a new --store")
    staging = target.with_name(f".{target.name}.new")
    retired = target.with_name(f".{target.name}.old")
    for stale in (staging, retired):
        if stale.exists() and _is_store(stale):
            shutil.rmtree(stale)
    try:
        yield StudyStore(staging, study_hash, source, tasks)
    except BaseException:
        shutil.rmtree(staging, ignore_errors=True)
        raise
    os.replace(target, retired)
    os.replace(staging, target)
    shutil.rmtree(retired, ignore_errors=True)
