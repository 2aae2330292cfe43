"""The package layout keeps its promises: data flows one way, no private names cross modules,
condition files are read only by the experiments, modules stay short, tests mirror the folders,
no checked notebook output prints round-off, and the text cites nothing outside the repository."""

from __future__ import annotations

import ast
import json
import re
from pathlib import Path

import pytest

from roadnoise_utils.repro.cache import PACKAGE_DIR
from roadnoise_utils.repro.paths import REPO_ROOT

#: Layers in the order the data flows; a module may import from its own layer or an earlier one.
LAYERS = [
    ["analysis", "guards", "settings", "parallel", "repro.paths", "repro.cache", "repro.provenance"],
    ["tire"],
    ["road"],
    ["response"],
    # the tire models, one folder each, implementing the interface of tire.model
    ["tire.ring", "tire.cross_section", "tire.frf_file"],
    # the loaded FE tire: the cross-section tire's construction swept into 3-D solids
    ["tire.loaded"],
    ["rm"],
    ["vehicle"],
    # the tire for the user's vehicle tools (FMU, state-space files)
    ["fmu"],
    ["repro.style", "repro.inputs"],
    ["repro.stages"],
    ["experiments"],
    ["repro.claims", "repro.collection", "repro.evaluators"],
    ["figures"],
    ["repro.reproduce", "repro.book", "repro", "__init__", "__main__"],
]
MAX_LINES = 500


def _modules() -> dict[str, Path]:
    modules = {}
    for path in sorted(PACKAGE_DIR.rglob("*.py")):
        parts = path.relative_to(PACKAGE_DIR).with_suffix("").parts
        name = ".".join(parts[:-1]) if parts[-1] == "__init__" else ".".join(parts)
        modules[name or "__init__"] = path
    return modules


MODULES = _modules()


def _layer(name: str) -> int:
    best = None
    for k, layer in enumerate(LAYERS):
        for prefix in layer:
            if name == prefix or name.startswith(prefix + "."):
                if best is None or len(prefix) > best[1]:
                    best = (k, len(prefix))
    assert best is not None, f"module {name} is in no layer of the layout"
    return best[0]


def _imports(name: str, path: Path) -> list[tuple[str, list[str]]]:
    """(imported package module, names imported from it) for every relative import of a module."""
    package = name.split(".") if path.name == "__init__.py" else name.split(".")[:-1]
    if name == "__init__":
        package = []
    found = []
    for node in ast.walk(ast.parse(path.read_text())):
        if isinstance(node, ast.ImportFrom) and node.level:
            base = package[: len(package) - (node.level - 1)]
            module = ".".join(base + ([node.module] if node.module else []))
            found.append((module, [a.name for a in node.names]))
    return found


@pytest.mark.parametrize("name", sorted(MODULES))
def test_data_flows_one_way(name):
    own = _layer(name)
    for module, names in _imports(name, MODULES[name]):
        targets = [f"{module}.{n}" if f"{module}.{n}" in MODULES else module for n in names] if module else names
        for target in targets:
            assert _layer(target) <= own, f"{name} (layer {own}) imports {target} (layer {_layer(target)})"


#: The tire models' folders (``tire/<model>/``): only they know which model they are.
MODEL_FOLDERS = sorted(p.parent.name for p in (PACKAGE_DIR / "tire").glob("*/__init__.py"))
#: Modules outside the model folders that import one, and why: the registry, and a model's own chapter.
MODEL_IMPORTS = {
    "__init__": set(MODEL_FOLDERS),  # imports every model so that it registers; the ring FE tire's entry points
    "experiments.paper_defaults": {"ring"},  # ru.solve_static(fet): the ring FE tire with the paper's drum
    "figures.fe_tire_model": {"ring"},  # notebook 01, the ring tire's chapter: its mesh, shapes and modes
    "figures.cross_section": {"cross_section"},  # notebook 09, the cross-section tire's chapter: its layers
    "experiments.cross_section": {"cross_section"},  # notebook 09's tables of its construction
    "experiments.tire_models": {"frf_file"},  # notebook 13: any model written in the frf-file model's format
    "experiments.loaded_tire": {"loaded"},  # notebook 16, the loaded FE tire's chapter: its mesh, steps, load curves
    "figures.loaded_tire": {"loaded"},  # notebook 16: its loaded shape
}


#: Models built on another model's construction, and why.
MODEL_BUILDS_ON = {
    "loaded": {"cross_section"},  # its tire file, profile, layers and laminate rule are the cross-section tire's
}


def _model_of(module: str) -> str | None:
    parts = module.split(".")
    return parts[1] if len(parts) > 1 and parts[0] == "tire" and parts[1] in MODEL_FOLDERS else None


def _all_imports(name: str, path: Path) -> set[str]:
    """Every package module ``name`` imports (relative and absolute, at the top or inside functions)."""
    found = set()
    for module, names in _imports(name, path):
        found |= {f"{module}.{n}" if f"{module}.{n}" in MODULES else module for n in names} if module else set(names)
    for node in ast.walk(ast.parse(path.read_text())):
        if isinstance(node, ast.ImportFrom) and not node.level and (node.module or "").startswith("roadnoise_utils."):
            found.add(node.module.removeprefix("roadnoise_utils."))
    return found


