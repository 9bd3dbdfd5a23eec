"""The study commands: ``run``, ``validate``, ``report``, ``models``, ``demo``, ``cite``, and ``plot OUT/``.

``roughcontact run STUDY.toml -o OUT/ [--workers N | --scheduler ADDR] [--resume]`` validates the
whole study first (every problem reported at once, nothing computed), then runs the cases and
writes the table, provenance, figures and the HTML report.
"""

from __future__ import annotations

import argparse
import dataclasses
import sys
import textwrap
from pathlib import Path

from ..errors import InputError
from ..messages import Door, render
from .options import (
    EXIT_CASES_FAILED,
    EXIT_INTERRUPTED,
    add_device,
    new_command,
    output_folder,
    refuse_unused,
)
from .output import not_made

COMMANDS = {
    "run": "run a study file (TOML): every case, the results table, figures and an HTML report",
    "validate": "check a study file and list its cases without computing anything",
    "models": "list the models a study can name, or one model's keys",
    "report": "write OUT/report.html: the tables and figures of a study on one offline page",
    "demo": "run the embedded demo study (examples/demo.toml: an AFM scan's statistics, normal contact, "
    "the three papers on small grids) and write its report",
    "cite": "print the BibTeX of the papers a finished study's models implement, or one model's (--model)",
}
"""This module's commands and their lines in ``roughcontact --help``."""


def _describe(study) -> list[str]:
    lines = [f"study {study.name!r} ({study.path}): {len(study.cases)} cases"]
    for analysis in study.analyses:
        swept = f", swept: {', '.join(analysis.sweep_axes)}" if analysis.sweep_axes else ""
        lines.append(f"  {analysis.name:<16} {analysis.kind.name:<15} {len(analysis.cases):>4} cases{swept}")
    if study.files:
        lines.append(f"  input files: {len(study.files)} (hashes recorded)")
    return lines


def _notes(study) -> None:
    for note in study.notes:
        print(f"roughcontact: note: {render(note, Door.STUDY)}", file=sys.stderr)


def _validate(args: argparse.Namespace) -> int:
    from ..study import load_study

    study = load_study(args.study)
    _notes(study)
    print("\n".join(_describe(study)))
    print("valid: nothing was computed")
    return 0


def run_and_report(
    study,
    output: Path,
    *,
    progress: bool,
    resume: bool = False,
    workers: int | None = None,
    scheduler: str | None = None,
    worker_storage: Path | None = None,
) -> int:
    """Run ``study`` into ``output`` (:func:`roughcontact.study.answers.answer`) and say what happened.

    Ctrl-C keeps what finished. Returns the exit status.
    """
    from ..study.answers import answer

    try:
        result = answer(
            study,
            output,
            resume=resume,
            progress=progress,
            workers=workers,
            scheduler=scheduler,
            worker_storage=worker_storage,
        )
    except KeyboardInterrupt:
        print(
            f"\ninterrupted: finished cases are kept in {output}; "
            "rerun the same command with --resume to finish the study",
            file=sys.stderr,
        )
        return EXIT_INTERRUPTED
    for analysis, line in result.warnings():
        print(f"roughcontact: warning: {analysis}: {render(line, Door.STUDY)}", file=sys.stderr)
    summary = result.summary
    for note in summary.notes:  # a lock taken over, stored cases not reused and why
        print(f"roughcontact: note: {note}", file=sys.stderr)
    print(
        f"{summary.done} case{'s' if summary.done != 1 else ''} run, {summary.skipped} reused, "
        f"{summary.failed} failed "
        f"in {summary.wall_seconds:.1f} s ({summary.executor})"
    )
    for failure in summary.failures:
        print(f"  failed: {failure}", file=sys.stderr)
    print(f"wrote {result.folder}/results.csv, figures/, tables/ and {result.report}")
    products = not_made(result.problems())
    return EXIT_CASES_FAILED if summary.failed else products


