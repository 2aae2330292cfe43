"""The reproduction command, its report, the README's promises and the notebooks' parameters."""

from __future__ import annotations

import os
import re
import signal
import subprocess
import sys
import time
from pathlib import Path

import nbformat
import numpy as np
import psutil
import pytest

import roadnoise_utils as ru
from roadnoise_utils.repro import collection, reproduce
from roadnoise_utils.repro.paths import REPO_ROOT

README = (REPO_ROOT / "README.md").read_text()
#: The reference pages of the book (your own tire, road, car, formats, ...): the snippets the README sends users to.
REFERENCE = "\n".join(p.read_text() for p in sorted((REPO_ROOT / "book").rglob("*.md")))
GALLERY = (REPO_ROOT / "book" / "gallery.md").read_text()


@pytest.mark.parametrize("notebook", sorted(p.name for p in (REPO_ROOT / "notebooks").glob("*.ipynb")))
def test_every_notebook_has_a_parameters_cell(notebook):
    nb = nbformat.read(REPO_ROOT / "notebooks" / notebook, as_version=4)
    tagged = [c for c in nb.cells if "parameters" in c.get("metadata", {}).get("tags", [])]
    assert len(tagged) == 1 and tagged[0].cell_type == "code"


def test_the_book_gallery_is_generated_and_every_figure_exists():
    block = re.search(r"<!-- gallery -->\n(.*?)\n<!-- /gallery -->", GALLERY, re.S)
    assert block and block.group(1).strip() == collection.gallery_markdown().strip()
    images = re.findall(r'src="(figures/[^"]+)"', GALLERY)
    assert len(images) >= 12
    # every image is in the repository and is what reproduction writes from the committed notebooks
    produced = set()
    for path in (REPO_ROOT / "notebooks").glob("*.ipynb"):
        nb = nbformat.read(path, as_version=4)
        produced |= {name for name, *_ in reproduce.figure_names(nb, path.stem)}
    for image in images:
        assert (REPO_ROOT / image).exists(), image
        assert image.removeprefix("figures/") in produced, image


def test_the_book_s_own_road_snippet(tire, fet, flat):
    static = flat
    tire_F = ru.stages.assemble_fixed_hub("165_65R14")
    snippet = REFERENCE.split("# Your own road\n", 1)[1].split("```python", 1)[1].split("```", 1)[0]
    namespace = {"ru": ru, "static": static, "tire_F": tire_F}
    exec(compile(snippet, "book", "exec"), namespace)  # the book's code, as written
    force = namespace["force"].force
    assert force.size > 1000 and np.all(np.isfinite(force)) and np.std(force) > 0


def test_the_book_s_exchange_formats_snippet(flat, tmp_path, monkeypatch):
    """The book's UFF 58 and OpenCRG walk, as written, on a CRG road of the rough texture."""
    monkeypatch.chdir(tmp_path)
    spectrum = ru.textures.load_texture("rough")
    ru.road.save_crg("my_road.crg", ru.textures.generate_field(spectrum, 51.2, 0.005, np.array([-0.08, 0.0, 0.08]), 7))
    snippet = REFERENCE.split("# Exchange formats", 1)[1].split("```python", 1)[1].split("```", 1)[0]
    namespace = {"ru": ru, "static": flat}
    exec(compile(snippet, "book", "exec"), namespace)  # the book's code, as written
    visco, back = namespace["visco"], namespace["back"]
    assert back.H.shape == visco.H.shape and np.allclose(back.H, visco.H, rtol=1e-11, atol=0)
    assert namespace["u"].u.shape[0] == flat.tasselli.n and np.std(namespace["u"].u) > 0
    assert ru.road.crg_modifiers("rough.crg") == {} and (tmp_path / "165_65R14.uff").stat().st_size > 0


