"""The moving-hub RM tire as an FMI 2.0 co-simulation FMU, for the user's vehicle tools.

Paper, *Simulation of Wheel-Road Interaction*: the RM tire is meant to be "implemented in a car
model" (Eq. 5-8). Vehicle tools (Simcenter, Dymola/OpenModelica, Simulink, CarMaker, MBS codes)
exchange dynamic models as FMUs; :func:`write_fmu` packs the moving-hub tire of Eq. 7 into one:

* ``modelDescription.xml``: outputs ``F_M``, ``F_F``, ``F_H`` (N; Eq. 5), inputs
  ``hub_displacement`` (m) and ``road_height[k]`` (m, at the footprint's leading edge, one per
  lateral strip), and as constant outputs (a master reads them to build the road inputs, and
  never writes them) the ``speed`` and ``time_step`` it was built for, ``leading_edge_x`` (where
  the road heights are taken) and ``road_y[k]`` (each road input's lateral position). FMI 2.0 has no attribute for a
  step the FMU requires: ``canHandleVariableCommunicationStepSize="false"``, the default
  experiment's ``stepSize`` and ``time_step`` carry it, and the FMU refuses another step;
* ``resources/tire.bin``: the tire's numbers (:mod:`.tables`);
* ``sources/``: the C sources, the same for every tire, and the FMI 2.0 headers, so that any
  platform can build it;
* ``binaries/<platform>/roadnoise_rm_tire.<so|dylib|dll>``: that source compiled with the
  platform's C compiler at export (``cc``, or ``CC``); without one, a source-only FMU and a warning.

No Python runs inside the FMU.
"""

from __future__ import annotations

import os
import platform
import shutil
import subprocess
import sys
import tempfile
import uuid
import zipfile
from datetime import UTC, datetime
from pathlib import Path
from xml.sax.saxutils import quoteattr

from .. import guards
from .tables import TireTables, write_tables

MODEL_IDENTIFIER = "roadnoise_rm_tire"
SOURCE_DIR = Path(__file__).parent / "c"
#: The C sources compiled into the FMU's binary (the model, then the FMI functions it does not support).
SOURCES = (f"{MODEL_IDENTIFIER}.c", "fmi2_unsupported.c")
#: Value references of the C source (``roadnoise_rm_tire.c``): outputs, inputs, constants, road inputs from 10.
REFERENCES = {"F_M": 0, "F_F": 1, "F_H": 2, "hub_displacement": 3, "speed": 4, "time_step": 5, "leading_edge_x": 6}
ROAD_REFERENCE = 10
#: Value reference of ``road_y[1]``, the lateral position of ``road_height[1]`` (then one per strip).
ROAD_Y_REFERENCE = 100000


def platform_folder() -> str | None:
    """The FMI 2.0 binaries folder of this platform (``linux64``, ``darwin64``, ``win64``), None if it has none."""
    bits = "64" if sys.maxsize > 2**32 else "32"
    system = {"Linux": "linux", "Darwin": "darwin", "Windows": "win"}.get(platform.system())
    return None if system is None else system + bits


def compiler() -> str | None:
    """The C compiler to build with: ``CC`` if set, else ``cc``, ``gcc`` or ``clang`` on the path (None: none)."""
    chosen = os.environ.get("CC")
    if chosen:
        return shutil.which(chosen)
    return next((found for name in ("cc", "gcc", "clang") if (found := shutil.which(name))), None)


def _variable(name: str, reference: int, causality: str, description: str, unit: str, **attributes: str) -> str:
    variability = attributes.pop("variability", "continuous")
    initial = attributes.pop("initial", None)
    real = " ".join(f"{k}={quoteattr(v)}" for k, v in {"unit": unit, **attributes}.items())
    initial_attribute = f" initial={quoteattr(initial)}" if initial else ""
    return (
        f'    <ScalarVariable name={quoteattr(name)} valueReference="{reference}" causality="{causality}" '
        f'variability="{variability}"{initial_attribute} description={quoteattr(description)}>\n'
        f"      <Real {real}/>\n    </ScalarVariable>"
    )


