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
