"""The command line loads what a command needs, when it runs (issue 36).

``roughcontact --help`` and ``--version`` import no numerical or plotting library; each command
builds its own options (and imports what their help needs) only when it is the one given. What
the lazy paths could forget (a command's options, an import inside a handler) is exercised here
for every command: a forgotten import fails this test, not a user.
"""

import json
import subprocess
import sys

import pytest

from roughcontact.cli import GROUPS, build_parser, main

HEAVY = (
    "numba",
    "pyfftw",
    "scipy.fft",
    "scipy.ndimage",
    "scipy.optimize",
    "scipy.signal",
    "scipy.stats",
    "xarray",
    "pandas",
    "dask",
    "matplotlib",
    "pydantic",
    "SurfaceTopography",
    "h5netcdf",
    "roughcontact.contact",
    "roughcontact.papers",
    "roughcontact.study",
)
"""Libraries (and parts of roughcontact) that a command's help or version must not import."""

COMMANDS = [name for group in GROUPS for name in group.COMMANDS]


def _modules_after(argv: list[str]) -> set[str]:
    """Run ``roughcontact ARGV`` in a fresh interpreter; return the modules it imported."""
    script = (
        "import json, sys\n"
        "from roughcontact.cli import main\n"
        "try:\n"
        f"    main({argv!r})\n"
        "except SystemExit:\n"
        "    pass\n"
        "print(json.dumps(sorted(sys.modules)), file=sys.stderr)\n"
    )
    done = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, check=True)
    return set(json.loads(done.stderr.strip().splitlines()[-1]))


@pytest.mark.parametrize("argv", [["--help"], ["--version"], []])
def test_help_and_version_import_no_numerical_or_plotting_library(argv):
    assert not {module for module in _modules_after(argv) if module.startswith(HEAVY)}


def test_the_import_check_sees_what_a_command_imports():
    assert "roughcontact.study" in _modules_after(["models", "normal"])


def test_the_top_level_help_lists_every_command_with_its_summary(capsys):
    with pytest.raises(SystemExit) as stop:
        main(["--help"])
    assert stop.value.code == 0
    listed = capsys.readouterr().out
    for group in GROUPS:
        for name, summary in group.COMMANDS.items():
            assert name in listed and summary.split()[0] in listed


@pytest.mark.parametrize("command", COMMANDS)
def test_every_command_builds_its_options_and_help_when_given(command, capsys):
    with pytest.raises(SystemExit) as stop:
        main([command, "--help"])
    assert stop.value.code == 0
    assert f"usage: roughcontact {command}" in capsys.readouterr().out


@pytest.mark.parametrize("command", COMMANDS)
def test_the_parser_of_one_command_has_the_same_options_as_the_full_parser(command):
    def options(parser):
        chosen = next(a for a in parser._subparsers._actions if a.dest == "command").choices[command]
        return sorted(option for action in chosen._actions for option in action.option_strings)

    assert options(build_parser([command])) == options(build_parser())


def test_the_command_is_found_after_the_global_options(run):
    status, out, _ = run("-v", "models")
    assert status == 0 and "normal" in out


def test_an_unknown_command_is_refused_with_the_known_ones(capsys):
    with pytest.raises(SystemExit) as stop:
        main(["contcat"])
    assert stop.value.code == 2
    error = capsys.readouterr().err
    assert "contcat" in error and "contact" in error