@pytest.mark.parametrize("name", sorted(MODULES))
def test_only_the_registry_and_a_models_chapter_import_a_model(name):
    own = _model_of(name)
    allowed = {own} | MODEL_BUILDS_ON.get(own, set()) if own else MODEL_IMPORTS.get(name, set())
    imported = {_model_of(m) for m in _all_imports(name, MODULES[name])} - {None}
    assert imported <= allowed, f"{name} imports the model folders {sorted(imported - allowed)}"


#: What a type branch looks like: a test of a model's kind or of a model's, spec's or state's type.
MODEL_KINDS = ("ring", "cross-section", "frf-file", "loaded-fe")
#: A model's own chapter module may refuse every other model up front (a clear error naming the model it got).
CHAPTER_TYPE_CHECKS = {"experiments.loaded_tire": {"LoadedFEModel"}}


@pytest.mark.parametrize("name", sorted(n for n in MODULES if not _model_of(n) and n not in ("tire.model", "__init__")))
def test_no_type_branch_outside_the_models(name):
    """Outside ``tire/<model>/`` and the registry (``tire.model``) nothing asks which model it holds."""
    tree = ast.parse(MODULES[name].read_text())
    for node in ast.walk(tree):
        if isinstance(node, ast.Compare):
            texts = [c.value for c in [node.left, *node.comparators] if isinstance(c, ast.Constant)]
            assert not set(texts) & set(MODEL_KINDS), f"{name}:{node.lineno} compares a model name: {ast.unparse(node)}"
        if isinstance(node, ast.Call) and ast.unparse(node.func) in ("isinstance", "hasattr", "type"):
            named = {n.id for n in ast.walk(node) if isinstance(n, ast.Name)} | {
                n.attr for n in ast.walk(node) if isinstance(n, ast.Attribute)
            }
            model_types = {n for n in named if re.fullmatch(r"\w*(Spec|State|Tire|Model|FETModel)", n)} - {"TireModel"}
            model_types -= CHAPTER_TYPE_CHECKS.get(name, set())
            assert not model_types, f"{name}:{node.lineno} tests a model's type: {ast.unparse(node)}"
    assert not re.search(r"is_cross_section|model_name", MODULES[name].read_text()), name


@pytest.mark.parametrize("name", sorted(MODULES))
def test_no_private_name_crosses_modules(name):
    for module, names in _imports(name, MODULES[name]):
        private = [n for n in names if n.startswith("_") and n != "__version__"]
        assert not private, f"{name} imports private {private} from {module}"


@pytest.mark.parametrize("name", sorted(MODULES))
def test_only_the_experiments_read_condition_files(name):
    source = MODULES[name].read_text()
    reads = "load_conditions(" in source or '"conditions"' in source
    assert not reads or name.startswith("experiments"), f"{name} reads data/conditions"


@pytest.mark.parametrize("name", sorted(MODULES))
def test_modules_stay_short(name):
    lines = MODULES[name].read_text().count("\n")
    assert lines <= MAX_LINES, f"{name}: {lines} lines"


def test_tests_mirror_the_package_folders():
    tests = Path(__file__).parent
    folders = ["tire", "road", "response", "rm", "vehicle", "experiments", "repro"]
    folders += [f"tire/{p.parent.name}" for p in sorted((PACKAGE_DIR / "tire").glob("*/__init__.py"))]  # the models
    for folder in folders:
        assert (PACKAGE_DIR / folder).is_dir() and (tests / folder).is_dir(), folder
        # test_<module>.py, or test_<module>_contract.py for an interface's contract over its implementations
        names = {p.stem.removeprefix("test_").removesuffix("_contract") for p in (tests / folder).glob("test_*.py")}
        modules = {p.stem for p in (PACKAGE_DIR / folder).glob("*.py")}
        modules |= {p.parent.name for p in (PACKAGE_DIR / folder).glob("*/__init__.py")}  # a model's folder
        assert names <= modules, folder


#: A number in ``e`` format (``2.9e-12``, ``-1.0E-10``) not preceded by ``<`` (``< 1e-10`` is a bound).
E_FORMAT = re.compile(r"(?<![<\w.])(?<!< )[-+]?\d+(?:\.\d+)?[eE][-+]?\d+")
#: Below this a printed value is round-off: it changes with the BLAS build and the thread count.
ROUND_OFF = 1e-9


def round_off_values(text: str) -> list[str]:
    """The numbers in ``text`` printed in ``e`` format with a magnitude below :data:`ROUND_OFF`, bounds excepted."""
    return [m for m in E_FORMAT.findall(text) if abs(float(m)) < ROUND_OFF]