def _quiet_dask(verbose: int) -> None:
    """Keep Dask's INFO lines (cluster start and close) off the console unless -vv."""
    import logging

    import distributed  # noqa: F401  (sets its loggers' levels when imported: override them after)

    if verbose < 2:
        for name in ("distributed", "distributed.scheduler", "distributed.nanny", "distributed.worker"):
            logging.getLogger(name).setLevel(logging.WARNING)


def _run(args: argparse.Namespace) -> int:
    from ..study import load_study

    dask = args.workers is not None or args.scheduler is not None
    if dask:
        _quiet_dask(args.verbose)
        worker_storage = args.worker_storage
    else:
        args.taking(
            "without --workers or --scheduler the cases run in this process",
            "add --workers N",
            options=("worker_storage",),
        )
        worker_storage = None
    options = {"progress": not args.no_progress and sys.stderr.isatty(), "resume": args.resume}
    output, device = args.output, args.device
    refuse_unused(args)
    study = load_study(args.study)
    if device is not None:  # the command line overrides [study] device
        if device == "gpu":
            from .._device import resolve_device

            resolve_device("gpu")  # no GPU here: the user hears it now, not from every case
        study = dataclasses.replace(study, device=device)
    _notes(study)
    print("\n".join(_describe(study)))
    return run_and_report(
        study,
        output,
        workers=args.workers,
        scheduler=args.scheduler,
        worker_storage=worker_storage,
        **options,
    )


def _attribute_notes(schema) -> dict[str, str]:
    """Each entry of the numpy-style ``Attributes`` section of a schema's docstring, whole, on one line."""
    import inspect

    notes: dict[str, list[str]] = {}
    lines = inspect.cleandoc(schema.__doc__ or "").splitlines()
    inside, names = False, []
    for line in lines:
        if line.strip() == "Attributes":
            inside = True
            continue
        if not inside or (line.strip() and set(line.strip()) <= {"-"}):
            continue
        if line and not line.startswith(" "):
            if " : " not in line and not line.rstrip().isidentifier():
                break  # the next section
            names = [n.strip() for n in line.split(" : ")[0].split(",")]
            for name in names:
                notes.setdefault(name, [])
        elif line.strip() and names:
            for name in names:
                notes[name].append(line.strip())
        elif not line.strip():
            names = []
    return {name: " ".join(words) for name, words in notes.items()}


HELP_WIDTH = 110
"""Width of ``roughcontact models NAME``'s lines: each key's description wraps under itself."""


def describe_kind(kind) -> list[str]:
    """Lines describing a study model: its keys (type, default), figures, tables, compare keys, references."""
    from pydantic_core import PydanticUndefined

    from ..study.schema import unit_of

    lines = [f"{kind.name}: {kind.summary}", "  keys:"]
    notes = _attribute_notes(kind.parameters)
    for name, info in kind.parameters.model_fields.items():
        default = (
            "required"
            if info.default is PydanticUndefined and info.default_factory is None
            else (f"default {info.default!r}" if info.default_factory is None else "default []")
        )
        unit = kind.units.get(name) or unit_of(kind.parameters, name)
        shown = f"{name} [{unit}]" if unit else name
        note = info.description or notes.get(name, "")
        head = f"    {shown:<28} {default:<22} "
        wrapped = textwrap.wrap(note, width=max(HELP_WIDTH - len(head), 40)) or [""]
        lines.append((head + wrapped[0]).rstrip())
        lines += [" " * len(head) + more for more in wrapped[1:]]
    lines.append(f"  figures: {', '.join(kind.figures) or '-'}")
    if kind.tables:
        lines.append(f"  tables: {', '.join(kind.tables)}")
    if kind.compare is not None:
        lines.append(f"  [analysis.compare] keys: {', '.join(kind.compare.model_fields)}")
    cited = ", ".join(kind.references) + f" (roughcontact cite --model {kind.name} prints their BibTeX)"
    lines += textwrap.wrap(cited, HELP_WIDTH, initial_indent="  references: ", subsequent_indent="    ")
    return lines


