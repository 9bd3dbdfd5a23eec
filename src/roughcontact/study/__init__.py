"""Studies: one TOML file describes a whole investigation; one command runs it, locally or on Dask.

>>> from roughcontact.study import load_study, run_study          # doctest: +SKIP
>>> study = load_study("examples/demo.toml")                       # validates everything first
>>> run_study(study, "demo-output", workers=2)                     # restartable with resume=True

:mod:`~roughcontact.study.config` reads and validates the file and expands the sweeps into cases;
:mod:`~roughcontact.study.run` runs them and stores each as it finishes;
:mod:`~roughcontact.study.outputs` and :mod:`~roughcontact.study.report` turn the stored records
into the results table, figures and the HTML report; :mod:`~roughcontact.study.kinds` holds one
module per model a study can name.
"""

from .config import Study, StudyError, load_study
from .run import RunSummary, run_study

__all__ = ["RunSummary", "Study", "StudyError", "load_study", "run_study"]
