"""The claims report: tests of each claim, verdicts, exit status, an evaluator for every claim."""

from __future__ import annotations

import pytest

from roadnoise_utils.repro import claims, collection, reproduce

SMALL = [
    {"id": "a", "claim": "a number", "where": "Fig. 1", "paper": 10.0, "rel": 0.1, "notebook": "x.ipynb"},
    {"id": "b", "claim": "a bound", "where": "Eq. 2", "paper": "small", "max": 1.0, "notebook": "y.ipynb"},
    {
        "id": "c",
        "claim": "a deviation",
        "where": "Fig. 3",
        "paper": 5.0,
        "rel": 0.1,
        "notebook": "y.ipynb",
        "known_deviation": {"ring": "explained"},
    },
]


def test_report_passes_fails_and_deviations(tmp_path):
    table = claims.report(
        claims=SMALL, evaluators={"a": lambda m: 10.5, "b": lambda m: 0.5, "c": lambda m: 9.0}, models=("ring",)
    )
    assert list(table["verdict (ring)"]) == ["pass", "pass", "fail"]
    assert claims.exit_status(table) == 0  # the only failure is documented
    csv_path, md_path = claims.write_report(table, tmp_path)
    assert csv_path.read_text().count("\n") == 4
    text = md_path.read_text()
    assert "ring: 2 of 3 claims reproduced" in text and "known deviation: [ring: c]" in text and "explained" in text


def test_the_report_gives_round_off_as_the_bound_it_meets():
    """A residual of round-off size (here 1.2e-10 on one BLAS build, 7.3e-11 on another) is written
    as the bound, so the report's text is the same on every machine; larger values keep their digits."""
    table = claims.report(claims=SMALL[:2], evaluators={"a": lambda m: 10.5, "b": lambda m: 1.2e-10}, models=("ring",))
    assert list(table["ours (ring)"]) == ["10.5", "< 1e-09"] and list(table["verdict (ring)"]) == ["pass", "pass"]
    small = claims.report(claims=SMALL[1:2], evaluators={"b": lambda m: 2.85e-8}, models=("ring",))
    assert small["ours (ring)"].iloc[0] == "2.85e-08"


def test_each_tire_model_gets_its_column_deviations_and_exemptions():
    """A claim judged per model: the cross-section column has its own deviation and n/a reasons."""
    two = [
        {**SMALL[0], "known_deviation": {"cross-section": "why the cross-section tire differs"}},
        {**SMALL[1], "not_applicable": {"cross-section": "no such thing on this model"}},
    ]
    values = {"ring": 10.0, "cross-section": 20.0}
    evaluated = []
    table = claims.report(
        claims=two, evaluators={"a": values.get, "b": lambda m: evaluated.append(m) or 0.5}, models=tuple(values)
    )
    assert evaluated == ["ring"]  # not run where it does not apply
    assert list(table["verdict (ring)"]) == ["pass", "pass"]
    assert list(table["verdict (cross-section)"]) == ["fail", "n/a"]
    assert claims.exit_status(table) == 0
    assert claims.counts(table, "cross-section") == {"claims": 2, "pass": 0, "deviations": 1, "unexpected": 0, "n/a": 1}
    assert "a: ring pass, cross-section fail (documented deviation)" in claims.verdicts(table)
    assert "no such thing on this model" in claims.to_markdown(table)


def test_an_undocumented_failure_makes_the_exit_status_non_zero(tmp_path, monkeypatch):
    failing = claims.report(
        claims=SMALL, evaluators={"a": lambda m: 20.0, "b": lambda m: 0.5, "c": lambda m: 5.0}, models=("ring",)
    )
    assert claims.exit_status(failing) == 1
    with pytest.raises(AssertionError, match="a on ring .paper 10, ours 20"):
        claims.check(failing)
    monkeypatch.setattr(claims, "report", lambda **_: failing)
    assert reproduce.main(["--report-only", "--figures", str(tmp_path)]) == 1
    assert (tmp_path / "reproduction-report.md").exists()


def test_the_chapters_evaluate_the_overview_models_and_the_reproduction_every_model(tmp_path, monkeypatch):
    """A chapter's report (the default, run by the test suite) evaluates only ``OVERVIEW_MODELS``; the
    reproduction command asks for every model of ``data/paper/report.toml`` (the loaded FE tire's too)."""
    seen = []
    claims.report(claims=SMALL[:1], evaluators={"a": lambda m: seen.append(m) or 10.0})
    assert seen == list(claims.OVERVIEW_MODELS) and "loaded-fe" not in seen
    assert "loaded-fe" in claims.MODELS
    asked = {}
    table = claims.report(claims=SMALL[:1], evaluators={"a": lambda m: 10.0}, models=("ring",))
    monkeypatch.setattr(claims, "report", lambda **options: asked.update(options) or table)
    assert reproduce.main(["--report-only", "--figures", str(tmp_path)]) == 0
    assert asked == {"models": claims.MODELS}


def test_judge_tests():
    assert claims.judge({"paper": 2.0, "rel": 0.1}, 2.15)
    assert not claims.judge({"paper": 2.0, "rel": 0.1}, 2.3)
    assert claims.judge({"paper": "x", "min": 1.0, "max": 2.0}, 1.5)
    assert not claims.judge({"paper": 4, "equal": True}, 3.0)
    assert not claims.judge({"paper": 4, "min": 0}, float("nan"))


def test_every_claim_has_an_evaluator_and_a_notebook():
    ready = {nb["file"] for nb in collection.notebooks() if nb["status"] == "ready"}
    for c in claims.load_claims():
        assert c["id"] in claims.EVALUATORS, c["id"]
        assert c["notebook"] in ready, c["notebook"]


@pytest.mark.parametrize(
    ("ids", "message"),
    [
        (["fe_dof", "cleat_dynamik"], r"claim_ids: unknown id\(s\) \['cleat_dynamik'\]; valid ids are \["),
        ("fe_dof", r"claim_ids = 'fe_dof': give a list of claim ids"),
        ([], "claim_ids is empty"),
    ],
)
def test_a_misspelt_or_malformed_claim_selection_is_refused(ids, message):
    with pytest.raises(ValueError, match=message):
        claims.select_claims(ids)


def test_a_claim_selection_keeps_the_file_s_order():
    every = [c["id"] for c in claims.load_claims()]
    chosen = [c["id"] for c in claims.select_claims([every[3], every[0]])]
    assert chosen == [every[0], every[3]] and len(claims.select_claims(None)) == len(every)


def test_a_generator_of_claim_ids_is_read_once_and_checked():
    assert [c["id"] for c in claims.select_claims(i for i in ["fe_dof"])] == ["fe_dof"]
    with pytest.raises(ValueError, match=r"unknown id\(s\) \['nonexistent'\]"):
        claims.select_claims(i for i in ["nonexistent"])
