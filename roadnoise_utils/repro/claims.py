"""The paper's claims, our value for each on every tire model, and the reproduction report.

The claims, what the paper says, the tolerance and the notebook live in
``data/paper/claims.toml``; :mod:`.evaluators` computes *our* number for each claim on each tire
model (the ring, the cross-section tire and the loaded FE tire, :data:`MODELS`) with the same
experiments and cached stages the notebooks call, and this module judges it with the data's test.
:func:`report` is the table the chapters show (one column per model of :data:`OVERVIEW_MODELS`)
and the reproduction command writes (one per model of :data:`MODELS`); :func:`write_report`
writes it as CSV and Markdown.

A claim states per model a documented deviation (``[claim.known_deviation]``, one entry per model
kind) or why it does not apply (``[claim.not_applicable]``).
A check *beyond the paper* (``beyond``: the feature, e.g. the whole car) states what it is
compared with (``compared_with``: a closed form, a cited measurement); the report marks it and
counts it apart from the paper's claims.
"""

from __future__ import annotations

import os
from collections.abc import Callable, Iterable
from pathlib import Path

import numpy as np
import pandas as pd

from ..tire.model import NotApplicable
from .evaluators import EVALUATORS, OVERVIEW_MODELS
from .evaluators import MODELS as MODELS  # the reproduction report's columns, re-exported
from .evaluators import transmissibility_bands as transmissibility_bands  # Fig. 10's bands, re-exported
from .paths import data_dir, read_toml


def load_claims() -> list[dict]:
    """The claims of ``data/paper/claims.toml``, in order."""
    claims = read_toml(data_dir() / "paper" / "claims.toml")["claim"]
    tests = ("rel", "min", "max", "equal")
    for c in claims:
        if not any(t in c for t in tests):
            raise ValueError(f"claim {c.get('id')!r} has no test; give one of {tests}")
    return claims


def select_claims(claim_ids: Iterable[str] | None = None) -> list[dict]:
    """The claims with the ids ``claim_ids`` (every claim for ``None``), in the file's order.

    A misspelt id is an error listing the valid ones;
    so is a single string (a list of ids is expected).
    """
    claims = load_claims()
    if claim_ids is None:
        return claims
    if isinstance(claim_ids, str):
        raise ValueError(f"claim_ids = {claim_ids!r}: give a list of claim ids (str), or None for every claim")
    claim_ids = list(claim_ids)  # a generator is read once
    if not all(isinstance(i, str) for i in claim_ids):
        raise ValueError(f"claim_ids = {claim_ids!r}: give a list of claim ids (str), or None for every claim")
    known = [c["id"] for c in claims]
    unknown = sorted(set(claim_ids) - set(known))
    if unknown:
        raise ValueError(f"claim_ids: unknown id(s) {unknown}; valid ids are {known}")
    if not claim_ids:
        raise ValueError("claim_ids is empty: give at least one claim id, or None for every claim")
    return [c for c in claims if c["id"] in set(claim_ids)]


def paper_value(claim_id: str, key: str = "paper") -> float:
    """A number the paper reports, from ``data/paper/claims.toml``: the claim's ``paper`` value or another key (``measured``).

    Raises
    ------
    KeyError
        No claim ``claim_id``, or it has no numeric ``key``.
    """
    for c in load_claims():
        if c["id"] == claim_id:
            value = c.get(key)
            if isinstance(value, bool) or not isinstance(value, (int, float)):
                raise KeyError(f"claim {claim_id!r} has no number {key!r}")
            return float(value)
    raise KeyError(f"no claim {claim_id!r} in data/paper/claims.toml")


def judge(claim: dict, ours: float) -> bool:
    """Whether ``ours`` passes the claim's test (relative tolerance, bounds or equality)."""
    if not np.isfinite(ours):
        return False
    ok = True
    if "rel" in claim:
        ok &= abs(ours / float(claim["paper"]) - 1.0) <= claim["rel"]
    if "min" in claim:
        ok &= ours >= claim["min"]
    if "max" in claim:
        ok &= ours <= claim["max"]
    if claim.get("equal"):
        ok &= ours == float(claim["paper"])
    return bool(ok)


def tolerance_text(claim: dict) -> str:
    """The claim's test in words."""
    parts = []
    if "rel" in claim:
        parts.append(f"±{claim['rel']:.0%}")
    if "min" in claim:
        parts.append(f">= {claim['min']:g}")
    if "max" in claim:
        parts.append(f"<= {claim['max']:g}")
    if claim.get("equal"):
        parts.append("equal")
    return ", ".join(parts)


