"""The README's notebook table is the generated one; every listed ready notebook exists with its pair."""

from __future__ import annotations

import re

from roadnoise_utils.repro import collection
from roadnoise_utils.repro.paths import REPO_ROOT


def test_readme_notebook_table_is_generated():
    readme = (REPO_ROOT / "README.md").read_text()
    block = re.search(r"<!-- notebook-table -->\n(.*?)\n<!-- /notebook-table -->", readme, re.S)
    assert block, "README lacks the notebook-table markers"
    assert block.group(1).strip() == collection.markdown_table().strip(), (
        "run python -m roadnoise_utils --print notebook-table"
    )


def test_ready_notebooks_exist_with_their_jupytext_pair():
    for nb in collection.notebooks():
        path = REPO_ROOT / "notebooks" / nb["file"]
        if nb["status"] == "ready":
            assert path.exists(), path
            assert path.with_suffix(".py").exists(), f"{path.stem}.py (py:percent pair) missing"


def test_readme_has_exactly_two_setup_commands():
    readme = (REPO_ROOT / "README.md").read_text()
    quick = readme.split("## Quick start", 1)[1].split("##", 1)[0]
    commands = [ln for ln in quick.splitlines() if ln.startswith("python3 -m venv")]
    assert len(commands) == 2
    assert commands[0].endswith("-m roadnoise_utils") and commands[1].endswith("-m pytest")


def test_widget_cells_do_not_print_the_callback():
    """``interact(f, ...)`` returns ``f``: left as a cell's last expression, its repr
    (``<function show_...>``) prints under the widget. Every widget cell assigns it away, and no
    executed notebook shows a function's repr."""
    import json

    for nb in collection.notebooks():
        source = (REPO_ROOT / "notebooks" / nb["file"]).with_suffix(".py").read_text()
        bare = re.findall(r"^interact(?:ive)?\(", source, re.M)
        assert not bare, f"{nb['file']}: assign the widget (_ = interact(...))"
        executed = json.loads((REPO_ROOT / "notebooks" / nb["file"]).read_text())
        for cell in executed["cells"]:
            for output in cell.get("outputs", []):
                text = "".join(output.get("data", {}).get("text/plain", ""))
                assert not text.startswith("<function"), f"{nb['file']}: {text[:60]}"
