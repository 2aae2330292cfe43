"""The RM tire for the user's vehicle tools: an FMI 2.0 co-simulation FMU and state-space files.

* :mod:`.tables` — the tire's numbers at one speed and step (road taps, modal sections)
* :mod:`.export` — the FMU: model description, resources, the C source compiled at export
* :mod:`.drive` — driving an FMU from Python with fmpy (a standard FMU runner)
* :mod:`.statespace_files` — the fixed- and moving-hub state spaces as MATLAB ``.mat`` files
"""