#: Below this a value is round-off (a residual, a superposition error): the report gives the bound
#: it meets, as the notebooks do, so that its text does not change with the BLAS build.
ROUND_OFF = 1e-9


def _format(value: float) -> str:
    if abs(value) < ROUND_OFF:
        return f"< {ROUND_OFF:.0e}"
    if 1e-3 <= abs(value) < 1e5:
        return f"{value:.4g}"
    return f"{value:.2e}"


def deviation(claim: dict, model: str) -> str:
    """The claim's documented deviation for the tire model ``model`` ("" if none)."""
    return claim.get("known_deviation", {}).get(model, "")


def not_applicable(claim: dict, model: str) -> str:
    """Why the claim does not apply to the tire model ``model`` ("" if it does)."""
    return claim.get("not_applicable", {}).get(model, "")


def report(
    notebook: str | None = None,
    claims: list[dict] | None = None,
    evaluators: dict[str, Callable[[str], float]] | None = None,
    models: tuple[str, ...] = OVERVIEW_MODELS,
) -> pd.DataFrame:
    """One row per claim: claim, where, paper, tolerance, notebook, and per tire model ``m``
    the columns ``ours (m)``, ``verdict (m)`` (pass, fail or n/a) and ``deviation (m)`` (the
    documented deviation of a failed claim, or why it does not apply).

    ``models``: default the chapters' (:data:`OVERVIEW_MODELS`, which the test suite computes); the
    reproduction's report takes every model of ``data/paper/report.toml`` (:data:`MODELS`).

    ``notebook`` keeps the claims shown by one notebook; ``claims``/``evaluators`` replace the
    data file and the evaluators (tests; an evaluator takes the model name).
    """
    claims = load_claims() if claims is None else claims
    evaluators = EVALUATORS if evaluators is None else evaluators
    rows = []
    for c in claims:
        if notebook is not None and c["notebook"] != notebook:
            continue
        if c["id"] not in evaluators:
            raise KeyError(f"no evaluator for claim {c['id']!r}")
        row = {
            "id": c["id"],
            "kind": f"beyond the paper ({c['beyond']})" if "beyond" in c else "paper",
            "claim": c["claim"] + (f" [compared with {c['compared_with']}]" if "compared_with" in c else ""),
            "where": c["where"],
            "paper": c["paper"] if isinstance(c["paper"], str) else _format(float(c["paper"])),
            "tolerance": tolerance_text(c),
            "notebook": c["notebook"],
        }
        for model in models:
            row.update(_evaluate(c, evaluators[c["id"]], model))
        rows.append(row)
    return pd.DataFrame(rows).set_index("id")


def _evaluate(claim: dict, evaluator: Callable[[str], float], model: str) -> dict:
    reason = not_applicable(claim, model)
    if reason:
        return {f"ours ({model})": "", f"verdict ({model})": "n/a", f"deviation ({model})": reason}
    try:
        ours = float(evaluator(model))
    except NotApplicable as lacking:
        return {f"ours ({model})": "", f"verdict ({model})": "n/a", f"deviation ({model})": str(lacking)}
    passed = judge(claim, ours)
    return {
        f"ours ({model})": _format(ours),
        f"verdict ({model})": "pass" if passed else "fail",
        f"deviation ({model})": "" if passed else deviation(claim, model),
    }


def models_of(table: pd.DataFrame) -> list[str]:
    """The tire models a report has columns for."""
    return [c[len("verdict (") : -1] for c in table.columns if c.startswith("verdict (")]


def unexpected_failures(table: pd.DataFrame) -> pd.DataFrame:
    """Failed claims, on any model, that are not documented known deviations."""
    bad = np.zeros(len(table), bool)
    for m in models_of(table):
        bad |= (table[f"verdict ({m})"] == "fail").to_numpy() & (table[f"deviation ({m})"] == "").to_numpy()
    return table[bad]


def _is_paper(table: pd.DataFrame) -> np.ndarray:
    return (table["kind"] == "paper").to_numpy() if "kind" in table else np.ones(len(table), bool)


def counts(table: pd.DataFrame, model: str, beyond: bool = False) -> dict[str, int]:
    """The paper's claims (or, with ``beyond``, the checks beyond the paper) passed, failed as
    documented deviations, failed unexpectedly and not applicable for ``model``."""
    table = table[~_is_paper(table)] if beyond else table[_is_paper(table)]
    verdict, note = table[f"verdict ({model})"], table[f"deviation ({model})"]
    return {
        "claims": len(table),
        "pass": int((verdict == "pass").sum()),
        "deviations": int(((verdict == "fail") & (note != "")).sum()),
        "unexpected": int(((verdict == "fail") & (note == "")).sum()),
        "n/a": int((verdict == "n/a").sum()),
    }


