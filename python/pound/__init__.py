"""pound: probabilistic seismic pounding assessment of adjacent buildings, in Python.

The engine of the ``pound`` program as a module, built from the same sources with the same
numbers (docs/python.md):

    import pound
    r = pound.simulate("studies/ch8-five-three.ini", contact__model="hc-linear", pair1__gap=0.02)
    r["buildings"][1]["floors"][2]["disp_amplification"]

- simulate(study, motion=None, histories=False, **overrides): ``pound simulate --json``
- impact(config=None, **keys): ``pound impact --json``
- hysteresis(law, drifts, **keys): ``pound hysteresis`` on an array of drifts
- motion: read_record, response_spectrum, design_spectrum, generate, log_spaced_periods
- open_campaign(path): a campaign result file as a CampaignFile (samples, parameters,
  buildings, floors, intensity levels, responses, amplification)
- read_campaign(path, floors=False): a campaign result file as a pandas DataFrame
- fragility(campaign, out=None, **options): ``pound fragility --json``
- risk(campaign, hazard, out=None, **options): ``pound risk --json``
- lognormal_cdf(x, theta, beta): the fragility curves' lognormal CDF
- G: standard gravity, 9.80665 m/s2 per g (the engine's constant)
- Error (a ValueError): bad input, with the command's one-line message;
  NumericalError (a RuntimeError): a numerical failure

Units are SI throughout. Simulations release the GIL while the engine works, so that threads
(concurrent.futures.ThreadPoolExecutor) run them on every core; fragility and risk, which read
HDF5, keep it.
"""

from ._engine import G, Error, NumericalError, __version__, git_revision
from ._simulate import UnusedKeyWarning, impact, simulate
from ._hysteresis import hysteresis
from ._campaign import CampaignFile, open_campaign, read_campaign
from ._analysis import fragility, lognormal_cdf, risk
from . import motion

Error.__module__ = "pound"
NumericalError.__module__ = "pound"
Error.__doc__ = ("Bad input: the message is the line the command prints after 'pound COMMAND: "
                 "error: ' (what, where, and what would be valid). A ValueError.")
NumericalError.__doc__ = ("A numerical failure of a simulation (the command's exit code 3): "
                          "non-finite state, step-size underflow, chatter. A RuntimeError.")

__all__ = ["simulate", "impact", "hysteresis", "open_campaign", "CampaignFile", "read_campaign",
           "fragility", "risk", "lognormal_cdf", "G", "motion", "Error", "NumericalError",
           "UnusedKeyWarning", "__version__", "git_revision"]
