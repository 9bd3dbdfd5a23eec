"""Every command of README.md runs as written, at a reduced size, and leaves what it promises.

The ```bash blocks of README.md are read here, so an edited README is tested as it reads: a flag
that does not exist, a file name the demo does not write or a command that fails shows up as a
failing case named after the command. Each block runs in a folder of its own, its commands in
order as a reader types them (``roughcontact demo -o demo-output`` first, then the commands that
read ``demo-output/top-1.top``; ``A && B`` as one case). Where a command writes ``-o OUT`` into a
folder an earlier command of its block wrote, that folder is removed first (the README's ``-o
out/`` stands for a new folder each time), unless the command resumes it (``--resume``). A command
that an earlier block has word for word runs once; the later block takes its result and folder.

What the test changes, and only this:

* Placeholder file names become files of this repository (:data:`PLACEHOLDERS`): the AFM scan
  that ships with roughcontact for ``scan.di`` and ``tip.di``, the examples' CSV files, the demo's
  study file; ``afm.txt`` (plain-text heights) and ``ball.nc`` (a rough ball in the native format)
  are written from the same data by :func:`placeholder_files`. Nothing outside the repository is
  read (``../shared`` is not there in CI).
* Options that make a command smaller are appended where it accepts them (:func:`reduced`): fewer
  pixels, load steps and realisations, so the whole file runs in a few minutes on two cores.
  Appended options come after the README's, so they take precedence (``--grid 128 --grid 32``).

A command that is not ``roughcontact`` (the developer block's ``make demo``, ``make test``,
``make docs``) is not run: the test checks that it names a target of the Makefile.
"""

from __future__ import annotations

import contextlib
import json
import re
import shlex
import shutil
import traceback
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
import pytest

from roughcontact.cli import main
from roughcontact.units import quantity

ROOT = Path(__file__).resolve().parents[2]
README = ROOT / "README.md"
EXAMPLES = ROOT / "examples"
AFM_SCAN = ROOT / "src" / "roughcontact" / "data" / "top-1.top"

PLACEHOLDERS = {
    "scan.di": "top-1.top",
    "tip.di": "top-1.top",
    "afm.txt": "afm.txt",
    "ball.nc": "ball.nc",
    "programme.csv": EXAMPLES / "tangential_path_displacement.csv",
    "combined.csv": EXAMPLES / "frictional_programme.csv",
    "measured_mu.csv": EXAMPLES / "paper000_measured_mu.csv",
    "loop.csv": EXAMPLES / "paper001_measured_loop.csv",
    "curve.csv": EXAMPLES / "paper001_indentation_hdpe.csv",
    "study.toml": "study.toml",
}
"""README file name -> the file used: a name made by :func:`placeholder_files`, or a repository path."""


@dataclass(frozen=True)
class Command:
    """One line of a README block: one command, or several joined with ``&&``."""

    block: int
    index: int
    line: str
    steps: tuple[tuple[str, ...], ...]

    @property
    def id(self) -> str:
        words = [w for w in self.steps[0][1:] if not w.startswith("-o")][:4]
        return f"{self.block}.{self.index}-" + re.sub(r"[^A-Za-z0-9.-]+", "_", "-".join(words)).strip("_")


def readme_commands(text: str) -> list[Command]:
    """Return the commands of the ```bash blocks of ``text``: continuation lines joined, comments dropped."""
    commands = []
    for block, body in enumerate(re.findall(r"^```bash\n(.*?)^```", text, flags=re.S | re.M)):
        index = 0
        for line in re.sub(r"\\\n\s*", " ", body).splitlines():
            words = shlex.split(line, comments=True)
            if not words:
                continue
            steps, step = [], []
            for word in words:
                if word == "&&":
                    steps.append(tuple(step))
                    step = []
                else:
                    step.append(word)
            steps.append(tuple(step))
            commands.append(Command(block, index, line.split("#")[0].strip(), tuple(steps)))
            index += 1
    return commands


