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
def caches_of_the_session(tmp_path_factory):
    """FFTW wisdom and converted files go to folders of this session, not the user's cache.

    Subprocesses inherit them. The file cache stays on, so the suite reads through it.
    """
    import os

    from roughcontact import _fftw_wisdom
    from roughcontact.topography import file_cache

    paths = {
        _fftw_wisdom.ENVIRONMENT_VARIABLE: tmp_path_factory.mktemp("fftw") / "wisdom.json",
        file_cache.ENVIRONMENT_VARIABLE: tmp_path_factory.mktemp("converted-files"),
    }
    previous = {variable: os.environ.get(variable) for variable in paths}
    os.environ.update({variable: str(path) for variable, path in paths.items()})
    yield paths
    for variable, value in previous.items():
        if value is None:
            del os.environ[variable]
        else:
            os.environ[variable] = value
