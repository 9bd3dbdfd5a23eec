"""Sphinx extension: write the command-line reference from the parsers themselves.

``docs/cli.md`` (not kept in git) gets one section per command with its ``--help`` text, as
``roughcontact COMMAND --help`` prints it, so the reference cannot drift from the program.
"""

from __future__ import annotations

from pathlib import Path


def reference() -> str:
    """Return the Markdown of the command-line reference."""
    from roughcontact.cli import GROUPS, build_parser

    parser = build_parser()
    commands = next(a for a in parser._subparsers._actions if a.dest == "command").choices
    lines = [
        "# Command-line reference",
        "",
        "Written from the program's own parsers at every build: each section is what "
        "`roughcontact COMMAND --help` prints. Values with units are typed as strings with the unit "
        "(`'20 MPa'`, `'5 um'`); `roughcontact models NAME` lists a study model's keys.",
        "",
        "```text",
        parser.format_help().rstrip(),
        "```",
        "",
    ]
    for group in GROUPS:
        for name in group.COMMANDS:
            lines += [
                f"## `roughcontact {name}`",
                "",
                "```text",
                commands[name].format_help().rstrip(),
                "```",
                "",
            ]
    return "\n".join(lines)


def write_reference(app, config) -> None:
    """Write ``cli.md`` into the source folder when it changed (Sphinx ``config-inited``)."""
    page = Path(app.srcdir) / "cli.md"
    text = reference()
    if not page.exists() or page.read_text() != text:
        page.write_text(text)


def setup(app):
    """Register the writer."""
    app.connect("config-inited", write_reference)  # before Sphinx lists the source files
    return {"parallel_read_safe": True, "version": "1"}
