"""The loaded FE tire (``[tire] model = "loaded-fe"``): the paper's own kind of FE tire.

The cross-section tire's construction swept into 27-node layered solids (:mod:`.mesh`,
:mod:`.solid`), its layers hyperelastic and consistent with the small-strain moduli
(:mod:`.material`), the follower inflation pressure (:mod:`.pressure`); mounted, inflated and
pressed on the flat road or a drum by large-deformation statics (:mod:`.statics`: Newton on the
supports; :mod:`.road_contact`: frictionless one-sided contact; :mod:`.loading`: to a load case's
load), then linearised about that loaded state for its footprint FRFs (:mod:`.dynamics`, their
reference solve :mod:`.direct`) on tasselli of its own footprint (:mod:`.footprint`), the air of its
loaded cavity coupled where its file enables it (:mod:`.cavity`); the paper's modal reduction on
its loaded modes (:mod:`.modal`). :mod:`.linearised` holds the tire linearised
about its round or inflated state (the waveguide tire of the same file, with the circumference in
elements instead of harmonics: the verification). :mod:`.spec` reads its tire file,
:mod:`roadnoise_utils.tire.loaded.stages` caches its stages and :mod:`roadnoise_utils.tire.loaded.model`
answers the tire-model interface.
"""