def test_the_book_s_own_car_snippet():
    """The book's whole-car walk, as written (10 s at 120 km/h, four corners): every output's spectrum
    and the axles' coherence come back finite."""
    snippet = REFERENCE.split("# Your own car\n", 1)[1].split("```python", 1)[1].split("```", 1)[0]
    namespace = {"ru": ru}
    exec(compile(snippet, "book", "exec"), namespace)  # the book's code, as written
    run = namespace["run"]
    assert run.spectra.psd["a_hub_FL"].shape == run.spectra.freqs.shape and len(run.spectra.psd) == 18
    assert all(np.all(np.isfinite(v)) for v in run.spectra.psd.values())
    assert 0.0 <= run.spectra.force_coherence["front"].min() and run.spectra.force_coherence["front"].max() <= 1.0


def test_the_book_s_own_tire_snippet():
    """The book's Python walk through the stages, as written, on the paper's tire file."""
    snippet = REFERENCE.split("# Your own tire\n", 1)[1].split("```python", 1)[1].split("```", 1)[0]
    namespace = {}
    exec(compile(snippet.replace('"my_tire.toml"', '"165_65R14"'), "README", "exec"), namespace)
    force = namespace["force"].force
    assert namespace["tire_F"].nstates == 14 * namespace["static"].tasselli.n
    assert np.all(np.isfinite(force)) and force.max() > 100.0


def test_the_book_s_own_tire_instructions(tmp_path):
    """The book's new-tire recipe: copy a tire file, edit it, run notebook 01 on it with papermill."""
    text = (REPO_ROOT / "data" / "tires" / "165_65R14.toml").read_text()
    my_tire = tmp_path / "my_tire.toml"
    my_tire.write_text(text.replace("inflation_pressure = 2.3e5", "inflation_pressure = 2.6e5"))
    out = tmp_path / "my-tire.ipynb"
    result = subprocess.run(
        [
            sys.executable,
            "-m",
            "papermill",
            str(REPO_ROOT / "notebooks" / "01-fe-tire-model.ipynb"),
            str(out),
            "--cwd",
            str(REPO_ROOT / "notebooks"),
            "-p",
            "tire_name",
            str(my_tire),
            "-p",
            "n_modes",
            "30",
        ],
        capture_output=True,
        text=True,
        timeout=600,
    )
    assert result.returncode == 0, result.stderr[-3000:]
    nb = nbformat.read(out, as_version=4)
    printed = "".join(o.get("text", "") for c in nb.cells if c.cell_type == "code" for o in c.get("outputs", []))
    spec = ru.load_tire(my_tire)
    assert f"T = p b R = {spec.hoop_tension:.0f} N" in printed  # the notebook ran on the new tire
    assert re.search(r"vertical stiffness\s+-\s+\d", printed)  # no targets for it: obtained values only


# ---------------------------------------------------------------- the reproduction is atomic


def _notebook(path, *sources):
    nb = nbformat.v4.new_notebook(cells=[nbformat.v4.new_code_cell(s) for s in sources])
    nb.metadata["kernelspec"] = {"name": "python3", "display_name": "Python 3", "language": "python"}
    nbformat.write(nb, path)
    return path


PLOT = "# Fig. 1 analogue: a line\nimport matplotlib.pyplot as plt\nplt.plot([0, 1])\nplt.show()"


def test_figures_are_written_whatever_the_matplotlib_backend(tmp_path, monkeypatch):
    """MPLBACKEND=Agg (as .ci/run exports it) once deleted every figure; the kernels now draw inline."""
    monkeypatch.setenv("MPLBACKEND", "Agg")
    nb = _notebook(tmp_path / "01-demo.ipynb", PLOT)
    out = tmp_path / "figures"
    out.mkdir()
    (out / "stale.png").write_bytes(b"old")
    (out / "notes.txt").write_text("mine")
    rows, table = reproduce.reproduce([nb], out, report=False, workers=1)  # one: in this process
    assert table is None and [r["file"] for r in rows] == ["01-demo-fig01-a-line.png"]
    assert (out / "01-demo-fig01-a-line.png").read_bytes().startswith(b"\x89PNG")
    assert not (out / "stale.png").exists() and (out / "notes.txt").read_text() == "mine"
    assert (out / "index.csv").read_text().count("\n") == 2
    assert reproduce.figure_names(nbformat.read(nb, as_version=4), nb.stem)  # the notebook keeps its outputs
    assert not list(tmp_path.glob(".figures.*"))  # no staging folder left behind