def model_description(tables: TireTables, name: str, guid: str) -> str:
    """The ``modelDescription.xml`` of the FMU of ``tables`` (FMI 2.0, co-simulation)."""
    dt = repr(float(tables.dt))
    variables = [
        _variable("F_M", 0, "output", "hub force, moving hub: F_F + F_H (Eq. 5), upward, from the static preload", "N"),
        _variable("F_F", 1, "output", "hub force of the road with the hub held (Eq. 3-4)", "N"),
        _variable("F_H", 2, "output", "hub force of the hub's motion, road level (G_H, Eq. 6)", "N"),
        _variable("hub_displacement", 3, "input", "vertical hub displacement, upward, from the static state", "m",
                  start="0"),
        _variable("speed", 4, "output", "rolling speed the FMU was built for (export another FMU for another)", "m/s",
                  variability="constant", initial="exact", start=repr(float(tables.speed))),
        _variable("time_step", 5, "output", "the only communication step the FMU takes", "s",
                  variability="constant", initial="exact", start=dt),
        _variable("leading_edge_x", 6, "output",
                  "road_height is the road this far ahead of the footprint centre, along the travel", "m",
                  variability="constant", initial="exact", start=repr(float(tables.leading_edge))),
    ]  # fmt: skip
    for k, y in enumerate(tables.strip_y):
        where = f"at y = {y * 1e3:.1f} mm across the tread" if tables.n_strips > 1 else "uniform across the width"
        variables.append(
            _variable(f"road_height[{k + 1}]", ROAD_REFERENCE + k, "input",
                      f"road height at the footprint's leading edge, {where}", "m", start="0")
        )  # fmt: skip
    for k, y in enumerate(tables.strip_y):
        variables.append(
            _variable(f"road_y[{k + 1}]", ROAD_Y_REFERENCE + k, "output",
                      f"lateral position of road_height[{k + 1}] from the tread's centre line", "m",
                      variability="constant", initial="exact", start=repr(float(y)))
        )  # fmt: skip
    inputs = " ".join(str(i + 1) for i in [3] + list(range(7, 7 + tables.n_strips)))
    road_inputs = " ".join(str(i + 1) for i in range(7, 7 + tables.n_strips))
    structure = [f'      <Unknown index="1" dependencies="{inputs}"/>', f'      <Unknown index="2" dependencies="{road_inputs}"/>',
                 '      <Unknown index="3" dependencies="4"/>']  # fmt: skip
    constants = [5, 6, 7] + list(range(8 + tables.n_strips, 8 + 2 * tables.n_strips))  # speed .. road_y[n]
    outputs = structure + [f'      <Unknown index="{i}" dependencies=""/>' for i in constants]
    description = (
        f"Moving-hub RM tire (Belluzzo et al. 2002, Eq. 7): {tables.n_tasselli} tasselli, {tables.n_states} states, "
        f"{tables.speed:g} m/s, step {tables.dt:.6g} s. Set the inputs, read the outputs, then step (direct feedthrough)."
    )
    return "\n".join(
        [
            '<?xml version="1.0" encoding="UTF-8"?>',
            f'<fmiModelDescription fmiVersion="2.0" modelName={quoteattr(name)} guid="{guid}" '
            f'description={quoteattr(description)} generationTool="roadnoise" '
            f'generationDateAndTime="{datetime.now(UTC).strftime("%Y-%m-%dT%H:%M:%SZ")}" '
            'variableNamingConvention="structured" numberOfEventIndicators="0">',
            f'  <CoSimulation modelIdentifier="{MODEL_IDENTIFIER}" canHandleVariableCommunicationStepSize="false" '
            'canInterpolateInputs="false" canBeInstantiatedOnlyOncePerProcess="false" '
            'canNotUseMemoryManagementFunctions="true" canGetAndSetFMUstate="false" canSerializeFMUstate="false" '
            'providesDirectionalDerivative="false">',
            "    <SourceFiles>",
            *(f'      <File name="{source}"/>' for source in SOURCES),
            "    </SourceFiles>",
            "  </CoSimulation>",
            "  <UnitDefinitions>",
            '    <Unit name="m"><BaseUnit m="1"/></Unit>',
            '    <Unit name="N"><BaseUnit kg="1" m="1" s="-2"/></Unit>',
            '    <Unit name="m/s"><BaseUnit m="1" s="-1"/></Unit>',
            '    <Unit name="s"><BaseUnit s="1"/></Unit>',
            "  </UnitDefinitions>",
            '  <LogCategories>\n    <Category name="logStatusDiscard"/>\n    <Category name="logStatusError"/>\n'
            "  </LogCategories>",
            f'  <DefaultExperiment startTime="0" stepSize="{dt}"/>',
            "  <ModelVariables>",
            *variables,
            "  </ModelVariables>",
            "  <ModelStructure>",
            "    <Outputs>",
            *outputs,
            "    </Outputs>",
            "    <InitialUnknowns>",
            *structure,
            "    </InitialUnknowns>",
            "  </ModelStructure>",
            "</fmiModelDescription>",
            "",
        ]
    )


