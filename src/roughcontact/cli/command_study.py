"""A command as a study: :class:`CommandStudy` builds the study document a command's options make.

A command that computes is a *view* of a study model (:mod:`roughcontact.study.kinds`): it turns
its options into the document a study file would hold, which is validated by the same schemas and
run by the same code as ``roughcontact run``. :class:`CommandStudy` remembers which option set
each value, so a problem is reported in the user's own terms: the option and the value as typed
(``--material-youngs-modulus: '-70 GPa' ...``), not a study key and an SI float.
"""

from __future__ import annotations

import argparse
import sys
from collections.abc import Iterable, Mapping
from pathlib import Path
from typing import Any

from ..errors import InputError
from ..messages import Door, render

FLAG_ALIASES = {"counter_body": ("counter",)}
"""Option spellings of release 0.1 still accepted (``--counter`` for ``--counter-body``)."""


def flag_of(name: str) -> str:
    """Return the option that sets the key ``name`` (``counter_body``: ``--counter-body``)."""
    return f"--{name.replace('_', '-')}"


def options(
    args: argparse.Namespace, *names: str, spelled: Mapping[str, str] | None = None
) -> dict[str, tuple[Any, str]]:
    """Return model keys as (value, option), the values read from ``args``.

    ``names`` are keys whose option is spelled like them (``stress_depths``: ``--stress-depths``);
    each ``key: "--option"`` of ``spelled`` is a key that an option of another name sets.
    """
    keys = {name: (getattr(args, name), flag_of(name)) for name in names}
    for key, option in (spelled or {}).items():
        keys[key] = (getattr(args, option.lstrip("-").replace("-", "_")), option)
    return keys


