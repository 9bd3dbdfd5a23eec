r"""Studies: one TOML file describes a whole investigation; one command runs it, locally or on Dask.

>>> from roughcontact.study import answer, load_study             # doctest: +SKIP
>>> study = load_study("examples/demo.toml")                       # validates everything first
>>> result = answer(study)                                          # in memory, nothing written
>>> result = answer(study, "demo-output", workers=2)                # restartable with resume=True
>>> print("\n".join(result.text_lines()))                           # what the commands print

:mod:`~roughcontact.study.config` reads and validates the file and expands the sweeps into cases;
:mod:`~roughcontact.study.answers` is the one entry point that runs them (in memory, or through
:mod:`~roughcontact.study.run`, which stores each as it finishes) and renders the answer as text
(numbers through :mod:`~roughcontact.study.display`) or JSON;
:mod:`~roughcontact.study.outputs` and :mod:`~roughcontact.study.report` turn the stored records
into the results table, figures and the HTML report; :mod:`~roughcontact.study.kinds` holds one
module per model a study can name.
"""

from .answers import StudyAnswer, answer
from .config import Study, StudyError, load_study
from .run import RunSummary, run_study

__all__ = ["RunSummary", "Study", "StudyAnswer", "StudyError", "answer", "load_study", "run_study"]