def summary(table: pd.DataFrame) -> str:
    """One line per model: how many claims it reproduces."""
    lines = []
    for m in models_of(table):
        n = counts(table, m)
        evaluated = n["claims"] - n["n/a"]
        lines.append(
            f"{m}: {n['pass']} of {evaluated} claims reproduced, {n['deviations']} documented deviations, "
            f"{n['unexpected']} unexpected failures" + (f", {n['n/a']} not applicable" if n["n/a"] else "")
        )
    for m in models_of(table):
        n = counts(table, m, beyond=True)
        if n["claims"]:
            lines.append(
                f"{m}, beyond the paper: {n['pass']} of {n['claims'] - n['n/a']} checks pass, "
                f"{n['deviations']} documented deviations, {n['unexpected']} unexpected failures"
            )
    return "\n".join(lines)


def exit_status(table: pd.DataFrame) -> int:
    """0 when every claim passes or fails only as a documented deviation, on every model, else 1."""
    return int(len(unexpected_failures(table)) > 0)


def _cell(row: pd.Series, cid: str, model: str) -> str:
    verdict = row[f"verdict ({model})"]
    if verdict == "n/a":
        return f"n/a ([{model}: {cid}](#{model}-{cid}))"
    text = f"{row[f'ours ({model})']} {verdict}"
    return text + (f" (known deviation: [{model}: {cid}](#{model}-{cid}))" if row[f"deviation ({model})"] else "")


def to_markdown(table: pd.DataFrame) -> str:
    """The report as a GitHub Markdown table, one column per tire model (deviations as footnotes)."""
    models = models_of(table)
    columns = ["claim", "where", "paper", "tolerance", *models, "notebook"]
    lines = ["| " + " | ".join(columns) + " |", "|" + "---|" * len(columns)]
    notes = []
    for cid, row in table.iterrows():
        for m in models:
            if row[f"deviation ({m})"]:
                label = "does not apply" if row[f"verdict ({m})"] == "n/a" else "deviation"
                notes.append(f'- <a id="{m}-{cid}"></a>**{m}: {cid}** ({label}): {row[f"deviation ({m})"]}')
        kind = row.get("kind", "paper")
        text = row["claim"] if kind == "paper" else f"*{kind}:* {row['claim']}"
        cells = [text, row["where"], row["paper"], row["tolerance"], *(_cell(row, cid, m) for m in models)]
        lines.append("| " + " | ".join(str(c).replace("|", "/") for c in [*cells, row["notebook"]]) + " |")
    body = [summary(table).replace("\n", "  \n"), "", *lines, ""]
    return "\n".join(body + (["Known deviations and claims that do not apply:", "", *notes] if notes else [])) + "\n"


def write_report(table: pd.DataFrame, folder: Path) -> tuple[Path, Path]:
    """Write ``reproduction-report.csv`` and ``.md`` into ``folder``, each atomically; returns their paths."""
    folder = Path(folder)
    folder.mkdir(parents=True, exist_ok=True)
    csv_path = folder / "reproduction-report.csv"
    md_path = folder / "reproduction-report.md"
    _write_atomically(csv_path, table.to_csv())
    title = "# Reproduction report: Belluzzo et al. (2002), on every tire model\n\n"
    _write_atomically(md_path, title + to_markdown(table))
    return csv_path, md_path


def _write_atomically(path: Path, text: str) -> None:
    tmp = path.with_name(f".{path.name}.tmp")
    tmp.write_text(text)
    os.replace(tmp, path)


def verdicts(table: pd.DataFrame) -> str:
    """One line per claim, ``id: ring pass, cross-section fail (documented deviation)``: stable printed output."""
    lines = []
    for cid, row in table.iterrows():
        parts = []
        for m in models_of(table):
            verdict = row[f"verdict ({m})"]
            note = " (documented deviation)" if verdict == "fail" and row[f"deviation ({m})"] else ""
            parts.append(f"{m} {verdict}{note}")
        lines.append(f"{cid}: {', '.join(parts)}")
    return "\n".join(lines)


def check(table: pd.DataFrame) -> None:
    """Raise ``AssertionError`` naming every claim and model that fails without a documented deviation."""
    failures = []
    for cid, row in unexpected_failures(table).iterrows():
        for m in models_of(table):
            if row[f"verdict ({m})"] == "fail" and not row[f"deviation ({m})"]:
                failures.append(f"{cid} on {m} (paper {row['paper']}, ours {row[f'ours ({m})']}, {row['tolerance']})")
    if failures:
        raise AssertionError("claims not reproduced: " + "; ".join(failures))
