"""Progress bars of long computations: on a terminal only, never in a library call or a pipe."""

import io

from roughcontact.progress import shown, tracked


def test_loops_are_untouched_unless_the_caller_asks():
    items = [1, 2, 3]
    assert tracked(items) is items
    with shown(False):
        assert tracked(items) is items


def test_inside_shown_a_loop_draws_a_bar_and_still_yields_every_item(monkeypatch):
    stream = io.StringIO()
    monkeypatch.setattr("sys.stderr", stream)
    with shown():
        assert list(tracked(range(4), what="tangential steps")) == [0, 1, 2, 3]
    assert "tangential steps" in stream.getvalue()
    assert tracked([1]) == [1]  # off again after the block
