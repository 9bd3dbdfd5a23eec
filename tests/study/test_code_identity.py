"""A stored case is reused only by the code that computed it (issue 32: make demo reused older results)."""

import json

from roughcontact._version import code_fingerprint, code_identity
from roughcontact.study.store import sealed

STUDY = """
[study]
name = "identity"

[topographies.surface]
generate = "self_affine"
shape = 32
size = "1 um"
hurst = 0.8
rms_height = "1 nm"
seed = 1

[[analysis]]
name = "contact"
model = "normal"
topography = "surface"
material = "polysilicon"
sweep.mean_pressure = ["5 MPa", "20 MPa"]
"""


def test_the_identity_of_the_running_code():
    identity = code_identity()
    assert identity["fingerprint"] == code_fingerprint() and len(identity["fingerprint"]) == 16
    assert identity["version"]
    assert identity["commit"] is None or len(identity["commit"]) == 12


def test_cases_stored_by_other_code_are_recomputed_with_a_note(tmp_path, cli):
    study = tmp_path / "study.toml"
    study.write_text(STUDY)
    output = tmp_path / "out"
    status, out, _ = cli("run", study, "-o", output, "--no-progress")
    assert status == 0 and "2 cases run, 0 reused" in out
    records = sorted((output / "cases" / "contact").glob("*.json"))
    stored = json.loads(records[0].read_text())
    assert stored["code"] == code_identity()
    status, out, err = cli("run", study, "-o", output, "--resume", "--no-progress")
    assert "0 cases run, 2 reused" in out and "other code" not in err
    stored["code"]["fingerprint"] = "0123456789abcdef"  # as an older roughcontact would have left it,
    records[0].write_text(json.dumps(sealed(stored)))  # sealed as it would have sealed it
    status, out, err = cli("run", study, "-o", output, "--resume", "--no-progress")
    assert status == 0 and "1 case run, 1 reused" in out
    assert (
        "1 case stored by other code (another version of roughcontact, or changed sources) was recomputed"
        in err
    )
    assert json.loads(records[0].read_text())["code"] == code_identity()
    assert "checksum mismatch" not in err
