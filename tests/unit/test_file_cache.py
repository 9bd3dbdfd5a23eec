"""Converted copies of instrument files (issue 36): a file is parsed once; a later read is the same scan."""

import json
import logging
import os
import shutil
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from roughcontact.errors import MissingMetadataError, UnsupportedFormatError
from roughcontact.topography import file_cache
from roughcontact.topography.io import list_channels, read_scan, read_topography

SCAN = Path(__file__).resolve().parents[2] / "src" / "roughcontact" / "data" / "top-1.top"


@pytest.fixture
def folder(tmp_path, monkeypatch):
    """A cache folder of this test only."""
    path = tmp_path / "copies"
    monkeypatch.setenv(file_cache.ENVIRONMENT_VARIABLE, str(path))
    return path


def copies(folder: Path) -> list[str]:
    return sorted(p.name for p in folder.iterdir()) if folder.exists() else []


def assert_same_types(first, second, where="info"):
    """Assert that two equal values hold the same Python types all the way down (tuples stay tuples)."""
    assert type(first) is type(second), where
    if isinstance(first, dict):
        for key, value in first.items():
            assert_same_types(value, second[key], f"{where}[{key!r}]")
    elif isinstance(first, tuple | list):
        for index, (one, other) in enumerate(zip(first, second, strict=True)):
            assert_same_types(one, other, f"{where}[{index}]")


def assert_same_scan(first, second):
    assert first.heights.dtype == second.heights.dtype
    np.testing.assert_array_equal(first.heights, second.heights)  # NaN where NaN
    assert first.heights.tobytes() == second.heights.tobytes()
    assert first.size == second.size and all(type(s) is float for s in second.size)
    assert type(second.size) is tuple and type(second.periodic) is bool
    assert first.periodic == second.periodic
    assert first.info == second.info
    assert_same_types(first.info, second.info)
    assert first.path == second.path


def whole_copy(folder: Path) -> bool:
    """Whether the folder holds exactly one copy, whose heights load and match its record."""
    heights, record = sorted(folder.glob("*.npy")), sorted(folder.glob("*.json"))
    if len(heights) != 1 or len(record) != 1 or heights[0].stem != record[0].stem:
        return False
    try:
        shape, dtype = json.loads(record[0].read_text())["heights"]
        loaded = np.load(heights[0], allow_pickle=False)
    except (ValueError, EOFError, KeyError):
        return False
    return [list(loaded.shape), str(loaded.dtype)] == [shape, dtype]


def test_a_second_read_is_the_same_scan_from_the_copy(folder, tmp_path):
    file = shutil.copy(SCAN, tmp_path / "scan.top")
    first = read_scan(file)
    assert len(copies(folder)) == 2  # KEY.npy and KEY.json
    second = read_scan(file)
    assert_same_scan(first, second)
    assert isinstance(second.info["history"], tuple)


def test_undefined_points_a_gzip_file_and_instrument_metadata_keep_their_values(folder, shared_topographies):
    for name in ("sur-2.sur", "matrix-4.txt.gz", "di-3.di", "dektak-1.csv"):
        first = read_scan(shared_topographies / name)
        assert_same_scan(first, read_scan(shared_topographies / name))
        if name == "sur-2.sur":
            assert np.isnan(first.heights).sum() == 117
        if name == "dektak-1.csv":  # nested dicts of the instrument's parameters
            assert isinstance(first.info["instrument"]["parameters"]["tip_radius"], dict)


def test_a_read_from_the_copy_says_so_at_info_level(folder, tmp_path, caplog):
    file = shutil.copy(SCAN, tmp_path / "scan.top")
    read_scan(file)
    with caplog.at_level(logging.DEBUG, logger=file_cache.__name__):
        read_scan(file)
    [record] = [r for r in caplog.records if r.name == file_cache.__name__]
    assert record.levelno == logging.INFO  # roughcontact -v shows it
    assert record.getMessage().startswith("read scan.top (scan) from its converted copy ")


