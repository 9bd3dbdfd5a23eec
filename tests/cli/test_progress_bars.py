"""A command draws progress bars on a terminal only."""


def test_a_command_in_a_pipe_prints_no_bar(run, shared_topographies):
    args = ("presliding", "--paper001", "--pixels", "64", "--window", "32", "--steps-per-stroke", "6")
    status, out, err = run(*args, "--cycles", "2", "--normal-forces", "25 mN")
    assert status == 0, err
    assert "%|" not in err and "tangential steps" not in err and "cases" not in err


def test_on_a_terminal_a_long_case_shows_its_steps(run, monkeypatch):
    monkeypatch.setattr("sys.stderr.isatty", lambda: True)
    args = ("presliding", "--paper001", "--pixels", "64", "--window", "32", "--steps-per-stroke", "6")
    status, out, err = run(*args, "--cycles", "2", "--normal-forces", "25 mN", "50 mN")
    assert status == 0, err
    assert "tangential steps" in err and "cases" in err