def _models(args: argparse.Namespace) -> int:
    from ..study.kinds import get_kind, kind_names

    names = kind_names() if args.name is None else [args.name]
    if args.name is not None and args.name not in kind_names():
        raise InputError("NAME", f"unknown model {args.name!r}.", f"use one of {kind_names()}.")
    width = max(map(len, names))
    for name in names:
        kind = get_kind(name)
        print("\n".join(describe_kind(kind) if args.name else [f"{kind.name:<{width}} {kind.summary}"]))
    if args.name is None:
        print("roughcontact models NAME lists a model's keys")
    return 0


def _report(args: argparse.Namespace) -> int:
    from ..study.report import write_report
    from ..study.store import locked

    with locked(args.folder, field="OUT", create=False) as note:
        _stored_warnings(args.folder, note)
        print(f"wrote {write_report(args.folder)}")
    return 0


def _stored_warnings(folder: Path, lock_note: str | None) -> None:
    """Say which stored cases ``plot`` and ``report`` leave out (damaged) or use unverified (no checksum)."""
    from ..study.outputs import read_study
    from ..study.store import record_path

    if lock_note:
        print(f"roughcontact: note: {lock_note}", file=sys.stderr)
    if not (Path(folder) / "study.json").is_file():
        return  # read_study says what the folder lacks
    for analysis in read_study(folder)[1]:
        for case, problem in analysis.damaged:
            print(
                f"roughcontact: warning: case {case} ({analysis.name}): {problem}; left out of the tables, "
                "figures and report (pending in results.csv). Fix: rerun the study into this folder with "
                "--resume to compute it again.",
                file=sys.stderr,
            )
        if analysis.unsealed:
            many = len(analysis.unsealed) != 1
            example = record_path(Path(folder).expanduser().resolve(), analysis.name, analysis.unsealed[0])
            print(
                f"roughcontact: warning: {analysis.name}: {len(analysis.unsealed)} case{'s' if many else ''} "
                f"stored without a checksum by a roughcontact before checksums (e.g. {example}): used as "
                "stored, not verified. Fix: rerun the study into this folder with --resume to compute "
                f"{'them' if many else 'it'} again.",
                file=sys.stderr,
            )


def plot_study(folder: Path) -> int:
    """Re-draw the figures and tables of a study's output folder from its stored records.

    Cases whose stored files do not match their checksums are left out, each named on standard
    error; the folder is locked while its tables and figures are written.
    """
    from ..study.outputs import draw_figures, write_tables
    from ..study.store import locked

    with locked(folder, field="OUT", create=False) as note:
        _stored_warnings(folder, note)
        tables, table_problems = write_tables(folder)
        figures, problems = draw_figures(folder)
    problems = table_problems + problems
    for path in [*tables, *figures]:
        print(f"wrote {path}")
    for problem in problems:
        print(f"roughcontact: not drawn: {problem}", file=sys.stderr)
    return 0 if not problems else EXIT_CASES_FAILED


SAMPLE = "top-1.top"
"""The AFM scan the demo uses, shipped with roughcontact (WSxM, 600 nm x 600 nm, heights in nm)."""


def demo_study() -> Path:
    """Path of the embedded demo study (``roughcontact/data/demo.toml``, also ``examples/demo.toml``)."""
    from importlib.resources import files

    path = Path(str(files("roughcontact") / "data" / "demo.toml"))
    if not path.is_file():  # pragma: no cover - a broken installation
        raise InputError("demo", f"the embedded demo study is missing ({path}).", "reinstall roughcontact.")
    return path


def _demo(args: argparse.Namespace) -> int:
    import shutil

    from ..study import load_study

    path = demo_study()
    study = load_study(path)
    print(f"demo study {study.name!r}: {len(study.cases)} cases ({path})")
    status = run_and_report(study, args.output, progress=sys.stderr.isatty(), resume=True)
    # the sample scan beside OUT/study.toml: the study reruns from there, and a first user has a
    # real instrument file to try every command on
    sample = Path(args.output).expanduser().resolve() / SAMPLE
    if status != EXIT_INTERRUPTED and not sample.exists():
        shutil.copyfile(path.parent / SAMPLE, sample)
    if status == 0:
        print(f"sample AFM scan for your first commands: {sample} (try: roughcontact inspect {sample})")
    return status


