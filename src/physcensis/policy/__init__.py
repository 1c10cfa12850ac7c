"""Policies learned from demonstrations and evaluated in unseen generated scenes (the `policy` extra).

    from physcensis import policy
    trained = policy.train("demos/demos.hdf5", "runs/bc")
    result = policy.evaluate("runs/bc", "scenes/unseen", "runs/bc/eval")
    result.reaching.rate, result.placing.rate

torch and robomimic are imported only when a policy is trained, loaded or evaluated.
"""

from __future__ import annotations

from physcensis.policy.backend import INSTALL, MissingLearnerError, PolicyError
from physcensis.policy.checkpoint import Policy, load_policy
from physcensis.policy.evaluate import EpisodeResult, EvalResult, EvalSettings, Rate, evaluate, wilson
from physcensis.policy.train import TrainResult, TrainSettings, train

__all__ = [
    "INSTALL",
    "EpisodeResult",
    "EvalResult",
    "EvalSettings",
    "MissingLearnerError",
    "Policy",
    "PolicyError",
    "Rate",
    "TrainResult",
    "TrainSettings",
    "evaluate",
    "load_policy",
    "train",
    "wilson",
]
