"""The catalog of documented mechanisms (koppel catalog find)."""
from typing import List, Optional, Union

from . import _koppel

Count = Union[int, str, None]


def find(links: Count = None, binary: Count = None, ternary: Count = None,
         quaternary: Count = None, joints: Count = None, revolute: Count = None,
         prismatic: Count = None, drives: Count = None, outputs: Count = None,
         kind: str = "", klass: str = "", motion: str = "", text: str = "",
         directory: str = "") -> List["_koppel.CatalogEntry"]:
    """Entries whose access features (Zugriffsmerkmale) match every criterion given.

    Counts are a number or a range as at the CLI: 4, "4..6", "..6", "4..". kind: "transfer" or
    "guidance"; klass: a class such as "slider-crank"; motion: e.g. "rotation -> translation";
    text: words in the id, titles, classes, keywords, motion or applications, English or German
    (the CLI's `catalog find --text`: umlauts and case ignored, synonyms found, best matches
    first). directory: another catalog (default: the one installed with
    koppel, or $KOPPEL_CATALOG). Each entry's load(set=...) reads it as a koppel.Mechanism.
    Raises koppel.InputError for a malformed count or an unreadable catalog.
    """
    counts = {"links": links, "binary": binary, "ternary": ternary, "quaternary": quaternary,
              "joints": joints, "revolute": revolute, "prismatic": prismatic, "drives": drives,
              "outputs": outputs}
    return _koppel._catalog_find(counts, kind, klass, motion, text, directory)


def directory() -> str:
    """The catalog directory find() reads by default."""
    return _koppel._catalog_directory()


def load(entry_id: str, set: Optional[dict] = None) -> "_koppel.Mechanism":
    """The catalog entry `entry_id` (e.g. "slider-crank-offset") as a koppel.Mechanism."""
    for entry in find(text=entry_id):
        if entry.id == entry_id:
            return entry.load(set=set)
    error = _koppel.InputError(f"{directory()}: no catalog entry '{entry_id}'")
    error.file, error.line, error.column, error.field = directory(), 0, 0, "id"
    error.diagnostics = [{"file": directory(), "line": 0, "column": 0, "field": "id",
                          "message": f"no catalog entry '{entry_id}'"}]
    raise error
