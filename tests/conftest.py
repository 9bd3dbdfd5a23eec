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
