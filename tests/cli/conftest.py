"""Helpers of the command-line tests: run a command, read its ``--json`` document (as fixtures)."""

import json

import pytest

from roughcontact.cli import main


@pytest.fixture
def run(capsys):
    """``run(*argv)`` runs ``roughcontact ARGV``; returns (exit status, stdout, stderr)."""

    def run(*argv):
        status = main([str(a) for a in argv])
        captured = capsys.readouterr()
        return status, captured.out, captured.err

    return run


def _analysis(output: str, analysis: str | None) -> dict:
    analyses = json.loads(output)["analyses"]
    return analyses[0] if analysis is None else next(a for a in analyses if a["name"] == analysis)


@pytest.fixture
def cases():
    """``cases(output, analysis=None)``: the cases of an analysis of a command's ``--json`` output."""
    return lambda output, analysis=None: _analysis(output, analysis)["cases"]


@pytest.fixture
def scalars():
    """``scalars(output, analysis=None, case=0)``: the scalars of one case of a ``--json`` output."""
    return lambda output, analysis=None, case=0: _analysis(output, analysis)["cases"][case]["scalars"]


@pytest.fixture
def table():
    """``table(output, name, analysis=None)``: a table of a command's ``--json`` output."""
    return lambda output, name, analysis=None: _analysis(output, analysis)["tables"][name]
