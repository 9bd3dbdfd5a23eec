"""Helpers of the study tests: run the CLI, and copy an example study at a reduced size."""

import shutil
from pathlib import Path

import pytest

from roughcontact.cli import main

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


def run_cli(capsys, *argv):
    """Run ``roughcontact ARGV``; return (exit status, stdout, stderr)."""
    status = main([str(a) for a in argv])
    captured = capsys.readouterr()
    return status, captured.out, captured.err


def shrink_example(name: str, folder: Path, replacements: dict[str, str], copy: tuple[str, ...] = ()) -> Path:
    """Copy ``examples/NAME`` into ``folder`` with each replacement made (each must be found once or more).

    ``copy`` names files of ``examples/`` the study refers to by a relative path; they are copied too.
    """
    text = (EXAMPLES / name).read_text()
    for old, new in replacements.items():
        if old not in text:
            raise AssertionError(f"{old!r} not found in examples/{name}; the test is out of date")
        text = text.replace(old, new)
    for extra in copy:
        shutil.copy(EXAMPLES / extra, folder / extra)
    path = folder / name
    path.write_text(text)
    return path


@pytest.fixture
def shrunk():
    """``shrunk(name, folder, replacements, copy=())``: :func:`shrink_example` (tests cannot import it)."""
    return shrink_example


@pytest.fixture
def examples():
    """The examples/ folder."""
    return EXAMPLES


@pytest.fixture
def cli(capsys):
    """``cli(*argv)`` runs the command line and returns (status, out, err)."""
    return lambda *argv: run_cli(capsys, *argv)