COMMANDS = readme_commands(README.read_text(encoding="utf-8"))
RUN = [c for c in COMMANDS if c.steps[0][0] == "roughcontact"]
OTHER = [c for c in COMMANDS if c.steps[0][0] != "roughcontact"]


def reduced(words: tuple[str, ...]) -> list[str]:
    """Return the options appended to a ``roughcontact`` command to make it small (none for most)."""
    command = words[1]
    extra: list[str] = []
    if command == "adhesion":
        extra += ["--steps", "8"]  # load and unload steps each way (40)
    if command == "asperity":
        extra += ["--grid", "32", "--steps", "20"]  # the island's grid (64, 128), the KKE curve's points
        if "volume" in words:
            extra += ["--layers", "4"]  # cells through the plastic depth (16)
    if command == "presliding" and "--paper001" in words:
        # 128 pixels over the 1.1 mm scan (512); the window stays the command's own (sized to the contact)
        extra += ["--pixels", "128", "--steps-per-stroke", "6", "--cycles", "2"]
    if command == "friction-compare":
        extra += ["--grid", "40"]  # the synthetic scans' points per side (250)
    if "--realisations" in words or command == "friction-compare":
        extra += ["--realisations", "2"]  # draws per setting (5; friction-compare: 7)
    return extra


def output_of(words: tuple[str, ...]) -> str | None:
    """Return the ``-o``/``--output`` value of a command, or None."""
    for flag in ("-o", "--output"):
        if flag in words:
            return words[words.index(flag) + 1]
    return None


def placeholder_files(folder: Path) -> None:
    """Write the files the README names into ``folder``: the AFM scan, its heights as text, a ball, a study.

    ``afm.txt`` holds the shipped scan's heights in nm (plain text, as an instrument exports them;
    the README gives its size and unit). ``ball.nc`` is paper 001's POM ball (sphere R = 5 mm with
    Table 2's roughness) at 256 pixels over 1.1 mm, its central 48 pixels (206 um; the Hertz
    contact at 25 mN is 75 um across). ``study.toml`` is the demo's study file, beside the scan it
    reads (what ``roughcontact demo`` writes as ``demo-output/study.toml``).
    """
    from roughcontact.papers import paper001
    from roughcontact.topography.io import read_topography
    from roughcontact.topography.native import save_topography
    from roughcontact.topography.process import central_window

    shutil.copy(AFM_SCAN, folder / "top-1.top")
    np.savetxt(folder / "afm.txt", read_topography(AFM_SCAN).heights * 1e9, fmt="%.4f")
    save_topography(central_window(paper001.roughness("POM", pixels=256), 48), folder / "ball.nc")
    shutil.copy(ROOT / "src" / "roughcontact" / "data" / "demo.toml", folder / "study.toml")


@dataclass
class Block:
    """The folder of one README block and what its commands gave: (exit status, stdout, stderr) by index."""

    folder: Path
    results: dict[int, tuple[int, str, str]] = field(default_factory=dict)

    def run(self, command: Command, capsys, blocks: dict[int, Block]) -> tuple[int, str, str]:
        """Run ``command`` in the block's folder after the block's earlier commands (each run once).

        A command an earlier block has already (``roughcontact demo -o demo-output`` twice) is not
        run again: its result and its output folder are taken from there.
        """
        for earlier in RUN:
            if earlier.block == command.block and earlier.index <= command.index:
                if earlier.index not in self.results:
                    self.results[earlier.index] = self._once(earlier, capsys, blocks)
        return self.results[command.index]

    def _once(self, command: Command, capsys, blocks: dict[int, Block]) -> tuple[int, str, str]:
        twin = next((c for c in RUN if c.steps == command.steps and c.block < command.block), None)
        if twin is None:
            return self._run(command, capsys)
        source = blocks[twin.block]
        result = source.run(twin, capsys, blocks)
        for words in command.steps:
            written = output_of(words)
            if written and (source.folder / written).is_dir():
                shutil.rmtree(self.folder / written, ignore_errors=True)
                shutil.copytree(source.folder / written, self.folder / written)
        return result

    def _run(self, command: Command, capsys) -> tuple[int, str, str]:
        status, out, err = 0, "", ""
        with contextlib.chdir(self.folder):
            for words in command.steps:
                written = output_of(words)
                if written and "--resume" not in words and Path(written).is_dir():
                    shutil.rmtree(written)  # the README's '-o out/' is a new folder each time
                argv = [_substituted(word) for word in words[1:]] + reduced(words)
                capsys.readouterr()
                try:
                    status = main(argv)
                except SystemExit as stop:
                    status = stop.code if isinstance(stop.code, int) else 1
                except Exception:  # a crash is this command's failure, not the next command's
                    status, err = -1, traceback.format_exc()
                captured = capsys.readouterr()
                out, err = out + captured.out, err + captured.err
                if status != 0:
                    break
        return status, out, err


