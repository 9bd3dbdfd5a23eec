"""Shared fixtures: the real instrument files in ../shared/data/topographies."""

from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
SHARED_TOPOGRAPHIES = ROOT.parent / "shared" / "data" / "topographies"


@pytest.fixture(scope="session")
def shared_topographies() -> Path:
    """Directory of the real instrument files (CI has ../shared beside the clone)."""
    if not SHARED_TOPOGRAPHIES.is_dir():
        pytest.fail(
            f"real instrument files not found at {SHARED_TOPOGRAPHIES}; clone with ../shared beside it"
        )
    return SHARED_TOPOGRAPHIES


@pytest.fixture(scope="session", autouse=True)
def fftw_wisdom_of_the_session(tmp_path_factory):
    """FFTW wisdom goes to a file of this session, not the user's cache (subprocesses inherit it)."""
    import os

    from roughcontact import _fftw_wisdom

    path = tmp_path_factory.mktemp("fftw") / "wisdom.json"
    previous = os.environ.get(_fftw_wisdom.ENVIRONMENT_VARIABLE)
    os.environ[_fftw_wisdom.ENVIRONMENT_VARIABLE] = str(path)
    yield path
    if previous is None:
        del os.environ[_fftw_wisdom.ENVIRONMENT_VARIABLE]
    else:
        os.environ[_fftw_wisdom.ENVIRONMENT_VARIABLE] = previous