def test_a_read_from_the_copy_loads_no_reader(folder, tmp_path):
    file = shutil.copy(SCAN, tmp_path / "scan.top")
    script = (
        "import sys\n"
        "from roughcontact.topography.io import list_channels, read_topography\n"
        f"list_channels({str(file)!r}), read_topography({str(file)!r})\n"
        "print('SurfaceTopography' in sys.modules)\n"
    )
    environment = os.environ | {file_cache.ENVIRONMENT_VARIABLE: str(folder)}
    runs = [
        subprocess.run(
            [sys.executable, "-c", script], capture_output=True, text=True, env=environment, check=True
        )
        for _ in range(2)
    ]
    assert [run.stdout.strip() for run in runs] == ["True", "False"]


def test_the_channel_list_is_kept_too(folder, shared_topographies):
    first = list_channels(shared_topographies / "di-3.di")
    assert len(first) > 1 and len(copies(folder)) == 1  # a record, no heights
    assert list_channels(shared_topographies / "di-3.di") == first


def test_a_record_without_a_scan_s_keys_is_read_afresh(folder, tmp_path):
    file = shutil.copy(SCAN, tmp_path / "scan.top")
    first = read_scan(file)
    record = next(folder.glob("*.json"))
    stored = json.loads(record.read_text())
    stored["record"] = json.dumps({"size": [1.0, 1.0]})
    record.write_text(json.dumps(stored))
    assert_same_scan(first, read_scan(file))


def test_a_record_without_the_channel_list_is_read_afresh(folder, tmp_path):
    file = shutil.copy(SCAN, tmp_path / "scan.top")
    first = list_channels(file)
    record = next(folder.glob("*.json"))
    stored = json.loads(record.read_text())
    stored["record"] = json.dumps({"size": [1.0, 1.0]})
    record.write_text(json.dumps(stored))
    assert list_channels(file) == first


def test_a_changed_file_is_read_again(folder, tmp_path):
    file = tmp_path / "matrix.txt"
    np.savetxt(file, np.arange(16.0).reshape(4, 4))
    before = read_topography(file, size="1 um", height_unit="nm", detrend="none")  # a plane: keep it
    np.savetxt(file, 2 * np.arange(16.0).reshape(4, 4))
    after = read_topography(file, size="1 um", height_unit="nm", detrend="none")
    np.testing.assert_allclose(after.heights, 2 * before.heights)
    assert len(copies(folder)) == 4


def test_a_copy_of_the_file_under_another_name_has_its_own_name(folder, tmp_path):
    first = read_scan(shutil.copy(SCAN, tmp_path / "a.top"))
    second = read_scan(shutil.copy(SCAN, tmp_path / "b.top"))
    assert (first.info["name"], second.info["name"]) == ("a.top", "b.top")
    assert second.info["source"].endswith("b.top")


@pytest.mark.parametrize(
    "options",
    [
        {"channel": 0},
        {"height_unit": "um", "override_file_values": True},
        {"size": "1 um", "override_file_values": True},
        {"periodic": True},
    ],
)
def test_other_options_are_another_copy(folder, tmp_path, options):
    file = shutil.copy(SCAN, tmp_path / "scan.top")
    plain = read_scan(file)
    other = read_scan(file, **options)
    assert len(copies(folder)) == 4
    assert_same_scan(read_scan(file, **options), other)
    assert_same_scan(read_scan(file), plain)


@pytest.mark.parametrize(
    ("suffix", "damage"),
    [
        (".npy", lambda content: content[:100]),  # a torn write
        (".npy", lambda content: content[: len(content) // 2]),
        (".npy", lambda content: b""),  # a rename not flushed before a crash
        (".npy", lambda content: b"garbage"),
        (".json", lambda content: content[: len(content) // 2]),
        (".json", lambda content: b""),
        (".json", lambda content: json.dumps({"shape": [1, 1]}).encode()),
        (".json", lambda content: content.replace(b"[256, 256]", b"[256, 255]")),
    ],
)
def test_a_damaged_copy_is_read_afresh_and_written_again(folder, tmp_path, suffix, damage):
    file = shutil.copy(SCAN, tmp_path / "scan.top")
    first = read_scan(file)
    part = next(folder.glob(f"*{suffix}"))
    part.write_bytes(damage(part.read_bytes()))
    assert not whole_copy(folder)
    assert_same_scan(first, read_scan(file))
    assert whole_copy(folder)  # written again
    assert_same_scan(first, read_scan(file))


def test_off_keeps_no_copy(tmp_path, monkeypatch):
    monkeypatch.setenv(file_cache.ENVIRONMENT_VARIABLE, "off")
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path / "xdg"))
    read_scan(SCAN)
    assert file_cache.cache_folder() is None
    assert not (tmp_path / "xdg").exists()


def test_the_default_folder_is_in_the_user_cache(tmp_path, monkeypatch):
    monkeypatch.delenv(file_cache.ENVIRONMENT_VARIABLE)
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path))
    assert file_cache.cache_folder() == tmp_path / "roughcontact" / "files"