def _substituted(word: str) -> str:
    return str(PLACEHOLDERS.get(word, word))


@pytest.fixture(scope="module")
def blocks(tmp_path_factory) -> dict[int, Block]:
    found = {}
    for number in sorted({c.block for c in RUN}):
        folder = tmp_path_factory.mktemp(f"readme-block-{number}")
        placeholder_files(folder)
        found[number] = Block(folder)
    return found


def promised(words: tuple[str, ...], folder: Path) -> list[Path]:
    """Return the files a command promises (the README: an ``-o OUT`` holds results.csv, report.html, ...)."""
    command, written = words[1], output_of(words)
    if command == "plot" and written:
        return [folder / written]  # a figure file
    if command == "plot":
        return [folder / words[2] / "figures"]
    if command == "report":
        return [folder / words[2] / "report.html"]
    if written is None:
        return []
    files = [folder / written / name for name in ("report.html", "results.csv", "study.toml")]
    if command == "demo":
        files.append(folder / written / "top-1.top")  # what the next commands read
    return files


def test_the_readme_has_the_commands_this_test_knows():
    """A README without its blocks (a renamed fence, say) would make this test pass on nothing."""
    assert len(RUN) >= 30 and {words[1] for c in RUN for words in c.steps} >= {
        "demo", "inspect", "plot", "contact", "friction", "friction-compare", "adhesion", "asperity",
        "presliding", "loop-analysis", "nanoindent", "cite", "validate", "run", "report", "models",
    }  # fmt: skip
    used = {word for c in RUN for words in c.steps for word in words}
    assert set(PLACEHOLDERS) <= used, f"placeholders the README no longer names: {set(PLACEHOLDERS) - used}"


@pytest.mark.parametrize("command", OTHER, ids=lambda c: c.id)
def test_the_developer_commands_are_makefile_targets(command):
    words = command.steps[0]
    assert words[0] == "make" and len(words) == 2, f"a README command this test does not know: {command.line}"
    targets = re.findall(r"^([A-Za-z0-9_-]+):", (ROOT / "Makefile").read_text(), flags=re.M)
    assert words[1] in targets


@pytest.mark.parametrize("command", RUN, ids=lambda c: c.id)
def test_a_readme_command_runs_as_written(command, blocks, capsys):
    block = blocks[command.block]
    status, out, err = block.run(command, capsys, blocks)
    assert status == 0, f"{command.line}\n{err[-3000:]}"
    for words in command.steps:
        for path in promised(words, block.folder):
            assert path.exists(), f"{command.line}: no {path.relative_to(block.folder)}"
        verb = words[1]
        if verb == "inspect" and "--json" in words:
            document = json.loads(out)
            if "--size" in words:  # read with the size the command gives
                size = quantity(words[words.index("--size") + 1], "length")
                assert document["size_m"] == pytest.approx([size, size], rel=1e-12)
        elif verb in ("inspect", "validate", "models", "friction") and output_of(words) is None:
            assert out.strip(), f"{command.line} printed nothing"
        elif verb == "cite":
            assert out.lstrip().startswith("@") and "doi = {" in out