@pytest.mark.parametrize(
    ("second", "message"),
    [
        ("raise ValueError('broken stage')", "cell 0 .* failed: ValueError: broken stage"),
        ("# a plot that draws nothing\nimport matplotlib.pyplot as plt\nplt.show()", "no figure from cell 0"),
    ],
)
def test_a_failure_writes_nothing(tmp_path, second, message):
    first = _notebook(tmp_path / "01-good.ipynb", PLOT)
    bad = _notebook(tmp_path / "02-bad.ipynb", second)
    before = {p: p.read_bytes() for p in (first, bad)}
    out = tmp_path / "figures"
    out.mkdir()
    (out / "previous.png").write_bytes(b"kept")
    with pytest.raises(reproduce.ReproductionError, match=message):
        reproduce.reproduce([first, bad], out, report=False, workers=1)
    assert [p.name for p in out.iterdir()] == ["previous.png"]
    assert all(p.read_bytes() == data for p, data in before.items())


def test_a_stalled_notebook_is_retried_once(tmp_path):
    marker = tmp_path / "first-attempt"
    stall = f"import pathlib, time\nm = pathlib.Path({str(marker)!r})\nif not m.exists():\n    m.touch()\n    time.sleep(60)"
    nb = _notebook(tmp_path / "01-slow.ipynb", stall, PLOT)
    rows, _ = reproduce.reproduce([nb], tmp_path / "figures", timeout=3, report=False, workers=1)
    assert marker.exists() and len(rows) == 1


def test_main_exits_non_zero_and_keeps_the_figures_on_failure(tmp_path, monkeypatch):
    notebooks = tmp_path / "notebooks"
    notebooks.mkdir()
    _notebook(notebooks / "00-overview.ipynb", "1 / 0")
    out = tmp_path / "figures"
    out.mkdir()
    (out / "kept.png").write_bytes(b"x")
    monkeypatch.setattr(reproduce, "notebooks", lambda: [{"file": "00-overview.ipynb", "status": "ready"}])
    assert reproduce.main(["--notebooks", str(notebooks), "--figures", str(out)]) == 2
    assert [p.name for p in out.iterdir()] == ["kept.png"]


def test_chapters_start_longest_first_and_the_overview_last():
    paths = [Path(f"{i:02d}.ipynb") for i in range(5)]
    seconds = {paths[1]: 10.0, paths[2]: 90.0, paths[4]: 40.0}  # paths[3]: unknown, 0
    assert reproduce.start_order(paths, seconds) == [paths[2], paths[4], paths[1], paths[3], paths[0]]
    assert reproduce.start_order(paths, {}) == paths[1:] + paths[:1]


def test_the_report_only_models_stages_start_first_and_the_claims_wait_for_them(monkeypatch):
    """The pool's first task computes the report-only models' stages (their claims, last first); the
    report is evaluated after it and after every chapter, whichever ends last."""
    order = []
    monkeypatch.setattr(reproduce, "REPORT_ONLY_MODELS", ("loaded-fe",))
    monkeypatch.setattr(reproduce, "_report_only_stages", lambda one_thread: order.append("early stages"))
    monkeypatch.setattr(reproduce, "_evaluated_claims", lambda one_thread: order.append("claims") or "table")
    monkeypatch.setattr(
        reproduce, "_timed_execution", lambda path, timeout, one_thread: order.append(path.name) or ({}, 0.0)
    )
    paths = [Path("00.ipynb"), Path("01.ipynb"), Path("02.ipynb")]
    done, table = reproduce._execute_all(paths, 1, workers=1, report=True)
    assert order == ["early stages", "01.ipynb", "02.ipynb", "00.ipynb", "claims"] and table == "table"
    assert list(done) == paths
    order.clear()
    reproduce._execute_all(paths, 1, workers=1, report=False)
    assert order == ["01.ipynb", "02.ipynb", "00.ipynb"]  # no report: nothing of the claims computed