def test_a_cache_folder_that_cannot_be_made_does_not_fail_the_read(tmp_path, monkeypatch):
    blocker = tmp_path / "not-a-folder"
    blocker.write_text("")
    monkeypatch.setenv(file_cache.ENVIRONMENT_VARIABLE, str(blocker))
    assert_same_scan(read_scan(SCAN), read_scan(SCAN))


def test_a_cache_folder_that_cannot_be_written_does_not_fail_the_read(folder, tmp_path, monkeypatch):
    file = shutil.copy(SCAN, tmp_path / "scan.top")
    first = read_scan(file)
    kept = copies(folder)

    def refused(path):
        raise PermissionError(13, "Permission denied", str(path))

    monkeypatch.setattr(file_cache, "replacing", refused)  # as a read-only folder refuses
    other = read_scan(file, periodic=True)
    assert other.periodic and copies(folder) == kept
    assert_same_scan(first, read_scan(file))  # the copies there are still read


@pytest.mark.skipif(os.name != "posix" or os.geteuid() == 0, reason="root writes to read-only folders")
def test_a_read_only_cache_folder_does_not_fail_the_read(folder, tmp_path):
    file = shutil.copy(SCAN, tmp_path / "scan.top")
    first = read_scan(file)
    kept = copies(folder)
    folder.chmod(0o555)
    try:
        assert read_scan(file, periodic=True).periodic
        assert_same_scan(first, read_scan(file))
        assert copies(folder) == kept
    finally:
        folder.chmod(0o755)


def test_a_refused_read_keeps_nothing(folder, shared_topographies):
    with pytest.raises(MissingMetadataError):
        read_scan(shared_topographies / "xyz-1.txt")
    with pytest.raises(UnsupportedFormatError):
        read_scan(shared_topographies / "nonsense_txt_file.txt")
    assert copies(folder) == []
    read_scan(shared_topographies / "xyz-1.txt", position_unit="um", height_unit="um")
    assert len(copies(folder)) == 2  # the same file, given what it lacks


def test_the_least_recently_used_copies_go_beyond_the_limit(folder, tmp_path):
    files = [shutil.copy(SCAN, tmp_path / f"scan{i}.top") for i in range(3)]
    for file in files:
        read_scan(file)
    stamps = sorted(folder.glob("*.npy"), key=lambda p: p.stat().st_mtime)
    for age, copy in enumerate(stamps):  # the first read is the oldest
        for part in (copy, copy.with_suffix(".json")):
            os.utime(part, (1000.0 + age, 1000.0 + age))
    read_scan(files[0])  # used again: now the newest
    one = sum(p.stat().st_size for p in folder.iterdir()) // 3
    assert file_cache.prune(folder, limit=2 * one + 1) == 1
    kept = {p.stem for p in folder.iterdir()}
    assert stamps[0].stem in kept and stamps[1].stem not in kept and stamps[2].stem in kept


def test_the_folder_stays_within_the_limit(folder, tmp_path, monkeypatch):
    files = [shutil.copy(SCAN, tmp_path / f"scan{i}.top") for i in range(4)]
    read_scan(files[0])
    one = sum(p.stat().st_size for p in folder.iterdir())
    monkeypatch.setattr(file_cache, "LIMIT", 2 * one + one // 2)
    for file in files[1:]:
        read_scan(file)
        assert sum(p.stat().st_size for p in folder.iterdir()) <= file_cache.LIMIT
    assert len(copies(folder)) == 4  # the two copies read last
    assert_same_scan(read_scan(files[3]), read_scan(files[3]))
