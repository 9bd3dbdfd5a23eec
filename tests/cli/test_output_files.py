"""Output files follow the user's umask, and -o never silently replaces an earlier run (issue 15)."""

import os
import stat
import subprocess
import sys

SHARED = "../shared/data/topographies"
CONTACT = ("contact", f"{SHARED}/top-1.top", "--material", "SU-8")


def test_study_files_are_0644_under_umask_022(tmp_path):
    """In a fresh process (the umask is read once, at import): every file the study writes is 0644."""
    code = (
        "import os, sys; os.umask(0o022); from roughcontact.cli import main; "
        f"sys.exit(main(['contact', '{SHARED}/top-1.top', '--material', 'SU-8', '--pressure', '5 MPa', "
        f"'-o', r'{tmp_path / 'out'}']))"
    )
    subprocess.run([sys.executable, "-c", code], check=True, capture_output=True)
    files = [p for p in (tmp_path / "out").rglob("*") if p.is_file()]
    assert len(files) >= 5
    modes = {p.relative_to(tmp_path): oct(stat.S_IMODE(p.stat().st_mode)) for p in files}
    assert set(modes.values()) == {"0o644"}, modes


def test_the_same_command_resumes_and_other_options_need_overwrite(run, tmp_path):
    out = tmp_path / "out"
    status, _, err = run(*CONTACT, "--pressure", "5 MPa", "-o", out)
    assert status == 0, err
    first = (out / "results.csv").read_text()
    status, _, err = run(*CONTACT, "--pressure", "5 MPa", "-o", out)  # same options: its results reused
    assert status == 0 and (out / "results.csv").read_text() == first
    status, _, err = run(*CONTACT, "--pressure", "10 MPa", "-o", out)
    assert status == 2
    assert "earlier 'roughcontact contact' with other options" in err and "--overwrite" in err
    assert (out / "results.csv").read_text() == first  # nothing lost
    status, _, err = run(*CONTACT, "--pressure", "10 MPa", "-o", out, "--overwrite")
    assert status == 0, err
    assert (out / "results.csv").read_text() != first
    assert len(list((out / "cases" / "contact").glob("*.json"))) == 1  # the old case is gone


def test_plot_does_not_replace_a_figure_without_overwrite(run, tmp_path):
    figure = tmp_path / "top.png"
    assert run("plot", f"{SHARED}/top-1.top", "-o", figure)[0] == 0
    before = os.stat(figure).st_mtime_ns
    status, _, err = run("plot", f"{SHARED}/top-1.top", "-o", figure)
    assert status == 2 and "exists" in err and os.stat(figure).st_mtime_ns == before
    assert run("plot", f"{SHARED}/top-1.top", "-o", figure, "--overwrite")[0] == 0


def test_a_single_case_is_named_by_its_surface_and_load_not_its_hash(run, tmp_path):
    from roughcontact.study.outputs import read_study

    assert run(*CONTACT, "--pressure", "5 MPa", "-o", tmp_path / "out")[0] == 0
    (analysis,) = read_study(tmp_path / "out")[1]
    assert analysis.records[0].label == "surface, mean pressure 5 MPa"