def test_a_failing_notebook_stops_the_run_without_waiting_for_the_report_only_stages(tmp_path, monkeypatch):
    """Two workers (processes): the first task stands for minutes of stages; a chapter that fails ends the
    run at once, its workers terminated (measured: a few seconds, against the ten minutes the task sleeps)."""
    from tests.repro import slow_task

    monkeypatch.setattr(reproduce, "_report_only_stages", slow_task.sleep_long)
    monkeypatch.setattr(reproduce, "REPORT_ONLY_MODELS", ("loaded-fe",))
    paths = [_notebook(tmp_path / "00-overview.ipynb", PLOT), _notebook(tmp_path / "01-bad.ipynb", "1 / 0")]
    start = time.perf_counter()
    with pytest.raises(reproduce.ReproductionError, match="01-bad.ipynb"):
        reproduce._execute_all(paths, 60, workers=2, report=True)
    assert time.perf_counter() - start < 300.0


def test_the_report_only_models_are_those_notebook_00_does_not_show():
    from roadnoise_utils.repro import claims

    assert set(reproduce.REPORT_ONLY_MODELS) == set(claims.MODELS) - set(claims.OVERVIEW_MODELS) == {"loaded-fe"}


def test_the_collection_gives_every_ready_notebook_its_cold_time():
    ready = [nb for nb in collection.notebooks() if nb["status"] == "ready"]
    assert all(float(nb["cold_seconds"]) > 0 for nb in ready)


def test_a_figures_path_that_cannot_be_a_folder_is_refused_before_any_notebook_runs(tmp_path, monkeypatch, capsys):
    blocker = tmp_path / "a file"
    blocker.write_text("in the way")
    monkeypatch.setattr(reproduce, "reproduce", lambda *a, **k: pytest.fail("a notebook ran"))
    with pytest.raises(SystemExit):
        reproduce.main(["--figures", str(blocker / "figures")])
    assert "is a file, not a folder" in capsys.readouterr().err
    assert reproduce.output_folder_problem(tmp_path / "new" / "figures") == ""


#: Run by a fresh interpreter: a reproduction whose report-only stages fail while a chapter runs.
_FAILING_BESIDE_A_CHAPTER = """
import sys
from pathlib import Path
from roadnoise_utils.repro import reproduce
from tests.repro import slow_task
reproduce._report_only_stages = slow_task.fail_soon
reproduce._timed_execution = slow_task.chapter_deaf_to_sigterm
reproduce.STOP_GRACE = 1.0
reproduce.REPORT_ONLY_MODELS = ("loaded-fe",)
try:
    reproduce._execute_all([Path(p) for p in sys.argv[1:]], 900, workers=2, report=True)
except RuntimeError as error:
    print("stopped:", error)
"""


def test_a_failure_beside_a_chapter_deaf_to_sigterm_ends_the_run(tmp_path):
    """The report-only stages fail while the other worker runs a chapter that SIGTERM does not end (a
    worker executing a notebook: nbclient's handler shuts the kernel down and carries on). The run
    ends with the failure within seconds, that worker killed after its grace; a pool waiting for
    it would wait for ever."""
    marker = tmp_path / "chapter.pid"
    start = time.perf_counter()
    run = subprocess.Popen(
        [sys.executable, "-c", _FAILING_BESIDE_A_CHAPTER, str(tmp_path / "00.ipynb"), str(tmp_path / "01.ipynb")],
        cwd=REPO_ROOT, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, start_new_session=True,
        env={**os.environ, "SLOW_TASK_WAIT_FOR": str(marker)},
    )  # fmt: skip
    try:
        out, err = run.communicate(timeout=60)
    except subprocess.TimeoutExpired:
        os.killpg(run.pid, signal.SIGKILL)  # the run and its workers
        pytest.fail("the run did not end within 60 s of its failure")
    assert "stopped: a report-only stage failed" in out, err[-2000:]
    assert time.perf_counter() - start < 30.0
    assert (
        not psutil.pid_exists(int(marker.read_text())) or psutil.Process(int(marker.read_text())).status() == "zombie"
    )