def _provenance_references(folder: Path) -> list[dict]:
    """Return the references of a study's ``provenance.json``; InputError naming the folder without one."""
    import json

    path = folder / "provenance.json"
    if not path.is_file():
        raise InputError(
            str(folder),
            "has no provenance.json: it is not the output folder of a finished study.",
            "give the folder that 'roughcontact run STUDY.toml -o OUT' (or a command's -o OUT) wrote.",
        )
    references = json.loads(path.read_text()).get("references")
    if not references:
        raise InputError(
            str(path),
            "lists no references (an older roughcontact wrote it).",
            f"rerun the study into it with --resume: roughcontact run STUDY.toml -o {folder} --resume.",
        )
    return references


def _cite(args: argparse.Namespace) -> int:
    from ..references import Reference, bibtex, cited

    if (args.folder is None) == (args.model is None):
        raise InputError(
            "cite",
            "give a study's output folder or --model NAME.",
            "roughcontact cite OUT/ or roughcontact cite --model normal.",
        )
    if args.model is None:
        references = [Reference.from_dict(entry) for entry in _provenance_references(args.folder)]
    else:
        from ..study.kinds import get_kind, kind_names

        if args.model not in kind_names(aliases=True):
            raise InputError("--model", f"unknown model {args.model!r}.", f"use one of {kind_names()}.")
        references = cited(get_kind(args.model).references)
    print(bibtex(references), end="")
    return 0


def add_commands(commands) -> None:
    """Add ``run``, ``validate``, ``report``, ``models``, ``demo`` and ``cite`` to the subparsers."""
    run = new_command(
        commands,
        "run",
        _run,
        COMMANDS["run"],
        "Validate STUDY (all problems at once, nothing computed), run its cases in-process, on a "
        "local Dask cluster (--workers) or on a running one (--scheduler), and write OUT/results.csv, "
        "OUT/cases/, OUT/figures/, OUT/tables/, OUT/provenance.json and OUT/report.html.",
    )
    run.add_argument("study", type=Path, help="study file (TOML; its keys: the documentation's Studies page)")
    run.add_argument("-o", "--output", type=output_folder, required=True, help="output folder")
    where = run.add_mutually_exclusive_group()
    where.add_argument("--workers", type=int, help="run on a local Dask cluster of N worker processes")
    where.add_argument("--scheduler", help="address of a running Dask scheduler, e.g. tcp://10.0.0.5:8786")
    run.add_argument(
        "--resume", action="store_true", help="continue a study in OUT: keep finished cases, redo the rest"
    )
    run.add_argument(
        "--worker-storage", type=Path, help="folder the workers write the fields to (only scalars come back)"
    )
    run.add_argument("--no-progress", action="store_true", help="no progress bar")
    add_device(run)

    simple = (  # name, handler, its one argument (flags, keywords)
        ("validate", _validate, (("study",), {"type": Path, "help": "study file (TOML)"})),
        ("models", _models, (("name",), {"nargs": "?", "help": "a model, e.g. normal"})),
        ("report", _report, (("folder",), {"type": Path, "help": "the output folder of 'roughcontact run'"})),
        ("demo", _demo, (("-o", "--output"), {"type": output_folder, "default": Path("demo-output"),
                          "help": "folder of its results and report.html (default demo-output)"})),
    )  # fmt: skip
    for name, handler, (flags, keywords) in simple:
        summary = COMMANDS[name]
        description = summary[0].upper() + summary[1:] + "."
        new_command(commands, name, handler, summary, description).add_argument(*flags, **keywords)

    cite = new_command(
        commands,
        "cite",
        _cite,
        COMMANDS["cite"],
        "Print as BibTeX the papers and books a finished study's models implement (read from "
        "OUT/provenance.json) and roughcontact itself; with --model NAME, those of one model. "
        "CITATION.cff in the repository says how to cite roughcontact.",
    )
    cite.add_argument(
        "folder", type=Path, nargs="?", help="the output folder of 'roughcontact run' or a command's -o"
    )
    cite.add_argument(
        "--model", help="a model instead of a study, e.g. presliding (roughcontact models lists them)"
    )
