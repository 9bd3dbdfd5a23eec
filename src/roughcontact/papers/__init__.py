"""The seed papers' scenarios: their inputs, printed numbers and models, one module per paper.

* :mod:`.paper000`: the SiO2 tip on LPCVD polysilicon of paper 000 (samples, synthetic scans and
  tip, the model's inputs; :func:`~.paper000.paper000_simulation`);
* :mod:`.paper001`: the rough polymer ball on a wafer of paper 001 (Tables 1-2, the generated
  balls, :func:`~.paper001.run_case` on the model of :mod:`roughcontact.contact.presliding`, and the
  Mindlin reference of eqs. 10-12 in both readings, :func:`~.paper001.paper001_mindlin`);
* :mod:`.paper002`: the SU-8 island of paper 002 (printed moments, Table I, section IV's numbers
  and the paper-vs-ours table, the synthetic island :func:`~.paper002.paper002_island`);
  and its deterministic model, the island under a flat punch (:func:`~.paper002.compress_island`
  on :func:`roughcontact.contact.load_unload.load_unload`).

A scenario lives here, not in ``contact/``, ``asperity/`` or ``friction/``, because it combines a
topography, materials, a contact model and its analysis. Nothing here reads or writes files,
formats text or knows of the command line; the study models (:mod:`roughcontact.study.kinds`) and
the commands are the front doors.
"""