class CommandStudy:
    """The study a command builds from its options, and which option gave each value.

    Parameters
    ----------
    name : str
        The study's name (``"roughcontact contact"``): a later run of the same command into the
        same ``-o`` folder reuses its finished cases.
    description : str
        One line for the report.
    """

    def __init__(self, name: str, description: str = ""):
        self.name = name
        self.document: dict[str, Any] = {
            "study": {"name": name, "description": description, "seed": 0},
            "topographies": {},
            "materials": {},
            "analysis": [],
        }
        self.flags: dict[tuple, str] = {}
        self.words: dict[str, str] = {}
        self.table_words: dict[tuple, dict[str, str]] = {}
        self.options = None  # key -> the command's option of that name (RecordedOptions.option_for)

    # --- building the document ---------------------------------------------------------------

    def set(self, path: tuple, value: Any, flag: str | None = None) -> None:
        """Set ``value`` at ``path`` of the document; ``flag`` is the option the user typed it as."""
        node = self.document
        for key in path[:-1]:
            node = node[key]
        node[path[-1]] = value
        if flag is not None:
            self.name_flag(path, flag)

    def name_flag(self, path: tuple, flag: str) -> None:
        """Say that the value at ``path`` (and a key of that name in messages) came from ``flag``."""
        self.flags[path] = flag
        key = str(path[-1])
        if key not in ("file", "material", "counter_body", "topography") or flag.startswith("-"):
            self.words.setdefault(key, flag)

    def topography_file(self, name: str, args: argparse.Namespace, *, file: Path | None = None) -> str:
        """Add FILE (or ``file``) as the topography ``name``, read as the file options say; return it."""
        table: dict[str, Any] = {"file": str(Path(file if file is not None else args.file).resolve())}
        where = ("topographies", name)
        self.document["topographies"][name] = table
        for key in (
            "size",
            "height_unit",
            "position_unit",
            "channel",
            "fill_undefined",
            "max_filled",
            "treat_as_height",
            "override_file_values",
            "remove_specks",
            "exclude_filled",
            "crop",
        ):
            self.words.setdefault(key, flag_of(key))
        self.flags[(*where, "max_filled")] = "--max-filled"
        self.name_flag((*where, "file"), "FILE" if file is None else str(file))
        self.flags[where] = "FILE" if file is None else str(file)
        # FILE's own options; the file's units (--size, --height-unit) and --detrend hold for every file
        for key in (
            ("channel", "height_unit", "position_unit", "max_filled")
            if file is None
            else (
                "height_unit",
                "position_unit",
            )
        ):
            if getattr(args, key, None) is not None:
                self.set((*where, key), getattr(args, key), flag_of(key))
        if getattr(args, "size", None) is not None:
            self.set((*where, "size"), list(args.size) if len(args.size) > 1 else args.size[0], "--size")
        if getattr(args, "crop", None):
            self.set((*where, "crop"), list(args.crop), "--crop")
        if getattr(args, "override_file_values", False):
            self.set((*where, "override_file_values"), True, "--override-file-values")
        flags = ("fill_undefined", "periodic", "treat_as_height", "remove_specks", "exclude_filled")
        for key in flags if file is None else ():
            if getattr(args, key, False):
                self.set((*where, key), True, flag_of(key))
        if getattr(args, "detrend", None) is not None:
            self.set((*where, "detrend"), args.detrend, "--detrend")
        return name

    def two_bodies(self, args: argparse.Namespace) -> dict[str, tuple[Any, str]]:
        """Return the keys of FILE merged with COUNTER_FILE (when given) and their two materials.

        ``topography``, ``counter_topography``, ``material`` (required), ``counter_body`` and
        ``resample``, each with the option that gave it, for the commands of two rough bodies
        (friction, adhesion; their options from :func:`add_two_bodies`).
        """
        counter = None
        if args.counter_file is not None:
            counter = self.topography_file("counter_surface", args, file=args.counter_file)
        return {
            "topography": (self.topography_file("surface", args), "FILE"),
            "counter_topography": (counter, "COUNTER_FILE"),
            "material": (self.material("material", args, required=True), "--material"),
            "counter_body": (self.material("counter_body", args), "--counter-body"),
            "resample": (args.resample or None, "--resample"),
        }

    def topography(self, name: str, table: dict[str, Any], flag: str) -> str:
        """Add a generated topography (a ``generate = ...`` table); return ``name``."""
        self.document["topographies"][name] = table
        self.flags[("topographies", name)] = flag
        return name

    def realisations(self, index: int, args: argparse.Namespace, *redrawn: str) -> None:
        """Run analysis ``index`` on ``--realisations`` draws of the generated topographies ``redrawn``.

        With more than one, their fixed seed gives way to seeds derived from the study's seed
        (``--seed``), one per realisation.
        """
        count = args.realisations
        if count is None:
            return
        self.set(("analysis", index, "realisations"), count, "--realisations")
        if count > 1:
            for name in redrawn:
                self.document["topographies"][name].pop("seed", None)
            self.set(("study", "seed"), args.seed, "--seed")

    def material(self, prefix: str, args: argparse.Namespace, *, required: bool = False) -> str | None:
        """Return the study name of the material of ``--PREFIX`` options (None where none is given).

        A library name alone is used as it is; Young's modulus and Poisson's ratio make a
        ``[materials.PREFIX]`` table (overrides of the library entry when a name is also given).
        """
        name = getattr(args, prefix)
        overrides = {
            key: getattr(args, f"{prefix}_{key}")
            for key in ("youngs_modulus", "poissons_ratio")
            if getattr(args, f"{prefix}_{key}") is not None
        }
        flag = flag_of(prefix)
        self.table_words[("materials", prefix)] = {"library": flag} | {
            key: f"{flag}-{key.replace('_', '-')}" for key in ("youngs_modulus", "poissons_ratio")
        }
        if name is None and not overrides:
            if required:
                raise InputError(flag, "no material given.", f"pass {flag} NAME or {flag}-youngs-modulus.")
            return None
        if not overrides:
            return name
        table = ({"library": name} if name is not None else {}) | overrides
        self.document["materials"][prefix] = table
        self.flags[("materials", prefix)] = flag
        for key in overrides:
            self.name_flag(("materials", prefix, key), f"{flag}-{key.replace('_', '-')}")
        self.words.setdefault("library", flag)
        return prefix

    def analysis(self, name: str, model: str, keys: dict[str, tuple[Any, str | None]]) -> int:
        """Add an analysis of ``model``; ``keys`` maps each key to (value, the option that gave it).

        A value of None is left out (the model's default). Returns the analysis' index.
        """
        index = len(self.document["analysis"])
        self.document["analysis"].append({"name": name, "model": model})
        self.flags[("analysis", index)] = name
        for key, (value, flag) in keys.items():
            if value is not None:
                self.set(("analysis", index, key), value, flag)
            elif flag is not None and flag.startswith("-"):
                self.words.setdefault(key, flag)  # named in messages even when not given
        return index

    def sweep(self, index: int, key: str, values: list, flag: str) -> None:
        """Sweep ``key`` of analysis ``index`` over ``values`` (one case each), given as ``flag``."""
        self.document["analysis"][index].setdefault("sweep", {})[key] = values
        self.name_flag(("analysis", index, "sweep", key), flag)
        self.name_flag(("analysis", index, key), flag)

    def zipped(self, index: int, axes: dict[str, tuple[list, str]]) -> None:
        """Take the lists of ``axes`` (key -> (values, option)) together: one case per position."""
        table = self.document["analysis"][index].setdefault("zip", {})
        for key, (values, flag) in axes.items():
            table[key] = values
            self.name_flag(("analysis", index, "zip", key), flag)
            self.name_flag(("analysis", index, key), flag)

    def compare(self, index: int, keys: dict[str, tuple[Any, str | None]]) -> None:
        """Add the ``[analysis.compare]`` table (measured data) to analysis ``index``."""
        table = self.document["analysis"][index].setdefault("compare", {})
        for key, (value, flag) in keys.items():
            if value is not None:
                table[key] = value
                if flag is not None:
                    self.name_flag(("analysis", index, "compare", key), flag)

    # --- validating and reporting problems in the command's terms ------------------------------

    def text(self) -> str:
        """Return the document as a study file (TOML), kept with the results (``run`` reruns it)."""
        import shlex

        import tomli_w

        document = {key: value for key, value in self.document.items() if value}
        return f"# written by: roughcontact {shlex.join(sys.argv[1:])}\n" + tomli_w.dumps(document)

    def build(self):
        """Validate the document and build its cases (:func:`roughcontact.study.config.build_study`).

        Raises
        ------
        InputError
            Every problem, each naming the option and the value as typed.
        """
        from ..study.config import StudyError, build_study

        try:
            return build_study(self.document, folder=Path.cwd(), text=self.text(), source=self.name)
        except StudyError as error:
            found = self.explain(error.problems)
            if len(found) == 1:
                raise InputError(*found[0]) from None
            lines = [
                f"{option}: {problem}" + (f" Fix: {fix}" if fix else "") for option, problem, fix in found
            ]
            raise InputError(self.name, f"{len(found)} problems:\n  " + "\n  ".join(lines)) from None

    def option_of(self, path: tuple) -> str | None:
        """Return the option that set the value at ``path``, else its key's option, else one above it.

        The key's option names a value that was not given (a missing ``--counter-surface-energy``).
        """
        if path in self.flags:
            return self.flags[path]
        if path and path[0] == "analysis" and str(path[-1]) in self.words:
            return self.words[str(path[-1])]
        for end in range(len(path) - 1, 0, -1):
            if path[:end] in self.flags:
                return self.flags[path[:end]]
        return None

    def name_of(self, key: str, path: tuple = ()) -> str | None:
        """Return the option that names ``key`` in this command's messages, None if it has none.

        The option the user typed it as (or the command gives it); at ``path`` (a problem's place)
        the words of its table first (a material's own options); else the command's option of
        that name (:meth:`RecordedOptions.option_for`). None: the command has no option for the
        key, and a message names it as the study key it is (:func:`roughcontact.messages.render`).
        """
        for end in range(len(path), 0, -1):
            if path[:end] in self.table_words and key in self.table_words[path[:end]]:
                return self.table_words[path[:end]][key]
        if key in self.words:
            return self.words[key]
        return self.options(key) if self.options is not None else None

    def render(self, text: str | None, path: tuple = ()) -> str | None:
        """Return a message with its marked keys named as this command's options (``--pressure``)."""
        return render(text, Door.CLI, lambda key: self.name_of(key, path))

    def explain(self, problems: Iterable) -> list[tuple[str, str, str | None]]:
        """Return (option, problem, fix) per problem, in the command's terms and the values as typed."""
        return [
            (
                self.option_of(p.path) or p.field,
                *p.said(Door.CLI, lambda key, path=p.path: self.name_of(key, path)),
            )
            for p in problems
        ]

    def input_error(self, error: InputError) -> InputError:
        """Return a model's refusal (named by its Python parameter) named by the option instead."""
        field, problem, fix = error.rendered(Door.CLI, self.name_of)
        return InputError(self.words.get(error.field, field), problem, fix)
