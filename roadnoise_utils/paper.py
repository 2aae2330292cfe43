"""The paper's reported values (``data/paper/belluzzo2002.toml``) and "paper vs ours" tables."""

from __future__ import annotations

import functools
import tomllib
from typing import Any

import pandas as pd

from .paths import data_dir


@functools.lru_cache(maxsize=1)
def _reported() -> dict[str, dict[str, Any]]:
    with open(data_dir() / "paper" / "belluzzo2002.toml", "rb") as fh:
        return tomllib.load(fh)


def reported(key: str) -> float:
    """A value reported by the paper (its unit in ``reported_unit``)."""
    try:
        return _reported()[key]["value"]
    except KeyError as exc:
        raise KeyError(f"the paper file has no value {key!r}; known: {sorted(_reported())}") from exc


def comparison_table(rows: list[tuple[str, str, float, float, str]]) -> pd.DataFrame:
    """A "quantity / paper / ours / tolerance / ok" table.

    ``rows``: ``(quantity, paper_key, ours, relative_tolerance, note)``; the paper value comes
    from the data file, ``ok`` is ``|ours / paper - 1| <= relative_tolerance``.
    """
    out = []
    for quantity, key, ours, tol, note in rows:
        paper = reported(key)
        out.append(
            {
                "quantity": quantity,
                "unit": _reported()[key]["unit"],
                "paper": paper,
                "ours": ours,
                "tolerance": f"±{tol:.0%}",
                "ok": bool(abs(ours / paper - 1.0) <= tol),
                "note": note,
            }
        )
    return pd.DataFrame(out).set_index("quantity")


def claims_table(rows: list[tuple[str, str, str, bool]]) -> pd.DataFrame:
    """A "claim / paper / ours / ok" table for claims that are statements rather than numbers."""
    return pd.DataFrame([{"claim": c, "paper": p, "ours": o, "ok": bool(ok)} for c, p, o, ok in rows]).set_index(
        "claim"
    )