def compile_binary(sources: Path, target: Path) -> str | None:
    """Compile the C sources (:data:`SOURCES`) in ``sources`` to the shared library ``target``; the compiler's complaint, or None."""
    cc = compiler()
    if cc is None:
        return "no C compiler found (set CC or install cc/gcc/clang)"
    command = [
        cc,
        "-shared",
        "-O2",
        "-std=c99",
        f"-I{sources}",
        "-o",
        str(target),
        *(str(sources / source) for source in SOURCES),
    ]
    if platform.system() != "Windows":
        command[2:2] = ["-fPIC"]
        command.append("-lm")
    done = subprocess.run(command, capture_output=True, text=True, check=False)
    return None if done.returncode == 0 else f"{' '.join(command)} failed:\n{done.stderr.strip()}"


def write_fmu(tables: TireTables, path: str | Path, name: str = "roadnoise RM tire", binary: bool = True) -> Path:
    """Write the FMU of ``tables`` (:func:`.tables.tire_tables`) to ``path`` (``.fmu``); returns its path.

    ``binary=False`` writes a source-only FMU (as without a C compiler, which warns). The file is
    written whole or not at all (built in a temporary folder, then moved into place).
    """
    if not isinstance(tables, TireTables):
        raise TypeError(
            f"tables must be TireTables (roadnoise_utils.fmu.tables.tire_tables), got {type(tables).__name__}"
        )
    path = Path(path)
    if path.suffix != ".fmu":
        raise ValueError(f"path = {str(path)!r} must end in .fmu")
    if not path.parent.is_dir():
        raise ValueError(f"path = {str(path)!r}: its folder {str(path.parent)!r} does not exist")
    guards.flag("binary", binary)
    with tempfile.TemporaryDirectory(dir=path.parent) as work:
        root = Path(work) / "fmu"
        (root / "resources").mkdir(parents=True)
        (root / "sources").mkdir()
        for source in [*SOURCES, f"{MODEL_IDENTIFIER}.h"]:
            shutil.copy(SOURCE_DIR / source, root / "sources")
        for header in (SOURCE_DIR / "fmi2").iterdir():
            shutil.copy(header, root / "sources")
        guid = "{" + str(uuid.uuid4()) + "}"
        write_tables(tables, root / "resources" / "tire.bin", guid)
        (root / "modelDescription.xml").write_text(model_description(tables, name, guid), encoding="utf-8")
        folder = platform_folder()
        if binary and folder is not None:
            suffix = {"linux": ".so", "darwin": ".dylib", "win": ".dll"}[folder[:-2]]
            (root / "binaries" / folder).mkdir(parents=True)
            problem = compile_binary(root / "sources", root / "binaries" / folder / (MODEL_IDENTIFIER + suffix))
            if problem is not None:
                shutil.rmtree(root / "binaries")
                guards.warn(f"the FMU is source-only (a tool must compile sources/ itself): {problem}")
        elif binary:
            guards.warn(f"the FMU is source-only: no FMI platform folder for {platform.system()}")
        staged = Path(work) / path.name
        with zipfile.ZipFile(staged, "w", zipfile.ZIP_DEFLATED) as archive:
            for file in sorted(root.rglob("*")):
                if file.is_file():
                    archive.write(file, file.relative_to(root).as_posix())
        os.replace(staged, path)
    return path
