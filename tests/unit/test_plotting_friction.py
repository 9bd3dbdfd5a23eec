"""Paper 000's friction figures say where the scans come from: a generated stand-in is not a measured scan."""

from dataclasses import dataclass

import pytest

from roughcontact.plotting.friction import friction_vs_load_figure, mu_boxes_figure, mu_means_figure


@dataclass
class _Case:
    """The part of a study case that the friction figures read."""

    parameters: dict
    scalars: dict
    label: str = ""
    has_fields: bool = False

    def dataset(self):
        return None


def _cases(origin, loads=(1e-6, 1e-5), scans=3):
    found = []
    for sample, mu in (("Ra 1.45 nm", 0.8), ("Ra 1.7 nm", 0.7)):
        for load in loads:
            for replicate in range(scans):
                scalars = {
                    "mu": mu + 0.01 * replicate,
                    "adhesive_friction": 2e-6,
                    "mechanical_friction": 0.5 * load,
                }
                if origin is not None:
                    scalars["surface_origin"] = origin
                found.append(_Case({"sample": sample, "normal_force": load, "replicate": replicate}, scalars))
    return found


def _texts(figure):
    axes = figure.axes
    titles = [ax.get_title() for ax in axes]
    legends = [t.get_text() for ax in axes if ax.get_legend() for t in ax.get_legend().get_texts()]
    return titles, legends


@pytest.mark.parametrize("origin", ["synthetic", "measured"])
def test_the_figures_name_the_scans_origin(origin):
    titles, _ = _texts(friction_vs_load_figure(_cases(origin)))
    assert f"mean and range of 3 {origin} scans" in titles[0]
    one_load = _cases(origin, loads=(1e-5,))
    titles, _ = _texts(mu_boxes_figure(one_load))
    assert f"simulated on {origin} scans" in titles[0]
    _, legends = _texts(mu_means_figure(one_load))
    assert legends == [f"simulated on {origin} scans"]


def test_cases_that_do_not_say_their_origin_claim_none():
    titles, _ = _texts(friction_vs_load_figure(_cases(None)))
    assert "mean and range of 3 scans" in titles[0]
    _, legends = _texts(mu_means_figure(_cases(None, loads=(1e-5,))))
    assert legends == ["simulated"]