def test_the_round_off_pattern_finds_values_and_spares_bounds():
    assert round_off_values("difference: 2.9e-12, row 2.467e-12  -1.0E-10, zero 0.0e+00") == [
        "2.9e-12",
        "2.467e-12",
        "-1.0E-10",
        "0.0e+00",
    ]
    assert round_off_values("< 1e-10; max DC error <1e-12; 5.51e-05; 1e-09; 4.4e-08; 2.32e-03; x1e-12") == []


def _checked_outputs() -> list[tuple[str, int, str]]:
    found = []
    for path in sorted((REPO_ROOT / "notebooks").glob("[0-9][0-9]-*.ipynb")):
        for k, cell in enumerate(json.loads(path.read_text())["cells"]):
            if cell["cell_type"] == "code" and "NBVAL_CHECK_OUTPUT" in "".join(cell["source"]):
                text = []
                for out in cell.get("outputs", []):
                    text.append("".join(out.get("text", "")) + "".join(out.get("data", {}).get("text/plain", "")))
                found.append((path.name, k, "".join(text)))
    return found


def test_no_checked_output_prints_round_off():
    """A checked output that prints a residual (< 1e-9) as a value passes only on the machine that
    stored it: print the bound it meets (``ru.analysis.format_small``) and assert it instead."""
    checked = _checked_outputs()
    assert len(checked) > 50  # the notebooks were found
    offending = {f"{name} cell {k}": values for name, k, text in checked if (values := round_off_values(text))}
    assert not offending, f"checked outputs print round-off as values: {offending}"


#: A reference to something not in the repository: an issue number or the design document.
OUTSIDE_REFERENCE = re.compile(r"\b[Ii]ssues? #?\d+|\bDESIGN\b")


def _project_texts() -> list[Path]:
    """The files that speak of the project: the package, the tests, the notebooks' sources, the
    benchmarks, the README, the book's pages and the data files; this file, which names the pattern, left out."""
    paths = [
        *PACKAGE_DIR.rglob("*.py"),
        *(REPO_ROOT / "tests").rglob("*.py"),
        *(REPO_ROOT / "notebooks").glob("*.py"),
        *(REPO_ROOT / "benchmarks").rglob("*.py"),
        REPO_ROOT / "conftest.py",
        REPO_ROOT / "README.md",
        *(REPO_ROOT / "book").rglob("*.md"),
        *(REPO_ROOT / "data").rglob("*.toml"),
    ]
    return sorted(path for path in paths if path.is_file() and path.resolve() != Path(__file__).resolve())


def test_the_outside_reference_pattern_finds_issues_and_the_design_document():
    for text in ("issue 15", "(Issue 13, item 5)", "issues 14 and 16", "issue #12", "DESIGN section 2", "DESIGN §2"):
        assert OUTSIDE_REFERENCE.search(text), text
    for text in ("designs", "the design sweep", "tissue 5", "the issue of the fits", "DESIGNS"):
        assert not OUTSIDE_REFERENCE.search(text), text


#: Remarks on the project's past instead of its subject: its test runs, goals, costs or sessions.
HISTORY_REMARK = re.compile(r"\bCI\b|\bthe goal\b|\bcost us\b|\bthis session\b|\bno network\b", re.IGNORECASE)


def test_the_history_pattern_finds_remarks_on_the_past():
    for text in ("CI runs this small grid", "(the goal: < 2 s)", "they cost us 1.5 s", "this session's code"):
        assert HISTORY_REMARK.search(text), text
    for text in ("the circle", "specific", "the goals of the design", "costs"):
        assert not HISTORY_REMARK.search(text), text


def test_the_chapters_and_the_book_speak_of_their_subject_not_of_the_project_s_past():
    """A chapter or a book page teaches the method: no remarks on how the collection is tested, on goals
    or on costs of the past (a measured time is a result and says what it measures; the scripts
    under ``.ci/`` are named as files)."""
    chapters = sorted((REPO_ROOT / "notebooks").glob("[0-9][0-9]-*.py"))
    pages = sorted((REPO_ROOT / "book").rglob("*.md"))
    assert len(chapters) > 10 and len(pages) > 10
    offending = [
        f"{path.name}:{k}: {line.strip()}"
        for path in [*chapters, *pages]
        for k, line in enumerate(path.read_text(encoding="utf-8").splitlines(), start=1)
        if HISTORY_REMARK.search(line.replace(".ci/", ""))
    ]
    assert not offending, "remarks on the project's past:\n" + "\n".join(offending)


def test_no_references_outside_the_repository():
    """Code, notebooks and docs speak of the project only: say what an issue or a document outside
    the repository said, or point to the file or the paper that holds it."""
    texts = _project_texts()
    assert len(texts) > 100  # the files were found
    offending = [
        f"{path.relative_to(REPO_ROOT)}:{k}: {line.strip()}"
        for path in texts
        for k, line in enumerate(path.read_text(encoding="utf-8").splitlines(), start=1)
        if OUTSIDE_REFERENCE.search(line)
    ]
    assert not offending, "references outside the repository:\n" + "\n".join(offending)
